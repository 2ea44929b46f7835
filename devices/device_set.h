#pragma once
// The devices one engine drives: a stage, a force sensor, and what else the set can do
// (ground truth, a calibration load, a clock it paces itself). Drivers and simulators make
// DeviceSets; nothing downstream knows which made it.

#include "devices/force_sensor.h"
#include "devices/ground_truth.h"
#include "devices/stage.h"

#include <QString>
#include <memory>

namespace nb::devices {

struct DeviceSet {
    std::unique_ptr<Stage> stage;
    std::unique_ptr<ForceSensor> sensor;
    std::shared_ptr<GroundTruthSource> truth;          // null: no truth columns are recorded
    std::shared_ptr<CalibrationLoad> calibrationLoad;  // null: the operator hangs the masses
    // True when the sensor's clock runs as fast as it is read (a simulation on its own
    // clock): the host does not pace it, and an idle engine waits instead of racing it.
    bool selfPacedClock = false;
    QString description;                     // "simulated rig (liver1, beveled tip, seed 1)", in the operator's language
    QString fileDescription;                 // the same in English, as run files record it (empty: `description`)
    double nominalSlope_V_per_g = 0.0;       // the sensor chain's nominal calibration, 0 = unknown
};

}  // namespace nb::devices
