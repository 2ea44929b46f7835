#pragma once
// The details of a lab session (organ, specimen, needle tip, slab thickness, operator,
// protocol, notes): filled in for a new session, where it also asks for the parent folder,
// and edited later (Session ▸ Details…); every run recorded after carries them.

#include "core/session.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QPlainTextEdit;

namespace nb {

class SessionInfoDialog : public QDialog {
    Q_OBJECT
public:
    enum class Mode { New, Edit };
    // `parentFolder` is asked for in Mode::New only.
    SessionInfoDialog(Mode mode, const SessionInfo& info, const QString& parentFolder = {}, QWidget* parent = nullptr);

    SessionInfo info() const;  // the creation time of the given info is kept
    QString parentFolder() const;

private:
    SessionInfo original_;
    QLineEdit* organ_;
    QLineEdit* specimen_;
    QComboBox* tip_;
    QDoubleSpinBox* thickness_;
    QLineEdit* operator_;
    QLineEdit* protocol_;
    QPlainTextEdit* notes_;
    QLineEdit* folder_ = nullptr;
};

}  // namespace nb
