#include "frame_samples.h"

#include "needle_strip.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace nb::video {

namespace {

using strip::median;

// The pixels that change from `a` to `b` (quarter-size float copies) far beyond the noise
// (the typical change of a pixel between the two). A count, not a mean: a thin needle that
// moves is a few hundred pixels of the picture, and its change averaged over the picture
// stayed under the noise's (a stroke of 8 mm at 10 mm/s after 14 s of rest: no needle found).
double changedPixels(const cv::Mat& a, const cv::Mat& b)
{
    cv::Mat diff;
    cv::absdiff(b, a, diff);
    const double far = 6.0 * 1.4826 * median(std::vector<double>(diff.begin<float>(), diff.end<float>())) + 1.0;
    return double(std::count_if(diff.begin<float>(), diff.end<float>(), [&](float v) { return v > far; }));
}

// Of frames spread evenly over a video, the first and last (indices into `gray`) of the
// stretch in which the picture changes well beyond its usual change, when that stretch is a
// small part of the video; nothing when the video changes alike all along. One change alone
// may be a glitch, and spreading frames over its one interval would make a needle that moves
// all along look still.
std::optional<std::pair<std::size_t, std::size_t>> movingStretch(const std::vector<cv::Mat>& gray)
{
    if (gray.size() < 8)
        return std::nullopt;
    // Each frame reduced once, then compared with its neighbours.
    std::vector<cv::Mat> small(gray.size());
    for (std::size_t k = 0; k < gray.size(); ++k) {
        cv::resize(gray[k], small[k], cv::Size(std::max(1, gray[k].cols / 4), std::max(1, gray[k].rows / 4)), 0, 0, cv::INTER_AREA);
        small[k].convertTo(small[k], CV_32F);
    }
    std::vector<double> change;
    for (std::size_t k = 0; k + 1 < small.size(); ++k)
        change.push_back(changedPixels(small[k], small[k + 1]));
    const double usual = median(change);
    std::vector<double> deviation;
    for (double c : change)
        deviation.push_back(std::abs(c - usual));
    const double threshold = usual + std::max(3.0, 6.0 * 1.4826 * median(deviation));
    std::vector<std::size_t> moving;
    for (std::size_t k = 0; k < change.size(); ++k)
        if (change[k] > threshold)
            moving.push_back(k);
    if (moving.size() < 2 || 2 * moving.size() >= change.size())
        return std::nullopt;
    return std::pair{moving.front(), moving.back() + 1};
}

}  // namespace

// `count` frames spread evenly over the video, and as many again over the stretch in which
// the picture changes when that is a small part of it. A video begun long before the run
// shows the needle at rest in most evenly spread frames: its tip at rest then counts as
// what is always there (staticPart) and its motion as a few stray frames (14 s of rest
// before a 3 s sine: the needle's line was passed over and the sync missed by 12 frames).
FrameSamples sampleFrames(FrameReader& reader, int count, FrameSpan span)
{
    FrameSamples s;
    const FrameIndex& index = reader.index();
    s.width = index.width;
    s.height = index.height;
    s.span = span.within(index.size());
    const int first = s.span.first, n = s.span.last + 1;
    if (n <= first)
        return s;
    std::vector<int> taken;
    auto take = [&](int i) {
        while (i < n - 1 && index.frames[std::size_t(i)].duplicate)
            ++i;
        if (std::find(taken.begin(), taken.end(), i) != taken.end())
            return;
        taken.push_back(i);
        if (const std::optional<cv::Mat> g = reader.grayUnlessDamaged(i))
            s.gray.push_back(g->clone());
        else
            taken.pop_back();  // a damaged frame: the samples are one fewer
    };
    count = std::clamp(count, 1, n - first);
    for (int k = 0; k < count; ++k)
        take(first + (count == 1 ? 0 : int(std::lround(double(k) * (n - 1 - first) / (count - 1)))));
    const auto stretch = movingStretch(s.gray);
    if (!stretch)
        return s;
    const int from = taken[stretch->first], to = taken[stretch->second];
    for (int k = 1; k < count - 1; ++k)
        take(from + int(std::lround(double(k) * (to - from) / (count - 1))));
    return s;
}

}  // namespace nb::video
