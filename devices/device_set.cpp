#include "device_set.h"

#include "devices/sim/simulated_rig.h"

#include <QCoreApplication>

namespace nb::devices {

DeviceSet makeSimulatedDevices(const sim::RigConfig& config)
{
    DeviceSet set;
    set.rig = std::make_shared<sim::SimulatedRig>(config);
    set.stage = set.rig->makeStage();
    set.sensor = set.rig->makeSensor();
    set.nominalSlope_V_per_g = config.sensor.slope_V_per_g();
    set.description = QCoreApplication::translate("nb::devices", "simulated rig (%1, %2 tip, seed %3%4)")
                          .arg(config.tissue, sim::tipName(config.tip))
                          .arg(config.seed)
                          .arg(config.realtime ? QString() : QCoreApplication::translate("nb::devices", ", simulated clock"));
    return set;
}

}  // namespace nb::devices
