#pragma once
// Which devices a session drives: `--daq sim|u6[:SERIAL]` and `--stage sim|zaber:PORT` on the
// command line, the same strings under QSettings keys devices/daq and devices/stage, the
// simulated rig being the default for each. Also lists what is connected.

#include "devices/device_set.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

class QSettings;

namespace nb::devices {

// The simulated rig's settings, used for whatever the spec says is "sim".
struct SimulatedRigSpec {
    QString tissue = QStringLiteral("liver1");  // a preset: simulatedTissues()
    QString tip;                                // beveled | diamond | blunt; empty: the preset's usual tip
    QString setup;                              // organ | platform; empty: platform for the friction slab (liver7)
    quint64 seed = 1;
    bool realtime = true;                       // false: as fast as possible on a simulated clock
};

struct DeviceSpec {
    QString daq = QStringLiteral("sim");     // sim | u6 | u6:SERIAL
    QString stage = QStringLiteral("sim");   // sim | zaber:PORT
    double zaberMicrostepsPerMm = 20997.375; // 0.047625 um micro-steps
    int u6Channel = 0;
    int u6GainIndex = 2;                     // x100: +-100 mV, a bridge without an amplifier
    double slope_V_per_g = 0.0;              // the sensor chain's calibration; 0: nominal 12.3 mV/N at the U6
    SimulatedRigSpec simulated;
};

// Empty when `spec` is valid, else what is wrong with it (for the user).
QString checkDaqSpec(const QString& spec);
QString checkStageSpec(const QString& spec);

// Reads devices/daq, devices/stage, devices/zaber_microsteps_per_mm, devices/u6_channel,
// devices/u6_gain_index, devices/slope_V_per_g and sim/tissue, sim/tip, sim/setup, sim/seed;
// missing keys keep the defaults.
DeviceSpec specFromSettings(const QSettings& settings);
void saveSpec(QSettings& settings, const DeviceSpec& spec);

// Opens the devices (throws DeviceError naming the one that failed). Whatever is "sim" comes
// from a simulated rig made from `spec.simulated`.
DeviceSet openDevices(const DeviceSpec& spec);
// The same, but never leaves the operator without a rig: what cannot be opened is replaced by
// the simulated rig, and `problem` says which device failed and why.
DeviceSet openDevicesOrSimulated(const DeviceSpec& spec, QString* problem);

// What the simulated rig offers, for choosers: preset names and tip names.
QStringList simulatedTissues();
QStringList tipNames();
// The tip the simulated rig runs with: the spec's, else the tissue preset's usual one.
QString simulatedTip(const SimulatedRigSpec& spec);
// Where a sine run should oscillate about so that it works in tissue with the default
// amplitude: inside the simulated rig's tissue; nullopt for a real stage (the operator knows).
std::optional<double> suggestedSineCentre_mm(const DeviceSpec& spec);

// Empty when the simulated rig's settings are valid, else what is wrong (for the user).
QString checkSimulatedRig(const SimulatedRigSpec& spec);
// As kept in a session: {tissue, tip, setup, seed}; nullopt for an object that is not a valid one.
QJsonObject toJson(const SimulatedRigSpec& spec);
std::optional<SimulatedRigSpec> simulatedRigFromJson(const QJsonObject& object);

struct ConnectedDevice {
    QString kind;         // "daq" | "serial"
    QString spec;         // what to pass to --daq / --stage
    QString description;
    QString problem;      // why it cannot be used right now, if known
};
std::vector<ConnectedDevice> listDevices();

}  // namespace nb::devices
