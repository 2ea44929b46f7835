// Issue 16's scenario in the real window on the simulated rig: a child process (this program
// run again with --walk-child) walks three runs of a plan — checklist ticked, Start, the run's
// end — and starts the fourth; this process kills it with SIGKILL while plan.json says run four
// is running, then opens a fresh window on the same session and checks that the plan resumes at
// run four: its settings set and locked, "Run 4 of 5", runs 1-3 done with their run files and
// factor levels, run four's dead attempt recorded as interrupted. Then skip, leave and return
// work on the resumed plan, and a plan is made from a template through the Session menu.
#include "main_window.h"
#include "widgets/analysis/analysis_workspace.h"
#include "plan_walker.h"
#include "support/simulated_window.h"

#include "core/plan.h"
#include "core/plan_session.h"
#include "core/run_file.h"
#include "devices/acquisition_engine.h"
#include "devices/sim/simulated_rig.h"
#include "widgets/control_panel.h"
#include "widgets/plan_panel.h"

#include <QMessageBox>
#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QGroupBox>
#include <QLineEdit>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QListWidget>
#include <QtTest>
#include <csignal>
#include <cstdio>

using nb::Control;

namespace {

constexpr int kRuns = 5;
constexpr double kSlowVelocity_mm_s = 0.5;  // run four: long enough to be killed mid-run

// Five insertions at five sites, 12 mm at 10 mm/s, run four slow.
nb::Plan testPlan()
{
    nb::PlanTemplate design;
    design.name = QStringLiteral("walk-test");
    design.title = QStringLiteral("walk test");
    design.description = QStringLiteral("five short insertions");
    design.defaults = QJsonObject{{QStringLiteral("protocol"), QStringLiteral("stiffness")}, {QStringLiteral("motion"), QStringLiteral("linear")},
                                  {QStringLiteral("tissue"), QStringLiteral("liver1")},      {QStringLiteral("tip"), QStringLiteral("beveled")},
                                  {QStringLiteral("velocity_mm_s"), 10.0},                   {QStringLiteral("depth_mm"), 12.0}};
    nb::PlanFactor site{QStringLiteral("site"), {}, true};
    for (int i = 1; i <= kRuns; ++i)
        site.levels.emplace_back(i);
    design.factors = {site};
    nb::Plan plan = nb::generatePlan(design, nb::PlanOrder::Listed, 7);
    plan.runs[3].settings.insert(QStringLiteral("velocity_mm_s"), kSlowVelocity_mm_s);
    return plan;
}

QAction* menuAction(nb::MainWindow& w, const QString& text)
{
    for (QAction* a : w.menuBar()->findChildren<QAction*>())
        if (a->text() == text)
            return a;
    return nullptr;
}

// Waits while processing events; false when `ready` did not come true in time.
bool waitFor(const std::function<bool()>& ready, int ms = 30000)
{
    QElapsedTimer t;
    t.start();
    while (!ready()) {
        if (t.elapsed() > ms)
            return false;
        QTest::qWait(10);
    }
    return true;
}

int childFail(const char* what)
{
    std::fprintf(stderr, "walk child: %s\n", what);
    return 2;
}

// One plan run as an operator makes it in the window: the rig switched for the run (a new
// engine), enable, bias, zero (the checklist ticks those itself), the operator's step ticked by
// hand, Start. `oldEngine` is the engine of the run before, replaced for this run's rig.
int childStartRun(nb::MainWindow& w, const nb::devices::AcquisitionEngine* oldEngine)
{
    nb::ControlPanel* p = w.controlPanel();
    nb::PlanPanel* plan = w.planPanel();
    if (!waitFor([&] { return w.engine() != oldEngine; }))
        return childFail("the rig was not switched for the run");
    // The new engine's own status, not the panel's last (the old engine's may trail it).
    if (!waitFor([&] { return w.engine()->status().running; }))
        return childFail("devices not running");
    if (!p->motionLocked())
        return childFail("the run's settings are not locked");
    if (!waitFor([&] { return p->button(Control::Enable)->isEnabled() && !p->interlockState().stageEnabled; }))
        return childFail("the new rig's stage is not offered to enable");
    p->button(Control::Enable)->click();
    if (!waitFor([&] { return w.engine()->status().stageEnabled && p->interlockState().stageEnabled; }))
        return childFail("stage not enabled");
    if (p->button(Control::StartInsertion)->isEnabled())
        return childFail("Start enabled before bias and zero");
    if (plan->checkBox(nb::PlanPanel::Item::Bias)->isChecked() || plan->checkBox(nb::PlanPanel::Item::Zero)->isChecked())
        return childFail("bias or zero ticked before they were done for this run");
    p->button(Control::Bias)->click();
    if (!waitFor([&] { return plan->checkBox(nb::PlanPanel::Item::Bias)->isChecked(); }))
        return childFail("bias not ticked by the engine's report");
    if (!waitFor([&] { return p->button(Control::Zero)->isEnabled(); }))
        return childFail("zero not enabled");
    p->button(Control::Zero)->click();
    if (!waitFor([&] { return plan->checkBox(nb::PlanPanel::Item::Zero)->isChecked(); }))
        return childFail("zero not ticked by the engine's report");
    QCheckBox* step = plan->checkBox(nb::PlanPanel::Item::Instruction);
    if (!step->isVisible() || step->isChecked())
        return childFail("the operator's step is not offered unticked");
    // The step unticked holds Start back, whatever else is ready.
    QTest::qWait(100);
    if (p->button(Control::StartInsertion)->isEnabled())
        return childFail("Start enabled with the operator's step unticked");
    QTest::mouseClick(step, Qt::LeftButton, {}, QPoint(5, step->height() / 2));
    if (!waitFor([&] { return p->button(Control::StartInsertion)->isEnabled(); }))
        return childFail(qPrintable(QStringLiteral("Start not enabled: ") + p->button(Control::StartInsertion)->toolTip()));
    QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
    return 0;
}

// The rig as the operator waits for it after start: the devices run, the stage rests, and the
// window has heard so, for it refuses a calibration or a plan before ("Not now: The devices are
// not running.", seen when the window's state trailed the engine's under load).
bool readyAtRest(nb::MainWindow& w)
{
    const nb::devices::EngineStatus s = w.engine()->status();
    return s.running && !s.moving && !s.approaching && !s.recording && w.controlPanel()->interlockState().devicesRunning;
}

int walkChild(const QString& sessionDir)
{
    std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
    nb::MainWindow w(nbtest::simulatedWindow(sessionDir, true, &rig));
    w.resize(1366, 768);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w))
        return childFail("window not exposed");
    const nb::devices::AcquisitionEngine* engine = w.engine();
    // As the operator waits for the device line to say the rig is ready: the window refuses a
    // plan until the devices report running, and while the stage moves or records (seen in
    // ctest: "plan refused" a second after start, twice in some thirty runs).
    if (!waitFor([&] { return readyAtRest(w); }))
        return childFail("the rig did not come to rest after start");
    QAction* nominal = menuAction(w, QStringLiteral("Use the sensor's &nominal calibration"));
    if (!nominal)
        return childFail("no nominal calibration action");
    nominal->trigger();
    if (!w.session() || !w.session()->activeCalibration())
        return childFail(qPrintable(QStringLiteral("no calibration: ") + w.statusBar()->currentMessage()));
    if (!w.startPlan(testPlan()))
        return childFail(qPrintable(QStringLiteral("plan refused: ") + w.statusBar()->currentMessage()));
    for (int run = 1; run <= 4; ++run) {
        if (const int code = childStartRun(w, engine))
            return code;
        engine = w.engine();
        std::printf("started run %d\n", run);
        std::fflush(stdout);
        if (run == 4)
            break;
        if (!waitFor([&] { return w.runsEnded() == run; }, 60000))
            return childFail("the run did not end");
        std::printf("ended run %d: %s\n", run, qPrintable(w.lastEndReason()));
        std::fflush(stdout);
    }
    // Run four moves slowly: the test kills this process before it ends.
    QTest::qWait(120000);
    return childFail("not killed");
}

nb::Plan readPlan(const QString& sessionDir)
{
    try {
        return nb::readPlanFile(nb::planFilePath(sessionDir));
    } catch (const nb::PlanError&) {
        return {};  // not written yet, or being replaced
    }
}

}  // namespace

class TestPlanWalk : public QObject {
    Q_OBJECT
private slots:
    void killedAtRunFourResumesAtRunFour()
    {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const QString sessionDir = tmp.filePath(QStringLiteral("walk"));

        QProcess child;
        child.setProcessChannelMode(QProcess::SeparateChannels);
        child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("--walk-child"), sessionDir});
        QVERIFY(child.waitForStarted());
        QElapsedTimer clock;
        clock.start();
        QString runFourFile;
        // Killed for real once plan.json says run four is running and its file is being written.
        const bool caught = waitFor(
            [&] {
                if (child.state() == QProcess::NotRunning)
                    return true;
                const nb::Plan plan = readPlan(sessionDir);
                if (plan.runs.size() != kRuns || plan.runs[3].status != nb::PlanRunStatus::Running)
                    return false;
                runFourFile = QDir(sessionDir).filePath(plan.runs[3].attempts.back().runFile);
                return QFileInfo(runFourFile).size() > 2000;
            },
            90000);
        const QByteArray childOut = child.readAllStandardOutput() + child.readAllStandardError();
        QVERIFY2(caught && child.state() == QProcess::Running, childOut.constData());
        ::kill(pid_t(child.processId()), SIGKILL);
        QVERIFY(child.waitForFinished(10000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        qInfo("three runs walked and run four started in %.1f s; killed", clock.elapsed() / 1000.0);
        QVERIFY(QFileInfo::exists(runFourFile));
        QCOMPARE(readPlan(sessionDir).runs[3].status, nb::PlanRunStatus::Running);  // as the crash left it

        // A fresh window on the same session: the plan resumes at run four.
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(nbtest::simulatedWindow(sessionDir, true, &rig));
        const nb::devices::AcquisitionEngine* factoryEngine = w.engine();
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.engine() != factoryEngine, 20000);  // run four's rig (its seed)
        nb::PlanWalker* walker = w.planWalker();
        QVERIFY(walker->hasPlan());
        QVERIFY(walker->walking());
        QVERIFY(walker->nextRun());
        QCOMPARE(walker->nextRun()->number, 4);
        QVERIFY2(w.planPanel()->progressText().startsWith(QStringLiteral("Run 4 of 5 · ")), qPrintable(w.planPanel()->progressText()));
        QVERIFY(w.recoveredRuns().join(QLatin1Char(' ')).contains(QFileInfo(runFourFile).fileName()));

        // Run four's settings in the control panel, locked.
        nb::ControlPanel* p = w.controlPanel();
        QVERIFY(p->motionLocked());
        auto* velocity = p->findChild<QDoubleSpinBox*>(QStringLiteral("velocity"));
        auto* depth = p->findChild<QDoubleSpinBox*>(QStringLiteral("depth"));
        QCOMPARE(velocity->value(), kSlowVelocity_mm_s);
        QCOMPARE(depth->value(), 12.0);
        QVERIFY(!velocity->isEnabled());
        QCOMPARE(p->motionPlan().linear.velocity_mm_s, kSlowVelocity_mm_s);
        QVERIFY(!p->button(Control::StartInsertion)->isEnabled());
        QVERIFY(walker->hold().contains(QStringLiteral("checklist")));
        // With the rig ready, the operator's unticked step is what still holds Start back.
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().running && !p->interlockState().stageEnabled && p->button(Control::Enable)->isEnabled(), 20000);
        p->button(Control::Enable)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().stageEnabled && p->interlockState().stageEnabled, 20000);
        p->button(Control::Bias)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.planPanel()->checkBox(nb::PlanPanel::Item::Bias)->isChecked(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(p->button(Control::Zero)->isEnabled(), 20000);
        p->button(Control::Zero)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.planPanel()->checkBox(nb::PlanPanel::Item::Zero)->isChecked(), 20000);
        QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::StartInsertion)->toolTip().contains(QStringLiteral("tick the checklist")),
                                  qPrintable(p->button(Control::StartInsertion)->toolTip()), 20000);
        QVERIFY(!p->button(Control::StartInsertion)->isEnabled());
        QCOMPARE(readPlan(sessionDir).runs[3].attempts.size(), std::size_t(1));  // nothing started behind the operator's back

        // On disk: runs 1-3 done with their run files and factor levels; run four's dead attempt.
        const nb::Plan plan = readPlan(sessionDir);
        QCOMPARE(int(plan.runs.size()), kRuns);
        for (int i = 0; i < 3; ++i) {
            const nb::PlannedRun& r = plan.runs[std::size_t(i)];
            QCOMPARE(r.status, nb::PlanRunStatus::Done);
            QCOMPARE(int(r.attempts.size()), 1);
            QVERIFY(nb::isCompletingEndReason(r.attempts.back().result));
            const QString file = QDir(sessionDir).filePath(r.attempts.back().runFile);
            const nb::Run run = nb::readRunFile(file).run;
            QVERIFY(run.size() > 100);
            QCOMPARE(run.meta(QStringLiteral("factor_site")).value_or(QString()), QString::number(i + 1));
            QCOMPARE(run.meta(QStringLiteral("plan_run")).value_or(QString()), QString::number(i + 1));
            QCOMPARE(run.meta(QStringLiteral("plan_runs")).value_or(QString()), QString::number(kRuns));
            QCOMPARE(run.meta(QStringLiteral("plan_template")).value_or(QString()), QStringLiteral("walk-test"));
            QCOMPARE(run.meta(QStringLiteral("plan_file")).value_or(QString()), QStringLiteral("plan.json"));
            QCOMPARE(run.meta(QStringLiteral("velocity_mm_s")).value_or(QString()), QStringLiteral("10"));
            QCOMPARE(run.meta(QStringLiteral("sim_seed")).value_or(QString()), QString::number(7000 + i + 1));
        }
        const nb::PlannedRun& four = plan.runs[3];
        QCOMPARE(four.status, nb::PlanRunStatus::Pending);
        QCOMPARE(int(four.attempts.size()), 1);
        QCOMPARE(four.attempts.back().result, QStringLiteral("interrupted"));
        QCOMPARE(QDir(sessionDir).filePath(four.attempts.back().runFile), runFourFile);
        QCOMPARE(nb::readRunFile(runFourFile).run.meta(QStringLiteral("plan_run")).value_or(QString()), QStringLiteral("4"));

        // Leave plan frees the settings; returning sets and locks them again.
        QTest::mouseClick(w.planPanel()->leaveButton(), Qt::LeftButton);
        QVERIFY(!p->motionLocked());
        QVERIFY(velocity->isEnabled());
        velocity->setValue(3.0);
        // A run of the operator's own meanwhile: while it records, the plan's buttons wait
        // (Return to plan locked the panel to the plan's settings under the moving stage, and
        // Skip went through mid-run).
        QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::StartInsertion)->isEnabled(), qPrintable(p->button(Control::StartInsertion)->toolTip()), 20000);
        const int ownBefore = w.runsEnded();
        p->button(Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().recording, 20000);
        QTRY_VERIFY(!w.planPanel()->leaveButton()->isEnabled());
        QVERIFY(!w.planPanel()->skipButton()->isEnabled());
        QVERIFY(!w.planPanel()->redoButton()->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), ownBefore + 1, 30000);
        QVERIFY(!p->motionLocked());
        QTRY_VERIFY_WITH_TIMEOUT(w.planPanel()->leaveButton()->isEnabled(), 10000);
        QTest::mouseClick(w.planPanel()->leaveButton(), Qt::LeftButton);
        QVERIFY(p->motionLocked());
        QCOMPARE(velocity->value(), kSlowVelocity_mm_s);

        // Skipping asks for a reason and moves on to run five.
        QTest::mouseClick(w.planPanel()->skipButton(), Qt::LeftButton);
        auto* dialog = w.planPanel()->findChild<nb::PlanReasonDialog*>();
        QVERIFY(dialog && dialog->isVisible());
        QTest::keyClicks(dialog->edit(), QStringLiteral("vessel at site 4"));
        dialog->accept();
        QTRY_COMPARE(walker->nextRun()->number, 5);
        QVERIFY(w.planPanel()->progressText().startsWith(QStringLiteral("Run 5 of 5 · ")));
        const nb::Plan skipped = readPlan(sessionDir);
        QCOMPARE(skipped.runs[3].status, nb::PlanRunStatus::Skipped);
        QCOMPARE(skipped.runs[3].reason, QStringLiteral("vessel at site 4"));
        QCOMPARE(velocity->value(), 10.0);
        QVERIFY(p->motionLocked());

        // Redo asks for a reason and makes the run done last (three) again; its attempt stays.
        QVERIFY(w.planPanel()->redoButton()->isEnabled());
        QTest::mouseClick(w.planPanel()->redoButton(), Qt::LeftButton);
        nb::PlanReasonDialog* redoDialog = nullptr;
        QTRY_VERIFY([&] {
            for (auto* d : w.planPanel()->findChildren<nb::PlanReasonDialog*>())
                if (d->isVisible())
                    redoDialog = d;
            return redoDialog != nullptr;
        }());
        QVERIFY(!redoDialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled());  // no reason yet
        QTest::keyClicks(redoDialog->edit(), QStringLiteral("air bubble in the trace"));
        const auto* runFourRig = w.engine();
        redoDialog->accept();
        QTRY_COMPARE(walker->nextRun()->number, 3);
        QVERIFY(w.planPanel()->progressText().startsWith(QStringLiteral("Run 3 of 5 · ")));
        const nb::Plan redone = readPlan(sessionDir);
        QCOMPARE(redone.runs[2].status, nb::PlanRunStatus::Pending);
        QCOMPARE(int(redone.runs[2].attempts.size()), 1);
        QCOMPARE(redone.runs[2].attempts[0].discarded, QStringLiteral("air bubble in the trace"));
        // Analysis leaves the discarded run out of its fits (as plan report does), saying why.
        {
            const QString discarded = QFileInfo(redone.runs[2].attempts[0].runFile).completeBaseName();
            QListWidgetItem* item = nullptr;
            for (QListWidget* list : w.analysisWorkspace()->findChildren<QListWidget*>())
                for (QListWidgetItem* candidate : list->findItems(discarded, Qt::MatchExactly))
                    item = candidate;
            QVERIFY2(item, qPrintable(discarded));
            QCOMPARE(item->checkState(), Qt::Unchecked);
            QVERIFY(item->toolTip().contains(QStringLiteral("air bubble in the trace")));
        }
        // The dock says why run three is made again (it said "again (completed)").
        QVERIFY2(w.planPanel()->view().runs.join(QLatin1Char('\n')).contains(QStringLiteral("again: air bubble in the trace")),
                 qPrintable(w.planPanel()->view().runs.join(QLatin1Char('\n'))));
        QVERIFY(QFileInfo::exists(QDir(sessionDir).filePath(redone.runs[2].attempts[0].runFile)));
        QCOMPARE(redone.runs[3].status, nb::PlanRunStatus::Skipped);

        // The emergency stop works on a plan run as on any: Esc ends it, the attempt is recorded
        // as such and the run stays next.
        // Run three's rig (its seed) replaces run four's once the redo is handled and the stage
        // rests, and starts disabled. Enable is pressed when the panel shows that: a fixed
        // 200 ms wait let it go to the rig about to be replaced under ASan on a loaded machine,
        // and pressed while the panel still showed the old rig's enabled stage it disables.
        QTRY_VERIFY_WITH_TIMEOUT(w.engine() != runFourRig, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().running && !p->interlockState().stageEnabled && p->button(Control::Enable)->isEnabled(), 20000);
        p->button(Control::Enable)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().stageEnabled && p->interlockState().stageEnabled, 20000);
        p->button(Control::Bias)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.planPanel()->checkBox(nb::PlanPanel::Item::Bias)->isChecked(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(p->button(Control::Zero)->isEnabled(), 20000);
        p->button(Control::Zero)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.planPanel()->checkBox(nb::PlanPanel::Item::Zero)->isChecked(), 20000);
        QCheckBox* step = w.planPanel()->checkBox(nb::PlanPanel::Item::Instruction);
        QTest::mouseClick(step, Qt::LeftButton, {}, QPoint(5, step->height() / 2));
        QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::StartInsertion)->isEnabled(), qPrintable(p->button(Control::StartInsertion)->toolTip()), 20000);
        const int ended = w.runsEnded();
        QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().moving && w.engine()->status().recording, 20000);
        QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : static_cast<QWidget*>(&w), Qt::Key_Escape);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), ended + 1, 10000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("emergency_stop"));
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().latched, 5000);
        QCOMPARE(walker->nextRun()->number, 3);
        const nb::Plan stopped = readPlan(sessionDir);
        QCOMPARE(int(stopped.runs[2].attempts.size()), 2);
        QCOMPARE(stopped.runs[2].attempts[1].result, QStringLiteral("emergency_stop"));
        QCOMPARE(stopped.runs[2].status, nb::PlanRunStatus::Pending);
        const nb::Run stoppedRun = nb::readRunFile(w.lastRunPath()).run;
        QCOMPARE(QFileInfo(w.lastRunPath()).fileName(), stopped.runs[2].attempts[1].runFile);
        QCOMPARE(stoppedRun.meta(QStringLiteral("plan_attempt")).value_or(QString()), QStringLiteral("2"));
        QCOMPARE(stoppedRun.meta(QStringLiteral("sim_seed")).value_or(QString()), QStringLiteral("7003"));
        QVERIFY(!w.planPanel()->checkBox(nb::PlanPanel::Item::Bias)->isChecked());  // again before the next attempt
    }

    // Quitting during a plan run (Yes to "stop the stage now and quit?") records the attempt as
    // the emergency stop its file says: plan.json kept it "running", and the next start called
    // it interrupted.
    void quitDuringAPlanRunRecordsIt()
    {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const QString sessionDir = tmp.filePath(QStringLiteral("quit"));
        {
            nb::MainWindow w(nbtest::simulatedWindow(sessionDir, true));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(waitFor([&] { return readyAtRest(w); }));
            QAction* nominal = menuAction(w, QStringLiteral("Use the sensor's &nominal calibration"));
            QVERIFY(nominal);
            nominal->trigger();
            QVERIFY2(w.session() && w.session()->activeCalibration(), qPrintable(w.statusBar()->currentMessage()));
            nb::Plan plan = testPlan();
            plan.runs[0].settings.insert(QStringLiteral("velocity_mm_s"), kSlowVelocity_mm_s);
            const nb::devices::AcquisitionEngine* before = w.engine();
            QVERIFY(w.startPlan(plan));
            QCOMPARE(childStartRun(w, before), 0);
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().recording, 20000);
            QVERIFY(!w.close());
            auto* question = w.findChild<QMessageBox*>(QStringLiteral("quitQuestion"));
            QVERIFY(question && question->isVisible());
            question->button(QMessageBox::Yes)->click();
            QTRY_VERIFY(!w.isVisible());
        }
        const nb::Plan after = readPlan(sessionDir);
        QCOMPARE(int(after.runs[0].attempts.size()), 1);
        QCOMPARE(after.runs[0].attempts[0].result, QStringLiteral("emergency_stop"));
        QCOMPARE(after.runs[0].status, nb::PlanRunStatus::Pending);
    }

    void planFromTemplateThroughTheMenu()
    {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const QString sessionDir = tmp.filePath(QStringLiteral("menu"));
        nb::MainWindow w(nbtest::simulatedWindow(sessionDir, false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(!w.planWalker()->hasPlan());
        QVERIFY(!w.controlPanel()->motionLocked());
        QAction* action = w.findChild<QAction*>(QStringLiteral("actionNewPlan"));
        QVERIFY(action);
        bool answered = false;
        QTimer::singleShot(0, &w, [&] {
            auto* dialog = w.findChild<nb::NewPlanDialog*>();
            if (!dialog)
                return;
            dialog->setTemplate(QStringLiteral("friction-imaging"));
            dialog->setOrder(QStringLiteral("blocked"));
            answered = true;
            dialog->accept();
        });
        action->trigger();
        QVERIFY(answered);
        QVERIFY(w.planWalker()->hasPlan());
        const nb::Plan plan = readPlan(sessionDir);
        QCOMPARE(int(plan.runs.size()), 15);
        QCOMPARE(plan.templateName, QStringLiteral("friction-imaging"));
        QCOMPARE(plan.order, nb::PlanOrder::Blocked);
        // Blocked by site: the first three runs are at site 1, in an order drawn with the seed.
        for (int i = 0; i < 3; ++i)
            QCOMPARE(plan.runs[std::size_t(i)].factors.value(QStringLiteral("site")).toDouble(), 1.0);
        nb::ControlPanel* p = w.controlPanel();
        QVERIFY(p->motionLocked());
        QCOMPARE(p->motionName(), QStringLiteral("sine"));
        QCOMPARE(p->findChild<QDoubleSpinBox*>(QStringLiteral("frequency"))->value(),
                 plan.runs[0].factors.value(QStringLiteral("frequency_hz")).toDouble());
        QVERIFY(w.planPanel()->progressText().startsWith(QStringLiteral("Run 1 of 15 · ")));
        // The plan's dock shares the bottom with the runs: the window still fits 700 px of height.
        qInfo("window minimum %d x %d with the plan dock (%d px minimum)", w.minimumSizeHint().width(), w.minimumSizeHint().height(),
              w.planPanel()->minimumSizeHint().height());
        QVERIFY(w.planPanel()->isVisible());
        QVERIFY(w.minimumSizeHint().height() <= 700);
        QVERIFY(w.planPanel()->findChild<QLabel*>(QStringLiteral("planInstruction"))->text().contains(QStringLiteral("site 1")));
        // A second plan over one with no runs made replaces it; the session's plan opens with it.
        w.openSession(sessionDir);
        QVERIFY(w.planWalker()->hasPlan());
        QCOMPARE(w.planWalker()->nextRun()->number, 1);
    }
};

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
    QCoreApplication::setApplicationName(QStringLiteral("test_plan_walk"));
    if (argc == 3 && qstrcmp(argv[1], "--walk-child") == 0)
        return walkChild(QString::fromLocal8Bit(argv[2]));
    TestPlanWalk test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_plan_walk.moc"
