#include "video_sync.h"

#include "frame_reader.h"
#include "motion_signal.h"
#include "needle_axis_finder.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace nb::video {

namespace {

constexpr std::size_t kRetracked = 16;  // lines tracked again without the place they kept to (one more pass)
constexpr std::size_t kTurned = 32;     // lines tracked again the other way round (in that pass)

// The stretch of its axis that a track kept to, when it kept to one: the shortest stretch
// holding three quarters of the frames in which a tip was read, when that is no longer than
// six steps of the tip's edge detector (48 px) and a tip was read in half the frames at least.
// Not three (24 px): a shaft that runs from a burnt-in counter held the track on two of its
// digits 30 px apart, in turn (slow-small probe seed 161616 case 4, the operator's own line
// 187 frames off; tracked again without them, 1.0 frames at confidence 0.48).
std::optional<AxisStretch> heldStretch(const NeedleTrack& track)
{
    std::vector<double> at;
    for (double d : track.displacement_px)
        if (std::isfinite(d))
            at.push_back(d);
    if (at.size() < 20 || 2 * at.size() < track.displacement_px.size())
        return std::nullopt;
    std::sort(at.begin(), at.end());
    const std::size_t k = (3 * at.size() + 3) / 4;
    std::size_t best = 0;
    for (std::size_t i = 0; i + k <= at.size(); ++i)
        if (at[i + k - 1] - at[i] < at[best + k - 1] - at[best])
            best = i;
    if (at[best + k - 1] - at[best] > 48.0)
        return std::nullopt;
    return AxisStretch{at[best], at[best + k - 1]};
}

// The frames that any offset searched can put beside the recording: its span moved by every
// offset (and stretched by the largest drift), with a few seconds either side for the rest
// before the onset and after the stop. A half-hour video synced to a minute's run was tracked
// whole, five minutes for the 100 s that can matter (video probe).
FrameSpan framesInReach(const FrameIndex& index, const Run& run, const SyncOptions& o)
{
    if (run.time_s.size() < 2 || index.frames.empty() || !index.timestampsMonotonic)
        return {};
    constexpr double kMargin_s = 3.0;
    const double drift = std::abs(o.maxDrift);
    const double from_s = std::min((1.0 - drift) * run.time_s.front(), (1.0 + drift) * run.time_s.front()) - o.maxOffset_s - kMargin_s;
    const double to_s = std::max((1.0 - drift) * run.time_s.back(), (1.0 + drift) * run.time_s.back()) + o.maxOffset_s + kMargin_s;
    // Frame times count from the first frame (FrameIndex::timeOrigin_s), as the sync's do.
    return FrameSpan{index.frameAt(from_s), index.frameAt(to_s)}.within(index.size());
}

// One line's track fitted to the recording, with the coder's trail as the track's pictures and
// the operator say.
SyncResult fitTrack(const NeedleTrack& track, const FrameIndex& index, const Run& run, const VideoSyncOptions& options)
{
    SyncOptions so = options.sync;
    so.coding = track.coding;
    so.coding.motion = motionCodingOf(index.codec);  // the video's, whichever line is tracked
    so.coding.codedOnce = options.codedOnce;
    return synchroniseDisplacement({track.time_s, track.displacement_px}, needlePosition(run), index.frameDuration(), so);
}

// One sync over the frames `reader` gives.
VideoSync syncOnce(FrameReader& reader, const FrameIndex& index, const Run& run, const VideoSyncOptions& options,
                   const FrameSpan reach, const std::function<void(int, int)>& progress, const std::atomic_bool* cancel)
{
    VideoSync out;
    out.frames = index.size();
    out.tracked = reach.within(index.size());
    const bool detected = !options.axis;
    std::vector<double> scores;
    std::vector<std::pair<double, NeedleAxis>> spares;
    // Every line that looks at all like a needle is tracked, not the few that look most like
    // one: a surface that moves across the picture (the tissue pushed by the needle) makes a
    // fan of lines crossing it at a shallow angle, along which its edge races, and those look
    // more like a moving tip than the needle itself (seed 461476: the needle's line ranked
    // seventh behind six of them). Which one is the needle, the fit to the recording decides.
    // One sampling serves the line finder and both passes of the tracker.
    const FrameSamples samples = sampleFrames(reader, 40, reach);
    std::vector<NeedleAxis> axes = detected ? needleAxisCandidates(samples, options.roi, 16, &scores, &spares)
                                            : std::vector<NeedleAxis>{*options.axis};
    if (!axes.empty()) {
        // Several lines may look like a needle (a plate's edge, a line of text): the one
        // whose motion explains the recording is the needle.
        // A line that only looks a little like a needle (a fraction of the best line's
        // score) must explain the recording much better to be taken: a tip that leaves a
        // slanted strip can still fit a different offset.
        std::vector<double> looks;
        for (std::size_t a = 0; a < axes.size(); ++a)
            looks.push_back(scores.empty() ? 1.0 : std::sqrt(scores[a] / scores.front()));
        // A line beside a shaft too faint to settle it on is tracked as it is and on the shaft
        // read at 3 σ: that reading put a line 0.5° off a needle 28 grey levels over grain of 25
        // and noise of 29 onto it (probe seed 662607 case 12: 67 frames off, now 0.67 frames), and put
        // lines closer to the truth that tracked worse (161803 case 14: 0.3 px from the needle
        // all along, confidence 0 where the line 1.5 to 3 px off had 0.99).
        const std::vector<std::optional<NeedleAxis>> faint = settledOnFaintShafts(samples, axes);
        for (std::size_t a = 0; a < faint.size(); ++a)
            if (faint[a]) {
                axes.push_back(*faint[a]);
                looks.push_back(looks[a]);
            }
        // Where the operator marked a region, the tip is read in it alone: the line beyond it may
        // run through a clock or counter whose digits hold the track (slow-small probe seed
        // 954840 case 1: the drawn line through a clock ahead of a faint tip, 184 frames off).
        std::vector<NeedleTrack> tracks = trackNeedles(reader, samples, axes, progress, cancel, {}, options.roi);
        // Tracks are compared where they lie (`tracks`, `retracked`), and the best one moved out.
        std::vector<NeedleTrack> retracked;
        NeedleTrack* best = nullptr;
        double bestRank = -1.0;
        std::string problem;
        auto consider = [&](NeedleTrack& track, double looksLikeNeedle) {
            // Even a perfect fit (confidence 1, |r| 1) could not outrank the best so far.
            if (best && looksLikeNeedle + 1e-3 <= bestRank)
                return;
            try {
                const SyncResult r = fitTrack(track, index, run, options);
                const double rank = r.trackConfidence * looksLikeNeedle + 1e-3 * std::abs(r.correlation);
                if (!best || rank > bestRank) {
                    best = &track;
                    bestRank = rank;
                    out.result = r;
                }
            } catch (const std::invalid_argument& e) {
                problem = e.what();
            }
        };
        for (std::size_t a = 0; a < tracks.size(); ++a)
            consider(tracks[a], looks[a]);
        // No line's track explains the recording: along a line whose track kept to one place,
        // that place may be burnt-in text whose digits change (edges far stronger than a faint
        // tip's, at a place that never moves) and the tip be elsewhere on the line (probe seed
        // 577215 case 14: a counter's hundreds digit ahead of a faint tip held the track in
        // every frame, the sync 15 frames off). Those lines are tracked once more without it,
        // up to kRetracked of them, and the recording decides again. Not only the best-looking
        // few: a short path of change found apart from the digits ranks low among the lines,
        // and on it a counter behind the tip held the track (slow-small probe seed 6 case 13:
        // the 18th line of 18, on the needle; tracked again, 0.54 frames off).
        if (!(out.result.trackConfidence >= kSyncAcceptConfidence) && !(cancel && cancel->load())) {
            std::vector<NeedleAxis> again;
            std::vector<std::optional<AxisStretch>> without;
            std::vector<double> againLooks;
            std::vector<AxisReading> readings;
            auto trackAgain = [&](const NeedleAxis& axis, const std::optional<AxisStretch>& notRead, double looksLikeNeedle,
                                  const AxisReading& reading) {
                again.push_back(axis);
                without.push_back(notRead);
                againLooks.push_back(looksLikeNeedle);
                readings.push_back(reading);
            };
            std::vector<std::optional<AxisStretch>> held;
            for (const NeedleTrack& track : tracks)
                held.push_back(heldStretch(track));
            for (std::size_t a = 0; a < tracks.size() && again.size() < kRetracked; ++a)
                if (held[a])
                    trackAgain(tracks[a].axis, held[a], looks[a], {});
            // Every line is tracked the other way round too, as it points: which end a faint
            // needle's shaft comes from, its frames may tell wrong, a clock's digits on the line
            // voting with the tip, or a coder showing the tip late (probe seed 60613 case 14 and
            // slow-small --recode seed 4242 case 9: the needle's line found and turned to point
            // from the tip, the sync 223 and 226 frames off; tracked the other way, 0.0 and 0.5).
            // And where no shaft stood out along a line, its tip was read as the edge of whichever
            // sign stood out more, a coin toss for a faint needle at rest half the time: read
            // again as the end of a shaft of the other sign (slow-small seed 112358 case 18: a
            // line 0.3° and 0.2 px off the needle, its tip read as the wrong edge, the sync 152
            // frames off; read as a dark shaft's end, 0.2 frames).
            // Turned, a line whose track kept to one place is tracked without it as well: the
            // digits of a counter a shaft runs from may hold the track either way round.
            for (std::size_t a = 0; a < tracks.size() && a < kTurned; ++a) {
                const NeedleAxis turned(tracks[a].axis.p2(), tracks[a].axis.p1());
                trackAgain(turned, std::nullopt, looks[a], {.asPointed = true});
                if (held[a]) {
                    const double length = tracks[a].axis.length();
                    trackAgain(turned, AxisStretch{length - held[a]->to_px, length - held[a]->from_px}, looks[a], {.asPointed = true});
                }
                if (!tracks[a].shaftSeen && tracks[a].tipPolarity != 0)
                    trackAgain(tracks[a].axis, std::nullopt, looks[a], {.asPointed = true, .shaftSign = tracks[a].tipPolarity});
            }
            // And the spare lines the finder gave, which looked less like a needle than those
            // tracked (slow-small 112358 #17: the needle's shaft ranked after the rows of
            // burnt-in text in the frames' mean, and the sync was 163 frames off), each way
            // round: along a tip's short path the shaft behind it may be too faint for the
            // frames to tell which way it points (112358 #5: tracked as the frames turned it,
            // r −0.64 and 76 frames off; from the shaft's side, 0.6 frames).
            for (const auto& [score, axis] : spares) {
                const double looksLikeNeedle = scores.empty() || !(scores.front() > 0) ? 1.0 : std::sqrt(score / scores.front());
                for (const NeedleAxis& way : {axis, NeedleAxis(axis.p2(), axis.p1())})
                    trackAgain(way, std::nullopt, looksLikeNeedle, {.asPointed = true});
            }
            if (!again.empty()) {
                retracked = trackNeedles(reader, samples, again, progress, cancel, without, options.roi, readings);
                for (std::size_t a = 0; a < retracked.size(); ++a)
                    consider(retracked[a], againLooks[a]);
            }
        }
        if (!best)
            throw std::invalid_argument(problem);
        out.track = std::move(*best);
        out.track.axisDetected = detected;
        return out;
    }
    // No needle to follow: the old, weaker comparison, never confident enough to accept.
    out.tracked = FrameSpan{}.within(index.size());
    const MotionSignal m = computeMotionSignal(reader, options.roi, progress, cancel);
    out.result = synchronise({m.time_s, m.value}, needleSpeed(run), options.sync);
    out.result.method = QStringLiteral("picture motion vs needle speed (no needle found)");
    out.result.confidence = std::min(out.result.confidence, 0.9 * kSyncAcceptConfidence);
    return out;
}

}  // namespace

VideoSync refitVideoSync(VideoSync done, const FrameIndex& index, const Run& run, const VideoSyncOptions& options)
{
    if (done.track.time_s.empty())
        return done;  // no needle was followed: the picture's motion has no coder's trail
    done.result = fitTrack(done.track, index, run, options);
    return done;
}

VideoSync syncVideoToRun(const FrameIndex& index, const Run& run, const VideoSyncOptions& options,
                         const std::function<void(int, int)>& progress, const std::atomic_bool* cancel)
{
    FrameReader reader(index, 8);
    const FrameSpan reach = framesInReach(index, run, options.sync);
    reader.keepGrayFrames(kPassesGrayBudget_bytes, reach);  // sampled, tracked, maybe tracked again
    VideoSync without = syncOnce(reader, index, run, options, reach, progress, cancel);
    // The frames decoded across damage, up to the next keyframe, are left out: their pictures
    // are partly made up (seed 124387 --damage case 6: 123.5 frames off with them, 0.3 without).
    // But x264 puts a keyframe only every 250 frames, and without them the motion's onset may
    // be gone (seed 22502 --damage case 1: 114 frames off at confidence 0.08; with them, right
    // at 0.99). Where there are such frames in reach, the sync is made with them as well, and
    // the more confident answer taken: confidence is what tells a right answer from a wrong one.
    const FrameSpan span = reach.within(index.size());
    bool across = false;
    for (int n = span.first; n <= span.last && !across; ++n)
        across = index.decodedAcrossDamage(n);
    if (!across || (cancel && cancel->load()))
        return without;
    reader.leaveOutDecodedAcrossDamage(false);
    try {
        VideoSync with = syncOnce(reader, index, run, options, reach, progress, cancel);
        if (with.result.trackConfidence > without.result.trackConfidence)
            return with;
    } catch (const std::invalid_argument&) {
    }
    return without;
}

}  // namespace nb::video
