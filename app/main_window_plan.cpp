// The main window's part of experiment plans (issue 16): the Plan dock, the session's plan.json
// opened (and resumed after a crash) with the session, the next run's settings set and locked
// in the control panel, the checklist as a hold on Start that the interlocks enforce, and each
// plan run's attempt recorded as `plan run` records it. Kept apart from main_window.cpp so the
// window's own file stays about the window.
#include "main_window.h"
#include "widgets/analysis/analysis_workspace.h"

#include "plan_runner.h"
#include "plan_walker.h"

#include "core/data_names.h"
#include "core/end_reason.h"
#include "core/plan.h"
#include "devices/acquisition_engine.h"
#include "devices/device_spec.h"
#include "widgets/control_panel.h"
#include "widgets/calibration_wizard.h"
#include "widgets/plan_panel.h"

#include <QDockWidget>
#include <QDir>
#include <QFileDialog>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QTimer>

namespace nb {

namespace {

QString statusText(const PlannedRun& r)
{
    switch (r.status) {
    case PlanRunStatus::Pending: {
        if (r.attempts.empty())
            return MainWindow::tr("pending");
        // Why it is made again, in the operator's words: the reason given for a redo, else how
        // the last attempt ended (shown as the session list shows it, not the file's key).
        const PlanAttempt& last = r.attempts.back();
        if (!last.discarded.isEmpty())
            return MainWindow::tr("again: %1").arg(last.discarded);
        const std::optional<EndReason> ended = endReasonFromFileName(last.result);
        return MainWindow::tr("again (%1)").arg(ended ? displayName(*ended) : last.result);
    }
    case PlanRunStatus::Running:
        return MainWindow::tr("running");
    case PlanRunStatus::Done:
        return MainWindow::tr("done");
    case PlanRunStatus::Skipped:
        return MainWindow::tr("skipped: %1").arg(r.reason);
    case PlanRunStatus::Redone:
        return MainWindow::tr("redone");
    }
    return {};
}

// One line of what a run will do, for the operator.
QString settingsLine(const QJsonObject& s, const devices::RunPlan& m, bool simulated)
{
    QStringList parts;
    if (m.motion == devices::RunPlan::Motion::Sine)
        parts << MainWindow::tr("sine ±%1 mm at %2 Hz, %3 cycles").arg(QLocale().toString(m.sine.amplitude_mm)).arg(QLocale().toString(m.sine.frequency_hz)).arg(m.sine.cycles);
    else
        parts << MainWindow::tr("linear to %1 mm at %2 mm/s").arg(QLocale().toString(m.linear.target_mm)).arg(QLocale().toString(m.linear.velocity_mm_s));
    QStringList specimen;
    if (s.contains(QStringLiteral("tissue")))
        specimen << tissueDisplayName(levelText(s.value(QStringLiteral("tissue"))));
    if (s.contains(QStringLiteral("tip")))
        specimen << tipDisplayName(levelText(s.value(QStringLiteral("tip"))));
    if (simulated && s.contains(QStringLiteral("seed")))
        specimen << MainWindow::tr("seed %1").arg(levelText(s.value(QStringLiteral("seed"))));
    if (!specimen.isEmpty())
        parts << specimen.join(QStringLiteral(", "));
    if (m.stopAtPuncture == 1)
        parts << MainWindow::tr("stop at the first puncture");
    else if (m.stopAtPuncture > 1)
        parts << MainWindow::tr("stop after %1 punctures").arg(m.stopAtPuncture);
    if (m.slowAfterPuncture_mm_s > 0.0)
        parts << MainWindow::tr("slow to %1 mm/s after a puncture").arg(QLocale().toString(m.slowAfterPuncture_mm_s));
    if (s.contains(QStringLiteral("max_force_n")))
        parts << MainWindow::tr("force limit %1 N").arg(QLocale().toString(s.value(QStringLiteral("max_force_n")).toDouble()));
    return parts.join(QStringLiteral(" · "));
}

// The plan's name in the operator's language. A template's identifier (e.g. "friction-imaging")
// is a key for files and scripts, not words: the template is named by its title, and only when
// the plan was renamed from it.
QString planHeading(const Plan& plan)
{
    const QString name = planTitleDisplayName(plan.name);
    const PlanTemplate* from = findPlanTemplate(plan.templateName);
    if (!from || from->title == plan.name)
        return name;
    return MainWindow::tr("%1 (from the template %2)").arg(name, planTitleDisplayName(from->title));
}

bool onSimulatedRig(const devices::DeviceSpec& spec)
{
    return spec.daq == QLatin1String("sim") && spec.stage == QLatin1String("sim");
}

}  // namespace

void MainWindow::buildPlanDock()
{
    planWalker_ = new PlanWalker(this);
    planPanel_ = new PlanPanel(this);
    planDock_ = new QDockWidget(tr("Plan"), this);
    planDock_->setObjectName(QStringLiteral("planDock"));
    planDock_->setWidget(planPanel_);
    // Beside the session's runs, below the plots: never more rows in the control panel.
    addDockWidget(Qt::BottomDockWidgetArea, planDock_);
    tabifyDockWidget(sessionDock_, planDock_);
    sessionDock_->raise();
    // Shown with a plan (or from the View menu): its tab bar takes rows from the run list.
    planDock_->hide();

    connect(planWalker_, &PlanWalker::changed, this, &MainWindow::showPlan);
    connect(planWalker_, &PlanWalker::armed, this, &MainWindow::armPlanRun);
    connect(planPanel_, &PlanPanel::itemToggled, this, [this](PlanPanel::Item item, bool on) {
        planWalker_->setChecked(item == PlanPanel::Item::Instruction ? PlanWalker::Check::Instruction
                                : item == PlanPanel::Item::Bias      ? PlanWalker::Check::Bias
                                                                     : PlanWalker::Check::Zero,
                                on);
    });
    connect(planPanel_, &PlanPanel::skipRequested, this, [this](const QString& reason) {
        const PlannedRun* r = planWalker_->nextRun();
        const int number = r ? r->number : 0;
        QString error;
        if (!planWalker_->skipNext(reason, &error))
            showMessage(error, true);
        else
            showMessage(tr("Plan run %1 skipped: %2").arg(number).arg(reason));
    });
    connect(planPanel_, &PlanPanel::redoRequested, this, [this](const QString& reason) {
        const int i = planWalker_->lastDoneIndex();
        QString error;
        if (!planWalker_->redo(i, reason, &error)) {
            showMessage(error, true);
        } else {
            showMessage(tr("Plan run %1 is made again: %2").arg(planWalker_->plan().runs[std::size_t(i)].number).arg(reason));
            if (session_)
                analysis_->openSession(session_->dir());  // the discarded run leaves the fits
        }
    });
    connect(planPanel_, &PlanPanel::leaveRequested, this, [this] {
        planWalker_->leave();
        showMessage(tr("Left the plan: the control panel is yours; runs made now are not the plan's."));
    });
    connect(planPanel_, &PlanPanel::rejoinRequested, planWalker_, &PlanWalker::rejoin);
    connect(planPanel_, &PlanPanel::newPlanRequested, this, &MainWindow::newPlanDialog);
}

void MainWindow::addPlanActions(QMenu* sessionMenu)
{
    QAction* fromTemplate = sessionMenu->addAction(tr("New &plan from template…"), this, &MainWindow::newPlanDialog);
    fromTemplate->setObjectName(QStringLiteral("actionNewPlan"));
    QAction* open = sessionMenu->addAction(tr("Open plan &file…"), this, [this] {
        if (!session_ || refused(Control::MotionSettings))
            return;
        // Qt's own chooser, never the desktop's: Esc must reach the emergency stop's filter.
        const QString path = QFileDialog::getOpenFileName(this, tr("Open plan file"), session_->dir(), tr("Plans (*.json)"), nullptr,
                                                          QFileDialog::DontUseNativeDialog);
        if (path.isEmpty())
            return;
        try {
            startPlan(readPlanFile(path));
        } catch (const PlanError& e) {
            QMessageBox::warning(this, tr("Open plan file"), e.message());
        }
    });
    open->setObjectName(QStringLiteral("actionOpenPlan"));
}

void MainWindow::newPlanDialog()
{
    if (!session_) {
        showMessage(tr("Open a session first: the plan is kept in it."), true);
        return;
    }
    if (refused(Control::MotionSettings))
        return;
    NewPlanDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const PlanTemplate* design = findPlanTemplate(dialog.templateName());
    const std::optional<PlanOrder> order = planOrderFromName(dialog.orderName());
    if (!design || !order)
        return;
    try {
        startPlan(generatePlan(*design, *order, dialog.seed()));
    } catch (const PlanError& e) {
        QMessageBox::warning(this, tr("New plan"), e.message());
    }
}

bool MainWindow::startPlan(const Plan& plan)
{
    if (refused(Control::MotionSettings))
        return false;
    QString error;
    if (!planWalker_->adopt(plan, &error)) {
        QMessageBox::warning(this, tr("Experiment plan"), error);
        return false;
    }
    planDock_->show();
    planDock_->raise();
    showMessage(tr("Plan \"%1\": %n run(s), kept in %2", nullptr, int(plan.runs.size()))
                    .arg(plan.name, QDir::toNativeSeparators(planWalker_->planPath())));
    return true;
}

void MainWindow::openSessionPlan()
{
    QString error;
    QStringList notes;
    if (!planWalker_->openSession(session_->dir(), &error, &notes))
        showMessage(tr("The session's plan could not be opened: %1").arg(error), true);
    if (!notes.isEmpty())
        showMessage(notes.join(QLatin1Char(' ')), true);
    planDock_->setVisible(planWalker_->hasPlan());
    if (planWalker_->hasPlan())
        planDock_->raise();
}

void MainWindow::armPlanRun()
{
    if (!planWalker_->walking()) {
        showPlan();
        return;
    }
    const PlannedRun* run = planWalker_->nextRun();
    const QJsonObject settings = planWalker_->nextSettings();
    const QString why = tr("Set by plan run %1 (%2); Leave plan in the Plan dock frees it.")
                            .arg(run->number)
                            .arg(describeRun(planWalker_->plan(), *run));
    if (const QString problem = panel_->lockMotion(cli::runPlanForSettings(settings), why); !problem.isEmpty()) {
        showMessage(tr("Plan run %1 cannot be set: %2. Left the plan.").arg(run->number).arg(problem), true);
        planWalker_->leave();
        return;
    }
    if (settings.contains(QStringLiteral("max_force_n")))
        panel_->setForceLimit(settings.value(QStringLiteral("max_force_n")).toDouble());
    // The rig changes once the event that armed this run has been handled (a run's end).
    planRigPending_ = true;
    QTimer::singleShot(0, this, &MainWindow::applyPlanRig);
    showPlan();
}

void MainWindow::applyPlanRig()
{
    if (!planRigPending_)
        return;
    const devices::DeviceSpec current = currentSpec();
    if (!planWalker_->walking() || !onSimulatedRig(current)) {
        planRigPending_ = false;  // real devices: the operator mounts what the instruction says
        return;
    }
    devices::DeviceSpec spec = current;
    spec.simulated = cli::simulatedRigForSettings(planWalker_->nextSettings(), current.simulated);
    if (devices::toJson(spec.simulated) == devices::toJson(current.simulated)) {
        planRigPending_ = false;
        return;
    }
    if (const QString problem = devices::checkSimulatedRig(spec.simulated); !problem.isEmpty()) {
        planRigPending_ = false;
        showMessage(tr("Plan run %1: %2").arg(planWalker_->nextRun()->number).arg(problem), true);
        return;
    }
    // Only at rest, as the operator's own change of rig (retried from the status).
    InterlockState state = engine_->status().interlocks();
    if (motionCommand_.isValid() && motionCommand_.elapsed() < 300)
        state.moving = true;
    if (!permission(Control::ChangeSetup, state).enabled || wizard_)
        return;
    planRigPending_ = false;
    if (switchDevices(spec))
        showMessage(tr("Simulated rig for plan run %1: %2, seed %3 (enable, bias and zero again)")
                        .arg(planWalker_->nextRun()->number)
                        .arg(spec.simulated.tissue)
                        .arg(spec.simulated.seed));
    planWalker_->engineReplaced();
}

void MainWindow::showPlan()
{
    PlanPanelView v;
    if (planWalker_->hasPlan()) {
        const Plan& plan = planWalker_->plan();
        v.hasPlan = true;
        v.walking = planWalker_->walking();
        // Any run or motion, the plan's or one made after leaving it: skip, redo, leave and
        // return would change the plan (and lock the panel to its settings) under a run.
        v.recording = planWalker_->attemptOpen() || planPanelBusy_;
        v.title = planHeading(plan);
        v.progress = planWalker_->progressText();
        if (const PlannedRun* r = planWalker_->nextRun()) {
            v.next = tr("Run %1: %2").arg(r->number).arg(describeRun(plan, *r));
            v.settings = settingsLine(planWalker_->nextSettings(), cli::runPlanForSettings(planWalker_->nextSettings()),
                                      onSimulatedRig(currentSpec()));
            v.instruction = r->instruction;
            // A template's plan says its instructions in the operator's language, whichever
            // language wrote plan.json; a plan written by hand keeps its own words.
            if (!plan.templateName.isEmpty() && !r->instruction.isEmpty()) {
                const std::size_t at = std::size_t(r - plan.runs.data());
                if (const QString now = operatorInstruction(plan, at ? &plan.runs[at - 1] : nullptr, *r); !now.isEmpty())
                    v.instruction = now;
            }
            v.nextRow = planWalker_->nextIndex();
        }
        v.instructionDone = planWalker_->checked(PlanWalker::Check::Instruction);
        v.biasDone = planWalker_->checked(PlanWalker::Check::Bias);
        v.zeroDone = planWalker_->checked(PlanWalker::Check::Zero);
        for (const PlannedRun& r : plan.runs) {
            QString line = tr("%1. %2 – %3").arg(r.number).arg(describeRun(plan, r), statusText(r));
            if (const PlanAttempt* a = r.currentAttempt())
                line += QStringLiteral(" (") + a->runFile + QLatin1Char(')');
            v.runs << line;
        }
        if (const int i = planWalker_->lastDoneIndex(); i >= 0)
            v.redoWhat = tr("run %1 (%2)").arg(plan.runs[std::size_t(i)].number).arg(describeRun(plan, plan.runs[std::size_t(i)]));
    }
    planPanel_->setView(v);
    if (!planWalker_->walking() && panel_->motionLocked())
        panel_->unlockMotion();
    panel_->setStartHold(planWalker_->hold());
}

bool MainWindow::beginPlanRun(devices::RunPlan& plan)
{
    if (!planWalker_->walking())
        return true;  // not a plan run
    QString path, error;
    Metadata metadata;
    if (!planWalker_->beginRun(plan.outPath, &path, &metadata, &error)) {
        showMessage(error, true);
        return false;
    }
    plan.outPath = path;
    for (const auto& [k, v] : metadata.entries())
        plan.metadata.set(k, v);
    return true;
}

void MainWindow::endPlanRun(const QString& endReason)
{
    if (!planWalker_->attemptOpen())
        return;
    const int number = planWalker_->plan().runs[std::size_t(planWalker_->nextIndex())].number;
    QString error;
    if (!planWalker_->finishRun(endReason, &error))
        showMessage(tr("Plan run %1 could not be recorded in plan.json: %2").arg(number).arg(error), true);
}

void MainWindow::planStatus(const devices::EngineStatus& status)
{
    planWalker_->noteEngineCounts(status.biasCount, status.zeroCount);
    if (const bool busy = status.recording || status.moving; busy != planPanelBusy_) {
        planPanelBusy_ = busy;
        showPlan();
    }
    if (planRigPending_ && !status.moving && !status.recording)
        applyPlanRig();
}

}  // namespace nb
