#pragma once
// One helper connects the simulated rig to every window test, as QGroundControl's MockLink does
// for its vehicle: the window drives the rig through the ordinary device set, and the test keeps
// a hand on it (faults, calibration masses, truth) through `rig`.

#include "main_window.h"

#include "devices/sim/simulated_rig.h"
#include "widgets/control_panel.h"

#include <QAbstractButton>
#include <QMessageBox>
#include <QtTest>

#include <memory>

namespace nbtest {

// A window on a fresh session folder, settings not persisted, 1 kHz, a short calibration dwell.
// `rig` (optional) receives the simulated rig the window's engine runs on.
inline nb::WorkbenchOptions simulatedWindow(const QString& sessionDir, bool realtime,
                                            std::shared_ptr<nb::devices::sim::SimulatedRig>* rig = nullptr)
{
    nb::WorkbenchOptions o;
    if (rig)
        o.deviceFactory = [realtime, rig] {
            nb::devices::sim::RigConfig c;
            c.realtime = realtime;
            *rig = std::make_shared<nb::devices::sim::SimulatedRig>(c);
            return nb::devices::sim::simulatedDeviceSet(*rig);
        };
    o.realtime = realtime;
    o.rateHz = 1000.0;
    o.sessionDir = sessionDir;
    o.persistSettings = false;
    o.calibrationDwell_s = 0.2;
    return o;
}

// The operator's preparation through the control panel's buttons, once the devices run: enable
// the stage, bias the sensor, zero the position, until Start insertion is offered (the test
// fails at the step that is refused).
inline void prepareToRecord(nb::MainWindow& w)
{
    nb::ControlPanel* p = w.controlPanel();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().devicesRunning, 20000);
    p->button(nb::Control::Enable)->click();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().stageEnabled, 20000);
    p->button(nb::Control::Bias)->click();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().biased, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(p->button(nb::Control::Zero)->isEnabled(), 20000);
    p->button(nb::Control::Zero)->click();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().zeroed, 20000);
    QTRY_VERIFY2_WITH_TIMEOUT(p->button(nb::Control::StartInsertion)->isEnabled(),
                              qPrintable(p->button(nb::Control::StartInsertion)->toolTip()), 20000);
}

// The operator ends a recording run: Stop while the stage moves (the run keeps recording), then
// End run once it is offered, which is at rest (interlocks.cpp). A click on a greyed-out button is
// lost, as it is for the operator, so each click waits until the panel offers it.
inline void endRun(nb::MainWindow& w)
{
    nb::ControlPanel* p = w.controlPanel();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().recording, 20000);
    if (p->interlockState().moving) {
        QVERIFY(p->button(nb::Control::StopMotion)->isEnabled());
        p->button(nb::Control::StopMotion)->click();
    }
    QTRY_VERIFY2_WITH_TIMEOUT(p->button(nb::Control::EndRun)->isEnabled(),
                              qPrintable(p->button(nb::Control::EndRun)->toolTip()), 20000);
    p->button(nb::Control::EndRun)->click();
    QTRY_VERIFY_WITH_TIMEOUT(!p->interlockState().recording, 20000);
}

// The operator quits; where the window asks first (the stage enabled with the needle in the
// tissue, say), they confirm.
inline void quitConfirming(nb::MainWindow& w)
{
    if (!w.close()) {
        auto* question = w.findChild<QMessageBox*>(QStringLiteral("quitQuestion"));
        QVERIFY(question && question->isVisible());
        question->button(QMessageBox::Yes)->click();
    }
    QTRY_VERIFY(!w.isVisible());
}

}  // namespace nbtest
