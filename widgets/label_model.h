#pragma once
// The labels of the run under review, as a table model (track, label, start_s, end_s,
// comment), with the protocol's label set (which labels exist, on which track, their hotkey
// and colour). Interval labels never overlap within a track; point labels may coincide.
// Edits from the GUI go through QUndoStack commands (label_commands.h), not these setters.

#include "core/labels.h"

#include <QAbstractTableModel>
#include <QColor>
#include <QList>

namespace nb {

struct LabelDef {
    QString track;
    QString label;
    bool point = false;
    int key = 0;  // Qt::Key, the label's hotkey
    QColor color;
};

// "friction": a, b1, b2, c on the insertion and withdrawal tracks (keys 1-4, 5-8);
// "stiffness" (and anything else): contact C, puncture P, relaxation R, internal puncture I.
QList<LabelDef> protocolLabelSet(const QString& protocol);
// The protocol's label set as last edited by the operator (QSettings "labelSets/<protocol>"),
// else protocolLabelSet(protocol); saveLabelSet() stores an edited set.
QList<LabelDef> savedLabelSet(const QString& protocol);
void saveLabelSet(const QString& protocol, const QList<LabelDef>& defs);

class LabelModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Track, Name, Start, End, Comment, ColumnCount };
    explicit LabelModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    const Labels& labels() const { return labels_; }
    void setLabels(Labels labels);
    const QList<LabelDef>& definitions() const { return defs_; }
    void setDefinitions(QList<LabelDef> defs);
    const LabelDef* definitionForKey(int key) const;
    QColor colorOf(const Label& l) const;
    QStringList tracks() const;  // label-set tracks first, then any others found in the labels

    // False when `l` would overlap another interval of its track (`ignore` excluded).
    bool canPlace(const Label& l, const Label* ignore = nullptr) const;
    // Returns false (and changes nothing) when the label cannot be placed / is not there.
    bool insertLabel(const Label& l);
    bool removeLabel(const Label& l);
    bool replaceLabel(const Label& before, const Label& after);
    // The interval of `track` covering t (nullptr if none).
    const Label* intervalAt(const QString& track, double t) const;

signals:
    void labelsChanged();

private:
    Labels labels_;
    QList<LabelDef> defs_;
};

}  // namespace nb
