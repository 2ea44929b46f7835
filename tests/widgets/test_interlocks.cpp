// The operator's sequence: each control enabled only when its prerequisites hold, with the
// reason in its tooltip; the pure rules first, then the real panel driven with QTest.
#include "widgets/control_panel.h"
#include "core/local_number.h"
#include "devices/interlocks.h"

#include <QAbstractButton>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalSpy>
#include <QLocale>
#include <QPushButton>
#include <QToolButton>
#include <QtTest>

using nb::Control;
using nb::InterlockState;
using nb::permission;

class TestInterlocks : public QObject {
    Q_OBJECT
private slots:
    // What the window says writes numbers as the operator's language does: "fahre auf 14.00 mm"
    // stood in the German status line. No group separator ("1001 ppm"), no "-0,000".
    void numbersAreWrittenInTheOperatorsLanguage()
    {
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QCOMPARE(nb::localNumber(14.0, 2), QStringLiteral("14,00"));
        QCOMPARE(nb::localNumber(1001.0, 0), QStringLiteral("1001"));
        QCOMPARE(nb::localNumber(-0.0004, 3), QStringLiteral("0,000"));
        QLocale::setDefault(QLocale::c());
        QCOMPARE(nb::localNumber(14.0, 2), QStringLiteral("14.00"));
        QLocale::setDefault(before);
    }

    void escapeStopsOnlyWhileBusy()
    {
        InterlockState s;
        s.devicesRunning = true;
        QVERIFY(!escapeStops(s));  // at rest Esc closes dialogs
        s.moving = true;
        QVERIFY(escapeStops(s));
        s.moving = false;
        s.recording = true;        // stopped but still recording: Esc still ends it as a stop
        QVERIFY(escapeStops(s));
        // While busy, every mode switch is refused with a reason.
        for (Control c : {Control::ChangeSetup, Control::Calibrate, Control::Quit}) {
            const nb::Permission p = permission(c, s);
            QVERIFY(!p.enabled);
            QVERIFY(!p.reason.isEmpty());
        }
    }

    void sequenceOfThePanel()
    {
        InterlockState s;
        s.sessionOpen = true;
        s.calibrated = true;
        s.forceLimit_N = 8.0;
        // Nothing moves before the devices run; the E-stop is always there.
        QVERIFY(!permission(Control::Enable, s).enabled);
        QVERIFY(permission(Control::EmergencyStop, s).enabled);
        s.devicesRunning = true;
        QVERIFY(permission(Control::Enable, s).enabled);
        QVERIFY(permission(Control::Bias, s).enabled);
        QVERIFY(!permission(Control::Zero, s).enabled);
        QVERIFY(permission(Control::Zero, s).reason.contains(QStringLiteral("Enable")));
        QVERIFY(!permission(Control::StartInsertion, s).enabled);
        s.stageEnabled = true;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("Bias")));
        s.biased = true;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("Zero")));
        QVERIFY(!permission(Control::Withdraw, s).enabled);
        s.zeroed = true;
        QVERIFY(permission(Control::StartInsertion, s).enabled);
        QVERIFY(permission(Control::Withdraw, s).enabled);
        QVERIFY(!permission(Control::StopMotion, s).enabled);
        QVERIFY(!permission(Control::EndRun, s).enabled);

        // Recording and moving: only stop and E-stop; nothing that would spoil the run.
        s.recording = s.moving = true;
        QVERIFY(permission(Control::StopMotion, s).enabled);
        QVERIFY(!permission(Control::StartInsertion, s).enabled);
        QVERIFY(!permission(Control::Bias, s).enabled);
        QVERIFY(!permission(Control::Zero, s).enabled);
        QVERIFY(!permission(Control::Enable, s).enabled);
        QVERIFY(!permission(Control::MotionSettings, s).enabled);
        QVERIFY(!permission(Control::Calibrate, s).enabled);
        // End run does not stop the stage: it waits for Stop motion.
        QVERIFY(!permission(Control::EndRun, s).enabled);
        QVERIFY(permission(Control::EndRun, s).reason.contains(QStringLiteral("Stop the motion")));
        s.moving = false;
        QVERIFY(permission(Control::EndRun, s).enabled);
        QVERIFY(permission(Control::Withdraw, s).enabled);
        QVERIFY(!permission(Control::Enable, s).enabled);  // disabling mid-run would end it unrecorded
        s.recording = false;
        QVERIFY(permission(Control::Enable, s).enabled);

        // After an emergency stop's reset the zero is asked for again before a run, but the
        // needle comes out towards the start the last zero set.
        s.zeroed = false;
        s.startKnown = true;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("Zero")));
        QVERIFY(permission(Control::Withdraw, s).enabled);
        s.startKnown = false;
        QVERIFY(!permission(Control::Withdraw, s).enabled);

        // The calibration wizard's masses would be recorded as force: no run while it is open.
        s.zeroed = true;
        QVERIFY(permission(Control::StartInsertion, s).enabled);
        s.calibrating = true;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("calibration wizard")));
        QVERIFY(permission(Control::Withdraw, s).enabled);
        QVERIFY(permission(Control::Jog, s).enabled);
    }

    void prerequisitesOfAnInsertion()
    {
        InterlockState s;
        s.devicesRunning = s.stageEnabled = s.biased = s.zeroed = true;
        s.forceLimit_N = 8.0;
        s.calibrated = true;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("session")));
        s.sessionOpen = true;
        s.calibrated = false;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("calibration")));
        s.calibrated = true;
        s.forceLimit_N = 0.0;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("limit")));
        s.forceLimit_N = 8.0;
        s.motionProblem = QStringLiteral("too deep");
        QCOMPARE(permission(Control::StartInsertion, s).reason, QStringLiteral("too deep"));
        s.motionProblem.clear();
        // A plan's checklist holds the start; it never lifts another rule.
        s.planHold = QStringLiteral("Tick the plan's checklist first.");
        QCOMPARE(permission(Control::StartInsertion, s).reason, s.planHold);
        QVERIFY(permission(Control::EmergencyStop, s).enabled);
        QVERIFY(permission(Control::Bias, s).enabled);
        s.biased = false;
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("Bias")));
        s.biased = true;
        s.planHold.clear();
        QVERIFY(permission(Control::StartInsertion, s).enabled);
        // Still loaded near the limit (after it tripped, the needle in the tissue): a run
        // would stop at once. Pushing or pulling alike; the needle can come out.
        for (const double force : {7.5, -7.0}) {
            s.force_N = force;
            QVERIFY2(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("withdraw the needle first")),
                     qPrintable(permission(Control::StartInsertion, s).reason));
            QVERIFY(permission(Control::Withdraw, s).enabled);
        }
        s.force_N = 6.0;
        QVERIFY(permission(Control::StartInsertion, s).enabled);
        s.fault = QStringLiteral("sensor: no reply");
        QVERIFY(!permission(Control::StartInsertion, s).enabled);
        QVERIFY(permission(Control::StartInsertion, s).reason.contains(QStringLiteral("no reply")));
        QVERIFY(permission(Control::EmergencyStop, s).enabled);
        s.recording = true;
        QVERIFY(permission(Control::EndRun, s).enabled);  // a faulted run can still be closed
    }

    void panelFollowsTheEngineState()
    {
        nb::ControlPanel panel;
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy estop(&panel, &nb::ControlPanel::emergencyStopRequested);
        QSignalSpy enable(&panel, &nb::ControlPanel::enableRequested);
        QSignalSpy start(&panel, &nb::ControlPanel::startRequested);
        auto* startButton = panel.button(Control::StartInsertion);
        auto* estopButton = panel.button(Control::EmergencyStop);
        QVERIFY(!startButton->isEnabled());
        QVERIFY(estopButton->isEnabled());
        QTest::mouseClick(estopButton, Qt::LeftButton);
        QCOMPARE(estop.count(), 1);
        // Clicking a disabled control does nothing.
        QTest::mouseClick(startButton, Qt::LeftButton);
        QCOMPARE(start.count(), 0);

        nb::devices::EngineStatus s;
        s.running = true;
        s.slope_V_per_g = 0.012;
        s.calibrationName = QStringLiteral("cal_1");
        panel.setSessionOpen(true);
        panel.setStatus(s);
        QTest::mouseClick(panel.button(Control::Enable), Qt::LeftButton);
        QCOMPARE(enable.count(), 1);
        QCOMPARE(enable.first().first().toBool(), true);
        QVERIFY(startButton->toolTip().contains(QStringLiteral("Enable the stage first")));
        s.stageEnabled = true;
        panel.setStatus(s);
        QCOMPARE(panel.button(Control::Enable)->text(), QStringLiteral("Disable stage"));
        QVERIFY(startButton->toolTip().contains(QStringLiteral("Bias")));
        s.biased = s.zeroed = true;
        panel.setStatus(s);
        QVERIFY(startButton->isEnabled());
        QVERIFY(panel.button(Control::Withdraw)->text().contains(QStringLiteral("not recorded")));
        QCOMPARE(panel.button(Control::StopMotion)->text(), QStringLiteral("Stop"));  // nothing records: nothing is kept

        // A depth shallower than the needle already is cannot start.
        auto* depth = panel.findChild<QDoubleSpinBox*>(QStringLiteral("depth"));
        QVERIFY(depth);
        s.position_mm = 40.0;
        panel.setStatus(s);
        QVERIFY(!startButton->isEnabled());
        QVERIFY(startButton->toolTip().contains(QStringLiteral("not deeper")));
        s.position_mm = 0.0;
        panel.setStatus(s);
        QTest::mouseClick(startButton, Qt::LeftButton);
        QCOMPARE(start.count(), 1);
        QCOMPARE(panel.motionPlan().linear.target_mm, depth->value());

        // No force limit: no run.
        auto* limit = panel.findChild<QDoubleSpinBox*>(QStringLiteral("forceLimit"));
        limit->setValue(0.0);
        QVERIFY(!startButton->isEnabled());
        limit->setValue(5.0);
        QVERIFY(startButton->isEnabled());

        s.recording = s.moving = true;
        s.force_N = 4.5;
        s.forceMargin_N = 0.5;  // the engine's, against the limit in force
        s.forceMarginOf_N = 5.0;
        panel.setStatus(s);
        QVERIFY(!startButton->isEnabled());
        QVERIFY(panel.button(Control::StopMotion)->isEnabled());
        QVERIFY(!panel.button(Control::EndRun)->isEnabled());
        QVERIFY(panel.button(Control::Withdraw)->text() == QStringLiteral("Withdraw (recorded)"));
        QCOMPARE(panel.button(Control::StopMotion)->text(), QStringLiteral("Stop (keeps recording)"));
        QVERIFY(panel.findChild<QLabel*>(QStringLiteral("status_margin"))->text().startsWith(QStringLiteral("0.50 N")));
        QVERIFY(!panel.findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->isEnabled());
        QVERIFY(estopButton->isEnabled());

        // Jog is folded away until asked for, and folds away again.
        auto* jogToggle = panel.findChild<QToolButton*>(QStringLiteral("jogToggle"));
        auto* jogOut = panel.findChild<QPushButton*>(QStringLiteral("jogOut"));
        QVERIFY(jogToggle && jogOut);
        QVERIFY(!jogOut->isVisibleTo(&panel));
        jogToggle->click();
        QVERIFY(jogOut->isVisibleTo(&panel));
        jogToggle->click();
        QVERIFY(!jogOut->isVisibleTo(&panel));

        // Numbers in the status are written as in the fields beside them: 4,500 N in German.
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        s.rateHz = 10000.0;
        panel.setStatus(s);
        QCOMPARE(panel.findChild<QLabel*>(QStringLiteral("status_force"))->text(), QStringLiteral("4,500 N"));
        QCOMPARE(panel.findChild<QLabel*>(QStringLiteral("status_devices"))->text(), QStringLiteral("10000 Hz"));
        QLocale::setDefault(before);
    }
};

QTEST_MAIN(TestInterlocks)
#include "test_interlocks.moc"
