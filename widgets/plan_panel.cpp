#include "plan_panel.h"
#include "core/data_names.h"
#include "core/plan.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace nb {

PlanPanel::PlanPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("planPanel"));
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);

    empty_ = new QLabel(tr("No experiment plan in this session. Session ▸ New plan from template… makes one; "
                           "its runs are then set here one after the other."),
                        this);
    empty_->setWordWrap(true);
    newPlan_ = new QPushButton(tr("New plan from template…"), this);
    newPlan_->setObjectName(QStringLiteral("planNew"));
    connect(newPlan_, &QPushButton::clicked, this, &PlanPanel::newPlanRequested);
    outer->addWidget(empty_);

    // The walker: what is next and its checklist on the left, the runs on the right. Wide and
    // low, for the bottom dock.
    walker_ = new QWidget(this);
    auto* row = new QHBoxLayout(walker_);
    row->setContentsMargins(0, 0, 0, 0);
    auto* left = new QVBoxLayout;
    left->setSpacing(2);
    title_ = new QLabel(walker_);
    title_->setObjectName(QStringLiteral("planTitle"));
    progress_ = new QLabel(walker_);
    progress_->setObjectName(QStringLiteral("planProgress"));
    // The plan's name, then where the walk stands: "friction under imaging  Run 1 of 15 · …";
    // the other way round the two read as one sentence ("… 5 min left friction under imaging").
    title_->setStyleSheet(QStringLiteral("font-weight: bold;"));
    auto* head = new QHBoxLayout;
    head->addWidget(title_);
    head->addWidget(progress_, 1);
    left->addLayout(head);
    next_ = new QLabel(walker_);
    next_->setObjectName(QStringLiteral("planNext"));
    settings_ = new QLabel(walker_);
    settings_->setObjectName(QStringLiteral("planSettings"));
    settings_->setStyleSheet(QStringLiteral("color: palette(mid);"));
    // Four rows at most: the dock shares the height with the plots on a 768 px laptop.
    settings_->setWordWrap(false);
    auto* nextRow = new QHBoxLayout;
    nextRow->addWidget(next_);
    nextRow->addWidget(settings_, 1);
    left->addLayout(nextRow);
    instruction_ = new QCheckBox(walker_);
    instruction_->setObjectName(QStringLiteral("planCheckInstruction"));
    bias_ = new QCheckBox(tr("Bias done"), walker_);
    bias_->setObjectName(QStringLiteral("planCheckBias"));
    bias_->setToolTip(tr("Ticks itself when the sensor has been biased since the last run"));
    zero_ = new QCheckBox(tr("Zero done"), walker_);
    zero_->setObjectName(QStringLiteral("planCheckZero"));
    zero_->setToolTip(tr("Ticks itself when the position has been zeroed since the last run"));
    // A check box's text never wraps: the German instruction ("Leber 7 einspannen. Die
    // 30-mm-Gewebescheibe einspannen. …") widened the window past a laptop's 1366 px. The box
    // says "Done:" and the instruction beside it wraps; a click on it ticks the box as well.
    instruction_->setText(tr("Done:"));
    instructionText_ = new QLabel(walker_);
    instructionText_->setObjectName(QStringLiteral("planInstruction"));
    instructionText_->setWordWrap(true);
    instructionText_->installEventFilter(this);
    auto* instructionRow = new QHBoxLayout;
    instructionRow->addWidget(instruction_, 0, Qt::AlignTop);
    instructionRow->addWidget(instructionText_, 1);
    left->addLayout(instructionRow);
    const std::pair<QCheckBox*, Item> items[] = {{instruction_, Item::Instruction}, {bias_, Item::Bias}, {zero_, Item::Zero}};
    for (const auto& [box, item] : items)
        connect(box, &QCheckBox::clicked, this, [this, item](bool on) { emit itemToggled(item, on); });
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(bias_);
    buttons->addWidget(zero_);
    buttons->addStretch();
    skip_ = new QPushButton(tr("Skip run…"), walker_);
    skip_->setObjectName(QStringLiteral("planSkip"));
    skip_->setToolTip(tr("Marks the next run skipped, with a reason, and moves on"));
    redo_ = new QPushButton(tr("Redo run…"), walker_);
    redo_->setObjectName(QStringLiteral("planRedo"));
    leave_ = new QPushButton(walker_);
    leave_->setObjectName(QStringLiteral("planLeave"));
    for (QPushButton* b : {skip_, redo_, leave_})
        buttons->addWidget(b);
    left->addLayout(buttons);
    left->addStretch();
    connect(skip_, &QPushButton::clicked, this, [this] {
        askReason(tr("Skip run"), tr("Why is %1 skipped?").arg(view_.next), &PlanPanel::skipRequested);
    });
    connect(redo_, &QPushButton::clicked, this, [this] {
        askReason(tr("Redo run"), tr("Why is %1 made again? Its attempt stays in the plan, marked discarded.").arg(view_.redoWhat),
                  &PlanPanel::redoRequested);
    });
    connect(leave_, &QPushButton::clicked, this, [this] { view_.walking ? emit leaveRequested() : emit rejoinRequested(); });
    row->addLayout(left, 3);
    runs_ = new QListWidget(walker_);
    runs_->setObjectName(QStringLiteral("planRuns"));
    runs_->setSelectionMode(QAbstractItemView::NoSelection);
    runs_->setFocusPolicy(Qt::NoFocus);
    runs_->setMinimumHeight(40);
    row->addWidget(runs_, 2);
    outer->addWidget(walker_);
    outer->addWidget(newPlan_, 0, Qt::AlignLeft);
    setView({});
}

QCheckBox* PlanPanel::checkBox(Item item) const
{
    return item == Item::Instruction ? instruction_ : item == Item::Bias ? bias_ : zero_;
}

QString PlanPanel::progressText() const { return progress_->text(); }

void PlanPanel::setView(const PlanPanelView& v)
{
    view_ = v;
    empty_->setVisible(!v.hasPlan);
    newPlan_->setVisible(!v.hasPlan);
    walker_->setVisible(v.hasPlan);
    if (!v.hasPlan)
        return;
    title_->setText(v.title);
    progress_->setText(v.progress);
    next_->setText(v.next.isEmpty() ? tr("Every run of the plan is completed.") : tr("Next: %1").arg(v.next));
    settings_->setText(v.settings);
    const bool ready = v.walking && !v.next.isEmpty();
    instruction_->setVisible(!v.instruction.isEmpty());
    instructionText_->setVisible(!v.instruction.isEmpty());
    instructionText_->setText(v.instruction);
    instruction_->setChecked(v.instructionDone);
    bias_->setChecked(v.biasDone);
    zero_->setChecked(v.zeroDone);
    for (QCheckBox* b : {instruction_, bias_, zero_})
        b->setEnabled(ready && !v.recording);
    instructionText_->setEnabled(instruction_->isEnabled());
    bias_->setVisible(!v.next.isEmpty());
    zero_->setVisible(!v.next.isEmpty());
    skip_->setEnabled(ready && !v.recording);
    redo_->setEnabled(!v.recording && !v.redoWhat.isEmpty());
    redo_->setToolTip(v.redoWhat.isEmpty() ? tr("No run of the plan is done yet") : tr("Makes %1 again, with a reason").arg(v.redoWhat));
    leave_->setText(v.walking ? tr("Leave plan") : tr("Return to plan"));
    leave_->setToolTip(v.walking ? tr("Releases the control panel's settings; runs made meanwhile are not the plan's")
                                 : tr("Sets and locks the next plan run's settings again"));
    leave_->setEnabled(!v.recording && !v.next.isEmpty());
    runs_->clear();
    runs_->addItems(v.runs);
    if (v.nextRow >= 0 && v.nextRow < runs_->count()) {
        QFont bold = runs_->font();
        bold.setBold(true);
        runs_->item(v.nextRow)->setFont(bold);
        runs_->scrollToItem(runs_->item(v.nextRow), QAbstractItemView::PositionAtCenter);
    }
}

bool PlanPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == instructionText_ && event->type() == QEvent::MouseButtonRelease && instruction_->isEnabled())
        instruction_->click();
    return QWidget::eventFilter(watched, event);
}

void PlanPanel::askReason(const QString& title, const QString& question, void (PlanPanel::*done)(const QString&))
{
    auto* dialog = new PlanReasonDialog(title, question, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, done] { emit(this->*done)(dialog->reason()); });
    dialog->open();
}

PlanReasonDialog::PlanReasonDialog(const QString& title, const QString& question, QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("planReasonDialog"));
    setWindowTitle(title);
    auto* layout = new QVBoxLayout(this);
    auto* label = new QLabel(question, this);
    label->setWordWrap(true);
    edit_ = new QLineEdit(this);
    edit_->setObjectName(QStringLiteral("planReason"));
    edit_->setPlaceholderText(tr("e.g. a vessel at this site"));
    auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    QPushButton* ok = box->button(QDialogButtonBox::Ok);
    ok->setEnabled(false);
    connect(edit_, &QLineEdit::textChanged, this, [ok](const QString& t) { ok->setEnabled(!t.trimmed().isEmpty()); });
    connect(box, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(label);
    layout->addWidget(edit_);
    layout->addWidget(box);
}

QString PlanReasonDialog::reason() const { return edit_->text().trimmed(); }

NewPlanDialog::NewPlanDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("newPlanDialog"));
    setWindowTitle(tr("New plan from template"));
    auto* form = new QFormLayout(this);
    template_ = new QComboBox(this);
    template_->setObjectName(QStringLiteral("planTemplate"));
    for (const PlanTemplate& t : planTemplates())
        template_->addItem(planTitleDisplayName(t.title), t.name);
    description_ = new QLabel(this);
    description_->setWordWrap(true);
    order_ = new QComboBox(this);
    order_->setObjectName(QStringLiteral("planOrder"));
    order_->addItem(tr("as listed"), QStringLiteral("listed"));
    order_->addItem(tr("randomised"), QStringLiteral("random"));
    order_->addItem(tr("blocked by site"), QStringLiteral("blocked"));
    seed_ = new QSpinBox(this);
    seed_->setObjectName(QStringLiteral("planSeed"));
    seed_->setRange(0, 999999);
    seed_->setValue(1);
    seed_->setToolTip(tr("Recorded in the plan: the same seed gives the same order"));
    form->addRow(tr("Template"), template_);
    form->addRow(QString(), description_);
    form->addRow(tr("Order"), order_);
    form->addRow(tr("Seed"), seed_);
    auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(box, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(box);
    const auto describe = [this] {
        const PlanTemplate* t = findPlanTemplate(templateName());
        description_->setText(t ? t->description : QString());
    };
    connect(template_, &QComboBox::currentIndexChanged, this, describe);
    describe();
}

QString NewPlanDialog::templateName() const { return template_->currentData().toString(); }
QString NewPlanDialog::orderName() const { return order_->currentData().toString(); }
quint64 NewPlanDialog::seed() const { return quint64(seed_->value()); }
void NewPlanDialog::setTemplate(const QString& name) { template_->setCurrentIndex(std::max(0, template_->findData(name))); }
void NewPlanDialog::setOrder(const QString& name) { order_->setCurrentIndex(std::max(0, order_->findData(name))); }

}  // namespace nb
