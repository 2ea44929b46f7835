#pragma once
// Undoable label edits. Commands hold labels by value (rows move as labels are edited).
// A command whose edit the model refuses (an overlap) is marked obsolete and does nothing.

#include "core/labels.h"

#include <QUndoCommand>

namespace nb {

class LabelModel;

class AddLabelCommand : public QUndoCommand {
public:
    AddLabelCommand(LabelModel* model, Label label);
    void redo() override;
    void undo() override;

private:
    LabelModel* model_;
    Label label_;
};

class RemoveLabelCommand : public QUndoCommand {
public:
    RemoveLabelCommand(LabelModel* model, Label label);
    void redo() override;
    void undo() override;

private:
    LabelModel* model_;
    Label label_;
};

// Moves edges, renames, re-comments: `before` becomes `after`.
class EditLabelCommand : public QUndoCommand {
public:
    EditLabelCommand(LabelModel* model, Label before, Label after);
    void redo() override;
    void undo() override;

private:
    LabelModel* model_;
    Label before_, after_;
};

// Splits an interval at t into two with the same label.
class SplitLabelCommand : public QUndoCommand {
public:
    SplitLabelCommand(LabelModel* model, Label label, double t);
    void redo() override;
    void undo() override;

private:
    LabelModel* model_;
    Label whole_, left_, right_;
};

}  // namespace nb
