#include "device_spec.h"
#include "core/tr.h"

#include "devices/device_error.h"
#include "devices/labjack_u6/u6_force_sensor.h"
#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"
#include "devices/zaber/zaber_stage.h"

#include <QCoreApplication>
#include <QSerialPortInfo>
#include <QSettings>

namespace nb::devices {

namespace {

// The thesis's load cell, 12.3 mV/N, straight into the U6's differential input.
constexpr double kBridgeSlope_V_per_g = 0.0123 * 9.81 / 1000.0;

sim::RigConfig rigConfig(const SimulatedRigSpec& spec)
{
    sim::RigConfig c;
    c.tissue = spec.tissue;
    c.tip = spec.tip.isEmpty() ? sim::usualTip(spec.tissue, false) : sim::tipFromName(spec.tip).value_or(c.tip);
    const QString setup = spec.setup.isEmpty() ? sim::usualSetup(spec.tissue) : spec.setup;
    c.setup = setup == QLatin1String("platform") ? sim::Setup::Platform : sim::Setup::Organ;
    c.seed = spec.seed;
    c.realtime = spec.realtime;
    return c;
}

}  // namespace

QStringList simulatedTissues() { return sim::tissueNames(); }

QStringList tipNames()
{
    return {sim::tipName(sim::Tip::Beveled), sim::tipName(sim::Tip::Diamond), sim::tipName(sim::Tip::Blunt)};
}

QString simulatedTip(const SimulatedRigSpec& spec) { return sim::tipName(rigConfig(spec).tip); }

QString checkSimulatedRig(const SimulatedRigSpec& spec)
{
    if (!sim::tissueNames().contains(spec.tissue))
        return nb::TrDevices::tr("unknown tissue '%1' (%2)").arg(spec.tissue, sim::tissueNames().join(QLatin1Char('|')));
    if (!spec.tip.isEmpty() && !sim::tipFromName(spec.tip))
        return nb::TrDevices::tr("unknown tip '%1' (%2)").arg(spec.tip, tipNames().join(QLatin1Char('|')));
    if (!spec.setup.isEmpty() && spec.setup != QLatin1String("organ") && spec.setup != QLatin1String("platform"))
        return nb::TrDevices::tr("unknown setup '%1' (organ|platform)").arg(spec.setup);
    return {};
}

QString checkDaqSpec(const QString& spec)
{
    if (spec == QLatin1String("sim") || spec == QLatin1String("u6"))
        return {};
    if (spec.startsWith(QLatin1String("u6:"))) {
        bool ok = false;
        spec.mid(3).toULongLong(&ok);
        return ok ? QString() : nb::TrDevices::tr("'%1': the U6 serial number must be digits (see 'needlebench devices')").arg(spec);
    }
    return nb::TrDevices::tr("unknown DAQ '%1' (sim | u6 | u6:SERIAL)").arg(spec);
}

QString checkStageSpec(const QString& spec)
{
    if (spec == QLatin1String("sim"))
        return {};
    if (spec.startsWith(QLatin1String("zaber:")) && spec.size() > 6)
        return {};
    return nb::TrDevices::tr("unknown stage '%1' (sim | zaber:PORT)").arg(spec);
}

QJsonObject toJson(const SimulatedRigSpec& spec)
{
    return {{QStringLiteral("tissue"), spec.tissue},
            {QStringLiteral("tip"), spec.tip},
            {QStringLiteral("setup"), spec.setup},
            {QStringLiteral("seed"), QString::number(spec.seed)}};
}

std::optional<SimulatedRigSpec> simulatedRigFromJson(const QJsonObject& o)
{
    SimulatedRigSpec spec;
    spec.tissue = o.value(QStringLiteral("tissue")).toString(spec.tissue);
    spec.tip = o.value(QStringLiteral("tip")).toString();
    spec.setup = o.value(QStringLiteral("setup")).toString();
    bool ok = true;
    const QJsonValue seed = o.value(QStringLiteral("seed"));
    if (seed.isString())
        spec.seed = seed.toString().toULongLong(&ok);
    else if (seed.isDouble() && seed.toDouble() >= 0)
        spec.seed = quint64(seed.toDouble());
    if (!ok || !checkSimulatedRig(spec).isEmpty())
        return std::nullopt;
    return spec;
}

DeviceSpec specFromSettings(const QSettings& s)
{
    DeviceSpec d;
    d.daq = s.value(QStringLiteral("devices/daq"), d.daq).toString();
    d.stage = s.value(QStringLiteral("devices/stage"), d.stage).toString();
    d.zaberMicrostepsPerMm = s.value(QStringLiteral("devices/zaber_microsteps_per_mm"), d.zaberMicrostepsPerMm).toDouble();
    d.u6Channel = s.value(QStringLiteral("devices/u6_channel"), d.u6Channel).toInt();
    d.u6GainIndex = s.value(QStringLiteral("devices/u6_gain_index"), d.u6GainIndex).toInt();
    d.slope_V_per_g = s.value(QStringLiteral("devices/slope_V_per_g"), d.slope_V_per_g).toDouble();
    d.simulated.tissue = s.value(QStringLiteral("sim/tissue"), d.simulated.tissue).toString();
    d.simulated.tip = s.value(QStringLiteral("sim/tip"), d.simulated.tip).toString();
    d.simulated.setup = s.value(QStringLiteral("sim/setup"), d.simulated.setup).toString();
    d.simulated.seed = s.value(QStringLiteral("sim/seed"), d.simulated.seed).toULongLong();
    if (!checkSimulatedRig(d.simulated).isEmpty())
        d.simulated = SimulatedRigSpec{};  // a hand-edited setting must not stop the window from opening
    return d;
}

void saveSpec(QSettings& s, const DeviceSpec& d)
{
    s.setValue(QStringLiteral("devices/daq"), d.daq);
    s.setValue(QStringLiteral("devices/stage"), d.stage);
    s.setValue(QStringLiteral("devices/zaber_microsteps_per_mm"), d.zaberMicrostepsPerMm);
    s.setValue(QStringLiteral("devices/u6_channel"), d.u6Channel);
    s.setValue(QStringLiteral("devices/u6_gain_index"), d.u6GainIndex);
    s.setValue(QStringLiteral("devices/slope_V_per_g"), d.slope_V_per_g);
    s.setValue(QStringLiteral("sim/tissue"), d.simulated.tissue);
    s.setValue(QStringLiteral("sim/tip"), d.simulated.tip);
    s.setValue(QStringLiteral("sim/setup"), d.simulated.setup);
    s.setValue(QStringLiteral("sim/seed"), d.simulated.seed);
}

DeviceSet openDevices(const DeviceSpec& spec)
{
    if (const QString e = checkSimulatedRig(spec.simulated); !e.isEmpty())
        throw DeviceError(nb::TrDevices::tr("simulated rig"), e);
    const sim::RigConfig simConfig = rigConfig(spec.simulated);
    if (const QString e = checkDaqSpec(spec.daq); !e.isEmpty())
        throw DeviceError(QStringLiteral("--daq"), e);
    if (const QString e = checkStageSpec(spec.stage); !e.isEmpty())
        throw DeviceError(QStringLiteral("--stage"), e);
    const bool simDaq = spec.daq == QLatin1String("sim");
    const bool simStage = spec.stage == QLatin1String("sim");
    if (simDaq && simStage)
        return sim::makeSimulatedDevices(simConfig);

    DeviceSet set;
    QStringList parts, fileParts;  // fileParts: in English, for run files
    if (simDaq || simStage) {
        // Half real, half simulated: the simulated half must keep wall-clock time.
        sim::RigConfig c = simConfig;
        c.realtime = true;
        DeviceSet simulated = sim::makeSimulatedDevices(c);
        if (simDaq) {
            // The simulated load cell's truth and masses are its own; a real stage moves
            // nothing the simulator sees, so its truth would be fiction: keep the masses only.
            set.calibrationLoad = simulated.calibrationLoad;
            set.sensor = std::move(simulated.sensor);
            set.nominalSlope_V_per_g = simulated.nominalSlope_V_per_g;
            parts << nb::TrDevices::tr("simulated load cell");
            fileParts << QStringLiteral("simulated load cell");
        } else {
            set.stage = std::move(simulated.stage);
            parts << nb::TrDevices::tr("simulated stage");
            fileParts << QStringLiteral("simulated stage");
        }
    }
    if (!simDaq) {
        U6Config c;
        c.serial = spec.daq.mid(3);
        c.channel = spec.u6Channel;
        c.gainIndex = spec.u6GainIndex;
        auto sensor = std::make_unique<U6ForceSensor>(c);
        parts.prepend(sensor->name());
        fileParts.prepend(sensor->name());
        set.sensor = std::move(sensor);
        set.nominalSlope_V_per_g = spec.slope_V_per_g > 0 ? spec.slope_V_per_g : kBridgeSlope_V_per_g;
    }
    if (!simStage) {
        ZaberConfig c;
        c.port = spec.stage.mid(6);
        c.units.microstepsPerMm = spec.zaberMicrostepsPerMm;
        auto stage = std::make_unique<ZaberStage>(c);
        parts << stage->name();
        fileParts << QStringLiteral("Zaber stage on %1").arg(c.port);
        set.stage = std::move(stage);
    }
    set.description = parts.join(QStringLiteral(", "));
    set.fileDescription = fileParts.join(QStringLiteral(", "));
    return set;
}

DeviceSet openDevicesOrSimulated(const DeviceSpec& spec, QString* problem)
{
    try {
        return openDevices(spec);
    } catch (const DeviceError& e) {
        *problem = e.message();
    }
    DeviceSpec fallback;
    fallback.simulated = spec.simulated;
    if (!checkSimulatedRig(fallback.simulated).isEmpty())
        fallback.simulated = SimulatedRigSpec{};
    fallback.simulated.realtime = spec.simulated.realtime;
    return sim::makeSimulatedDevices(rigConfig(fallback.simulated));
}

std::vector<ConnectedDevice> listDevices()
{
    std::vector<ConnectedDevice> out;
    try {
        for (const U6Found& u : findU6Devices()) {
            ConnectedDevice d;
            d.kind = QStringLiteral("daq");
            d.spec = u.serial.isEmpty() ? QStringLiteral("u6") : QStringLiteral("u6:%1").arg(u.serial);
            d.description = nb::TrDevices::tr("LabJack U6 (USB bus %1 device %2)").arg(u.bus).arg(u.address);
            d.problem = u.problem;
            out.push_back(d);
        }
    } catch (const DeviceError& e) {
        out.push_back({QStringLiteral("daq"), QString(), nb::TrDevices::tr("USB"), e.reason()});
    }
    for (const QSerialPortInfo& p : QSerialPortInfo::availablePorts()) {
        ConnectedDevice d;
        d.kind = QStringLiteral("serial");
        d.spec = QStringLiteral("zaber:%1").arg(p.systemLocation());
        QStringList words;
        for (const QString& w : {p.description(), p.manufacturer(), p.serialNumber()})
            if (!w.isEmpty())
                words << w;
        if (p.hasVendorIdentifier())
            words << QStringLiteral("%1:%2").arg(p.vendorIdentifier(), 4, 16, QLatin1Char('0')).arg(p.productIdentifier(), 4, 16, QLatin1Char('0'));
        d.description = words.join(QStringLiteral(", "));
        out.push_back(d);
    }
    return out;
}

std::optional<double> suggestedSineCentre_mm(const DeviceSpec& spec)
{
    if (spec.stage != QLatin1String("sim"))
        return std::nullopt;
    const sim::RigConfig c = rigConfig(spec.simulated);
    // 10 mm past the surface (half the slab on the platform): the default 10 mm amplitude
    // then spans from the surface to well inside.
    const double into_mm = c.setup == sim::Setup::Platform ? c.plateGap_mm + 0.5 * c.thickness_mm : 10.0;
    return c.surface_mm + into_mm;
}

}  // namespace nb::devices
