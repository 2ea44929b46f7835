#pragma once
// The devices one engine drives: a stage, a force sensor and, for the simulation, the rig
// behind both (ground truth, fault injection, calibration masses).

#include "devices/force_sensor.h"
#include "devices/stage.h"

#include <QString>
#include <memory>

namespace nb::devices {

namespace sim {
class SimulatedRig;
struct RigConfig;
}

struct DeviceSet {
    std::unique_ptr<Stage> stage;
    std::unique_ptr<ForceSensor> sensor;
    std::shared_ptr<sim::SimulatedRig> rig;  // null for real hardware
    QString description;                     // "simulated rig (liver1, beveled tip, seed 1)"
    double nominalSlope_V_per_g = 0.0;       // the sensor chain's nominal calibration, 0 = unknown
};

DeviceSet makeSimulatedDevices(const sim::RigConfig& config);

}  // namespace nb::devices
