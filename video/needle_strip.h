#pragma once
// Reading a needle's line in one picture: a strip sampled along the line, its profile, the
// step detector's edge response along it, and the tip as the edge where the shaft ends. The
// line finder (needle_axis_finder) scores lines with it and the tracker (needle_tracker) reads
// every frame with it; neither is needed to read a strip. Internal to the video library.

#include "frame_samples.h"
#include "needle_axis.h"

#include <QRect>
#include <opencv2/core.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace nb::video::strip {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The median of [first, last), reordering it; NaN when empty.
template <class It>
double medianInPlace(It first, It last)
{
    if (first == last)
        return kNaN;
    const It mid = first + (last - first) / 2;
    std::nth_element(first, mid, last);
    return *mid;
}

double median(std::vector<double> v);

// A strip along a line, sampled every pixel along it and `halfWidth` pixels to either side, as
// far as the line runs inside `within` (the whole picture when empty).
struct Strip {
    cv::Mat mapX, mapY;  // (2·halfWidth+1) rows × length columns
    int length = 0;
    double origin = 0.0;  // position along the axis (from p1) of profile sample 0

    Strip(const NeedleAxis& axis, int width, int height, int halfWidth, double sideOffset = 0.0, QRect within = {});

    // The strip's mean across its width, smoothed along it.
    std::vector<double> profile(const cv::Mat& gray, double smoothing_px = 0.8) const;
};

// What a needle strip sees in one frame: along its middle (the needle's width), and how much
// the middle differs from the picture a few pixels either side (the shaft, where there is
// one; a surface or a patch of text as wide as the sides cancels out).
inline constexpr int kMiddleHalfWidth_px = 2;
inline constexpr int kSideFrom_px = 5, kSideTo_px = 7;
struct StripProfile {
    std::vector<double> middle;
    std::vector<double> shaft;
};

struct NeedleStrip : Strip {
    NeedleStrip(const NeedleAxis& axis, int width, int height, QRect within = {})
        : Strip(axis, width, height, kSideTo_px, 0.0, within)
    {
    }

    StripProfile sample(const cv::Mat& gray, double smoothing_px = 0.8) const;
};

// A step detector along the profile: the mean of the next `w` samples minus the mean of
// the previous `w`. Long enough to see a faint edge through heavy noise, short enough to
// keep neighbouring edges apart.
inline constexpr int kStep = 8;
std::vector<double> gradient(const std::vector<double>& p);

// Fewer frames than this with their tip away from a sample say nothing of it.
inline constexpr std::size_t kFramesAway = 3;
// A tip further than this from a sample is away from it: beyond its edge response's reach.
inline constexpr double kAwayFromTip = kStep + 2;

// Per position, what is there even in the frames where the tip is not (edge responses of sign
// `polarity`, one per frame).
std::vector<double> staticPart(const std::vector<std::vector<double>>& gradients, int polarity);
// The same learnt again once the tips' places (`tipAt`, per frame) are known; never above `still`.
std::vector<double> staticPartAwayFromTips(const std::vector<std::vector<double>>& gradients, int polarity,
                                           const std::vector<double>& tipAt, std::vector<double> still);
// The strip's middle over its sides where no needle lies, per sample.
std::vector<double> shaftBackground(const std::vector<StripProfile>& profiles, const std::vector<double>& tipAt);
// Leaves out the frames coded clearly worse than the rest.
void withoutNoisierFrames(std::vector<StripProfile>& profiles, std::vector<std::vector<double>>& g);
// The noise of the edge response: its spread over frames around the median, per position.
double robustSigma(const std::vector<std::vector<double>>& gradients);
// Where the parabola through three neighbouring samples (b the highest) peaks, from b's sample.
double peakOffset(double a, double b, double c);

struct Peak {
    double position = kNaN;
    double strength = 0.0;
    double second = 0.0;  // the strongest edge of the same sign at least 2·kStep away
};

// An edge of strength `v` at sample `i`, as far as it is the end of a shaft.
double gatedStrength(const std::vector<double>& shaft, int polarity, double sigma, int i, double v);
// Whether an edge peaking at sample `b` of `n` is cut off by the strip's end.
bool cutOffAtEnd(int b, int n);
// The tip in samples [lo, hi] of one frame's profile: the strongest edge of sign `polarity`
// above what is always there (`still`), to a fraction of a sample.
Peak findTip(const std::vector<double>& g, const std::vector<double>& shaft, const std::vector<double>& still, int polarity,
             bool gated, double sigma, int lo = 2, int hi = std::numeric_limits<int>::max());
// Whether the shaft comes in from the strip's far end (towards p2) rather than its start.
bool shaftFromFarEnd(const std::vector<StripProfile>& profiles);

// The tip's edge sign along a strip and whether to look for it as the end of a shaft.
struct TipModel {
    int polarity = 1;
    bool gated = false;
    bool shaftSeen = false;  // a shaft's sign decided the polarity (false: the stronger edges' sign)
    std::vector<double> still;
};
// `shaft` (+1 brighter than beside it, −1 darker) where the caller knows it; 0: as the frames show.
TipModel tipModel(const std::vector<StripProfile>& profiles, const std::vector<std::vector<double>>& g, double sigma, int shaft = 0);
// How strongly a frame shows the shaft (of sign `shaftSign`) over the strip's first quarter
// (its median) and over its last 16 samples (their quarter point); NaN where the strip is too
// short or no shaft is seen.
struct ShaftAtEnds {
    double start = kNaN, end = kNaN;
};
ShaftAtEnds shaftAtEnds(const StripProfile& raw, int shaftSign);
// What the strip's end shows in nearly every frame (the tenth percentile of the sampled
// frames): beside a picture's corner the sides run out of it, and the strip's end shows a
// "shaft" that is always there; and how far the frames' noise alone takes it above that.
struct UsualAtEnd {
    double floor = 0.0, margin = 0.0;
};
UsualAtEnd usualShaftAtEnd(const std::vector<ShaftAtEnds>& frames);
// Whether a frame's shaft runs on to the strip's far end: beyond what is usual there, at
// least half as strong as over its first quarter and beyond the noise's reach. Its tip is
// then beyond the strip (out of the picture or the operator's region): no edge on it is the tip.
bool shaftReachesEnd(const ShaftAtEnds& frame, const UsualAtEnd& usual);

// What `strip` sees in each sampled frame.
std::vector<StripProfile> sampleStrip(const NeedleStrip& strip, const FrameSamples& s);
// `axis` pointing from the shaft to the tip.
NeedleAxis shaftBehindTip(const FrameSamples& s, const NeedleAxis& axis);
// The sampled frames' mean, in float.
cv::Mat framesMean(const FrameSamples& s);

}  // namespace nb::video::strip
