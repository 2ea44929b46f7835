#pragma once
// Labels as an interval table, one row per label with its video frames and the force in it:
// `label,track,start_s,end_s,duration_s,start_frame,end_frame,peak_force_N,mean_force_N,comment`.

#include "core/labels.h"
#include "core/run.h"

#include <QString>
#include <cmath>
#include <limits>
#include <vector>

namespace nb {

struct LabelInterval {
    QString label;
    QString track;
    double start_s = 0.0;
    double end_s = 0.0;
    double duration_s = 0.0;
    // -1 when the run has no video (the CSV leaves the cells empty).
    long long start_frame = 0;
    long long end_frame = 0;
    // The extreme force in the direction of motion (the largest for an insertion, the most
    // negative for a withdrawal; the largest magnitude when the needle stood still).
    // NaN when no sample falls in the interval (a point event takes its nearest sample).
    double peak_force_N = std::numeric_limits<double>::quiet_NaN();
    double mean_force_N = std::numeric_limits<double>::quiet_NaN();
    QString comment;
};

// Maps recording time to a video frame: either a frame rate and an offset (video time =
// recording time + offset) or a video index (each frame's time in recording time, sorted).
struct FrameClock {
    double fps = 29.97;
    double offset_s = 0.0;
    double drift = 0.0;  // video time = (1 + drift) · recording time + offset (core/sync.h)
    // The video's own frame times (its index, video time), when known: they win over `fps`
    // (dropped and repeated frames), and the video ends one frame after the last.
    std::vector<double> frameTimes_s;
    bool hasVideo = true;  // false: no frames are given

    // The frame on screen at recording time t; -1 before the video or after its end.
    long long frameAt(double t_s) const;
};

// The clock a run's metadata describes (sync offset and drift, frame rate; 29.97 fps when
// unsaid); without a video it has hasVideo false. From a Run: a video is assumed when its
// metadata names one or a sync offset; from a DatasetRun: when a video file was found, with its
// frame times when it was indexed.
FrameClock frameClockFor(const Run& run);
struct DatasetRun;
FrameClock frameClockFor(const DatasetRun& run);

// Rows in time order (then track, then label).
std::vector<LabelInterval> labelIntervals(const Run& run, const Labels& labels, const FrameClock& clock);

// Writes the table as CSV (atomically). Throws ExportError.
void writeLabelIntervalsCsv(const QString& path, const std::vector<LabelInterval>& rows);

}  // namespace nb
