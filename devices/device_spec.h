#pragma once
// Which devices a session drives: `--daq sim|u6[:SERIAL]` and `--stage sim|zaber:PORT` on the
// command line, the same strings under QSettings keys devices/daq and devices/stage, the
// simulated rig being the default for each. Also lists what is connected.

#include "devices/device_set.h"

#include <QString>
#include <optional>
#include <vector>

class QSettings;

namespace nb::devices {

namespace sim {
struct RigConfig;
}

struct DeviceSpec {
    QString daq = QStringLiteral("sim");     // sim | u6 | u6:SERIAL
    QString stage = QStringLiteral("sim");   // sim | zaber:PORT
    double zaberMicrostepsPerMm = 20997.375; // 0.047625 um micro-steps
    int u6Channel = 0;
    int u6GainIndex = 2;                     // x100: +-100 mV, a bridge without an amplifier
    double slope_V_per_g = 0.0;              // the sensor chain's calibration; 0: nominal 12.3 mV/N at the U6
};

// Empty when `spec` is valid, else what is wrong with it (for the user).
QString checkDaqSpec(const QString& spec);
QString checkStageSpec(const QString& spec);

// Reads devices/daq, devices/stage, devices/zaber_microsteps_per_mm, devices/u6_channel,
// devices/u6_gain_index, devices/slope_V_per_g; missing keys keep the defaults.
DeviceSpec specFromSettings(const QSettings& settings);
void saveSpec(QSettings& settings, const DeviceSpec& spec);

// Opens the devices (throws DeviceError naming the one that failed). Whatever is "sim" comes
// from a simulated rig made from `simConfig`.
DeviceSet openDevices(const DeviceSpec& spec, const sim::RigConfig& simConfig);

struct ConnectedDevice {
    QString kind;         // "daq" | "serial"
    QString spec;         // what to pass to --daq / --stage
    QString description;
    QString problem;      // why it cannot be used right now, if known
};
std::vector<ConnectedDevice> listDevices();

}  // namespace nb::devices
