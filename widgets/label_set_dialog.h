#pragma once
// Edits the label set of one protocol: add, rename and remove labels, their track, kind
// (interval phase or point event) and hotkey. Refuses, with a message in the dialog,
// duplicate labels, shared hotkeys and keys the review workspace already uses.

#include "label_model.h"

#include <QDialog>

class QLabel;
class QTableWidget;

namespace nb {

class LabelSetDialog : public QDialog {
    Q_OBJECT
public:
    enum Column { Track, Name, Kind, Hotkey, ColumnCount };
    LabelSetDialog(const QString& protocol, const QList<LabelDef>& defs, QWidget* parent = nullptr);

    // The set as edited; a hotkey that is not one plain key comes back as key -1.
    QList<LabelDef> definitions() const;
    // Why the edited set cannot be used; empty when it can.
    QString problem() const;
    QTableWidget* table() const { return table_; }
    void addRow(const LabelDef& def);

    void accept() override;

private:
    QTableWidget* table_;
    QLabel* error_;
};

}  // namespace nb
