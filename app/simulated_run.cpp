#include "simulated_run.h"

#include "core/run_file.h"
#include "core/run_keys.h"
#include "core/save_file.h"
#include "core/tr.h"
#include "devices/acquisition_engine.h"
#include "devices/sim/imaging_render.h"
#include "devices/sim/simulated_rig.h"
#include "video/capture.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <opencv2/videoio.hpp>

namespace nb::cli {

namespace {

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

// The run file's header holds the device time of the run's first sample.
double runStartDeviceTime(const QString& path)
{
    QFile f(path);
    if (f.open(QIODevice::ReadOnly)) {
        for (int i = 0; i < 64 && !f.atEnd(); ++i) {
            const QByteArray line = f.readLine();
            if (line.startsWith("# run_start_device_time_s:"))
                return line.mid(line.indexOf(':') + 1).trimmed().toDouble();
        }
    }
    return 0.0;
}

}  // namespace

Metadata simulatedRunMetadata(const SimulatedRunRequest& s)
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

SimulatedRunResult simulateRun(const SimulatedRunRequest& s, const devices::RunOnceOptions& options)
{
    SimulatedRunResult result;
    devices::EngineConfig config;
    config.rateHz = s.rateHz;
    config.forceLimit_N = s.maxForce_N;
    config.withdrawForceLimit_N = std::max(config.withdrawForceLimit_N, s.maxForce_N);
    config.realtimeScheduling = s.rig.realtime;  // a busy simulated clock must not hog a core at FIFO priority
    config.liveView = false;
    devices::AcquisitionEngine engine(devices::sim::makeSimulatedDevices(s.rig), config);

    devices::RunPlan plan;
    plan.outPath = s.out;
    plan.metadata = simulatedRunMetadata(s);
    for (const auto& [k, v] : s.extraMetadata.entries())
        plan.metadata.set(k, v);
    if (s.rig.setup == devices::sim::Setup::Platform) {
        plan.motion = devices::RunPlan::Motion::Sine;
        plan.sine = s.sine;
    } else {
        plan.motion = devices::RunPlan::Motion::Linear;
        plan.linear = {s.velocity_mm_s, s.depth_mm};
        plan.stopAtPuncture = s.stopAtPuncture;
        plan.slowAfterPuncture_mm_s = s.slowAfterPuncture_mm_s;
    }

    const devices::RunOnceResult r = devices::runOnce(engine, plan, options);
    result.summary = r.summary;
    if (!r.summary) {
        result.error = r.error;
        return result;
    }

    if (r.summary->endReason == EndReason::WriteError || r.summary->endReason == EndReason::Interrupted) {
        // No truth or video for a recording that did not end by itself: they would describe
        // samples that are not in the file.
        result.json = QJsonObject{{QStringLiteral("out"), r.summary->path},
                                  {QStringLiteral("end_reason"), fileName(r.summary->endReason)},
                                  {QStringLiteral("samples"), static_cast<double>(r.summary->samples)},
                                  {QStringLiteral("dropped"), static_cast<double>(r.summary->dropped)}};
        if (!r.summary->fault.isEmpty())
            result.json.insert(QStringLiteral("error"), r.summary->fault);
        return result;
    }
    if (auto source = engine.groundTruth())
        result.truth = truthOnRunTime(source->truthJson(), runStartDeviceTime(s.out));
    if (!s.video.isEmpty()) {
        try {
            devices::sim::ImagingOptions io;
            io.leadIn_s = s.videoOffset_s;
            io.width = s.videoWidth;
            io.height = s.videoHeight;
            io.seed = s.videoSeed;
            if (options.interruption)
                io.cancelled = [&options] { return options.interruption().count > 0; };
            const devices::sim::ImagingTruth vt = devices::sim::renderImagingVideo(readRunFile(s.out).run, s.video, io);
            if (vt.frames == 0) {
                result.error = nb::TrCli::tr("interrupted while the video was rendered: %1 and the truth are not written; the run "
                                             "file %2 is whole").arg(s.video, s.out);
                return result;
            }
            // An encoder on a full disk fails silently: count what can be read back.
            // Read back as NeedleBench reads every video, through FFmpeg: any backend tried a
            // file half written on a full disk with GStreamer, whose errors were printed.
            cv::VideoCapture check;
            const double readable = nb::video::openCapture(check, s.video) ? check.get(cv::CAP_PROP_FRAME_COUNT) : 0.0;
            if (readable < vt.frames - 2) {
                QFile::remove(s.video);
                result.error = nb::TrCli::tr("%1: only %2 of %3 frames could be written (disk full?); removed")
                                   .arg(s.video)
                                   .arg(readable)
                                   .arg(vt.frames);
                return result;
            }
            result.videoFrames = vt.frames;
            result.videoOffset_s = vt.offset_s;
            result.truth.insert(QStringLiteral("video"), QJsonObject{{QStringLiteral("file"), s.video},
                                                                    {QStringLiteral("offset_s"), vt.offset_s},
                                                                    {QStringLiteral("fps"), vt.fps},
                                                                    {QStringLiteral("frames"), vt.frames}});
            result.truth.insert(QStringLiteral("video_offset_s"), vt.offset_s);
        } catch (const std::exception& e) {
            result.error = QString::fromUtf8(e.what());
            return result;
        }
    }
    if (!s.truth.isEmpty()) {
        QSaveFile tf(s.truth);
        const QByteArray json = QJsonDocument(result.truth).toJson(QJsonDocument::Indented);
        if (!tf.open(QIODevice::WriteOnly) || tf.write(json) != json.size() || !commitWhole(tf) ||
            QFileInfo(s.truth).size() != json.size()) {
            result.error = nb::TrCli::tr("cannot write %1: %2").arg(s.truth, tf.errorString());
            return result;
        }
    }
    result.json = QJsonObject{
        {QStringLiteral("out"), r.summary->path},
        {QStringLiteral("end_reason"), fileName(r.summary->endReason)},
        {QStringLiteral("samples"), static_cast<double>(r.summary->samples)},
        {QStringLiteral("dropped"), static_cast<double>(r.summary->dropped)},
        {QStringLiteral("late_periods"), static_cast<double>(r.last.latePeriods)},
        {QStringLiteral("device"), engine.deviceDescription()},
    };
    if (!r.summary->fault.isEmpty())
        result.json.insert(QStringLiteral("fault"), r.summary->fault);
    if (!r.last.realtimeWarning.isEmpty() && s.rig.realtime)
        result.json.insert(QStringLiteral("realtime_warning"), r.last.realtimeWarning);
    if (!s.truth.isEmpty())
        result.json.insert(QStringLiteral("truth"), s.truth);
    return result;
}

}  // namespace nb::cli
