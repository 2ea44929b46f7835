// `needlebench simulate`: one run on the simulated rig, through the same acquisition engine
// and recorder as the workbench, headless. Options are read into SimulatedRunRequest in one
// place (addOptions/readOptions) so that more (e.g. --video) slot in without touching the run.

#include "cli_support.h"
#include "simulated_run.h"
#include "interrupt_watcher.h"
#include "core/disk_space.h"
#include "core/tr.h"

#include <cmath>

#include "devices/acquisition_engine.h"
#include "devices/run_once.h"
#include "core/run_file.h"
#include "devices/sim/imaging_render.h"
#include "devices/sim/tissue_presets.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <cmath>
#include <optional>
#include <opencv2/videoio.hpp>

namespace nb::cli {

namespace {


struct OptionSet {
    QCommandLineOption protocol{QStringLiteral("protocol"), nb::TrCli::tr("stiffness|internal|friction|prostate"), QStringLiteral("P")};
    QCommandLineOption tissue{QStringLiteral("tissue"), nb::TrCli::tr("liver1|liver2|liver3|liver5|liver7|prostate"), QStringLiteral("T")};
    QCommandLineOption tip{QStringLiteral("tip"), nb::TrCli::tr("beveled|diamond|blunt"), QStringLiteral("TIP")};
    QCommandLineOption seed{QStringLiteral("seed"), nb::TrCli::tr("random seed (default 1)"), QStringLiteral("N"), QStringLiteral("1")};
    QCommandLineOption rate{QStringLiteral("rate-hz"), nb::TrCli::tr("sampling rate, 100..10000 (default 500)"), QStringLiteral("R"), QStringLiteral("500")};
    QCommandLineOption velocity{QStringLiteral("velocity-mm-s"), nb::TrCli::tr("insertion velocity (default 4, internal 2.5)"), QStringLiteral("V")};
    QCommandLineOption depth{QStringLiteral("depth-mm"), nb::TrCli::tr("insertion depth from the start position (default 40)"), QStringLiteral("D")};
    QCommandLineOption amplitude{QStringLiteral("amplitude-mm"), nb::TrCli::tr("sine amplitude, at most the stage's 10 mm travel (default 10)"), QStringLiteral("A"), QStringLiteral("10")};
    QCommandLineOption frequency{QStringLiteral("frequency-hz"), nb::TrCli::tr("sine frequency (default 0.5)"), QStringLiteral("F"), QStringLiteral("0.5")};
    QCommandLineOption cycles{QStringLiteral("cycles"), nb::TrCli::tr("sine cycles (default 7)"), QStringLiteral("N"), QStringLiteral("7")};
    QCommandLineOption thickness{QStringLiteral("thickness-mm"), nb::TrCli::tr("tissue slab thickness on the friction platform (default 30)"), QStringLiteral("T"), QStringLiteral("30")};
    QCommandLineOption bone{QStringLiteral("bone-depth-mm"), nb::TrCli::tr("bone this far below the surface (very stiff)"), QStringLiteral("D")};
    QCommandLineOption maxForce{QStringLiteral("max-force-n"), nb::TrCli::tr("force limit that stops the stage (default 8)"), QStringLiteral("F"), QStringLiteral("8")};
    QCommandLineOption realtime{QStringLiteral("realtime"), nb::TrCli::tr("run on the wall clock (default: as fast as possible)")};
    QCommandLineOption truth{QStringLiteral("truth"), nb::TrCli::tr("write the ground truth as JSON"), QStringLiteral("FILE.json")};
    QCommandLineOption out{QStringLiteral("out"), nb::TrCli::tr("the run file to write"), QStringLiteral("RUN.csv")};
    QCommandLineOption video{QStringLiteral("video"), nb::TrCli::tr("also render the imaging view (29.97 frames/s; .avi, .mkv or .mp4)"), QStringLiteral("FILE")};
    QCommandLineOption stopAt{QStringLiteral("stop-at"), nb::TrCli::tr("stop the insertion at a puncture: puncture (the first) or puncture:N (the N-th)"), QStringLiteral("puncture[:N]")};
    QCommandLineOption slowAfter{QStringLiteral("slow-after-puncture"), nb::TrCli::tr("slow the insertion to V mm/s after the first puncture"), QStringLiteral("V")};
    QCommandLineOption stickBand{QStringLiteral("stick-band-mm-s"), nb::TrCli::tr("friction platform: the tissue sticks while the relative velocity is within ±V (default 2.5)"), QStringLiteral("V"), QStringLiteral("2.5")};
    QCommandLineOption plateGap{QStringLiteral("plate-gap-mm"), nb::TrCli::tr("friction platform: free travel of the slab before it meets a plate (default 1.5)"), QStringLiteral("MM"), QStringLiteral("1.5")};
    QCommandLineOption forceNoise{QStringLiteral("force-noise-n"), nb::TrCli::tr("rms noise of the force sensor in newtons (default about 0.0012)"), QStringLiteral("N")};
    QCommandLineOption videoOffset{QStringLiteral("video-offset-s"), nb::TrCli::tr("the video starts this long before the recording; negative: after it began (-600 to 600, default 0)"), QStringLiteral("S"), QStringLiteral("0")};
    QCommandLineOption overwrite{QStringLiteral("overwrite"), nb::TrCli::tr("replace existing output files (--out, --truth, --video)")};

    void addTo(QCommandLineParser& p) const
    {
        for (const auto* o : {&protocol, &tissue, &tip, &seed, &rate, &velocity, &depth, &amplitude, &frequency,
                              &cycles, &thickness, &bone, &maxForce, &realtime, &truth, &out, &video, &videoOffset, &stopAt, &slowAfter,
                              &stickBand, &plateGap, &forceNoise, &overwrite})
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
QString readOptions(const QCommandLineParser& p, const OptionSet& o, SimulatedRunRequest& s)
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
    // Every output is checked before the run: a run is not recorded only to fail on them.
    // --truth and --video as --out: a recorded run or a lab's video named by mistake was replaced
    // without a word.
    for (const auto& [option, path] : {std::pair{QStringLiteral("--out"), s.out}, {QStringLiteral("--truth"), s.truth}, {QStringLiteral("--video"), s.video}})
        if (!path.isEmpty()) {
            if (const QString e = existingOutput(option, path, p.isSet(o.overwrite)); !e.isEmpty())
                return e;
            if (const QString e = unwritableOutput(option, path); !e.isEmpty())
                return e;
        }
    if (!s.truth.isEmpty() && samePath(s.truth, s.out))
        return nb::TrCli::tr("--truth and --out name the same file %1").arg(s.out);
    if (!s.video.isEmpty()) {
        if (samePath(s.video, s.out) || (!s.truth.isEmpty() && samePath(s.video, s.truth)))
            return nb::TrCli::tr("--video names the same file as --out or --truth: %1").arg(s.video);
        if (const QString e = devices::sim::imagingVideoTypeProblem(s.video); !e.isEmpty())
            return QStringLiteral("--video %1: %2").arg(s.video, e);
    }
    {
        bool ok = false;
        s.videoOffset_s = p.value(o.videoOffset).toDouble(&ok);
        if (!ok || !(std::abs(s.videoOffset_s) <= 600))
            return nb::TrCli::tr("--video-offset-s wants seconds between -600 and 600");
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
        s.rig.tip = usualTip(s.rig.tissue, internal);
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
    // As `acquire` takes them: a run of 10^6 s filled the disk.
    if (*f < 0.01 || *f > 5.0)
        return nb::TrCli::tr("--frequency-hz must be in [0.01, 5]");
    // Within what the rig could hold: a slab of 1e300 mm, or a limit of 1e300 N, ran on to nonsense
    // without a word. The simulated load cell takes more than a real one (acquire and plans stop at
    // 20 N): the accuracy matrices set 40 N so that no deep run stops on it.
    if (*t <= 0.0 || *t > s.rig.stage.maxPosition_mm)
        return nb::TrCli::tr("--thickness-mm must be in (0, %1]").arg(s.rig.stage.maxPosition_mm);
    if (*m < 0.01 || *m > 100.0)
        return nb::TrCli::tr("--max-force-n must be in [0.01, 100]");
    const int cycles = p.value(o.cycles).toInt(&ok);
    if (!ok || cycles < 1 || cycles > 1000)
        return nb::TrCli::tr("--cycles must be a whole number in [1, 1000]");
    s.sine = {*a, *f, cycles};
    s.rig.thickness_mm = *t;
    s.maxForce_N = *m;
    auto band = number(p, o.stickBand, &error);
    auto gap = band ? number(p, o.plateGap, &error) : std::nullopt;
    if (!gap)
        return error;
    if (*band <= 0.0 || *band > 50.0)
        return nb::TrCli::tr("--stick-band-mm-s must be in (0, 50]");
    if (*gap < 0.0 || *gap > 20.0)
        return nb::TrCli::tr("--plate-gap-mm must be in [0, 20]");
    s.rig.stickBand_mm_s = *band;
    s.rig.plateGap_mm = *gap;
    if (p.isSet(o.forceNoise)) {
        auto noise = number(p, o.forceNoise, &error);
        if (!noise)
            return error;
        if (*noise < 0.0 || *noise > 1.0)
            return nb::TrCli::tr("--force-noise-n must be in [0, 1]");
        s.rig.sensor.noise_V = *noise * s.rig.sensor.sensitivity_V_per_N * s.rig.sensor.gain;
    }
    if (p.isSet(o.bone)) {
        auto b = number(p, o.bone, &error);
        if (!b)
            return error;
        if (*b <= 0.0 || *b > s.rig.stage.maxPosition_mm)
            return nb::TrCli::tr("--bone-depth-mm must be in (0, %1]").arg(s.rig.stage.maxPosition_mm);
        s.rig.boneDepth_mm = *b;
    }
    if (p.isSet(o.stopAt)) {
        const auto n = parseStopAt(p.value(o.stopAt));
        if (!n)
            return nb::TrCli::tr("--stop-at wants puncture or puncture:N with N ≥ 1 (got '%1')").arg(p.value(o.stopAt));
        s.stopAtPuncture = *n;
    }
    if (p.isSet(o.slowAfter)) {
        auto v = number(p, o.slowAfter, &error);
        if (!v)
            return error;
        if (*v <= 0.0 || *v > s.rig.stage.maxVelocity_mm_s)
            return nb::TrCli::tr("--slow-after-puncture must be in (0, %1] mm/s").arg(s.rig.stage.maxVelocity_mm_s);
        s.slowAfterPuncture_mm_s = *v;
    }
    return {};
}

// Watches the disk the run file goes to: warns once when it will be full within
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
    SimulatedRunRequest s;
    if (const QString error = readOptions(parser, o, s); !error.isEmpty()) {
        io.err << "needlebench simulate: " << error << "\n\n" << nb::TrCli::tr("Run 'needlebench simulate --help' for the options.") << '\n';
        return Usage;
    }

    // Progress lines carry the engine's run time: a killed recording can be checked against them.
    devices::RunOnceOptions run;
    run.onStarted = [&](const QString& path) {
        io.out << "recording " << path << '\n';
        io.out.flush();
    };
    QElapsedTimer sinceProgress;
    sinceProgress.start();
    SpaceWatch space(s.out);
    std::uint64_t lastReported = ~std::uint64_t{0};
    run.onTick = [&](const devices::EngineStatus& st) {
        if (st.recording)
            if (const QString w = space.check(); !w.isEmpty()) {
                io.err << "needlebench simulate: " << w << '\n';
                io.err.flush();
            }
        // The engine's status moves on every 40 ms or so: a line for each new one, not each tick.
        if (st.recording && s.rig.realtime && sinceProgress.elapsed() >= 20 && st.samples != lastReported) {
            sinceProgress.restart();
            lastReported = st.samples;
            io.out << "progress run_time_s=" << QString::number(st.runTime_s, 'f', 4) << " samples=" << st.samples << '\n';
            io.out.flush();
        }
    };
    // A signal stops the stage and closes the run as "interrupted"; a second one (or one
    // before the run started) does not wait.
    InterruptWatcher interrupts;
    interrupts.announceOn(io.err, QStringLiteral("simulate"));
    run.interruption = [&] { return interrupts.interruption(); };
    const SimulatedRunResult r = simulateRun(s, run);
    const int signalled = interrupts.signalNumber() ? 128 + interrupts.signalNumber() : 0;
    if (!r.summary) {
        io.err << "needlebench simulate: " << r.error << '\n';
        return signalled ? signalled : Failure;
    }
    // A run that did not end by itself gets no truth or video: they would describe a
    // recording that is not in the file.
    if (r.summary->endReason == EndReason::WriteError || r.summary->endReason == EndReason::Interrupted) {
        if (r.summary->endReason == EndReason::WriteError)
            io.err << "needlebench simulate: "
                   << nb::TrCli::tr("recording failed: %1; the run file keeps %2 whole rows").arg(r.summary->fault).arg(r.summary->samples)
                   << '\n';
        if (!s.video.isEmpty() || !s.truth.isEmpty())
            io.err << "needlebench simulate: " << nb::TrCli::tr("the run did not end by itself: no truth or video is written for it")
                   << '\n';
        printJson(io, r.json);
        return signalled ? signalled : Failure;
    }
    if (!r.error.isEmpty()) {  // recorded, but what follows the run failed (truth, video), or was interrupted
        io.err << "needlebench simulate: " << r.error << '\n';
        return signalled ? signalled : Failure;
    }
    printJson(io, r.json);
    if (signalled)
        return signalled;
    return r.summary->endReason == EndReason::Fault ? Failure : Ok;
}

}  // namespace nb::cli
