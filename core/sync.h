#pragma once
// One timeline for the video and the force record, in recording time:
//   video time = (1 + drift) · recording time + offset
// The offset is set by marking one event in both (two events, apart, set the drift too), or
// found by correlating a motion signal
// from the video with the needle's speed, coarse to fine, anchored on the motion onset
// (a sinusoid repeats, so correlation alone has many equal peaks).

#include "picture_lag.h"
#include "run.h"

#include <QString>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace nb {

struct TimelineMapping {
    double offset_s = 0.0;
    double drift = 0.0;  // relative clock-rate error of the video, e.g. 1e-4

    double toVideo(double recording_s) const { return (1.0 + drift) * recording_s + offset_s; }
    double toRecording(double video_s) const { return (video_s - offset_s) / (1.0 + drift); }
    // The mapping that puts `video_s` and `recording_s` on the same instant (same drift).
    static TimelineMapping fromEvent(double recording_s, double video_s, double drift = 0.0)
    {
        return {video_s - (1.0 + drift) * recording_s, drift};
    }
    // The mapping that puts two events on their instants in both: offset and drift. Needs the
    // events apart in recording time (nullopt otherwise).
    static std::optional<TimelineMapping> fromEvents(double recording1_s, double video1_s, double recording2_s, double video2_s)
    {
        if (!(std::abs(recording2_s - recording1_s) > 1e-6))
            return std::nullopt;
        const double drift = (video2_s - video1_s) / (recording2_s - recording1_s) - 1.0;
        return fromEvent(recording1_s, video1_s, drift);
    }
    void nudge(int frames, double frameDuration_s) { offset_s += frames * frameDuration_s; }
    friend bool operator==(const TimelineMapping&, const TimelineMapping&) = default;
};

// A sampled signal; NaN values are masked (e.g. duplicate video frames).
struct TimeSignal {
    std::vector<double> time_s;
    std::vector<double> value;
};

// |needle velocity| in mm/s: the run's velocity_mm_s column when present, else the
// derivative of position, smoothed over `smoothing_s`.
TimeSignal needleSpeed(const Run& run, double smoothing_s = 0.03);

// First time the signal rises clearly above its resting level (the median of its first
// `restWindow_s`): above rest + `fraction` · (95th percentile − rest). nullopt when it never does.
std::optional<double> motionOnset(const TimeSignal& s, double fraction = 0.25, double restWindow_s = 0.5);

struct SyncOptions {
    double maxOffset_s = 20.0;    // search offsets in [-max, +max]
    double coarseStep_s = 0.05;
    double fineStep_s = 0.001;
    bool anchorOnOnset = true;
    double anchorWindow_s = 0.3;  // the accepted peak lies this close to the onset estimate
    double maxDrift = 0.005;      // displacement sync: drifts searched in [-max, +max]
    PictureCoding coding;         // displacement sync: how the video shows a slow motion late
};

struct SyncResult {
    double offset_s = 0.0;         // video time minus recording time
    double correlation = 0.0;      // Pearson r at offset_s
    double confidence = 0.0;       // 0..1
    // The confidence as the picture alone gives it, as if the coder had shown the motion on
    // time: how well this track explains the recording. Tracks of one video (the needle, a line
    // of text) are chosen by it, since the coder's lag says nothing of which is the needle.
    double trackConfidence = 0.0;
    std::optional<double> onsetOffset_s;  // from the two motion onsets alone
    std::vector<std::pair<double, double>> curve;  // coarse scan: (offset, r), for display
    int pairs = 0;                 // samples compared at offset_s
    // From the displacement sync (synchroniseDisplacement); zero otherwise.
    double drift = 0.0;            // video clock rate error (TimelineMapping::drift)
    double scale_px_per_mm = 0.0;  // tracked displacement per recorded millimetre (signed)
    double intercept_px = 0.0;     // tracked displacement where the recorded position is 0 mm
    double uncertainty_s = 0.0;    // how far the offset could be off (split halves, fit noise); infinite: unknown
    double pictureLag_s = 0.0;     // how late the coded pictures show the motion (taken off offset_s)
    double pictureLagUncertainty_s = 0.0;  // how far that lag may be off; uncertainty_s is no less
    PictureTrail pictureTrail;     // the trail behind the tip that lag was read from (core/picture_lag.h)
    // Whether the coder's lag, known no better than pictureLagUncertainty_s, is what keeps the
    // offset uncertain: checking it on an event helps, drawing the needle's line does not.
    bool lagLimitsPrecision() const { return pictureLagUncertainty_s > 0.0 && pictureLagUncertainty_s >= uncertainty_s; }
    // And that lag is known only within a range that saying the video was coded once would close.
    bool codedOnceWouldHelp() const { return lagLimitsPrecision() && pictureTrail.narrowsIfCodedOnce; }
    QString method;                // what was compared, for the run's metadata

    TimelineMapping mapping() const { return {offset_s, drift}; }
    bool acceptable() const;       // confidence at or above kSyncAcceptConfidence
};

// A sync result below this confidence is not to be taken without the operator's say-so:
// the window disables Accept below it unless overridden, the command line says so.
inline constexpr double kSyncAcceptConfidence = 0.5;
inline bool SyncResult::acceptable() const { return confidence >= kSyncAcceptConfidence; }

// `videoMotion` in video time, `speed` in recording time. Throws std::invalid_argument when
// either signal is too short to compare.
SyncResult synchronise(const TimeSignal& videoMotion, const TimeSignal& speed, const SyncOptions& options = {});

// Synchronises on what the picture measures: `videoDisplacement` (the needle's tracked
// displacement along its axis, any unit, either sign, NaN masked; video time) against the
// recorded `position` (mm, recording time; the rig rests at its first and last position
// outside the recording). Finds offset, drift and scale that make the two one linear
// signal: coarse offset scan, then offset and drift refined together around the best
// peaks; among near-equal peaks the one that agrees with the motion onsets wins. The
// confidence multiplies how well the fit explains the picture, how unique the peak is, how
// closely the two halves of the video agree on the offset and whether the onsets agree, so a
// wrong or imprecise answer carries a low one. `frameDuration_s` sets the scale of
// "precise". Throws std::invalid_argument when a signal is too short or does not move.
SyncResult synchroniseDisplacement(const TimeSignal& videoDisplacement, const TimeSignal& position,
                                   double frameDuration_s, const SyncOptions& options = {});

// The tracked displacement (video time, pixels) as the position it stands for: in recording
// time through `mapping` and in millimetres through the fit's scale and intercept, to lay
// over the recorded position. Masked (NaN) samples stay masked; empty when `fit` has no
// scale (it did not come from the displacement sync).
TimeSignal trackedPosition(const TimeSignal& videoDisplacement, const SyncResult& fit, const TimelineMapping& mapping);

// The run's needle position (position_mm over time_s).
TimeSignal needlePosition(const Run& run);

// Pearson correlation of the motion with the speed shifted by `offset_s` (speed is 0 outside
// the recording: the rig rests). Returns r and the number of pairs.
std::pair<double, int> correlationAt(const TimeSignal& videoMotion, const TimeSignal& speed, double offset_s);

}  // namespace nb
