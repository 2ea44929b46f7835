#include "devices/sim/simulated_rig.h"
#include "core/data_names.h"
#include "core/tr.h"

#include <QCoreApplication>

namespace nb::devices::sim {

DeviceSet simulatedDeviceSet(const std::shared_ptr<SimulatedRig>& rig)
{
    DeviceSet set;
    set.stage = rig->makeStage();
    set.sensor = rig->makeSensor();
    set.truth = rig;
    set.calibrationLoad = rig;
    set.selfPacedClock = !rig->config().realtime;
    const RigConfig& config = rig->config();
    set.nominalSlope_V_per_g = config.sensor.slope_V_per_g();
    set.description = nb::TrDevices::tr("simulated rig (%1, %2 tip, seed %3%4)")
                          .arg(config.tissue, tipDisplayName(tipName(config.tip)))
                          .arg(config.seed)
                          .arg(config.realtime ? QString() : nb::TrDevices::tr(", simulated clock"));
    // Run files are in one language whatever the window speaks: a dataset mixes none.
    set.fileDescription = QStringLiteral("simulated rig (%1, %2 tip, seed %3%4)")
                              .arg(config.tissue, tipName(config.tip))
                              .arg(config.seed)
                              .arg(config.realtime ? QString() : QStringLiteral(", simulated clock"));
    return set;
}

DeviceSet makeSimulatedDevices(const RigConfig& config)
{
    return simulatedDeviceSet(std::make_shared<SimulatedRig>(config));
}

}  // namespace nb::devices::sim
