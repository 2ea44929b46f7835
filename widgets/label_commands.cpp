#include "label_commands.h"
#include "core/tr.h"

#include "label_model.h"

#include <QCoreApplication>

namespace nb {

AddLabelCommand::AddLabelCommand(LabelModel* model, Label label) : model_(model), label_(std::move(label))
{
    setText(nb::TrViews::tr("add %1").arg(label_.label));
}
void AddLabelCommand::redo() { setObsolete(!model_->insertLabel(label_)); }
void AddLabelCommand::undo() { model_->removeLabel(label_); }

RemoveLabelCommand::RemoveLabelCommand(LabelModel* model, Label label) : model_(model), label_(std::move(label))
{
    setText(nb::TrViews::tr("delete %1").arg(label_.label));
}
void RemoveLabelCommand::redo() { setObsolete(!model_->removeLabel(label_)); }
void RemoveLabelCommand::undo() { model_->insertLabel(label_); }

EditLabelCommand::EditLabelCommand(LabelModel* model, Label before, Label after)
    : model_(model), before_(std::move(before)), after_(std::move(after))
{
    setText(nb::TrViews::tr("edit %1").arg(before_.label));
}
void EditLabelCommand::redo() { setObsolete(!model_->replaceLabel(before_, after_)); }
void EditLabelCommand::undo() { model_->replaceLabel(after_, before_); }

SplitLabelCommand::SplitLabelCommand(LabelModel* model, Label label, double t) : model_(model), whole_(std::move(label))
{
    left_ = right_ = whole_;
    left_.end_s = t;
    right_.start_s = t;
    setText(nb::TrViews::tr("split %1").arg(whole_.label));
}
void SplitLabelCommand::redo()
{
    if (!(left_.start_s < left_.end_s && right_.start_s < right_.end_s) || !model_->removeLabel(whole_)) {
        setObsolete(true);
        return;
    }
    model_->insertLabel(left_);
    model_->insertLabel(right_);
}
void SplitLabelCommand::undo()
{
    model_->removeLabel(left_);
    model_->removeLabel(right_);
    model_->insertLabel(whole_);
}

}  // namespace nb
