// Issue 12's scenarios on the real main window and the simulated rig: Esc stops the stage
// from inside every dialog the window can open (and closes nothing), mode switches are refused
// mid-run, a low insertion limit never traps the needle, bias under load needs an explicit
// override, the emergency stop latches until the operator resets it, and a sine run with the
// default parameters reaches the tissue.
#include "main_window.h"
#include "support/simulated_window.h"

#include "core/data_names.h"
#include "core/run_file.h"
#include "core/session.h"
#include "devices/acquisition_engine.h"
#include "devices/device_spec.h"
#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"
#include "widgets/calibration_wizard.h"
#include "widgets/control_panel.h"
#include "widgets/review_workspace.h"
#include "widgets/session_view.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QComboBox>
#include <QApplication>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <functional>

using nb::Control;

namespace {

nb::WorkbenchOptions options(const QString& sessionDir, bool realtime, std::shared_ptr<nb::devices::sim::SimulatedRig>* rig)
{
    return nbtest::simulatedWindow(sessionDir, realtime, rig);
}

// Waits while processing events; false when `ready` did not come true in time. (No QTRY
// inside a modal dialog's loop: a failed check must not leave the dialog open.)
bool waitFor(const std::function<bool()>& ready, int ms = 20000)
{
    QElapsedTimer t;
    t.start();
    while (!ready()) {
        if (t.elapsed() > ms)
            return false;
        QTest::qWait(5);
    }
    return true;
}

void setLinear(nb::MainWindow& w, double velocity, double depth)
{
    w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->setValue(velocity);
    w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->setValue(depth);
}

QAction* action(nb::MainWindow& w, const QString& text)
{
    for (QAction* a : w.menuBar()->findChildren<QAction*>())
        if (a->text() == text)
            return a;
    return nullptr;
}

bool busy(const nb::devices::EngineStatus& s) { return s.moving || s.approaching || s.jogging; }

// The rig's state in a failed check's message: a scenario that fails on a loaded machine only
// must say where the rig was.
QString stateOf(nb::MainWindow& w)
{
    const nb::devices::EngineStatus s = w.engine()->status();
    const nb::InterlockState i = w.controlPanel()->interlockState();
    return QStringLiteral("position %1 mm, force %2 N, moving %3, recording %4, latched %5, enabled %6, zeroed %7, "
                          "in tissue %8, loaded %9, runs ended %10 (%11), status line '%12'")
        .arg(s.position_mm, 0, 'f', 3).arg(s.force_N, 0, 'f', 3).arg(busy(s)).arg(s.recording).arg(i.latched).arg(i.stageEnabled)
        .arg(i.zeroed).arg(i.inTissue).arg(i.loaded).arg(w.runsEnded()).arg(w.lastEndReason(), w.statusBar()->toolTip());
}

// The dialog on screen besides the main window, modal or not.
QWidget* visibleDialog()
{
    for (QWidget* t : QApplication::topLevelWidgets())
        if (qobject_cast<QDialog*>(t) && t->isVisible())
            return t;
    return nullptr;
}

// A click as the window system delivers it: through Qt's modality (QTest's QWidget overload
// would hand the event to the button directly, past a modal dialog that blocks it).
void clickLikeAMouse(QWidget* button)
{
    QWidget* top = button->window();
    QTest::mouseClick(top->windowHandle(), Qt::LeftButton, {}, button->mapTo(top, button->rect().center()));
}

// What one Esc inside a dialog did.
struct EscResult {
    QString error;           // empty when every step worked
    double stopDelay_s = -1; // device time from the key to the first status at rest
    bool dialogStayedOpen = false;
    QString dialogClass;
};

}  // namespace

class TestSafetyScenarios : public QObject {
    Q_OBJECT

    // Opens a dialog with `open` (it may block in exec or return at once), with the stage
    // moving (started before when `motionFirst`, else from inside the dialog as a run already
    // under way would be), presses Esc on whatever has the focus in it, then closes it.
    EscResult escInDialog(nb::MainWindow& w, bool motionFirst, const std::function<void()>& open,
                          const std::function<QWidget*()>& dialog)
    {
        EscResult r;
        nb::devices::AcquisitionEngine* engine = w.engine();
        QAbstractButton* start = w.controlPanel()->button(Control::StartInsertion);
        if (motionFirst) {
            start->click();
            if (!waitFor([&] { return engine->status().moving && engine->status().recording; }))
                r.error = QStringLiteral("the run did not start");
        }
        bool done = false;
        QTimer::singleShot(0, this, [&] {
            auto finish = qScopeGuard([&] {
                done = true;
                // Closes whatever is open, whatever happened: the test must not hang.
                for (int i = 0; i < 3; ++i)
                    if (QWidget* d = dialog(); d && d->isVisible()) {
                        if (auto* qd = qobject_cast<QDialog*>(d))
                            qd->reject();
                        else
                            d->close();
                        QTest::qWait(20);
                    }
            });
            if (!r.error.isEmpty())
                return;
            if (!waitFor([&] { return dialog() && dialog()->isVisible(); }, 5000)) {
                r.error = QStringLiteral("the dialog did not open");
                return;
            }
            QWidget* d = dialog();
            r.dialogClass = QString::fromLatin1(d->metaObject()->className());
            if (!motionFirst) {
                start->click();
                if (!waitFor([&] { return engine->status().moving && engine->status().recording; })) {
                    r.error = QStringLiteral("the run did not start: ") + start->toolTip();
                    return;
                }
            }
            QTest::qWait(300);  // well under way
            double stoppedAt = -1;
            QMetaObject::Connection c = connect(engine, &nb::devices::AcquisitionEngine::statusChanged, this,
                                                [&](const nb::devices::EngineStatus& s) {
                                                    if (stoppedAt < 0 && !busy(s))
                                                        stoppedAt = s.deviceTime_s;
                                                });
            QWidget* target = d->focusWidget() ? d->focusWidget() : d;
            const double keyAt = engine->status().deviceTime_s;
            QTest::keyClick(target, Qt::Key_Escape);
            const bool stopped = waitFor([&] { return stoppedAt >= 0; }, 5000);
            disconnect(c);
            if (!stopped) {
                r.error = QStringLiteral("the stage kept moving after Esc");
                return;
            }
            r.stopDelay_s = stoppedAt - keyAt;
            r.dialogStayedOpen = dialog() && dialog()->isVisible();
            // At rest, Esc does its usual job again.
            if (!waitFor([&] { return !engine->status().recording; }, 5000))
                r.error = QStringLiteral("the run did not end");
        });
        open();
        waitFor([&] { return done; }, 30000);
        return r;
    }

private slots:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_safety_scenarios"));
    }

    void escStopsFromEveryDialog_data()
    {
        QTest::addColumn<QString>("which");
        // (The calibration wizard is never open during a run: calibrationAndRunExcludeEachOther.)
        for (const char* name : {"new session", "file chooser", "session details", "devices", "simulated rig",
                                 "label set", "quit confirmation", "menu", "new plan"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void escStopsFromEveryDialog()
    {
        QFETCH(QString, which);
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setLinear(w, 5.0, 60.0);
        nbtest::prepareToRecord(w);
        const QString sessionDir = w.session()->dir();

        std::function<void()> open;
        std::function<QWidget*()> dialog = [] { return QApplication::activeModalWidget(); };
        bool motionFirst = false;  // the mode switches are refused mid-run: opened at rest
        if (which == QLatin1String("new session"))
            open = [&] { action(w, QStringLiteral("&New session…"))->trigger(); };
        else if (which == QLatin1String("file chooser"))
            open = [&] { action(w, QStringLiteral("&Open session…"))->trigger(); };
        else if (which == QLatin1String("session details"))
            open = [&] { action(w, QStringLiteral("Session &details…"))->trigger(); };
        else if (which == QLatin1String("devices"))
            open = [&] { action(w, QStringLiteral("&Choose devices…"))->trigger(); };
        else if (which == QLatin1String("new plan"))
            open = [&] { action(w, QStringLiteral("New &plan from template…"))->trigger(); };
        else if (which == QLatin1String("simulated rig"))
            open = [&] { action(w, QStringLiteral("&Simulated rig…"))->trigger(); };
        else if (which == QLatin1String("label set")) {
            motionFirst = true;  // allowed mid-run: it changes no run
            open = [&] { w.reviewWorkspace()->editLabelSet(); };
            dialog = [] { return visibleDialog(); };  // modeless: the stop button stays clickable
        } else if (which == QLatin1String("quit confirmation")) {
            motionFirst = true;
            open = [&] { w.close(); };
            dialog = [] { return visibleDialog(); };
        } else if (which == QLatin1String("menu")) {
            motionFirst = true;
            QMenu* menu = w.menuBar()->actions().at(0)->menu();
            open = [menu] { menu->popup(QPoint(10, 10)); };
            dialog = [menu] { return static_cast<QWidget*>(menu); };
        }
        const EscResult r = escInDialog(w, motionFirst, open, dialog);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        qInfo("%s (%s): stopped %.0f ms after Esc (device time)", qPrintable(which), qPrintable(r.dialogClass), r.stopDelay_s * 1000.0);
        // The figure is printed above (about 0.1 s on a quiet machine); the bound only catches a
        // stop that waited for something, with room for a machine busy with other work.
        QVERIFY2(r.stopDelay_s >= 0.0 && r.stopDelay_s <= 0.5, qPrintable(QString::number(r.stopDelay_s)));
        // Esc stopped; it closed nothing the operator was working in. A menu it closes: left
        // open, it covered the latched panel that says what happened.
        if (which == QLatin1String("menu"))
            QVERIFY(!r.dialogStayedOpen);
        else
            QVERIFY(r.dialogStayedOpen);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 10000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("emergency_stop"));
        const nb::RunReadResult file = nb::readRunFile(w.lastRunPath());
        QCOMPARE(file.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("emergency_stop"));
        // The list says so too, not just "stopped".
        QTRY_COMPARE_WITH_TIMEOUT(w.sessionView()->model()->index(0, nb::RunListModel::State).data().toString(), QStringLiteral("emergency stop"), 5000);
        QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("emergency stop")));
        QVERIFY(w.isVisible());                   // the quit question was not answered by the stop
        QCOMPARE(w.session()->dir(), sessionDir);  // nor a session switched
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().latched, 5000);
    }

    // Whatever the window offers while a run records opens without blocking it: the EMERGENCY
    // STOP button takes a click with any of them open (a modal one swallowed the click, and on
    // X11 the keyboard with it), and the dialog stays open.
    void stopButtonClickableWithEveryDialog_data()
    {
        QTest::addColumn<QString>("which");
        for (const char* name : {"export", "export folder", "video chooser", "label set", "quit confirmation", "save figure", "save tables"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void stopButtonClickableWithEveryDialog()
    {
        QFETCH(QString, which);
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setLinear(w, 5.0, 60.0);
        nbtest::prepareToRecord(w);
        nb::devices::AcquisitionEngine* engine = w.engine();
        // Review needs a run for its video chooser: a short one first.
        if (which == QLatin1String("video chooser")) {
            setLinear(w, 5.0, 2.0);
            w.controlPanel()->button(Control::StartInsertion)->click();
            QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 20000);
            w.reviewRun(w.lastRunPath());
            w.controlPanel()->button(Control::Withdraw)->click();
            QTRY_VERIFY_WITH_TIMEOUT(!engine->status().moving && w.controlPanel()->button(Control::StartInsertion)->isEnabled(), 20000);
            setLinear(w, 5.0, 60.0);
        }
        const int endedBefore = w.runsEnded();
        w.controlPanel()->button(Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(engine->status().moving && engine->status().recording, 20000);

        if (which == QLatin1String("export"))
            action(w, QStringLiteral("&Export session…"))->trigger();
        else if (which == QLatin1String("export folder")) {
            action(w, QStringLiteral("&Export session…"))->trigger();
            QTRY_VERIFY(visibleDialog());
            QPushButton* choose = nullptr;
            for (QPushButton* b : visibleDialog()->findChildren<QPushButton*>())
                if (b->text() == QStringLiteral("Choose…"))
                    choose = b;
            QVERIFY(choose);
            choose->click();
            QTRY_VERIFY(w.findChild<QFileDialog*>());
        } else if (which == QLatin1String("video chooser"))
            action(w, QStringLiteral("Open &video for the run in review…"))->trigger();
        else if (which == QLatin1String("label set"))
            w.reviewWorkspace()->editLabelSet();
        else if (which == QLatin1String("quit confirmation"))
            w.close();
        else if (which == QLatin1String("save figure") || which == QLatin1String("save tables")) {
            // The Analysis tab's buttons (its first page's).
            const QString text = which == QLatin1String("save figure") ? QStringLiteral("Save figure…") : QStringLiteral("Save tables…");
            QPushButton* b = nullptr;
            for (QPushButton* candidate : w.findChildren<QPushButton*>())
                if (!b && candidate->text() == text)
                    b = candidate;
            QVERIFY2(b, qPrintable(text));
            b->click();
        }
        QTRY_VERIFY(visibleDialog());
        QWidget* open = which == QLatin1String("export folder") ? w.findChild<QFileDialog*>() : visibleDialog();
        QVERIFY(open && open->isVisible());
        QCOMPARE(QApplication::activeModalWidget(), nullptr);
        QTest::qWait(200);
        QVERIFY(engine->status().moving);
        clickLikeAMouse(w.controlPanel()->button(Control::EmergencyStop));
        QTRY_VERIFY_WITH_TIMEOUT(!engine->status().moving, 2000);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), endedBefore + 1, 10000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("emergency_stop"));
        QVERIFY(open->isVisible());  // the click stopped; it closed nothing
        QVERIFY(w.isVisible());
        // The quit question no longer speaks of a moving stage and a run to save (it may speak of
        // the needle left in the tissue, or away from its start).
        if (auto* question = qobject_cast<QMessageBox*>(open); question && which == QLatin1String("quit confirmation"))
            QTRY_VERIFY2_WITH_TIMEOUT(question->text().startsWith(QStringLiteral("Nothing moves or records now"))
                                          || question->text().startsWith(QStringLiteral("The needle is still in the tissue"))
                                          || question->text().contains(QStringLiteral("mm from its start")),
                                      qPrintable(question->text()), 5000);
        for (QWidget* t : QApplication::topLevelWidgets())
            if (auto* d = qobject_cast<QDialog*>(t); d && d->isVisible())
                d->reject();
    }

    // The wizard's masses load the sensor and its Save and use changes the calibration: with
    // it open no run starts (its loads were recorded as the run's force, and a calibration
    // saved mid-run applied to part of it), and during a run it does not open.
    void calibrationAndRunExcludeEachOther()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setLinear(w, 5.0, 20.0);
        nbtest::prepareToRecord(w);
        QAbstractButton* start = w.controlPanel()->button(Control::StartInsertion);
        QVERIFY(w.openCalibrationWizard());
        QTRY_VERIFY(!start->isEnabled());
        QVERIFY2(start->toolTip().contains(QStringLiteral("calibration wizard")), qPrintable(start->toolTip()));
        // A start asked for all the same (as a plan's next run is) is refused by the window too.
        emit w.controlPanel()->startRequested();
        QTest::qWait(300);
        QVERIFY(!w.engine()->status().recording);
        w.findChild<nb::CalibrationWizard*>()->reject();
        QTRY_VERIFY(!w.findChild<nb::CalibrationWizard*>());
        QTRY_VERIFY(start->isEnabled());
        start->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().recording, 20000);
        QCOMPARE(w.openCalibrationWizard(), nullptr);
        w.controlPanel()->button(Control::EmergencyStop)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 10000);
    }

    // A calibration saved in one session is that session's: another session without one of its
    // own runs on the sensor's nominal calibration, and its runs say so.
    void calibrationStaysWithItsSession()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("a")), false, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().devicesRunning, 20000);
        nb::StoredCalibration cal;
        cal.date = QDateTime::currentDateTime();
        cal.sensor = QStringLiteral("test");
        cal.fit.slope_V_per_g = 0.0123;
        cal.fit.r2 = 0.9999;
        for (double g : {0.0, 50.0, 100.0})
            cal.points.push_back({g, 0.0123 * g});
        w.useCalibration(cal);
        QTRY_VERIFY(w.engine()->status().calibrationName.startsWith(QStringLiteral("cal_")));
        const QString saved = w.engine()->status().calibrationName;
        QVERIFY(w.createSession(tmp.filePath(QStringLiteral("b")), {}));
        QTRY_COMPARE(w.engine()->status().calibrationName, QString::fromLatin1(nb::kNominalCalibration));
        // Back in the first session, its own calibration again.
        QVERIFY(w.openSession(tmp.filePath(QStringLiteral("a"))));
        QTRY_COMPARE(w.engine()->status().calibrationName, saved);
    }

    void escAtRestClosesTheDialog()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().devicesRunning, 20000);
        bool closed = false;
        QTimer::singleShot(0, this, [&] {
            if (!waitFor([] { return QApplication::activeModalWidget() != nullptr; }, 5000))
                return;
            QWidget* d = QApplication::activeModalWidget();
            QTest::keyClick(d->focusWidget() ? d->focusWidget() : d, Qt::Key_Escape);
            closed = waitFor([d] { return !d->isVisible(); }, 2000);
            if (!closed)
                qobject_cast<QDialog*>(d)->reject();
        });
        action(w, QStringLiteral("&New session…"))->trigger();
        QVERIFY(closed);
        QVERIFY(!w.engine()->status().latched);  // nothing moved: no emergency stop
    }

    void modeSwitchesRefusedMidRun()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        w.activateWindow();  // under X without a window manager (xvfb-run) nothing else does
        QVERIFY(QTest::qWaitForWindowActive(&w));
        setLinear(w, 5.0, 60.0);
        nbtest::prepareToRecord(w);
        const QString sessionDir = w.session()->dir();
        w.controlPanel()->button(Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().recording, 20000);
        // Focus never lands in a parameter field on Start, and the fields are locked.
        QWidget* focus = QApplication::focusWidget();
        QVERIFY2(!qobject_cast<QAbstractSpinBox*>(focus), focus ? focus->metaObject()->className() : "none");
        QTRY_VERIFY_WITH_TIMEOUT(!w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("forceLimit"))->isEnabled(), 5000);
        for (const char* field : {"depth", "velocity", "withdrawForceLimit", "goToPosition"})
            QVERIFY2(!w.controlPanel()->findChild<QDoubleSpinBox*>(QString::fromLatin1(field))->isEnabled(), field);

        // Anything that would open a dialog is caught here rather than hang the test.
        int dialogs = 0;
        QTimer watchdog;
        connect(&watchdog, &QTimer::timeout, this, [&] {
            if (QWidget* d = QApplication::activeModalWidget()) {
                ++dialogs;
                if (auto* qd = qobject_cast<QDialog*>(d))
                    qd->reject();
            }
        });
        watchdog.start(50);
        // The status bar shortens a message to its room; its tooltip holds the whole text.
        const auto said = [&w] {
            return QStringLiteral("'%1' (whole: '%2'; %3)").arg(w.statusBar()->currentMessage(), w.statusBar()->toolTip(), stateOf(w));
        };
        QVERIFY2(QApplication::activeWindow() == &w, qPrintable(said()));
        QTest::keyClick(&w, Qt::Key_N, Qt::ControlModifier);  // Ctrl+N
        QTRY_VERIFY2_WITH_TIMEOUT(w.statusBar()->toolTip().contains(QStringLiteral("A run is recording")), qPrintable(said()), 5000);
        for (const char* text : {"&Open session…", "Session &details…", "&Choose devices…", "&Simulated rig…", "&Calibrate force sensor…"}) {
            w.statusBar()->clearMessage();
            w.statusBar()->setToolTip(QString());
            QAction* a = action(w, QString::fromUtf8(text));
            QVERIFY2(a, text);
            a->trigger();
            QTRY_VERIFY2_WITH_TIMEOUT(w.statusBar()->currentMessage().startsWith(QStringLiteral("Not now")), qPrintable(text + (": " + said())), 5000);
        }
        QCOMPARE(dialogs, 0);
        QVERIFY(!w.findChild<nb::CalibrationWizard*>());
        QCOMPARE(w.session()->dir(), sessionDir);
        QVERIFY2(w.engine()->status().recording, qPrintable(said()));  // the run went on
        QVERIFY(QFileInfo(w.engine()->status().runPath).absolutePath() == QDir(sessionDir).absolutePath());
        w.controlPanel()->button(Control::EmergencyStop)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 10000);
    }

    void latchHoldsUntilReset()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setLinear(w, 5.0, 60.0);
        nbtest::prepareToRecord(w);
        nb::ControlPanel* p = w.controlPanel();
        p->button(Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().moving, 20000);
        QTest::mouseClick(p->button(Control::EmergencyStop), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().latched, 5000);
        auto* banner = p->findChild<QWidget*>(QStringLiteral("latchBanner"));
        QVERIFY(banner->isVisible());
        // Held: nothing starts or moves, however long the operator waits or tries.
        QTest::qWait(1000);
        const double position = w.engine()->status().position_mm;
        QVERIFY(p->interlockState().latched);
        QVERIFY(!p->interlockState().stageEnabled);
        QVERIFY(!p->button(Control::StartInsertion)->isEnabled());
        QVERIFY(!p->button(Control::Withdraw)->isEnabled());
        QVERIFY(!p->findChild<QPushButton*>(QStringLiteral("jogOut"))->isEnabled());
        w.engine()->jog(-1.0, 5.0);  // even asked directly, the engine refuses
        QTest::qWait(500);
        QVERIFY2(w.engine()->status().position_mm == position,
                 qPrintable(QStringLiteral("%1 mm, latched at %2 mm; %3").arg(w.engine()->status().position_mm).arg(position).arg(stateOf(w))));
        // The deliberate reset.
        QTest::mouseClick(p->findChild<QPushButton*>(QStringLiteral("resetEmergencyStop")), Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(!p->interlockState().latched, qPrintable(stateOf(w)), 5000);
        QTRY_VERIFY2_WITH_TIMEOUT(p->interlockState().stageEnabled, qPrintable(stateOf(w)), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!banner->isVisible(), 5000);
        // The reset asks for a fresh zero before the next run, but the needle comes out without
        // one: Withdraw goes back towards the start the last zero set.
        QVERIFY(!p->interlockState().zeroed);
        QVERIFY(!p->button(Control::StartInsertion)->isEnabled());
        QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::Withdraw)->isEnabled(), qPrintable(p->button(Control::Withdraw)->toolTip()), 5000);
        // Jogging out works again, unrecorded.
        QTRY_VERIFY_WITH_TIMEOUT(p->findChild<QPushButton*>(QStringLiteral("jogOut"))->isEnabled(), 5000);
        p->findChild<QComboBox*>(QStringLiteral("jogStep"))->setCurrentIndex(1);  // 1 mm
        p->findChild<QPushButton*>(QStringLiteral("jogOut"))->click();
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(w.engine()->status().position_mm - (position - 1.0)) < 0.05 && !busy(w.engine()->status()),
                                  qPrintable(QStringLiteral("from %1 mm: %2").arg(position).arg(stateOf(w))), 10000);
        QVERIFY2(!w.engine()->status().recording, qPrintable(stateOf(w)));
    }

    void biasInTissueNeedsOverrideAndWithdrawalIsNeverTrapped()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setLinear(w, 15.0, 30.0);
        nbtest::prepareToRecord(w);
        nb::ControlPanel* p = w.controlPanel();
        p->button(Control::StartInsertion)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("completed"));
        QTRY_VERIFY2_WITH_TIMEOUT((p->interlockState().inTissue || p->interlockState().loaded) && !busy(w.engine()->status()),
                                  qPrintable(stateOf(w)), 5000);
        const double bias0 = w.engine()->status().bias_V;

        // Refused with the reason; the operator cancels.
        QString asked;
        const auto answer = [&](bool insist) {
            QTimer::singleShot(0, this, [&asked, insist] {
                if (!waitFor([] { return qobject_cast<QMessageBox*>(QApplication::activeModalWidget()) != nullptr; }, 5000))
                    return;
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                asked = box->text();
                for (QAbstractButton* b : box->buttons())
                    if ((box->buttonRole(b) == QMessageBox::DestructiveRole) == insist) {
                        b->click();
                        return;
                    }
            });
        };
        answer(false);
        p->button(Control::Bias)->click();
        QVERIFY2(asked.contains(QStringLiteral("noise band")) || asked.contains(QStringLiteral("met tissue")),
                 qPrintable(QStringLiteral("asked '%1'; status '%2'; %3").arg(asked, w.statusBar()->toolTip(), stateOf(w))));
        QTest::qWait(1000);
        QCOMPARE(w.engine()->status().bias_V, bias0);
        // The override works.
        asked.clear();
        answer(true);
        p->button(Control::Bias)->click();
        QVERIFY(!asked.isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().bias_V != bias0, 5000);

        // A low insertion limit does not keep the needle in: out to the start position.
        p->setForceLimit(0.1);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().forceLimit_N == 0.1, 5000);
        auto* out = p->findChild<QPushButton*>(QStringLiteral("withdrawToStart"));
        QTRY_VERIFY2_WITH_TIMEOUT(out->isEnabled(), qPrintable(out->toolTip()), 5000);
        QTest::mouseClick(out, Qt::LeftButton);
        // Out to the start (the move may be over before a look sees it moving).
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(w.engine()->status().position_mm) < 0.05 && !busy(w.engine()->status()),
                                  qPrintable(stateOf(w)), 20000);
        QVERIFY2(!w.engine()->status().forceLimitTripped, qPrintable(stateOf(w)));
        QCOMPARE(w.runsEnded(), 1);  // never recorded
        // The button clicked, disabled once the needle is out, leaves the focus with the
        // emergency stop, not in the next field (Max. force, its value selected, where a digit
        // typed changes the limit).
        QTRY_VERIFY_WITH_TIMEOUT(!out->isEnabled(), 5000);
        QWidget* focus = w.focusWidget();
        QVERIFY2(focus == p->button(Control::EmergencyStop), focus ? qPrintable(focus->objectName() + QLatin1Char(' ') + focus->metaObject()->className()) : "none");
    }

    void simulatedRigChosenInTheWindowIsRecorded()
    {
        QTemporaryDir tmp;
        QString chosen;
        {
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().devicesRunning, 20000);
        const nb::devices::AcquisitionEngine* before = w.engine();
        QTimer::singleShot(0, this, [&] {
            if (!waitFor([] { return QApplication::activeModalWidget() != nullptr; }, 5000))
                return;
            auto* d = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            auto* tissue = d->findChild<QComboBox*>(QStringLiteral("tissue"));
            tissue->setCurrentIndex(tissue->count() > 1 ? 1 : 0);
            chosen = tissue->currentData().toString();  // the stored name (the shown one is translated)
            d->findChild<QSpinBox*>(QStringLiteral("seed"))->setValue(7);
            d->accept();
        });
        action(w, QStringLiteral("&Simulated rig…"))->trigger();
        QVERIFY(!chosen.isEmpty());
        QVERIFY(w.engine() != before);  // rebuilt on the chosen rig
        QVERIFY2(w.engine()->deviceDescription().contains(chosen), qPrintable(w.engine()->deviceDescription()));
        QVERIFY2(w.engine()->deviceDescription().contains(QStringLiteral("seed 7")), qPrintable(w.engine()->deviceDescription()));
        setLinear(w, 20.0, 3.0);
        nbtest::prepareToRecord(w);
        w.controlPanel()->button(Control::StartInsertion)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 20000);
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QCOMPARE(r.run.meta(QStringLiteral("sim_tissue")).value_or(QString()), chosen);
        QCOMPARE(r.run.meta(QStringLiteral("sim_seed")).value_or(QString()), QStringLiteral("7"));
        // The tip the rig ran with, as its device line names it, also where none was chosen.
        const QString tip = r.run.meta(QStringLiteral("sim_tip")).value_or(QString());
        QVERIFY2(nb::devices::tipNames().contains(tip), qPrintable(tip));
        QVERIFY2(r.run.meta(QStringLiteral("device")).value_or(QString()).contains(tip + QStringLiteral(" tip")), qPrintable(tip));
        }
        // The session keeps the choice: reopened, it runs on the same simulated specimen.
        std::shared_ptr<nb::devices::sim::SimulatedRig> fresh;
        nb::MainWindow again(options(tmp.filePath(QStringLiteral("s")), true, &fresh));
        again.show();
        QTRY_VERIFY_WITH_TIMEOUT(again.controlPanel()->interlockState().devicesRunning, 20000);
        QVERIFY2(again.engine()->deviceDescription().contains(chosen), qPrintable(again.engine()->deviceDescription()));
        QVERIFY2(again.engine()->deviceDescription().contains(QStringLiteral("seed 7")), qPrintable(again.engine()->deviceDescription()));
    }

    // A force the load cell cannot read (a kilogram on the needle: 9.8 N against the 7.79 N the
    // nominal chain reads at +10 V, under the default 8 N limit) stops the stage in the window as
    // a force over the limit does, and the run says so. The reading stayed at 7.79 N and the
    // stage drove on (data probe: 20 mm into bone, saved "completed").
    void aForceBeyondTheSensorsRangeStopsTheStage()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.controlPanel()->forceLimit(), 8.0);
        setLinear(w, 2.0, 30.0);
        nbtest::prepareToRecord(w);
        w.controlPanel()->button(Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().moving, 20000);
        rig->setLoadMass_g(1000.0);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("force_limit"));
        QTRY_VERIFY_WITH_TIMEOUT(!w.controlPanel()->interlockState().moving, 20000);
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QCOMPARE(r.run.footer.value(QStringLiteral("force_over_range"), QString()), QStringLiteral("true"));
        const double highest = *std::max_element(r.run.force_N.begin(), r.run.force_N.end());
        QVERIFY2(highest < 8.0, qPrintable(QString::number(highest)));  // never read over the limit itself
        QVERIFY(*std::max_element(r.run.position_mm.begin(), r.run.position_mm.end()) < 30.0);
        rig->setLoadMass_g(0.0);
    }

    void sineWithDefaultsTouchesTissue()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        nbtest::prepareToRecord(w);
        nb::ControlPanel* p = w.controlPanel();
        p->findChild<QRadioButton*>(QStringLiteral("sine"))->setChecked(true);
        QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::StartInsertion)->isEnabled(), qPrintable(p->button(Control::StartInsertion)->toolTip()), 5000);
        p->button(Control::StartInsertion)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 60000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("completed"));
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QVERIFY(r.run.size() > 1000);
        const double peak = *std::max_element(r.run.force_N.begin(), r.run.force_N.end());
        qInfo("sine with default parameters: centre %.1f mm, peak force %.3f N", p->sineCentre(), peak);
        QVERIFY2(peak > 0.05, qPrintable(QString::number(peak)));
        // The engine writes the centre it reached.
        QVERIFY(std::abs(r.run.metadata.number(QStringLiteral("centre_mm")).value_or(-1.0) - p->sineCentre()) < 0.05);
    }
};

QTEST_MAIN(TestSafetyScenarios)
#include "test_safety_scenarios.moc"
