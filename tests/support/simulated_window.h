#pragma once
// One helper connects the simulated rig to every window test, as QGroundControl's MockLink does
// for its vehicle: the window drives the rig through the ordinary device set, and the test keeps
// a hand on it (faults, calibration masses, truth) through `rig`.

#include "main_window.h"

#include "devices/sim/simulated_rig.h"

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

}  // namespace nbtest
