#include "label_intervals.h"

#include "csv_text.h"
#include "dataset.h"
#include "export_error.h"

#include <QCoreApplication>
#include <QSaveFile>
#include <algorithm>
#include <cmath>

namespace nb {

long long FrameClock::frameAt(double t_s) const
{
    const double video_s = (1.0 + drift) * t_s + offset_s;
    if (!frameTimes_s.empty()) {
        // The frame on screen at t is the last one shown at or before t (to rounding, as the
        // window's index finds it); the last one is shown for a median frame's time.
        const auto it = std::upper_bound(frameTimes_s.begin(), frameTimes_s.end(), video_s + 1e-9);
        if (it == frameTimes_s.begin() || !std::isfinite(video_s))
            return -1;
        const auto k = (it - frameTimes_s.begin()) - 1;
        if (it == frameTimes_s.end()) {
            std::vector<double> steps;
            for (std::size_t i = 1; i < frameTimes_s.size(); ++i)
                steps.push_back(frameTimes_s[i] - frameTimes_s[i - 1]);
            double step = 1.0 / fps;
            if (!steps.empty()) {
                std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
                step = steps[steps.size() / 2];
            }
            if (video_s >= frameTimes_s.back() + step - 1e-9)
                return -1;
        }
        return k;
    }
    // A small epsilon keeps a time exactly on a frame boundary in that frame despite rounding.
    const double frame = std::floor(video_s * fps + 1e-9);
    // No frame for a time before the video or beyond any video (not a wrapped-around integer).
    if (!std::isfinite(frame) || frame < 0.0 || frame > 1e12)
        return -1;
    return static_cast<long long>(frame);
}

FrameClock frameClockFor(const Run& run)
{
    FrameClock c;
    c.fps = videoFps(run);
    c.offset_s = syncOffset(run);
    c.drift = syncDrift(run);
    c.hasVideo = false;
    for (const char* key : {"video", "video_file", "video_path", "sync_offset_s", "video_offset_s", "video_fps"})
        if (run.meta(QString::fromLatin1(key)))
            c.hasVideo = true;
    return c;
}

FrameClock frameClockFor(const DatasetRun& r)
{
    FrameClock c = frameClockFor(r.run);
    if (!r.sourcePath.isEmpty())
        c.hasVideo = !r.videoPath.isEmpty();
    if (c.hasVideo)
        c.frameTimes_s = r.videoFrameTimes_s;
    return c;
}

std::vector<LabelInterval> labelIntervals(const Run& run, const Labels& labels, const FrameClock& clock)
{
    std::vector<LabelInterval> rows;
    rows.reserve(labels.size());
    const auto& t = run.time_s;
    const auto& f = run.force_N;
    const std::size_t n = std::min(t.size(), f.size());
    for (const Label& l : labels) {
        LabelInterval r;
        r.label = l.label;
        r.track = l.track;
        r.start_s = l.start_s;
        r.end_s = l.end_s;
        r.duration_s = l.end_s - l.start_s;
        const bool frames = clock.hasVideo && std::isfinite(l.start_s) && std::isfinite(l.end_s);
        r.start_frame = frames ? clock.frameAt(l.start_s) : -1;
        r.end_frame = frames ? clock.frameAt(l.end_s) : -1;
        r.comment = l.comment;
        const auto begin = t.begin();
        const auto end = t.begin() + std::ptrdiff_t(n);
        if (l.isPoint()) {
            if (n > 0) {
                auto it = std::lower_bound(begin, end, l.start_s);
                if (it == end || (it != begin && l.start_s - *(it - 1) < *it - l.start_s))
                    --it;
                r.peak_force_N = r.mean_force_N = f[std::size_t(it - begin)];
            }
        } else {
            const auto first = std::lower_bound(begin, end, l.start_s);
            const auto last = std::lower_bound(first, end, l.end_s);
            if (first != last) {
                const std::size_t i0 = std::size_t(first - begin), i1 = std::size_t(last - begin) - 1;
                // Direction of motion over the interval: deeper (insertion) or back (withdrawal).
                const auto& p = run.position_mm;
                const double travel = i1 < p.size() ? p[i1] - p[i0] : 0.0;
                double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0.0;
                for (std::size_t i = i0; i <= i1; ++i) {
                    lo = std::min(lo, f[i]);
                    hi = std::max(hi, f[i]);
                    sum += f[i];
                }
                r.peak_force_N = travel < 0.0 ? lo : travel > 0.0 ? hi : (std::fabs(lo) > std::fabs(hi) ? lo : hi);
                r.mean_force_N = sum / double(last - first);
            }
        }
        rows.push_back(std::move(r));
    }
    std::stable_sort(rows.begin(), rows.end(), [](const LabelInterval& a, const LabelInterval& b) {
        if (a.start_s != b.start_s)
            return a.start_s < b.start_s;
        if (a.track != b.track)
            return a.track < b.track;
        return a.label < b.label;
    });
    return rows;
}

void writeLabelIntervalsCsv(const QString& path, const std::vector<LabelInterval>& rows)
{
    QByteArray out = "label,track,start_s,end_s,duration_s,start_frame,end_frame,peak_force_N,mean_force_N,comment\n";
    for (const LabelInterval& r : rows) {
        out += csvField(r.label) + ',' + csvField(r.track) + ',' + csvNumber(r.start_s, 6) + ',' + csvNumber(r.end_s, 6) + ',' +
               csvNumber(r.duration_s, 6) + ',' + (r.start_frame >= 0 ? QByteArray::number(r.start_frame) : QByteArray()) + ',' +
               (r.end_frame >= 0 ? QByteArray::number(r.end_frame) : QByteArray()) +
               ',' + csvNumber(r.peak_force_N, 6) + ',' + csvNumber(r.mean_force_N, 6) + ',' + csvField(r.comment) + '\n';
    }
    writeFileAtomically(path, out);
}

}  // namespace nb
