// `needlebench simulate`: one run on the simulated rig, through the same acquisition engine
// and recorder as the workbench, headless. Options are read into SimulateOptions in one
// place (addOptions/readOptions) so that more (e.g. --video) slot in without touching the run.

#include "cli_support.h"
#include "interrupt_watcher.h"
#include "core/disk_space.h"
#include "core/tr.h"

#include "devices/acquisition_engine.h"
#include "devices/device_set.h"
#include "core/run_file.h"
#include "devices/sim/imaging_render.h"
#include "devices/sim/simulated_rig.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QSaveFile>
#include <QTimer>
#include <atomic>
#include <cmath>
#include <optional>
#include <opencv2/videoio.hpp>

namespace nb::cli {

namespace {

struct SimulateOptions {
    QString protocol;
    devices::sim::RigConfig rig;
    double rateHz = 500.0;
    double velocity_mm_s = 4.0;
    double depth_mm = 40.0;
    devices::SineMotion sine;
    double maxForce_N = 8.0;
    QString out, truth;
    QString video;          // --video: the rendered imaging view
    double videoOffset_s = 0.0;
};

struct OptionSet {
    QCommandLineOption protocol{QStringLiteral("protocol"), nb::TrCli::tr("stiffness|internal|friction|prostate"), QStringLiteral("P")};
    QCommandLineOption tissue{QStringLiteral("tissue"), nb::TrCli::tr("liver1|liver2|liver3|liver5|liver7|prostate"), QStringLiteral("T")};
    QCommandLineOption tip{QStringLiteral("tip"), nb::TrCli::tr("beveled|diamond|blunt"), QStringLiteral("TIP")};
    QCommandLineOption seed{QStringLiteral("seed"), nb::TrCli::tr("random seed (default 1)"), QStringLiteral("N"), QStringLiteral("1")};
    QCommandLineOption rate{QStringLiteral("rate-hz"), nb::TrCli::tr("sampling rate, 100..10000 (default 500)"), QStringLiteral("R"), QStringLiteral("500")};
    QCommandLineOption velocity{QStringLiteral("velocity-mm-s"), nb::TrCli::tr("insertion velocity (default 4, internal 2.5)"), QStringLiteral("V")};
    QCommandLineOption depth{QStringLiteral("depth-mm"), nb::TrCli::tr("insertion depth from the start position (default 40)"), QStringLiteral("D")};
    QCommandLineOption amplitude{QStringLiteral("amplitude-mm"), nb::TrCli::tr("sine amplitude (default 10)"), QStringLiteral("A"), QStringLiteral("10")};
    QCommandLineOption frequency{QStringLiteral("frequency-hz"), nb::TrCli::tr("sine frequency (default 0.5)"), QStringLiteral("F"), QStringLiteral("0.5")};
    QCommandLineOption cycles{QStringLiteral("cycles"), nb::TrCli::tr("sine cycles (default 7)"), QStringLiteral("N"), QStringLiteral("7")};
    QCommandLineOption thickness{QStringLiteral("thickness-mm"), nb::TrCli::tr("tissue slab thickness on the friction platform (default 30)"), QStringLiteral("T"), QStringLiteral("30")};
    QCommandLineOption bone{QStringLiteral("bone-depth-mm"), nb::TrCli::tr("bone this far below the surface (very stiff)"), QStringLiteral("D")};
    QCommandLineOption maxForce{QStringLiteral("max-force-n"), nb::TrCli::tr("force limit that stops the stage (default 8)"), QStringLiteral("F"), QStringLiteral("8")};
    QCommandLineOption realtime{QStringLiteral("realtime"), nb::TrCli::tr("run on the wall clock (default: as fast as possible)")};
    QCommandLineOption truth{QStringLiteral("truth"), nb::TrCli::tr("write the ground truth as JSON"), QStringLiteral("FILE.json")};
    QCommandLineOption out{QStringLiteral("out"), nb::TrCli::tr("the run file to write"), QStringLiteral("RUN.csv")};
    QCommandLineOption video{QStringLiteral("video"), nb::TrCli::tr("also render the imaging view (29.97 frames/s; .avi, .mkv or .mp4)"), QStringLiteral("FILE")};
    QCommandLineOption videoOffset{QStringLiteral("video-offset-s"), nb::TrCli::tr("the video starts this long before the recording (default 0)"), QStringLiteral("S"), QStringLiteral("0")};

    void addTo(QCommandLineParser& p) const
    {
        for (const auto* o : {&protocol, &tissue, &tip, &seed, &rate, &velocity, &depth, &amplitude, &frequency,
                              &cycles, &thickness, &bone, &maxForce, &realtime, &truth, &out, &video, &videoOffset})
            p.addOption(*o);
    }
};

std::optional<double> number(const QCommandLineParser& p, const QCommandLineOption& o, QString* error)
{
    bool ok = false;
    const double v = p.value(o).toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        *error = nb::TrCli::tr("--%1: '%2' is not a number").arg(o.names().first(), p.value(o));
        return std::nullopt;
    }
    return v;
}

// Reads and checks every option; returns an error text for the user on bad input.
QString readOptions(const QCommandLineParser& p, const OptionSet& o, SimulateOptions& s)
{
    using namespace devices::sim;
    QString error;
    s.protocol = p.value(o.protocol);
    const QStringList protocols{QStringLiteral("stiffness"), QStringLiteral("internal"), QStringLiteral("friction"),
                                QStringLiteral("prostate")};
    if (!protocols.contains(s.protocol))
        return s.protocol.isEmpty() ? nb::TrCli::tr("--protocol is required (%1)").arg(protocols.join(QLatin1Char('|')))
                                    : nb::TrCli::tr("unknown protocol '%1' (%2)").arg(s.protocol, protocols.join(QLatin1Char('|')));
    if (!p.isSet(o.out))
        return nb::TrCli::tr("--out RUN.csv is required");
    s.out = p.value(o.out);
    s.truth = p.value(o.truth);
    s.video = p.value(o.video);
    {
        bool ok = false;
        s.videoOffset_s = p.value(o.videoOffset).toDouble(&ok);
        if (!ok || s.videoOffset_s < 0 || s.videoOffset_s > 600)
            return nb::TrCli::tr("--video-offset-s wants seconds between 0 and 600");
    }

    const bool internal = s.protocol == QLatin1String("internal");
    const bool friction = s.protocol == QLatin1String("friction");
    const bool prostate = s.protocol == QLatin1String("prostate");
    s.rig.tissue = p.isSet(o.tissue) ? p.value(o.tissue)
                   : prostate        ? QStringLiteral("prostate")
                   : (internal || friction) ? QStringLiteral("liver7")
                                     : QStringLiteral("liver1");
    if (!tissueNames().contains(s.rig.tissue))
        return nb::TrCli::tr("unknown tissue '%1' (%2)").arg(s.rig.tissue, tissueNames().join(QLatin1Char('|')));
    if (p.isSet(o.tip)) {
        const auto tip = tipFromName(p.value(o.tip));
        if (!tip)
            return nb::TrCli::tr("unknown tip '%1' (beveled|diamond|blunt)").arg(p.value(o.tip));
        s.rig.tip = *tip;
    } else {
        // The thesis's pairings: blunt for capsule-free tissue, diamond for livers 5, 7 and the prostate.
        const bool diamond = s.rig.tissue == QLatin1String("liver5") || s.rig.tissue == QLatin1String("liver7") ||
                             s.rig.tissue == QLatin1String("prostate");
        s.rig.tip = internal ? Tip::Blunt : diamond ? Tip::Diamond : Tip::Beveled;
    }
    s.rig.setup = friction ? Setup::Platform : Setup::Organ;
    bool ok = false;
    s.rig.seed = p.value(o.seed).toULongLong(&ok);
    if (!ok)
        return nb::TrCli::tr("--seed: '%1' is not a non-negative integer").arg(p.value(o.seed));
    s.rig.realtime = p.isSet(o.realtime);

    auto rate = number(p, o.rate, &error);
    if (!rate)
        return error;
    if (*rate < 100.0 || *rate > 10000.0)
        return nb::TrCli::tr("--rate-hz must be between 100 and 10000 (got %1)").arg(*rate);
    s.rateHz = *rate;
    s.velocity_mm_s = internal ? 2.5 : 4.0;
    if (p.isSet(o.velocity)) {
        auto v = number(p, o.velocity, &error);
        if (!v)
            return error;
        if (*v <= 0.0 || *v > s.rig.stage.maxVelocity_mm_s)
            return nb::TrCli::tr("--velocity-mm-s must be in (0, %1]").arg(s.rig.stage.maxVelocity_mm_s);
        s.velocity_mm_s = *v;
    }
    if (p.isSet(o.depth)) {
        auto d = number(p, o.depth, &error);
        if (!d)
            return error;
        if (*d <= 0.0 || *d > s.rig.stage.maxPosition_mm)
            return nb::TrCli::tr("--depth-mm must be in (0, %1]").arg(s.rig.stage.maxPosition_mm);
        s.depth_mm = *d;
    }
    auto a = number(p, o.amplitude, &error);
    auto f = a ? number(p, o.frequency, &error) : std::nullopt;
    auto t = f ? number(p, o.thickness, &error) : std::nullopt;
    auto m = t ? number(p, o.maxForce, &error) : std::nullopt;
    if (!m)
        return error;
    if (*a <= 0.0 || *a > -s.rig.stage.minPosition_mm)
        return nb::TrCli::tr("--amplitude-mm must be in (0, %1]").arg(-s.rig.stage.minPosition_mm);
    if (*f <= 0.0 || *f > 5.0)
        return nb::TrCli::tr("--frequency-hz must be in (0, 5]");
    if (*t <= 0.0)
        return nb::TrCli::tr("--thickness-mm must be positive");
    if (*m <= 0.0)
        return nb::TrCli::tr("--max-force-n must be positive");
    const int cycles = p.value(o.cycles).toInt(&ok);
    if (!ok || cycles < 1)
        return nb::TrCli::tr("--cycles must be a positive integer");
    s.sine = {*a, *f, cycles};
    s.rig.thickness_mm = *t;
    s.maxForce_N = *m;
    if (p.isSet(o.bone)) {
        auto b = number(p, o.bone, &error);
        if (!b)
            return error;
        s.rig.boneDepth_mm = *b;
    }
    return {};
}

Metadata runMetadata(const SimulateOptions& s)
{
    Metadata m;
    m.set(QStringLiteral("protocol"), s.protocol);
    m.set(QStringLiteral("tissue"), s.rig.tissue);
    m.set(QStringLiteral("tip"), devices::sim::tipName(s.rig.tip));
    m.set(QStringLiteral("seed"), QString::number(s.rig.seed));
    if (s.rig.setup == devices::sim::Setup::Platform) {
        m.set(QStringLiteral("amplitude_mm"), s.sine.amplitude_mm);
        m.set(QStringLiteral("frequency_hz"), s.sine.frequency_hz);
        m.set(QStringLiteral("cycles"), static_cast<double>(s.sine.cycles));
    } else {
        m.set(QStringLiteral("velocity_mm_s"), s.velocity_mm_s);
        m.set(QStringLiteral("depth_mm"), s.depth_mm);
    }
    m.set(QStringLiteral("thickness_mm"), s.rig.thickness_mm);
    if (s.rig.boneDepth_mm)
        m.set(QStringLiteral("bone_depth_mm"), *s.rig.boneDepth_mm);
    m.set(QStringLiteral("clock"), s.rig.realtime ? QStringLiteral("realtime") : QStringLiteral("simulated"));
    return m;
}

// The rig's truth on the run's time axis (run time 0 = the first recorded sample).
QJsonObject truthOnRunTime(const QJsonObject& truth, double origin_s)
{
    QJsonObject out = truth;
    for (const char* key : {"contact_s", "puncture_s", "relaxed_s"}) {
        const QString k = QLatin1String(key);
        if (out.value(k).isDouble())
            out.insert(k, out.value(k).toDouble() - origin_s);
    }
    for (const char* list : {"events", "phases"}) {
        QJsonArray a = out.value(QLatin1String(list)).toArray();
        for (auto it = a.begin(); it != a.end(); ++it) {
            QJsonObject e = it->toObject();
            for (const char* key : {"time_s", "start_s", "end_s"})
                if (e.contains(QLatin1String(key)))
                    e.insert(QLatin1String(key), e.value(QLatin1String(key)).toDouble() - origin_s);
            *it = e;
        }
        out.insert(QLatin1String(list), a);
    }
    out.insert(QStringLiteral("time_origin_device_s"), origin_s);
    return out;
}

// [issue 15] Watches the disk the run file goes to: warns once when it will be full within
// a minute at the rate the file grows.
class SpaceWatch {
public:
    explicit SpaceWatch(QString path) : path_(std::move(path)) { clock_.start(); }
    QString check()
    {
        if (warned_ || clock_.elapsed() < nextCheck_ms_)
            return {};
        nextCheck_ms_ = clock_.elapsed() + 1000;
        const qint64 size = QFileInfo(path_).size();
        const auto free = freeBytes(path_);
        const double elapsed_s = clock_.elapsed() / 1000.0;
        if (!free || size <= 0 || elapsed_s < 1.0)
            return {};
        const double left_s = secondsUntilFull(*free, size / elapsed_s);
        if (left_s >= kLowSpaceWarning_s)
            return {};
        warned_ = true;
        return nb::TrCli::tr("warning: the disk holding %1 will be full in about %2 s at the current rate (%3 kB free)")
            .arg(path_)
            .arg(left_s, 0, 'f', 0)
            .arg(*free / 1024);
    }

private:
    QString path_;
    QElapsedTimer clock_;
    qint64 nextCheck_ms_ = 1000;
    bool warned_ = false;
};

}  // namespace

int cmdSimulate(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const OptionSet o;
    o.addTo(parser);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("simulate"), args, io, 0, 0, &code))
        return code;
    SimulateOptions s;
    if (const QString error = readOptions(parser, o, s); !error.isEmpty()) {
        io.err << "needlebench simulate: " << error << "\n\n" << nb::TrCli::tr("Run 'needlebench simulate --help' for the options.") << '\n';
        return Usage;
    }

    devices::EngineConfig config;
    config.rateHz = s.rateHz;
    config.forceLimit_N = s.maxForce_N;
    config.realtimeScheduling = s.rig.realtime;  // a busy simulated clock must not hog a core at FIFO priority
    config.liveView = false;
    devices::AcquisitionEngine engine(devices::makeSimulatedDevices(s.rig), config);

    devices::RunPlan plan;
    plan.outPath = s.out;
    plan.metadata = runMetadata(s);
    if (s.rig.setup == devices::sim::Setup::Platform) {
        plan.motion = devices::RunPlan::Motion::Sine;
        plan.sine = s.sine;
    } else {
        plan.motion = devices::RunPlan::Motion::Linear;
        plan.linear = {s.velocity_mm_s, s.depth_mm};
    }

    QEventLoop loop;
    std::optional<devices::RunSummary> summary;
    QString refused, faultText;
    QObject::connect(&engine, &devices::AcquisitionEngine::runEnded, &loop, [&](const devices::RunSummary& r) {
        summary = r;
        loop.quit();
    });
    QObject::connect(&engine, &devices::AcquisitionEngine::runRefused, &loop, [&](const QString& why) {
        refused = why;
        loop.quit();
    });
    QObject::connect(&engine, &devices::AcquisitionEngine::faultOccurred, &loop,
                     [&](const QString& device, const QString& reason) { faultText = device + QStringLiteral(": ") + reason; });
    QObject::connect(&engine, &devices::AcquisitionEngine::runStarted, &loop, [&](const QString& path) {
        io.out << "recording " << path << '\n';
        io.out.flush();
    });

    // The operator's sequence: enable, bias (needle at rest, out of tissue), zero, start.
    // Started from the engine thread the moment the interlocks are met, so that on the
    // simulated clock the run begins at the same simulated time on every invocation.
    std::atomic<bool> started{false};
    QObject::connect(
        &engine, &devices::AcquisitionEngine::statusChanged, &engine,
        [&](const devices::EngineStatus& st) {
            if (st.biased && st.zeroed && st.stageEnabled && !started.exchange(true))
                engine.startRun(plan);
        },
        Qt::DirectConnection);
    // [issue 15] A signal stops the stage and closes the run as "interrupted"; a second one
    // (or one before the run started) does not wait.
    InterruptWatcher interrupts;
    QObject::connect(&interrupts, &InterruptWatcher::interrupted, &loop, [&](int signo) {
        io.err << "needlebench simulate: "
               << nb::TrCli::tr("%1 received: stopping the stage and closing the run").arg(InterruptWatcher::signalName(signo))
               << '\n';
        io.err.flush();
        if (interrupts.signalNumber() != signo || !started.load()) {
            loop.quit();
            return;
        }
        Metadata extra;
        extra.set(QStringLiteral("signal"), InterruptWatcher::signalName(signo));
        engine.endRun(QStringLiteral("interrupted"), extra);
    });
    // Queued before the thread starts: they run before its first sample.
    engine.enableStage(true);
    engine.biasSensor();
    engine.zeroStage();
    engine.start();
    QElapsedTimer wall;
    wall.start();
    SpaceWatch space(s.out);
    QTimer tick;
    tick.setInterval(s.rig.realtime ? 20 : 5);
    // Progress lines carry the engine's run time: a killed recording can be checked against them.
    QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
        const devices::EngineStatus st = engine.status();
        if (!st.fault.isEmpty() && !started.load()) {
            faultText = st.fault;
            loop.quit();
        }
        if (st.recording)
            if (const QString w = space.check(); !w.isEmpty()) {
                io.err << "needlebench simulate: " << w << '\n';
                io.err.flush();
            }
        if (st.recording && s.rig.realtime) {
            io.out << "progress run_time_s=" << QString::number(st.runTime_s, 'f', 4) << " samples=" << st.samples << '\n';
            io.out.flush();
        }
        if (wall.elapsed() > 30 * 60 * 1000) {
            faultText = nb::TrCli::tr("the run did not finish within 30 minutes");
            engine.endRun();
        }
    });
    tick.start();
    loop.exec();
    tick.stop();
    const devices::EngineStatus last = engine.status();
    engine.shutdown();

    if (!summary) {
        io.err << "needlebench simulate: " << (refused.isEmpty() ? faultText : refused) << '\n';
        return interrupts.signalNumber() ? 128 + interrupts.signalNumber() : Failure;
    }
    // [issue 15] A run that did not end by itself gets no truth or video: they would describe
    // a recording that is not in the file.
    if (summary->endReason == QLatin1String("write_error") || summary->endReason == QLatin1String("interrupted")) {
        if (summary->endReason == QLatin1String("write_error"))
            io.err << "needlebench simulate: "
                   << nb::TrCli::tr("recording failed: %1; the run file keeps %2 whole rows").arg(summary->fault).arg(summary->samples)
                   << '\n';
        QJsonObject result{{QStringLiteral("out"), summary->path},
                           {QStringLiteral("end_reason"), summary->endReason},
                           {QStringLiteral("samples"), static_cast<double>(summary->samples)},
                           {QStringLiteral("dropped"), static_cast<double>(summary->dropped)}};
        if (!summary->fault.isEmpty())
            result.insert(QStringLiteral("error"), summary->fault);
        printJson(io, result);
        return interrupts.signalNumber() ? 128 + interrupts.signalNumber() : Failure;
    }

    QJsonObject truth;
    if (auto rig = engine.rig()) {
        // Run metadata holds the device time of the run's first sample.
        double origin = 0.0;
        QFile f(s.out);
        if (f.open(QIODevice::ReadOnly)) {
            for (int i = 0; i < 64 && !f.atEnd(); ++i) {
                const QByteArray line = f.readLine();
                if (line.startsWith("# run_start_device_time_s:"))
                    origin = line.mid(line.indexOf(':') + 1).trimmed().toDouble();
            }
        }
        truth = truthOnRunTime(rig->truthJson(), origin);
    }
    if (!s.video.isEmpty()) {
        try {
            devices::sim::ImagingOptions io_;
            io_.leadIn_s = s.videoOffset_s;
            const devices::sim::ImagingTruth vt = devices::sim::renderImagingVideo(readRunFile(s.out).run, s.video, io_);
            // [issue 15] An encoder on a full disk fails silently: count what can be read back.
            cv::VideoCapture check(QFile::encodeName(s.video).toStdString());
            const double readable = check.isOpened() ? check.get(cv::CAP_PROP_FRAME_COUNT) : 0.0;
            if (readable < vt.frames - 2) {
                QFile::remove(s.video);
                io.err << "needlebench simulate: "
                       << nb::TrCli::tr("%1: only %2 of %3 frames could be written (disk full?); removed")
                              .arg(s.video)
                              .arg(readable)
                              .arg(vt.frames)
                       << '\n';
                return Failure;
            }
            truth.insert(QStringLiteral("video"), QJsonObject{{QStringLiteral("file"), s.video},
                                                             {QStringLiteral("offset_s"), vt.offset_s},
                                                             {QStringLiteral("fps"), vt.fps},
                                                             {QStringLiteral("frames"), vt.frames}});
            truth.insert(QStringLiteral("video_offset_s"), vt.offset_s);
        } catch (const std::exception& e) {
            io.err << "needlebench simulate: " << QString::fromUtf8(e.what()) << '\n';
            return Failure;
        }
    }
    if (!s.truth.isEmpty()) {
        QSaveFile tf(s.truth);
        const QByteArray json = QJsonDocument(truth).toJson(QJsonDocument::Indented);
        if (!tf.open(QIODevice::WriteOnly) || tf.write(json) != json.size() || !tf.commit() ||
            QFileInfo(s.truth).size() != json.size()) {
            io.err << "needlebench simulate: " << nb::TrCli::tr("cannot write %1: %2").arg(s.truth, tf.errorString()) << '\n';
            return Failure;
        }
    }
    QJsonObject result{
        {QStringLiteral("out"), summary->path},
        {QStringLiteral("end_reason"), summary->endReason},
        {QStringLiteral("samples"), static_cast<double>(summary->samples)},
        {QStringLiteral("dropped"), static_cast<double>(summary->dropped)},
        {QStringLiteral("late_periods"), static_cast<double>(last.latePeriods)},
        {QStringLiteral("device"), engine.deviceDescription()},
    };
    if (!summary->fault.isEmpty())
        result.insert(QStringLiteral("fault"), summary->fault);
    if (!last.realtimeWarning.isEmpty() && s.rig.realtime)
        result.insert(QStringLiteral("realtime_warning"), last.realtimeWarning);
    if (!s.truth.isEmpty())
        result.insert(QStringLiteral("truth"), s.truth);
    printJson(io, result);
    return summary->endReason == QLatin1String("fault") ? Failure : Ok;
}

}  // namespace nb::cli
