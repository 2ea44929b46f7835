// `needlebench sync RUN.csv VIDEO [--roi x,y,w,h] [--needle x1,y1,x2,y2] [--coded-once] [--json]`: finds the
// offset (and drift) between the video and the force record from the needle's displacement
// tracked in the picture (video/video_sync.h).
#include "cli_support.h"
#include "core/tr.h"

#include "core/run_file.h"
#include "core/sync.h"
#include "video/frame_index_store.h"
#include "video/video_error.h"
#include "video/video_sync.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QTextStream>
#include <QRect>

#include <cmath>

namespace nb::cli {

static constexpr char kTraceHeader[] = "time_s,displacement_px";
static constexpr int kSmallestPicture_px = 32;

int cmdSync(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Find the video's offset to the force record (video time = recording time + offset)."));
    parser.addPositionalArgument(QStringLiteral("RUN.csv"), nb::TrCli::tr("the run file"));
    parser.addPositionalArgument(QStringLiteral("VIDEO"), nb::TrCli::tr("the video of the run"));
    const QCommandLineOption roi(QStringLiteral("roi"), nb::TrCli::tr("region of the picture that moves with the needle, in pixels"),
                                 QStringLiteral("x,y,w,h"));
    const QCommandLineOption maxOffset(QStringLiteral("max-offset"), nb::TrCli::tr("largest offset to consider, seconds (default 20)"),
                                       QStringLiteral("S"), QStringLiteral("20"));
    const QCommandLineOption needle(QStringLiteral("needle"),
                                    nb::TrCli::tr("the needle's line in the picture, in pixels (default: found in the picture)"),
                                    QStringLiteral("x1,y1,x2,y2"));
    const QCommandLineOption codedOnce(QStringLiteral("coded-once"),
                                       nb::TrCli::tr("the video is as its camera or console coded it, never converted: its coder's lag "
                                                     "is then known more closely"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    const QCommandLineOption trace(QStringLiteral("trace"),
                                   nb::TrCli::tr("also write the needle's tracked displacement per frame (time_s,displacement_px) to FILE"),
                                   QStringLiteral("FILE.csv"));
    const QCommandLineOption overwrite(QStringLiteral("overwrite"),
                                       nb::TrCli::tr("let --trace replace a file that is not a trace (an earlier trace is replaced without it)"));
    parser.addOptions({roi, maxOffset, needle, codedOnce, trace, json, overwrite});
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("sync"), args, io, 2, 2, &code))
        return code;
    QRect region;
    if (parser.isSet(roi)) {
        const QStringList p = parser.value(roi).split(QLatin1Char(','));
        bool ok = p.size() == 4;
        int v[4] = {0, 0, 0, 0};
        for (int i = 0; ok && i < 4; ++i)
            v[i] = p[i].trimmed().toInt(&ok);
        if (!ok || v[2] <= 0 || v[3] <= 0) {
            io.err << nb::TrCli::tr("needlebench sync: --roi wants x,y,w,h in whole pixels, w and h > 0\n\n") << commandHelp(parser, QStringLiteral("sync"));
            return Usage;
        }
        region = QRect(v[0], v[1], v[2], v[3]);
    }
    video::VideoSyncOptions vso;
    vso.codedOnce = parser.isSet(codedOnce);
    if (parser.isSet(needle)) {
        const QStringList p = parser.value(needle).split(QLatin1Char(','));
        bool ok = p.size() == 4;
        double v[4] = {0, 0, 0, 0};
        for (int i = 0; ok && i < 4; ++i)
            v[i] = p[i].trimmed().toDouble(&ok);
        for (int i = 0; ok && i < 4; ++i)
            ok = std::isfinite(v[i]) && std::abs(v[i]) < 1e5;
        if (!ok || std::hypot(v[2] - v[0], v[3] - v[1]) < 2.0) {
            io.err << nb::TrCli::tr("needlebench sync: --needle wants x1,y1,x2,y2 in pixels, two distinct points\n\n") << commandHelp(parser, QStringLiteral("sync"));
            return Usage;
        }
        vso.axis = video::NeedleAxis(v[0], v[1], v[2], v[3]);
    }
    bool ok = false;
    SyncOptions& options = vso.sync;
    options.maxOffset_s = parser.value(maxOffset).toDouble(&ok);
    if (!ok || !std::isfinite(options.maxOffset_s) || options.maxOffset_s <= 0) {
        io.err << nb::TrCli::tr("needlebench sync: --max-offset wants a positive number of seconds\n");
        return Usage;
    }
    const QString runPath = parser.positionalArguments()[0], videoPath = parser.positionalArguments()[1];
    if (parser.isSet(trace)) {
        QString clash = overwritesInput(QStringLiteral("--trace"), parser.value(trace), {runPath, videoPath});
        if (clash.isEmpty())
            clash = replacesOtherThanTrace(QStringLiteral("--trace"), parser.value(trace), kTraceHeader, parser.isSet(overwrite));
        if (!clash.isEmpty()) {
            io.err << "needlebench sync: " << clash << '\n';
            return Usage;
        }
        // Before the minutes of tracking, not after them.
        if (const QString e = unwritableOutput(QStringLiteral("--trace"), parser.value(trace)); !e.isEmpty()) {
            io.err << "needlebench sync: " << e << '\n';
            return Failure;
        }
    }
    int videoFrames = -1;
    std::size_t runSamples = 0;
    try {
        RunReadResult read = readRunFile(runPath, {.dropTruncatedLastRow = true});
        for (const QString& w : read.warnings)
            io.err << nb::TrCli::tr("warning: %1\n").arg(w);
        const Run run = std::move(read.run);
        runSamples = run.size();
        const video::FrameIndex index = video::loadOrBuildFrameIndex(videoPath);
        videoFrames = index.size();
        // As video-info says them: a file cut off, a rotation, a second stream (video probe: a
        // cut-off video was synced without a word).
        for (const QString& w : index.warnings)
            io.err << nb::TrCli::tr("warning: %1: %2").arg(videoPath, w) << '\n';
        // A picture too small to show a needle gave an offset all the same (the search's edge,
        // -max_offset) with exit 0; the smallest picture the tracker reads is 32 px a side.
        if (index.width < kSmallestPicture_px || index.height < kSmallestPicture_px) {
            io.err << nb::TrCli::tr("needlebench sync: %1: the picture is %2x%3 px, too small to show a needle (%4 px a side "
                                    "at least)\n").arg(videoPath).arg(index.width).arg(index.height).arg(kSmallestPicture_px);
            return Failure;
        }
        if (!region.isEmpty() && !QRect(0, 0, index.width, index.height).contains(region)) {
            io.err << nb::TrCli::tr("needlebench sync: --roi %1,%2,%3,%4 lies outside the %5x%6 picture\n")
                          .arg(region.x()).arg(region.y()).arg(region.width()).arg(region.height())
                          .arg(index.width).arg(index.height);
            return Usage;
        }
        if (vso.axis) {
            // A line drawn for another video, or with its numbers mistyped, tracks nothing and
            // only gave "confidence 0.00".
            const QLineF& a = *vso.axis;
            const QRectF picture(0, 0, index.width, index.height);
            const int steps = int(std::ceil(a.length()));
            int inside = 0;
            for (int k = 0; k <= steps; ++k)
                inside += picture.contains(a.pointAt(double(k) / steps));
            if (inside < 8) {
                io.err << nb::TrCli::tr("needlebench sync: --needle %1,%2,%3,%4 lies outside the %5x%6 picture\n")
                              .arg(a.x1()).arg(a.y1()).arg(a.x2()).arg(a.y2()).arg(index.width).arg(index.height);
                return Usage;
            }
        }
        vso.roi = region;
        // No offset beyond the two records' lengths lets them overlap: a larger limit only
        // made the search take minutes and gigabytes.
        if (run.size() > 1)
            options.maxOffset_s = std::min(options.maxOffset_s, index.duration_s() + (run.time_s.back() - run.time_s.front()) + 1.0);
        const video::VideoSync vs = video::syncVideoToRun(index, run, vso);
        const SyncResult& r = vs.result;
        // A long video indexed from its packets finds its damage only as it is decoded.
        if (vs.track.damaged > 0)
            io.err << nb::TrCli::tr("warning: %1: %n frame(s) in damaged stretches of the file, or after one up to the next keyframe, were left out",
                                    "", vs.track.damaged).arg(videoPath)
                   << '\n';
        // Only the frames the offsets tried can put beside the recording are tracked.
        const video::FrameSpan& tracked = vs.tracked;
        // Nothing in the picture moved with the recording: there is no offset to be sure of,
        // and no uncertainty to give either (it read "0.00 frames").
        // The tracked needle moving against the recorded position (a mirrored picture, the
        // position's sign reversed) moved all the same: it said "none" for a correlation of -0.96.
        const bool reversed = r.scale_px_per_mm < 0.0;
        const bool moved = r.correlation > 0.0 || reversed;
        // Something moved, but nothing in its motion times the offset (a noise video).
        const bool measured = moved && std::isfinite(r.uncertainty_s);
        // A limit shorter than the records leaves offsets beyond it untried.
        const bool limited = options.maxOffset_s < index.duration_s() + (run.size() > 1 ? run.time_s.back() - run.time_s.front() : 0.0);
        if (parser.isSet(trace)) {
            const QByteArray csv = traceCsv(kTraceHeader, vs.track.time_s, vs.track.displacement_px, 3);
            if (const QString e = writeOutput(QStringLiteral("--trace"), parser.value(trace), csv); !e.isEmpty()) {
                io.err << "needlebench sync: " << e << '\n';
                return Failure;
            }
        }
        if (parser.isSet(json)) {
            QJsonObject o;
            // Where nothing moved, the search's edge was no offset (it gave -20, the limit).
            o[QStringLiteral("offset_s")] = moved ? QJsonValue(r.offset_s) : QJsonValue();
            o[QStringLiteral("confidence")] = r.confidence;
            o[QStringLiteral("correlation")] = r.correlation;
            o[QStringLiteral("reversed")] = reversed;
            if (r.onsetOffset_s)
                o[QStringLiteral("onset_offset_s")] = *r.onsetOffset_s;
            o[QStringLiteral("frames")] = index.size();
            o[QStringLiteral("frames_tracked")] = tracked.size();
            o[QStringLiteral("drift")] = r.drift;
            o[QStringLiteral("uncertainty_s")] = measured ? QJsonValue(r.uncertainty_s) : QJsonValue();
            o[QStringLiteral("uncertainty_frames")] = measured ? QJsonValue(r.uncertainty_s / index.frameDuration()) : QJsonValue();
            o[QStringLiteral("max_offset_s")] = options.maxOffset_s;
            o[QStringLiteral("scale_px_per_mm")] = r.scale_px_per_mm;
            o[QStringLiteral("picture_lag_s")] = r.pictureLag_s;
            o[QStringLiteral("picture_lag_frames")] = r.pictureLag_s / index.frameDuration();
            o[QStringLiteral("picture_lag_uncertainty_s")] = r.pictureLagUncertainty_s;
            o[QStringLiteral("picture_lag_uncertainty_frames")] = r.pictureLagUncertainty_s / index.frameDuration();
            o[QStringLiteral("coded_once")] = vso.codedOnce;
            o[QStringLiteral("method")] = r.method;
            o[QStringLiteral("accept_threshold")] = kSyncAcceptConfidence;
            o[QStringLiteral("acceptable")] = r.acceptable();
            if (!vs.track.time_s.empty()) {
                const QLineF& a = vs.track.axis;
                o[QStringLiteral("needle")] = QJsonArray{a.x1(), a.y1(), a.x2(), a.y2()};
                o[QStringLiteral("needle_found")] = vs.track.axisDetected;
                o[QStringLiteral("frames_masked")] = vs.track.masked;
                o[QStringLiteral("frames_damaged")] = vs.track.damaged;
                o[QStringLiteral("picture_memory")] = vs.track.coding.memory;
                o[QStringLiteral("picture_noise_grey")] = vs.track.coding.noise_grey;
                o[QStringLiteral("edge_slope_grey_per_px")] = vs.track.coding.edgeSlope_grey_per_px;
                o[QStringLiteral("picture_trail_px")] = QJsonArray{r.pictureTrail.least_px, r.pictureTrail.most_px};
            }
            printJson(io, o);
        } else {
            io.out << (moved ? nb::TrCli::tr("offset:      %1 s (video time minus recording time)\n").arg(r.offset_s, 0, 'f', 4)
                             : nb::TrCli::tr("offset:      none (nothing in the picture moved with the recording)\n"))
                   << nb::TrCli::tr("confidence:  %1\n").arg(r.confidence, 0, 'f', 2)
                   << nb::TrCli::tr("correlation: %1\n").arg(r.correlation, 0, 'f', 3);
            if (reversed)
                io.out << nb::TrCli::tr("reversed:    the needle in the picture moves against the recorded position "
                                        "(a mirrored picture, or the position's sign)\n");
            if (r.onsetOffset_s)
                io.out << nb::TrCli::tr("onsets say:  %1 s\n").arg(*r.onsetOffset_s, 0, 'f', 4);
            io.out << nb::TrCli::tr("drift:       %1 %\n").arg(100.0 * r.drift, 0, 'f', 4)
                   << (measured ? nb::TrCli::tr("uncertainty: %1 frames\n").arg(r.uncertainty_s / index.frameDuration(), 0, 'f', 2)
                       : moved  ? nb::TrCli::tr("uncertainty: unknown (what moved in the picture does not time the offset)\n")
                                : nb::TrCli::tr("uncertainty: unknown (nothing in the picture moved with the recording)\n"));
            if (r.pictureLag_s > 0.0)
                io.out << nb::TrCli::tr("coded late:  %1 frames (taken off the offset), known to ±%2 frames\n")
                              .arg(r.pictureLag_s / index.frameDuration(), 0, 'f', 2)
                              .arg(r.pictureLagUncertainty_s / index.frameDuration(), 0, 'f', 2);
            if (!vs.track.time_s.empty()) {
                const QLineF& a = vs.track.axis;
                io.out << nb::TrCli::tr("needle:      %1,%2 to %3,%4 (%5)\n")
                              .arg(a.x1(), 0, 'f', 1).arg(a.y1(), 0, 'f', 1).arg(a.x2(), 0, 'f', 1).arg(a.y2(), 0, 'f', 1)
                              .arg(vs.track.axisDetected ? nb::TrCli::tr("found in the picture") : nb::TrCli::tr("given"));
            }
            io.out << nb::TrCli::tr("method:      %1\n").arg(r.method);
            if (tracked.size() > 0 && tracked.size() < index.size())
                io.out << nb::TrCli::tr("tracked:     %1 to %2 s of %3 s (as far as the offsets tried reach)\n")
                              .arg(index.frames[std::size_t(tracked.first)].time_s, 0, 'f', 2)
                              .arg(index.frames[std::size_t(tracked.last)].time_s, 0, 'f', 2)
                              .arg(index.duration_s(), 0, 'f', 2);
            if (!r.acceptable()) {
                io.out << nb::TrCli::tr("LOW CONFIDENCE (below %1): check the offset by marking an event in both before using it\n")
                              .arg(kSyncAcceptConfidence, 0, 'f', 2);
                if (moved && r.lagLimitsPrecision())
                    io.out << nb::TrCli::tr("the video's coder shows this slow needle late by an amount known only to ±%1 frames: "
                                            "a region or a needle line will not make it surer, an event marked in both will\n")
                                  .arg(r.pictureLagUncertainty_s / index.frameDuration(), 0, 'f', 2);
                if (moved && r.codedOnceWouldHelp())
                    io.out << nb::TrCli::tr("if nobody converted this video (it is as its camera or console coded it), "
                                            "--coded-once narrows that\n");
                if (limited)
                    io.out << nb::TrCli::tr("offsets were tried within ±%1 s (--max-offset): if the video started further from the "
                                            "recording than that, try a larger --max-offset\n")
                                  .arg(options.maxOffset_s, 0, 'g', 4);
            }
        }
        return Ok;
    } catch (const RunFileError& e) {
        io.err << "needlebench sync: " << e.message() << '\n';
    } catch (const video::VideoError& e) {
        io.err << "needlebench sync: " << e.message() << '\n';
    } catch (const std::invalid_argument& e) {
        // Say which record is too short to hold a motion to match, by name.
        const QString why = videoFrames >= 0 && videoFrames < 10 ? nb::TrCli::tr("the video %1 has only %n frame(s)", nullptr, videoFrames).arg(videoPath)
                            : runSamples < 10 ? nb::TrCli::tr("the run %1 has only %n sample(s)", nullptr, int(runSamples)).arg(runPath)
                                              : QString::fromUtf8(e.what());
        io.err << "needlebench sync: " << nb::TrCli::tr("cannot synchronise %1 with %2: %3").arg(videoPath, runPath, why) << '\n';
    }
    return Failure;
}

}  // namespace nb::cli
