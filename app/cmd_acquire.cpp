// `needlebench acquire`: one run on real (or simulated) devices, headless, through the same
// acquisition engine and recorder as the workbench. The device selection is --daq/--stage,
// falling back to the settings (devices/daq, devices/stage) and then to the simulated rig.

#include "cli_support.h"
#include "interrupt_watcher.h"
#include "core/tr.h"

#include "devices/acquisition_engine.h"
#include "devices/device_error.h"
#include "devices/device_spec.h"
#include "devices/run_once.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSettings>
#include <QTimer>
#include <cmath>
#include <optional>

namespace nb::cli {

int cmdAcquire(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption daq(QStringLiteral("daq"), nb::TrCli::tr("sim | u6 | u6:SERIAL (default: settings, else sim)"), QStringLiteral("DAQ"));
    const QCommandLineOption stage(QStringLiteral("stage"), nb::TrCli::tr("sim | zaber:PORT (default: settings, else sim)"), QStringLiteral("STAGE"));
    const QCommandLineOption protocol(QStringLiteral("protocol"), nb::TrCli::tr("stiffness|internal|friction|prostate (friction: sine motion)"), QStringLiteral("P"));
    const QCommandLineOption out(QStringLiteral("out"), nb::TrCli::tr("the run file to write"), QStringLiteral("RUN.csv"));
    const QCommandLineOption rate(QStringLiteral("rate-hz"), nb::TrCli::tr("sampling rate, 100..10000 (default 500)"), QStringLiteral("R"), QStringLiteral("500"));
    const QCommandLineOption velocity(QStringLiteral("velocity-mm-s"), nb::TrCli::tr("insertion velocity (default 4)"), QStringLiteral("V"), QStringLiteral("4"));
    const QCommandLineOption depth(QStringLiteral("depth-mm"), nb::TrCli::tr("insertion depth from the start position (default 40)"), QStringLiteral("D"), QStringLiteral("40"));
    const QCommandLineOption amplitude(QStringLiteral("amplitude-mm"), nb::TrCli::tr("sine amplitude (default 10)"), QStringLiteral("A"), QStringLiteral("10"));
    const QCommandLineOption frequency(QStringLiteral("frequency-hz"), nb::TrCli::tr("sine frequency (default 0.5)"), QStringLiteral("F"), QStringLiteral("0.5"));
    const QCommandLineOption cycles(QStringLiteral("cycles"), nb::TrCli::tr("sine cycles (default 7)"), QStringLiteral("N"), QStringLiteral("7"));
    const QCommandLineOption maxForce(QStringLiteral("max-force-n"), nb::TrCli::tr("force limit that stops the stage (default 8)"), QStringLiteral("F"), QStringLiteral("8"));
    const QCommandLineOption steps(QStringLiteral("zaber-microsteps-per-mm"), nb::TrCli::tr("stage resolution (default: settings, else 20997.375)"), QStringLiteral("N"));
    const QCommandLineOption slope(QStringLiteral("slope-v-per-g"), nb::TrCli::tr("sensor calibration slope d in V/g (default: settings, else nominal)"), QStringLiteral("D"));
    const QCommandLineOption stopAt(QStringLiteral("stop-at"), nb::TrCli::tr("stop the insertion at a puncture: puncture (the first) or puncture:N (the N-th)"), QStringLiteral("puncture[:N]"));
    const QCommandLineOption slowAfter(QStringLiteral("slow-after-puncture"), nb::TrCli::tr("slow the insertion to V mm/s after the first puncture"), QStringLiteral("V"));
    const QCommandLineOption overwrite(QStringLiteral("overwrite"), nb::TrCli::tr("replace an existing run file"));
    for (const auto* o : {&daq, &stage, &protocol, &out, &rate, &velocity, &depth, &amplitude, &frequency, &cycles, &maxForce, &steps, &slope, &stopAt, &slowAfter, &overwrite})
        parser.addOption(*o);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("acquire"), args, io, 0, 0, &code))
        return code;

    auto usage = [&](const QString& why) {
        io.err << "needlebench acquire: " << why << "\n\n" << nb::TrCli::tr("Run 'needlebench acquire --help' for the options.") << '\n';
        return Usage;
    };
    QSettings settings;
    devices::DeviceSpec spec = devices::specFromSettings(settings);
    if (parser.isSet(daq))
        spec.daq = parser.value(daq);
    if (parser.isSet(stage))
        spec.stage = parser.value(stage);
    if (const QString e = devices::checkDaqSpec(spec.daq); !e.isEmpty())
        return usage(e);
    if (const QString e = devices::checkStageSpec(spec.stage); !e.isEmpty())
        return usage(e);
    const QStringList protocols{QStringLiteral("stiffness"), QStringLiteral("internal"), QStringLiteral("friction"), QStringLiteral("prostate")};
    if (!protocols.contains(parser.value(protocol)))
        return usage(nb::TrCli::tr("--protocol must be one of %1").arg(protocols.join(QLatin1Char('|'))));
    if (!parser.isSet(out))
        return usage(nb::TrCli::tr("--out RUN.csv is required"));
    // Before the devices move: an earlier recording is not replaced, and a run is not
    // recorded (the needle inserted) only to find it cannot be written.
    if (QString e = existingOutput(QStringLiteral("--out"), parser.value(out), parser.isSet(overwrite)); !e.isEmpty()
        || !(e = unwritableOutput(QStringLiteral("--out"), parser.value(out))).isEmpty())
        return usage(e);
    QString error;
    auto number = [&](const QCommandLineOption& o, double lo, double hi) -> std::optional<double> {
        bool ok = false;
        const double v = parser.value(o).toDouble(&ok);
        if (!ok || !std::isfinite(v) || v < lo || v > hi) {
            error = nb::TrCli::tr("--%1 must be a number in [%2, %3] (got '%4')").arg(o.names().first()).arg(lo).arg(hi).arg(parser.value(o));
            return std::nullopt;
        }
        return v;
    };
    const auto r = number(rate, 100, 10000), v = number(velocity, 0.01, 50), d = number(depth, 0.01, 150),
               a = number(amplitude, 0.01, 10), f = number(frequency, 0.01, 5), n = number(cycles, 1, 1000),
               m = number(maxForce, 0.01, 20);
    if (!r || !v || !d || !a || !f || !n || !m)
        return usage(error);
    if (parser.isSet(steps)) {
        const auto s = number(steps, 1, 1e7);
        if (!s)
            return usage(error);
        spec.zaberMicrostepsPerMm = *s;
    }
    if (parser.isSet(slope)) {
        const auto s = number(slope, 1e-9, 1);
        if (!s)
            return usage(error);
        spec.slope_V_per_g = *s;
    }

    spec.simulated.realtime = true;  // whatever is simulated keeps wall-clock time beside real devices
    devices::DeviceSet set;
    try {
        set = devices::openDevices(spec);
    } catch (const devices::DeviceError& e) {
        io.err << "needlebench acquire: " << e.message() << '\n';
        return Failure;
    }
    devices::EngineConfig config;
    config.rateHz = *r;
    config.forceLimit_N = *m;
    config.liveView = false;
    devices::AcquisitionEngine engine(std::move(set), config);

    devices::RunPlan plan;
    plan.outPath = parser.value(out);
    plan.metadata.set(QStringLiteral("protocol"), parser.value(protocol));
    plan.metadata.set(QStringLiteral("daq"), spec.daq);
    plan.metadata.set(QStringLiteral("stage"), spec.stage);
    if (spec.stage.startsWith(QLatin1String("zaber:")))
        // The engine reads the stage once per sensor batch (20 ms): about 50 Hz.
        plan.metadata.set(QStringLiteral("stage_position_source"), QStringLiteral("zaber polled 50 Hz, interpolated"));
    if (parser.value(protocol) == QLatin1String("friction")) {
        plan.motion = devices::RunPlan::Motion::Sine;
        plan.sine = {*a, *f, int(*n)};
        plan.metadata.set(QStringLiteral("amplitude_mm"), *a);
        plan.metadata.set(QStringLiteral("frequency_hz"), *f);
        plan.metadata.set(QStringLiteral("cycles"), *n);
    } else {
        plan.motion = devices::RunPlan::Motion::Linear;
        plan.linear = {*v, *d};
        if (parser.isSet(stopAt)) {
            const auto n = parseStopAt(parser.value(stopAt));
            if (!n)
                return usage(nb::TrCli::tr("--stop-at wants puncture or puncture:N with N ≥ 1 (got '%1')").arg(parser.value(stopAt)));
            plan.stopAtPuncture = *n;
        }
        if (parser.isSet(slowAfter)) {
            const auto sv = number(slowAfter, 0.001, 50);
            if (!sv)
                return usage(error);
            plan.slowAfterPuncture_mm_s = *sv;
        }
        plan.metadata.set(QStringLiteral("velocity_mm_s"), *v);
        plan.metadata.set(QStringLiteral("depth_mm"), *d);
    }

    // A signal stops the stage and closes the run as "interrupted"; a second one (or one
    // before the run started) does not wait.
    InterruptWatcher interrupts;
    interrupts.announceOn(io.err, QStringLiteral("acquire"));
    devices::RunOnceOptions options;
    options.interruption = [&] { return interrupts.interruption(); };
    const devices::RunOnceResult run = devices::runOnce(engine, plan, options);
    const std::optional<devices::RunSummary>& summary = run.summary;
    if (!summary) {
        io.err << "needlebench acquire: " << run.error << '\n';
        return interrupts.signalNumber() ? 128 + interrupts.signalNumber() : Failure;
    }
    if (summary->endReason == EndReason::WriteError)
        io.err << "needlebench acquire: "
               << nb::TrCli::tr("recording failed: %1; the run file keeps %2 whole rows").arg(summary->fault).arg(summary->samples)
               << '\n';
    QJsonObject result{{QStringLiteral("out"), summary->path},
                       {QStringLiteral("end_reason"), fileName(summary->endReason)},
                       {QStringLiteral("samples"), double(summary->samples)},
                       {QStringLiteral("dropped"), double(summary->dropped)},
                       {QStringLiteral("device"), engine.deviceDescription()}};
    if (!summary->fault.isEmpty())
        result.insert(QStringLiteral("fault"), summary->fault);
    printJson(io, result);
    if (interrupts.signalNumber())
        return 128 + interrupts.signalNumber();
    return summary->endReason == EndReason::Fault || summary->endReason == EndReason::WriteError ? Failure : Ok;
}

}  // namespace nb::cli
