#include "needle_tracker.h"

#include "picture_memory.h"
#include "static_edges.h"
#include "tip_path.h"
#include "video_error.h"

#include "core/tr.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>

namespace nb::video {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The median of [first, last), reordering it.
template <class It>
double medianInPlace(It first, It last)
{
    if (first == last)
        return kNaN;
    const It mid = first + (last - first) / 2;
    std::nth_element(first, mid, last);
    return *mid;
}

double median(std::vector<double> v) { return medianInPlace(v.begin(), v.end()); }

// A strip along a line, sampled every pixel along it and `halfWidth` pixels to either side.
struct Strip {
    cv::Mat mapX, mapY;  // (2·halfWidth+1) rows × length columns
    int length = 0;

    Strip(const NeedleAxis& axis, int width, int height, int halfWidth, double sideOffset = 0.0)
    {
        const double len = axis.length();
        if (len < 2.0)
            return;
        const double ux = (axis.x2() - axis.x1()) / len, uy = (axis.y2() - axis.y1()) / len;
        const double nx = -uy, ny = ux;
        // Extend the line across the whole picture: the tip may travel past the drawn ends.
        double s0 = -1e9, s1 = 1e9;
        auto clip = [&](double p, double d, double lo, double hi) {
            if (std::abs(d) < 1e-9)
                return;
            double a = (lo - p) / d, b = (hi - p) / d;
            if (a > b)
                std::swap(a, b);
            s0 = std::max(s0, a);
            s1 = std::min(s1, b);
        };
        clip(axis.x1(), ux, 0.0, width - 1.0);
        clip(axis.y1(), uy, 0.0, height - 1.0);
        if (!(s1 > s0 + 2))
            return;
        length = int(s1 - s0);
        origin = s0;
        mapX.create(2 * halfWidth + 1, length, CV_32F);
        mapY.create(2 * halfWidth + 1, length, CV_32F);
        for (int r = 0; r < mapX.rows; ++r) {
            double t = r - halfWidth;
            if (sideOffset != 0.0)
                t += t >= 0 ? sideOffset : -sideOffset;
            for (int j = 0; j < length; ++j) {
                const double s = s0 + j;
                mapX.at<float>(r, j) = float(axis.x1() + s * ux + t * nx);
                mapY.at<float>(r, j) = float(axis.y1() + s * uy + t * ny);
            }
        }
    }
    double origin = 0.0;  // position along the axis (from p1) of profile sample 0

    // The strip's mean across its width, smoothed along it.
    std::vector<double> profile(const cv::Mat& gray, double smoothing_px = 0.8) const
    {
        cv::Mat sampled, column;
        cv::remap(gray, sampled, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
        sampled.convertTo(sampled, CV_32F);
        cv::reduce(sampled, column, 0, cv::REDUCE_AVG);
        if (smoothing_px > 0)
            cv::GaussianBlur(column, column, cv::Size(0, 0), smoothing_px, 0.1);
        return std::vector<double>(column.begin<float>(), column.end<float>());
    }
};

// What a needle strip sees in one frame: along its middle (the needle's width), and how much
// the middle differs from the picture a few pixels either side (the shaft, where there is
// one; a surface or a patch of text as wide as the sides cancels out).
constexpr int kMiddleHalfWidth_px = 2;
constexpr int kSideFrom_px = 5, kSideTo_px = 7;
struct StripProfile {
    std::vector<double> middle;
    std::vector<double> shaft;
};

struct NeedleStrip : Strip {
    NeedleStrip(const NeedleAxis& axis, int width, int height) : Strip(axis, width, height, kSideTo_px) {}

    StripProfile sample(const cv::Mat& gray, double smoothing_px = 0.8) const
    {
        StripProfile out;
        if (length <= 0)
            return out;
        cv::Mat sampled, middle, sides, lower, upper;
        cv::remap(gray, sampled, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
        sampled.convertTo(sampled, CV_32F);
        cv::reduce(sampled.rowRange(kSideTo_px - kMiddleHalfWidth_px, kSideTo_px + kMiddleHalfWidth_px + 1), middle, 0,
                   cv::REDUCE_AVG);
        const int sideRows = kSideTo_px - kSideFrom_px + 1;
        cv::reduce(sampled.rowRange(0, sideRows), lower, 0, cv::REDUCE_AVG);
        cv::reduce(sampled.rowRange(sampled.rows - sideRows, sampled.rows), upper, 0, cv::REDUCE_AVG);
        sides = 0.5 * (lower + upper);
        cv::Mat shaft = middle - sides;
        if (smoothing_px > 0) {
            cv::GaussianBlur(middle, middle, cv::Size(0, 0), smoothing_px, 0.1);
            cv::GaussianBlur(shaft, shaft, cv::Size(0, 0), smoothing_px, 0.1);
        }
        out.middle.assign(middle.begin<float>(), middle.end<float>());
        out.shaft.assign(shaft.begin<float>(), shaft.end<float>());
        return out;
    }
};

// A step detector along the profile: the mean of the next `w` samples minus the mean of
// the previous `w`. Long enough to see a faint edge through heavy noise, short enough to
// keep neighbouring edges apart.
constexpr int kStep = 8;
std::vector<double> gradient(const std::vector<double>& p)
{
    const std::size_t n = p.size();
    std::vector<double> prefix(n + 1, 0.0), g(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        prefix[i + 1] = prefix[i] + p[i];
    for (std::size_t i = kStep; i + kStep < n; ++i)
        g[i] = ((prefix[i + 1 + kStep] - prefix[i + 1]) - (prefix[i] - prefix[i - kStep])) / kStep;
    return g;
}

// The low (15 %) percentile of `column` (reordered).
double lowPercentile(std::vector<double>& column)
{
    const std::size_t k15 = column.size() * 15 / 100;
    std::nth_element(column.begin(), column.begin() + std::ptrdiff_t(k15), column.end());
    return column[k15];
}

// Per position, what is there even in the frames where the tip is not: the low (15 %)
// percentile over frames of the edge response of one sign. A median would also remove a
// tip that rests at one place for most of the video.
std::vector<double> staticPart(const std::vector<std::vector<double>>& gradients, int polarity)
{
    if (gradients.empty())
        return {};
    const std::size_t n = gradients.front().size();
    std::vector<double> out(n), column(gradients.size());
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < gradients.size(); ++k)
            column[k] = polarity * gradients[k][i];
        // Below zero is the opposite edge (e.g. where the tip rests, seen from the other
        // side), not something of this sign that is always there.
        out[i] = std::max(0.0, lowPercentile(column));
    }
    return out;
}

// Fewer frames than this with their tip away from a sample say nothing of it.
constexpr std::size_t kFramesAway = 3;
// A tip further than this from a sample is away from it: beyond its edge response's reach.
constexpr double kAwayFromTip = kStep + 2;

// What is always there, learnt again once the tip's places are known: the same low percentile,
// over the frames whose tip was found beyond the edge response's reach of the sample, and no
// longer held at zero. A textured background's edges of the other sign are always there too;
// held at zero, they stayed in the response beside a resting tip and pulled its edge onto the
// texture's next edge (probe seed 314159 case 12: at the final rest, on texture of ±30 grey
// levels, the tip read 4.5 px ahead; 246810 case 15: 3.7 px short, the sync 1.5 frames off).
// Never above the first estimate: a frame whose tip was found in the wrong place shows its
// real tip here. Where fewer than 3 frames have their tip away, the first estimate stands.
// Of fewer than 7 frames the 15 % point is their lowest, and a frame's noise alone can put that
// 3 σ under the rest (probe seed 577215 case 14: a faint tip found in 4 of 40 frames; at still
// edges 250 px from any tip the lowest of the 4 stood 2-3 σ under the edge's usual response,
// which then stood out as much as the tip in every frame, and the tip's course kept to it).
// Where no frame's tip was found within reach of a sample, the frames whose tip was not found
// count there too. Near a tip found they do not: their tip may be there, and the lowest of the
// few frames with the tip away is the one its edge's tail reaches least (taken as 1.04 σ under
// their median there, a resting tip read up to 0.46 px from where its stroke put it).
constexpr std::size_t kFewFrames = 7;
std::vector<double> staticPartAwayFromTips(const std::vector<std::vector<double>>& gradients, int polarity,
                                           const std::vector<double>& tipAt, std::vector<double> still)
{
    std::vector<double> column;
    for (std::size_t i = 0; i < still.size(); ++i) {
        column.clear();
        for (std::size_t k = 0; k < gradients.size(); ++k)
            if (std::isfinite(tipAt[k]) && std::abs(tipAt[k] - double(i)) > kAwayFromTip)
                column.push_back(polarity * gradients[k][i]);
        auto nearATip = [&] { return std::any_of(tipAt.begin(), tipAt.end(), [&](double t) { return std::abs(t - double(i)) <= kAwayFromTip; }); };
        if (column.size() < kFewFrames && !nearATip())
            for (std::size_t k = 0; k < gradients.size(); ++k)
                if (!std::isfinite(tipAt[k]))
                    column.push_back(polarity * gradients[k][i]);
        if (column.size() >= kFramesAway)
            still[i] = std::min(still[i], lowPercentile(column));
    }
    return still;
}

// The strip's middle over its sides where no needle lies, per sample: the median over the
// frames whose tip was found short of it; zero where fewer than 3 frames show it so. On a
// textured background the middle and the sides differ by the texture as much as by a shaft
// (grain of 4 px: by ±30 grey levels), and a tip whose picture ahead is brighter in the
// middle than at the sides seems to end no shaft: the gate took it for a digit's stroke, and
// a clear tip (20 σ) went unread through a whole final rest (probe seed 314159 case 1).
constexpr double kShaftClear = 4.0;  // samples past a tip where its soft end has faded
std::vector<double> shaftBackground(const std::vector<StripProfile>& profiles, const std::vector<double>& tipAt)
{
    const std::size_t n = profiles.empty() ? 0 : profiles.front().shaft.size();
    std::vector<double> out(n, 0.0), column;
    for (std::size_t i = 0; i < n; ++i) {
        column.clear();
        for (std::size_t k = 0; k < profiles.size(); ++k)
            if (std::isfinite(tipAt[k]) && tipAt[k] < double(i) - kShaftClear)
                column.push_back(profiles[k].shaft[i]);
        if (column.size() >= kFramesAway)
            out[i] = median(column);
    }
    return out;
}

// The sampled frames (their profiles and edge responses) less those whose edge response
// scatters more than twice as much about the frames' median as the usual frame's: a frame
// coded worse than the rest. Of the few frames whose tip is away from a sample, its lowest
// edge is the 15 % point, and it would put what is always there far too low along the strip.
void withoutNoisierFrames(std::vector<StripProfile>& profiles, std::vector<std::vector<double>>& g)
{
    if (g.size() < 8)
        return;
    const std::size_t n = g.front().size();
    std::vector<double> middle(n), column(g.size());
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < g.size(); ++k)
            column[k] = g[k][i];
        middle[i] = median(column);
    }
    std::vector<double> scatter(g.size()), deviation(n);
    for (std::size_t k = 0; k < g.size(); ++k) {
        for (std::size_t i = 0; i < n; ++i)
            deviation[i] = std::abs(g[k][i] - middle[i]);
        scatter[k] = median(deviation);
    }
    const double usual = median(scatter);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < g.size(); ++k)
        if (!(scatter[k] > 2.0 * usual)) {
            if (kept != k) {
                profiles[kept] = std::move(profiles[k]);
                g[kept] = std::move(g[k]);
            }
            ++kept;
        }
    profiles.resize(kept);
    g.resize(kept);
}

// The noise of the edge response: its spread over frames around the median, per position.
double robustSigma(const std::vector<std::vector<double>>& gradients)
{
    if (gradients.empty())
        return 1e-6;
    const std::size_t n = gradients.front().size();
    std::vector<double> dev, column(gradients.size());
    for (std::size_t i = 0; i < n; i += 2) {
        for (std::size_t k = 0; k < gradients.size(); ++k)
            column[k] = gradients[k][i];
        const double m = medianInPlace(column.begin(), column.end());  // refilled for the next sample
        for (double v : column)
            dev.push_back(std::abs(v - m));
    }
    return std::max(1e-6, 1.4826 * medianInPlace(dev.begin(), dev.end()));
}

// Where the parabola through three neighbouring samples `a`, `b`, `c` (b the highest) peaks,
// from b's sample: within half a sample either way.
double peakOffset(double a, double b, double c)
{
    // Beside a stretch not read (+inf under what is always there), the peak is the sample.
    if (!std::isfinite(a) || !std::isfinite(c))
        return 0.0;
    const double den = a - 2 * b + c;
    return std::abs(den) > 1e-12 ? std::clamp(0.5 * (a - c) / den, -0.5, 0.5) : 0.0;
}

struct Peak {
    double position = kNaN;
    double strength = 0.0;
    double second = 0.0;  // the strongest edge of the same sign at least 2·kStep away
};

// How much of an edge at sample `i` is the end of a shaft: the shaft's median contrast over
// a stretch behind the edge, as far as it is gone over a longer stretch ahead. A tip ends
// the shaft (shaft behind, none ahead). The digits of a burnt-in clock or counter that the
// needle's line crosses change from frame to frame with edges stronger than the tip's, but
// have no shaft behind them (a counter beyond the tip) or the shaft again beyond them (a
// clock the shaft runs through). Seeds 956579, 271526, 167008: the tracker followed the
// digits and the sync missed by 75–165 frames.
constexpr int kShaftBehind = 16, kShaftAhead = 48, kShaftGap = 2;
double shaftEnding(const std::vector<double>& shaft, int i, int polarity)
{
    const int n = int(shaft.size());
    auto stretch = [&](int from, int to) {
        from = std::clamp(from, 0, n);
        to = std::clamp(to, 0, n);
        if (to - from < kShaftBehind / 4)
            return kNaN;
        // On the stack: this runs for every sample of every frame's profile.
        std::array<double, std::max(kShaftBehind, kShaftAhead)> values;
        return medianInPlace(values.begin(), std::copy(shaft.begin() + from, shaft.begin() + to, values.begin()));
    };
    // In the shaft's own sign: the tip's edge goes from the shaft to what lies beyond it.
    const double behind = -polarity * stretch(i - kShaftGap - kShaftBehind, i - kShaftGap);
    const double ahead = -polarity * stretch(i + kShaftGap + 1, i + kShaftGap + 1 + kShaftAhead);
    if (!std::isfinite(behind) || !std::isfinite(ahead))
        return 0.0;
    return std::min(behind, behind - ahead);
}

// An edge of strength `v` (above what is always there) at sample `i`, as far as it is the end
// of a shaft. The tip's edge is the shaft's ending, as strong as it: a digit's stroke that the
// shaft runs into is far stronger than the shaft that ends at it. Both are measured through
// the noise, the ending (medians of a few samples) more roughly: what the noise explains costs
// nothing (in heavy noise the tip was masked in 1-2 % more frames than without the gate). The
// edge is compared as it stands above what is always there: on a texture the raw edge is the
// tip's plus the texture's, and a tip on a texture's falling edge (25 grey levels down where
// the shaft ends 17 up) seemed to end no shaft and went unread at rest (probe seed 90210
// case 2: the course settled 4.5 px ahead and the sync was 4 frames off).
double gatedStrength(const std::vector<double>& shaft, int polarity, double sigma, int i, double v)
{
    const double ending = shaftEnding(shaft, i, polarity);
    const double mismatch = std::max(0.0, std::abs(v - ending) - 3.0 * sigma);
    return std::min(v, ending + 2.0 * sigma) - 0.5 * mismatch;
}

// The edge response reaches kStep samples short of the strip's ends (the picture's edges). A
// tip closer to an end than that is cut off, and its edge peaks on the last samples reached,
// short of it: no place is read there (probe seed 187716 case 13: a stroke ending 6 px from the
// picture's edge read 3.5 px short through its final rest, and the sync was 2.1 frames off).
// Two samples more: a tip 7.3 px from the edge, its edge whole, still peaked on the ramp two
// samples short. `b`: the edge's peak sample of `n`.
bool cutOffAtEnd(int b, int n)
{
    return b <= kStep + 2 || b >= n - 1 - kStep - 2;
}

// The tip in samples [lo, hi] of one frame's profile: the strongest edge of sign `polarity`
// above what is always there, to a fraction of a sample. `gated`: an edge counts only as
// far as a shaft ends at it, judged at the strongest few edges; `sigma` is the edge
// response's noise.
constexpr int kTipCandidates = 12;
Peak findTip(const std::vector<double>& g, const std::vector<double>& shaft, const std::vector<double>& still, int polarity,
             bool gated, double sigma, int lo = 2, int hi = std::numeric_limits<int>::max())
{
    Peak p;
    const int n = int(g.size());
    lo = std::max(lo, 2);
    hi = std::min(hi, n - 3);
    if (n < 5 || hi < lo)
        return p;
    auto v = [&](int i) { return polarity * g[std::size_t(i)] - still[std::size_t(i)]; };
    std::vector<std::pair<double, int>> peaks;  // (strength, sample)
    if (!gated) {
        for (int i = lo; i <= hi; ++i)
            peaks.emplace_back(v(i), i);
    } else {
        for (int i = lo; i <= hi; ++i)
            if ((i == lo || v(i) > v(i - 1)) && (i == hi || v(i) >= v(i + 1)))
                peaks.emplace_back(v(i), i);
        const std::size_t k = std::min<std::size_t>(peaks.size(), kTipCandidates);
        std::partial_sort(peaks.begin(), peaks.begin() + std::ptrdiff_t(k), peaks.end(), std::greater<>());
        peaks.resize(k);
        for (auto& [strength, i] : peaks)
            strength = gatedStrength(shaft, polarity, sigma, i, strength);
    }
    if (peaks.empty())
        return p;
    const auto best = *std::max_element(peaks.begin(), peaks.end());
    const int b = best.second;
    p.strength = best.first;
    for (const auto& [strength, i] : peaks)
        if (std::abs(i - b) > 2 * kStep)
            p.second = std::max(p.second, strength);
    if (cutOffAtEnd(b, n))
        return p;
    p.position = double(b) + peakOffset(v(b - 1), v(b), v(b + 1));
    return p;
}

// The sign of the needle's shaft along a strip (+1 brighter than its sides, −1 darker, 0 when
// none stands out), from the frames' mean. A shaft is long and of one sign; text that the
// line crosses gives both signs by turns (a gap between two bright strokes is darker than
// the strokes beside it) over its own short stretch, so every sample counts at most 3 σ of
// the mean's noise and the length decides, not the contrast.
int shaftSign(const std::vector<StripProfile>& profiles)
{
    if (profiles.size() < 3 || profiles.front().shaft.empty())
        return 0;
    std::vector<std::vector<double>> shafts;
    for (const StripProfile& p : profiles)
        shafts.push_back(p.shaft);
    const double frames = double(shafts.size());
    const double noise = robustSigma(shafts) / std::sqrt(frames);
    const std::size_t n = shafts.front().size();
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        double mean = 0.0;
        for (const auto& sk : shafts)
            mean += sk[i];
        sum += std::clamp(mean / frames, -3.0 * noise, 3.0 * noise);
    }
    // Noise alone sums to about noise·√(2n) (neighbouring samples share the smoothing).
    if (std::abs(sum) < 5.0 * noise * std::sqrt(2.0 * double(n)))
        return 0;
    return sum > 0 ? 1 : -1;
}

// Whether the shaft comes in from the strip's far end (towards p2) rather than its start.
// Against the frames' mean, a frame shows more shaft than usual from the tip's nearest reach
// to where its tip is now, and less from there to its furthest reach: the stretch of more
// lies before the stretch of less when the shaft comes from the start, after it when from
// the far end. What stays put (a textured background, the shaft's own marks) is no change.
// Each frame votes with how much better one split (more, then less) explains it than the
// other (less, then more): on the running sum of the change, the best split's gain is the
// sum's highest point against its lowest. The changing digits of a clock or counter that the
// line crosses change by more than the shaft, but in both signs by turns: each sample counts
// at most 3 σ of the noise, and along the running sum they cancel.
bool shaftFromFarEnd(const std::vector<StripProfile>& profiles)
{
    const int sign = shaftSign(profiles);
    if (sign == 0)
        return false;
    std::vector<std::vector<double>> shafts;
    for (const StripProfile& p : profiles)
        shafts.push_back(p.shaft);
    const std::size_t n = shafts.front().size();
    std::vector<double> mean(n, 0.0);
    for (const auto& sk : shafts)
        for (std::size_t i = 0; i < n; ++i)
            mean[i] += sk[i] / double(shafts.size());
    const double noise = robustSigma(shafts);
    double forward = 0.0, backward = 0.0;
    for (const auto& sk : shafts) {
        // More-then-less gains 2·highest − total, less-then-more total − 2·lowest.
        double sum = 0.0, highest = 0.0, lowest = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double z = std::clamp(sign * (sk[i] - mean[i]) / noise, -3.0, 3.0);
            sum += z > 0 ? std::max(0.0, z - 1.0) : std::min(0.0, z + 1.0);
            highest = std::max(highest, sum);
            lowest = std::min(lowest, sum);
        }
        const double vote = highest + lowest - sum;
        (vote > 0 ? forward : backward) += std::abs(vote);
    }
    if (backward > 2.0 * forward || forward > 2.0 * backward)
        return backward > forward;
    // Undecided: digits that change on the line (a clock on the shaft) vote both ways as much as
    // the tip votes one way (probe seed 531911 case 9: 184 against 175, the line left pointing
    // from the tip, the sync 217 frames off). A needle comes in from beyond the picture's edge:
    // its end of the line shows the shaft in every frame, the other end none. Each sample of
    // the frames' mean counts at most 3 σ (of the mean's noise) either way, over a quarter of
    // the line at each end.
    const double meanNoise = noise / std::sqrt(double(shafts.size()));
    const std::size_t quarter = n / 4;
    double start = 0.0, end = 0.0;
    for (std::size_t i = 0; i < quarter; ++i) {
        start += std::clamp(sign * mean[i] / meanNoise, -3.0, 3.0);
        end += std::clamp(sign * mean[n - 1 - i] / meanNoise, -3.0, 3.0);
    }
    return quarter > 0 && end - start > 1.0 * double(quarter);
}

// The tip's edge sign along a strip and whether to look for it as the end of a shaft, from
// the sampled frames. Where a shaft is seen, the tip is the edge of opposite sign at which it
// ends. If that edge stands out of the noise in most frames, edges of either sign that end no
// shaft (a clock's digits the line crosses, however strong) do not count. A fainter tip keeps
// the shaft's sign all the same: which sign of edge stands out more is a coin toss when the
// needle rests through half the frames, as the places the tip visits while moving show as
// edges of the other sign against the frames' usual (probe seed 271828 case 10: 187 against
// 180, the wrong sign taken, and the sync 715 frames off). Only with no shaft in view (a
// needle wider than the strip, a tip without a visible shaft) is the tip the strongest edge of
// the sign that stands out more.
struct TipModel {
    int polarity = 1;
    bool gated = false;
    std::vector<double> still;
};

TipModel tipModel(const std::vector<StripProfile>& profiles, const std::vector<std::vector<double>>& g, double sigma)
{
    TipModel m;
    if (const int shaft = shaftSign(profiles)) {
        m.polarity = -shaft;
        m.still = staticPart(g, m.polarity);
        std::vector<double> strength;
        for (std::size_t k = 0; k < g.size(); ++k)
            strength.push_back(findTip(g[k], profiles[k].shaft, m.still, m.polarity, true, sigma).strength);
        // Noise alone gives a strongest edge about 3 σ above the noise.
        m.gated = median(strength) > 5.0 * sigma;
        return m;
    }
    const std::vector<double> up = staticPart(g, 1), down = staticPart(g, -1);
    double sp = 0, sn = 0;
    for (std::size_t k = 0; k < g.size(); ++k) {
        sp += findTip(g[k], profiles[k].shaft, up, 1, false, sigma).strength;
        sn += findTip(g[k], profiles[k].shaft, down, -1, false, sigma).strength;
    }
    m.polarity = sp >= sn ? 1 : -1;
    m.gated = false;
    m.still = m.polarity > 0 ? up : down;
    return m;
}

// What `strip` sees in each sampled frame.
std::vector<StripProfile> sampleStrip(const NeedleStrip& strip, const FrameSamples& s)
{
    std::vector<StripProfile> profiles;
    for (const cv::Mat& f : s.gray)
        profiles.push_back(strip.sample(f));
    return profiles;
}

// `axis` pointing from the shaft to the tip, where the tip model looks for them (the shaft
// behind, towards p1): a line found in the picture points left to right or downwards
// whichever way the needle enters. The other way round, a shaft is seen ahead of its tip and
// the tip is lost in most frames (a needle entering from the picture's right: 273 of 475
// frames without a tip and the sync 116 frames off).
NeedleAxis shaftBehindTip(const FrameSamples& s, const NeedleAxis& axis)
{
    const NeedleStrip strip(axis, s.width, s.height);
    if (strip.length < 20)
        return axis;
    return shaftFromFarEnd(sampleStrip(strip, s)) ? NeedleAxis(axis.p2(), axis.p1()) : axis;
}

// The sampled frames' mean, in float.
cv::Mat framesMean(const FrameSamples& s)
{
    cv::Mat mean = cv::Mat::zeros(s.height, s.width, CV_32F);
    for (const cv::Mat& f : s.gray)
        cv::accumulate(f, mean);
    return mean / double(std::max<std::size_t>(1, s.gray.size()));
}

// Where a shaft of sign `sign` stands along a strip 2·kSettleHalfWidth_px + 1 rows wide
// (`sampled`): per segment of kSettleSegment_px, the peak of the mean across the strip
// (fractional row from the middle) where it stands more than `threshold_sigma` σ out of the
// picture beside it.
constexpr int kSettleSegment_px = 24, kSettleHalfWidth_px = 10;
std::vector<std::pair<double, double>> shaftCentres(const cv::Mat& sampled, double origin, double sign, double threshold_sigma)
{
    const int segments = sampled.cols / kSettleSegment_px;
    std::vector<std::vector<double>> across;
    std::vector<double> spread;
    for (int k = 0; k < segments; ++k) {
        cv::Mat column;
        cv::reduce(sampled.colRange(k * kSettleSegment_px, (k + 1) * kSettleSegment_px), column, 1, cv::REDUCE_AVG);
        std::vector<double> p(column.begin<float>(), column.end<float>());
        const double base = median(p);
        for (double& v : p) {
            v = sign * (v - base);
            spread.push_back(std::abs(v));
        }
        across.push_back(std::move(p));
    }
    std::vector<std::pair<double, double>> centres;  // (along the axis, across it)
    if (across.empty())
        return centres;
    const double noise = std::max(1e-3, 1.4826 * median(spread));
    for (int k = 0; k < segments; ++k) {
        const auto& p = across[std::size_t(k)];
        const auto peak = std::max_element(p.begin() + 1, p.end() - 1);
        if (!(*peak > threshold_sigma * noise))
            continue;
        const double across = double(peak - p.begin()) + peakOffset(*(peak - 1), *peak, *(peak + 1)) - kSettleHalfWidth_px;
        centres.emplace_back(origin + (k + 0.5) * kSettleSegment_px, across);
    }
    return centres;
}

// `axis` moved onto the shaft the frames' mean shows, when it shows one clearly over a good
// stretch; as it is otherwise. A line found from the tip's path is a few degrees off where the
// path is short (±34 px of travel: 1.7° off, 9 px from the shaft at the picture's edge, and the
// sync 17 s off at confidence 0), and so is one drawn by hand. The shaft's centres across the line
// (shaftCentres beyond `threshold_sigma`, of the sign that shows more of them) are fitted with a
// line (Theil-Sen: the digits of a clock on the line, grain that happens to stand out, are
// outliers); that line is the shaft if most centres lie on it, and it lies within 3° and 4 px of
// `axis`.
NeedleAxis settleOnShaft(const cv::Mat& mean, const NeedleAxis& axis, double threshold_sigma = 4.0)
{
    const Strip wide(axis, mean.cols, mean.rows, kSettleHalfWidth_px);
    if (wide.length < 5 * kSettleSegment_px)
        return axis;
    cv::Mat sampled;
    cv::remap(mean, sampled, wide.mapX, wide.mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    std::vector<std::pair<double, double>> centres = shaftCentres(sampled, wide.origin, 1.0, threshold_sigma);
    if (auto dark = shaftCentres(sampled, wide.origin, -1.0, threshold_sigma); dark.size() > centres.size())
        centres = std::move(dark);
    if (centres.size() < 5)
        return axis;
    std::vector<double> slopes;
    for (std::size_t i = 0; i < centres.size(); ++i)
        for (std::size_t j = i + 1; j < centres.size(); ++j)
            slopes.push_back((centres[j].second - centres[i].second) / (centres[j].first - centres[i].first));
    const double slope = median(slopes);
    std::vector<double> offsets;
    for (const auto& [t, o] : centres)
        offsets.push_back(o - slope * t);
    const double offset = median(offsets);  // across the axis at its first point
    // Most centres must lie on that line: a shaft, not grain that stands out here and there.
    const auto onLine = std::count_if(centres.begin(), centres.end(), [&](const auto& c) { return std::abs(c.second - offset - slope * c.first) < 1.5; });
    const double len = axis.length();
    if (onLine < 5 || 3 * onLine < 2 * std::ptrdiff_t(centres.size()) || std::abs(slope) > std::tan(3.0 * M_PI / 180.0)
        || std::abs(offset + slope * 0.5 * len) > 4.0)
        return axis;
    // The centres are read to a few tenths of a pixel: a line that close is left as it is.
    const double from = offset + slope * wide.origin, to = offset + slope * (wide.origin + wide.length);
    if (std::max(std::abs(from), std::abs(to)) < 0.5)
        return axis;
    const QPointF u = (axis.p2() - axis.p1()) / len, n(-u.y(), u.x());
    return NeedleAxis(axis.p1() + n * offset, axis.p2() + n * (offset + slope * len));
}

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

namespace {

struct AxisScore {
    NeedleAxis axis;
    double ridge = 0.0;
    double snr = 0.0;
};

// How many of `positions` lie more than a pixel from their median.
int movedFrames(const std::vector<double>& positions)
{
    std::vector<double> finite;
    for (double p : positions)
        if (std::isfinite(p))
            finite.push_back(p);
    if (finite.empty())
        return 0;
    const double usual = median(finite);
    return int(std::count_if(finite.begin(), finite.end(), [&](double p) { return std::abs(p - usual) > 1.0; }));
}

// The step detector's noise from rounding to whole grey levels alone (σ 1/√12 a pixel), over
// the middle's rows and kStep samples each side.
const double kRoundingSigma = std::sqrt(1.0 / 12.0) * std::sqrt(2.0 / kStep) / std::sqrt(2.0 * kMiddleHalfWidth_px + 1.0);

// How clearly an edge moves along `axis` in the sampled frames.
double movingEdgeSnr(const FrameSamples& s, const NeedleAxis& axis)
{
    const NeedleStrip strip(axis, s.width, s.height);
    if (strip.length < 20)
        return 0.0;
    std::vector<StripProfile> profiles;
    std::vector<std::vector<double>> g;
    for (const cv::Mat& f : s.gray) {
        profiles.push_back(strip.sample(f));
        g.push_back(gradient(profiles.back().middle));
    }
    const double sigma = robustSigma(g);
    const TipModel model = tipModel(profiles, g, sigma);
    double best = 0.0;
    for (int polarity : {1, -1}) {
        // The sign the tracker would not take does not count when a shaft ends at its tip.
        if (model.gated && polarity != model.polarity)
            continue;
        const std::vector<double> still = polarity == model.polarity ? model.still : staticPart(g, polarity);
        std::vector<double> strength, position, alone;
        for (std::size_t k = 0; k < g.size(); ++k) {
            const Peak p = findTip(g[k], profiles[k].shaft, still, polarity, model.gated, sigma);
            strength.push_back(p.strength);
            position.push_back(p.position);
            alone.push_back(p.strength > 0 ? 1.0 - p.second / p.strength : 0.0);
        }
        // An edge that moves: more than a pixel from its usual place in a few of the frames.
        // A few, not a share: a video begun long before the run shows the needle at rest in
        // most of them (17.3 s of rest before 4.7 s of a 1.4 Hz sine: 8 frames of 40 moved,
        // and the needle's 10th to 90th percentile spread was 0.13 px).
        if (movedFrames(position) < 2)
            continue;
        // One tip stands alone on its line; changing text has many edges alike. Against no
        // less noise than the 8-bit picture's rounding: a coder that holds a still picture's
        // pixels from frame to frame leaves no other, and a ratio to nothing outranked every
        // other line (the simulator's view as H.264 at -crf 30: a line 5° off the needle scored
        // 10⁷, the needle 608, and was never tried).
        best = std::max(best, median(strength) / std::max(sigma, kRoundingSigma) * median(alone));
    }
    return best;
}

// Refines a candidate line: the small turn and shift (±`turn_deg`, ±3 px) that puts the most
// ridge under it, at full resolution. With `plateau` > 0, the middle of the turns and shifts
// within that fraction of the most: on a picture clipped flat (PictureChange::counted) many
// lines sum alike, and the first of them tried lies at an edge of the band, not along it.
NeedleAxis refineAxis(const cv::Mat& ridge, const NeedleAxis& rough, double turn_deg = 1.5, double plateau = 0.0)
{
    const double len = rough.length();
    if (len < 2)
        return rough;
    const QPointF mid = 0.5 * (rough.p1() + rough.p2());
    const double base = std::atan2(rough.y2() - rough.y1(), rough.x2() - rough.x1());
    auto sumAlong = [&](double angle, double shift) {
        const double ux = std::cos(angle), uy = std::sin(angle), nx = -uy, ny = ux;
        double sum = 0.0;
        for (double s = -len / 2; s <= len / 2; s += 1.0) {
            const double x = mid.x() + s * ux + shift * nx, y = mid.y() + s * uy + shift * ny;
            const int xi = int(x), yi = int(y);
            if (xi < 0 || yi < 0 || xi + 1 >= ridge.cols || yi + 1 >= ridge.rows)
                continue;
            const double fx = x - xi, fy = y - yi;
            sum += (1 - fx) * (1 - fy) * ridge.at<float>(yi, xi) + fx * (1 - fy) * ridge.at<float>(yi, xi + 1)
                   + (1 - fx) * fy * ridge.at<float>(yi + 1, xi) + fx * fy * ridge.at<float>(yi + 1, xi + 1);
        }
        return sum;
    };
    double bestA = base, bestS = 0.0, bestV = -1.0;
    std::vector<std::array<double, 3>> tried;  // (sum, angle, shift)
    for (double da = -turn_deg; da <= turn_deg + 1e-9; da += 0.1)
        for (double sh = -3.0; sh <= 3.0 + 1e-9; sh += 0.25) {
            const double v = sumAlong(base + da * M_PI / 180.0, sh);
            if (plateau > 0.0)
                tried.push_back({v, base + da * M_PI / 180.0, sh});
            if (v > bestV) {
                bestV = v;
                bestA = base + da * M_PI / 180.0;
                bestS = sh;
            }
        }
    if (plateau > 0.0) {
        double angles = 0.0, shifts = 0.0;
        int alike = 0;
        for (const auto& [v, angle, shift] : tried)
            if (v >= (1.0 - plateau) * bestV) {
                angles += angle;
                shifts += shift;
                ++alike;
            }
        bestA = angles / alike;
        bestS = shifts / alike;
    }
    const double ux = std::cos(bestA), uy = std::sin(bestA);
    const QPointF c = mid + QPointF(-uy, ux) * bestS;
    return NeedleAxis(c - QPointF(ux, uy) * (len / 2), c + QPointF(ux, uy) * (len / 2));
}

// Straight-line sums of a picture at every whole degree (a Radon transform by rotation), on
// a copy at most 360 pixels wide: one row of sums per angle, one sum per line across it.
struct LineSums {
    std::vector<cv::Mat> rows;  // [angle in degrees], CV_32F column of diag sums
    int diag = 0;
    cv::Point2f centre;
    double scale = 1.0;  // of the copy against the picture
};

struct LineCandidate {
    int angle_deg = 0;
    int row = 0;  // index into LineSums::rows[angle_deg]
    double score = 0.0;
};

// The sums of `image` along horizontal lines of copies turned by every whole degree (a Radon
// transform by rotation): one column per angle. Sets `geometry`'s diag and centre.
std::vector<cv::Mat> sumAlongLines(const cv::Mat& image, LineSums& geometry)
{
    geometry.diag = int(std::ceil(std::hypot(image.cols, image.rows))) + 2;
    geometry.centre = cv::Point2f(image.cols / 2.0f, image.rows / 2.0f);
    std::vector<cv::Mat> out;
    for (int a = 0; a < 180; ++a) {
        cv::Mat m = cv::getRotationMatrix2D(geometry.centre, a, 1.0);
        m.at<double>(0, 2) += geometry.diag / 2.0 - geometry.centre.x;
        m.at<double>(1, 2) += geometry.diag / 2.0 - geometry.centre.y;
        cv::Mat rotated, rows;
        cv::warpAffine(image, rotated, m, cv::Size(geometry.diag, geometry.diag), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
        cv::reduce(rotated, rows, 1, cv::REDUCE_SUM);  // one sum per horizontal line
        out.push_back(rows);
    }
    return out;
}

// The median of a float picture's values, and their spread around it (1.4826 times their
// median distance from it: σ for Gaussian noise).
std::pair<float, float> middleAndSpread(const cv::Mat& image)
{
    std::vector<float> values(image.begin<float>(), image.end<float>());
    auto medianOf = [](std::vector<float>& v) {
        const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
        std::nth_element(v.begin(), mid, v.end());
        return *mid;
    };
    const float middle = medianOf(values);
    for (float& v : values)
        v = std::abs(v - middle);
    return {middle, 1.4826f * medianOf(values)};
}

LineSums lineSums(const cv::Mat& image)
{
    LineSums out;
    out.scale = std::min(1.0, 360.0 / std::max(image.cols, image.rows));
    cv::Mat small;
    cv::resize(image, small, cv::Size(), out.scale, out.scale, cv::INTER_AREA);
    // What noise leaves in the picture everywhere is taken off first: in a noisy picture it
    // adds up along a line with its length, and the picture's long diagonals outweighed a
    // needle reaching half across it (seed 586261: 16 candidates, all diagonals).
    const auto [floor, noise] = middleAndSpread(small);
    small -= floor;
    cv::max(small, 0.0f, small);
    // Capped so that a wide bright bar does not outweigh a long thin needle, but well above
    // the noise: a thin needle is less than a hundredth of the picture, and a cap at the
    // noise's own tail made it no more than noise.
    std::vector<float> values(small.begin<float>(), small.end<float>());
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() * 99 / 100), values.end());
    const float cap = std::max({1e-3f, values[values.size() * 99 / 100], 6.0f * noise});
    cv::min(small, cap, small);
    out.rows = sumAlongLines(small, out);
    return out;
}

// How long the line of sumAlongLines at `angle_deg` and `rho` (from the picture's centre,
// along the line's normal) runs inside a `width` × `height` picture: what the sums of a
// picture of ones would be (within 0.7 % on a 640x480 picture, lines of 40 px and more),
// without turning one 180 times.
double lengthInside(int width, int height, int angle_deg, double rho)
{
    const double th = angle_deg * M_PI / 180.0, dx = std::cos(th), dy = std::sin(th);
    const double px = width / 2.0 - rho * dy, py = height / 2.0 + rho * dx;
    double from = -1e9, to = 1e9;
    // Pixel k covers k ± 0.5.
    auto clip = [&](double p, double d, double size) {
        if (std::abs(d) < 1e-9) {
            if (p < -0.5 || p > size - 0.5)
                to = from;
            return;
        }
        const double a = (-0.5 - p) / d, b = (size - 0.5 - p) / d;
        from = std::max(from, std::min(a, b));
        to = std::min(to, std::max(a, b));
    };
    clip(px, dx, width);
    clip(py, dy, height);
    return std::max(0.0, to - from);
}

// Where a shaft of one sign stands along a straight line of the sampled frames' mean: per
// line, the signed sum of the picture's departure from its surroundings, in units of what a
// picture without lines sums to along as long a line (its spread grows with the root of the
// length). At full resolution, up to 1024 px: a faint needle (26 grey levels) on a grain as
// strong and as fine (4 px) stands out along its length, but not of the absolute departure,
// which the grain fills everywhere, nor on a copy 360 px wide, where the grain outweighs the
// shaft (probe seed 246810 case 10: the needle's line was none of the 14 lines of ridge or
// change; in a numpy copy of these sums it stands 9.9 spreads of all lines' sums out of their
// median, the next line 7.3, and on the copy 360 px wide it is second).
constexpr int kShaftLineMin_px = 40;
constexpr std::size_t kShaftLines = 3;
LineSums shaftLineSums(const cv::Mat& mean, cv::Mat& departure)
{
    LineSums out;
    out.scale = std::min(1.0, 1024.0 / std::max(mean.cols, mean.rows));
    cv::Mat small, local;
    cv::resize(mean, small, cv::Size(), out.scale, out.scale, cv::INTER_AREA);
    cv::blur(small, local, cv::Size(15, 15));
    departure = small - local;
    // Text and bright bars count no more than a strong shaft.
    const auto [middle, spread] = middleAndSpread(departure);
    const float noise = std::max(1e-3f, spread);
    departure -= middle;
    cv::min(departure, 3.0f * noise, departure);
    cv::max(departure, -3.0f * noise, departure);
    const std::vector<cv::Mat> sums = sumAlongLines(departure, out);
    for (std::size_t a = 0; a < sums.size(); ++a) {
        cv::Mat row(sums[a].size(), CV_32F, cv::Scalar(0));
        for (int y = 0; y < row.rows; ++y) {
            const double length = lengthInside(departure.cols, departure.rows, int(a), y - out.diag / 2.0);
            if (length >= kShaftLineMin_px)
                row.at<float>(y) = float(std::abs(sums[a].at<float>(y)) / std::sqrt(length));
        }
        out.rows.push_back(row);
    }
    return out;
}

// The strongest lines of `sums` (local maxima across the lines of one angle), at most
// `maxCount`, lines alike (within 8 degrees and 8 pixels of the copy) counted once.
std::vector<LineCandidate> strongestLines(const LineSums& sums, std::size_t maxCount)
{
    std::vector<LineCandidate> candidates;
    for (int a = 0; a < int(sums.rows.size()); ++a) {
        const cv::Mat& rows = sums.rows[std::size_t(a)];
        for (int y = 1; y + 1 < rows.rows; ++y) {
            const float v = rows.at<float>(y);
            if (v > rows.at<float>(y - 1) && v >= rows.at<float>(y + 1))
                candidates.push_back({a, y, double(v)});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const LineCandidate& x, const LineCandidate& y) { return x.score > y.score; });
    std::vector<LineCandidate> kept;
    const double half = sums.diag / 2.0;
    for (const LineCandidate& c : candidates) {
        bool near = false;
        for (const LineCandidate& k : kept) {
            // (angle, rho) and (angle ± 180, −rho) are the same line.
            const int raw = std::abs(c.angle_deg - k.angle_deg);
            const bool wrapped = raw > 90;
            const int da = wrapped ? 180 - raw : raw;
            const double rho = c.row - half, krho = k.row - half;
            if (da < 8 && std::abs(rho - (wrapped ? -krho : krho)) < 8.0)
                near = true;
        }
        if (!near)
            kept.push_back(c);
        if (kept.size() >= maxCount)
            break;
    }
    return kept;
}

// The line of `c` across the whole picture (`width` × `height`).
NeedleAxis lineAcross(const LineSums& sums, const LineCandidate& c)
{
    // A horizontal line at height rho (from the centre) in the rotated copy: with
    // getRotationMatrix2D's y' = −sin·x + cos·y it runs along (cos, sin) in the picture, rho
    // along the normal (−sin, cos).
    const double th = c.angle_deg * M_PI / 180.0, rho = c.row - sums.diag / 2.0;
    const double dx = std::cos(th), dy = std::sin(th);
    const double nx = -std::sin(th), ny = std::cos(th);
    const double cx = (sums.centre.x + rho * nx) / sums.scale, cy = (sums.centre.y + rho * ny) / sums.scale;
    return NeedleAxis(QPointF(cx - dx * sums.diag, cy - dy * sums.diag), QPointF(cx + dx * sums.diag, cy + dy * sums.diag));
}

// The largest of `sums` along `axis` and the lines either side of it at its nearest whole degree.
double sumAlong(const LineSums& sums, const NeedleAxis& axis)
{
    const double angle = std::fmod(std::fmod(axis.angle(), 180.0) + 180.0, 180.0);
    const int a = int(std::lround(angle)) % 180;
    const double th = a * M_PI / 180.0;
    const QPointF mid = 0.5 * (axis.p1() + axis.p2()) * sums.scale;
    const double rho = (mid.x() - sums.centre.x) * -std::sin(th) + (mid.y() - sums.centre.y) * std::cos(th);
    const cv::Mat& rows = sums.rows[std::size_t(a)];
    const int row = int(std::lround(rho + sums.diag / 2.0));
    double best = 0.0;
    for (int y = std::max(0, row - 1); y <= std::min(rows.rows - 1, row + 1); ++y)
        best = std::max(best, double(rows.at<float>(y)));
    return best;
}

// Two lines that are one: within `angle_deg` and the middle of `b` within `distance_px` of `a`.
bool alike(const NeedleAxis& a, const NeedleAxis& b, double angle_deg = 5.0, double distance_px = 6.0)
{
    const double angle = std::abs(std::remainder(b.angle() - a.angle(), 180.0));
    const QPointF mid = 0.5 * (b.p1() + b.p2());
    const double dist = std::abs((a.x2() - a.x1()) * (a.y1() - mid.y()) - (a.x1() - mid.x()) * (a.y2() - a.y1())) / a.length();
    return angle < angle_deg && dist < distance_px;
}

// The stretch of `line` along which the picture changes at least half as much as at the most,
// the best of a few pixels either side (smoothed over 9 px); nothing when under 10 px.
std::optional<NeedleAxis> stretchOfChange(const cv::Mat& change, const NeedleAxis& line)
{
    const double len = line.length();
    if (len < 20)
        return std::nullopt;
    const QPointF u((line.x2() - line.x1()) / len, (line.y2() - line.y1()) / len), n(-u.y(), u.x());
    std::vector<double> along(std::size_t(len), 0.0);
    for (std::size_t i = 0; i < along.size(); ++i)
        for (int side = -3; side <= 3; ++side) {
            const QPointF p = line.p1() + u * double(i) + n * double(side);
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (x >= 0 && y >= 0 && x < change.cols && y < change.rows)
                along[i] = std::max(along[i], double(change.at<float>(y, x)));
        }
    cv::Mat smooth(along, true);
    cv::blur(smooth, smooth, cv::Size(1, 9));
    const std::vector<double> level(smooth.begin<double>(), smooth.end<double>());
    const auto peak = std::max_element(level.begin(), level.end());
    std::size_t from = std::size_t(peak - level.begin()), to = from;
    while (from > 0 && level[from - 1] >= 0.5 * *peak)
        --from;
    while (to + 1 < level.size() && level[to + 1] >= 0.5 * *peak)
        ++to;
    if (to < from + 10)
        return std::nullopt;
    return NeedleAxis(line.p1() + u * double(from), line.p1() + u * double(to));
}

// `segment`'s line across the whole picture; nothing when under 20 px of it is inside.
std::optional<NeedleAxis> acrossPicture(const NeedleAxis& segment, int width, int height)
{
    const double len = segment.length(), across = std::hypot(width, height);
    const QPointF v((segment.x2() - segment.x1()) / len, (segment.y2() - segment.y1()) / len);
    const NeedleAxis whole(segment.p1() - v * across, segment.p1() + v * across);
    const Strip clipper(whole, width, height, 0);
    if (clipper.length < 20)
        return std::nullopt;
    return NeedleAxis(whole.p1() + v * clipper.origin, whole.p1() + v * (clipper.origin + clipper.length));
}

// How much each pixel changes over the sampled frames (its standard deviation): the path
// of a moving tip stands out here even where the still picture around it (tissue texture,
// speckle) hides the shaft in the mean. `counted` says whether a pixel changes, not how much
// (clipped at three noise widths): a burnt-in clock's digits change far more than a faint
// needle's path, and its lines would outweigh the needle's. `measured` is how much (above the
// usual change), for where across a path it changes most.
struct PictureChange {
    cv::Mat counted, measured;
};

constexpr int kMaxPathWidth_px = 20;
constexpr std::size_t kStreaks = 8;
constexpr double kStreakLengthPerWidth = 2.0;
constexpr double kFlatPlateau = 0.005;  // lines within half a percent of the most sum alike
constexpr std::size_t kMostChangePaths = 2;  // tracked whatever their rank
constexpr std::size_t kMostApartPaths = 3;   // the same, with the changing digits set aside
constexpr double kPathLengthPerWidth = 4.0;

// A line along which a tip's path was seen, and the change summed along that path (a line a
// little across the path crosses it over a shorter stretch; the change there is as strong).
struct PathLine {
    NeedleAxis axis;
    double changeOnPath = 0.0;
    double ridge = 0.0;  // the ridge's line sum where it was found (LineSums units)
};

// Refines a line along which the picture changes to the tip's path on it: the stretch of
// change on the line, turned (±4°) and shifted (±3 px) to put the most change under it, then
// carried across the picture, again until it turns no more. The line sums find the path's
// angle only to a few degrees (lines within 8° count once), and a line a few degrees off
// crosses only part of the path (refined once, one path came out as lines 3.5° apart). Summed
// along the stretch, not the whole line: along the whole line a compressed picture's block
// pattern (rows of slightly more noise every 8 pixels) outweighed the path. Nothing when the
// change is a patch, not a line (the digits of a clock or counter), or shorter than
// `lengthPerWidth` times its width.
// The stretch and the width are read on `change` (PictureChange::counted), the turn and shift on
// `centredOn`: counted where digits change in the picture (they would pull the line), taking the
// middle of the lines that sum alike (`plateau`, as refineAxis takes it), and the change measured
// where the digits are set aside. Counted, a faint tip's path is a flat-topped band as wide as
// the blur, and the first line tried that sums the most lay 2-6 px and up to 2.3° off the needle
// (slow-small probe seed 5 case 9, seed 6 case 13: the needle's line not found).
std::optional<PathLine> refinePath(const cv::Mat& change, const cv::Mat& centredOn, double plateau, const NeedleAxis& rough,
                                   int width, int height, double lengthPerWidth = kPathLengthPerWidth)
{
    NeedleAxis line = rough, path = rough;
    for (int pass = 0; pass < 4; ++pass) {
        const std::optional<NeedleAxis> stretch = stretchOfChange(change, line);
        if (!stretch)
            return std::nullopt;
        path = refineAxis(centredOn, *stretch, 4.0, plateau);
        const std::optional<NeedleAxis> whole = acrossPicture(path, width, height);
        if (!whole)
            return std::nullopt;
        const double turned = std::abs(std::remainder(whole->angle() - line.angle(), 180.0));
        line = *whole;
        if (turned < 0.5)
            break;
    }
    const double pathLen = path.length();
    const QPointF v((path.x2() - path.x1()) / pathLen, (path.y2() - path.y1()) / pathLen), w(-v.y(), v.x());
    // A tip's path is a line of change, far longer than it is wide; a patch of changing digits
    // changes as much well beside the line as on it.
    auto meanAlong = [&](double side) {
        double sum = 0.0;
        int count = 0;
        for (double t = 0.0; t <= pathLen; t += 1.0) {
            const QPointF p = path.p1() + v * t + w * side;
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (x >= 0 && y >= 0 && x < change.cols && y < change.rows) {
                sum += change.at<float>(y, x);
                ++count;
            }
        }
        return count > 0 ? sum / count : 0.0;
    };
    const double onLine = meanAlong(0.0);
    if (!(onLine > 0.0))
        return std::nullopt;
    int wide = 1;
    for (int side = 1; side <= kMaxPathWidth_px && meanAlong(side) >= 0.5 * onLine; ++side)
        ++wide;
    for (int side = 1; side <= kMaxPathWidth_px && meanAlong(-side) >= 0.5 * onLine; ++side)
        ++wide;
    if (wide > kMaxPathWidth_px || pathLen < lengthPerWidth * wide)
        return std::nullopt;
    return PathLine{line, onLine * pathLen, 0.0};
}

PictureChange changeOverFrames(const FrameSamples& s, const cv::Mat& mean)
{
    cv::Mat squares = cv::Mat::zeros(s.height, s.width, CV_32F);
    for (const cv::Mat& f : s.gray)
        cv::accumulateSquare(f, squares);
    cv::Mat variance = squares / double(s.gray.size()) - mean.mul(mean), deviation;
    cv::max(variance, 0.0, variance);
    cv::sqrt(variance, deviation);
    cv::GaussianBlur(deviation, deviation, cv::Size(0, 0), 1.0);
    std::vector<float> values(deviation.begin<float>(), deviation.end<float>());
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    const float usual = values[values.size() / 2];
    for (float& v : values)
        v = std::abs(v - usual);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    const float noise = std::max(1e-3f, 1.4826f * values[values.size() / 2]);
    PictureChange out;
    deviation -= usual;
    cv::max(deviation, 0.0f, out.measured);
    cv::min(out.measured, 3.0f * noise, out.counted);
    return out;
}

// Where burnt-in text changes (a clock's or a counter's digits): patches of change wider every
// way than a tip's path (a square of 11 px fits inside them, where a tip's path is a few pixels
// wide), and a few pixels round them.
cv::Mat changingPatches(const cv::Mat& change)
{
    double top = 0.0;
    cv::minMaxLoc(change, nullptr, &top);
    cv::Mat patches = change >= 0.5 * top;
    cv::morphologyEx(patches, patches, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(11, 11)));
    cv::dilate(patches, patches, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(9, 9)));
    return patches;
}

// The short streaks of change (blobs of half the strongest change or more, 20 px long or more
// and twice as long as wide), each as a rough line along it across the picture, the largest
// first: a tip that moves a few millimetres draws a path too short to stand out of the line
// sums, where the rows of a coder's blocks, summed over the whole picture, do (slow-small probe
// seed 5 case 9: a path of 19 px by 10 at -94.6°, the 32 strongest lines of change all within
// 11° of the rows).
std::vector<NeedleAxis> streaksOfChange(const cv::Mat& counted, int width, int height)
{
    double top = 0.0;
    cv::minMaxLoc(counted, nullptr, &top);
    if (!(top > 0.0))
        return {};
    const cv::Mat mask = counted >= 0.5 * top;
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    std::vector<std::pair<int, NeedleAxis>> streaks;  // (area, line)
    for (int i = 1; i < n; ++i) {
        const int area = stats.at<int>(i, cv::CC_STAT_AREA);
        if (area < 20)
            continue;
        const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP), stats.at<int>(i, cv::CC_STAT_WIDTH),
                           stats.at<int>(i, cv::CC_STAT_HEIGHT));
        const cv::Moments m = cv::moments(labels(box) == i, true);
        const double mu20 = m.mu20 / m.m00, mu02 = m.mu02 / m.m00, mu11 = m.mu11 / m.m00;
        const double common = std::sqrt(4.0 * mu11 * mu11 + (mu20 - mu02) * (mu20 - mu02));
        const double major = std::sqrt(std::max(0.0, 2.0 * (mu20 + mu02 + common)));
        const double minor = std::sqrt(std::max(0.0, 2.0 * (mu20 + mu02 - common)));
        if (2.0 * major < 20.0 || major < 2.0 * std::max(minor, 1.0))
            continue;
        const double angle = 0.5 * std::atan2(2.0 * mu11, mu20 - mu02);
        const QPointF c(box.x + m.m10 / m.m00, box.y + m.m01 / m.m00), u(std::cos(angle), std::sin(angle));
        if (const std::optional<NeedleAxis> line = acrossPicture(NeedleAxis(c - u * major, c + u * major), width, height))
            streaks.emplace_back(area, *line);
    }
    std::sort(streaks.begin(), streaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<NeedleAxis> out;
    for (std::size_t k = 0; k < streaks.size() && k < kStreaks; ++k)
        out.push_back(streaks[k].second);
    return out;
}

}  // namespace

std::vector<NeedleAxis> needleAxisCandidates(FrameReader& reader, QRect roi, int maxCount, int sampleFrames_,
                                             std::vector<double>* scores)
{
    return needleAxisCandidates(sampleFrames(reader, sampleFrames_), roi, maxCount, scores);
}

std::vector<NeedleAxis> needleAxisCandidates(const FrameSamples& s, QRect roi, int maxCount, std::vector<double>* scores)
{
    if (s.gray.size() < 3)
        return {};
    const cv::Mat mean = framesMean(s);
    // Thin structures of either polarity: the picture minus its local mean.
    cv::Mat local, ridge;
    cv::blur(mean, local, cv::Size(15, 15));
    ridge = cv::abs(mean - local);
    cv::GaussianBlur(ridge, ridge, cv::Size(0, 0), 1.0);

    // The strongest straight lines of the ridge are the candidates, and the strongest lines
    // along which the picture changes: a thin needle on textured tissue (speckle as strong as
    // the shaft) ranks below the texture's lines in the ridge, but its tip's path is the only
    // line that changes (a look not made by our renderer, 1024x768 MJPEG, a needle 26 grey
    // levels bright on texture of 25: no needle found and the sync was off by 7 s).
    const LineSums ridgeSums = lineSums(ridge);
    const PictureChange picture = changeOverFrames(s, mean);
    const cv::Mat& change = picture.counted;
    const LineSums changeSums = lineSums(change);
    // Line `c` of `sums`, as far as it runs inside the picture.
    auto clipped = [&](const LineSums& sums, const LineCandidate& c) -> std::optional<NeedleAxis> {
        const NeedleAxis rough = lineAcross(sums, c);
        const Strip clipper(rough, s.width, s.height, 0);
        if (clipper.length < 20)
            return std::nullopt;
        const double len = rough.length();
        const QPointF u((rough.x2() - rough.x1()) / len, (rough.y2() - rough.y1()) / len);
        return NeedleAxis(rough.p1() + u * clipper.origin, rough.p1() + u * (clipper.origin + clipper.length));
    };
    // The ridge's line sum under line `c` of a picture's sums (all share the ridge's geometry),
    // by which a line of the ridge is ranked.
    auto ridgeUnder = [&](const LineCandidate& c) {
        double most = 0.0;
        const cv::Mat& rows = ridgeSums.rows[std::size_t(c.angle_deg)];
        for (int y = std::max(0, c.row - 1); y <= std::min(rows.rows - 1, c.row + 1); ++y)
            most = std::max(most, double(rows.at<float>(y)));
        return most;
    };
    std::vector<std::pair<double, NeedleAxis>> scored;
    for (const LineCandidate& c : strongestLines(ridgeSums, 16)) {
        const std::optional<NeedleAxis> rough = clipped(ridgeSums, c);
        if (!rough)
            continue;
        const NeedleAxis axis = shaftBehindTip(s, refineAxis(ridge, *rough));
        // Noise alone gives a strongest edge about 3 σ above the noise; but under heavy noise a
        // tip's edge in single frames is no more, while its shaft is the strongest line of the
        // picture (probe seed 531911 case 11: 2.8 σ, the line 25 % above the next, and the sync
        // 24 frames off without it). Such lines are tracked too, ranked by what they show;
        // which line is the needle, the fit to the recording decides.
        const double snr = movingEdgeSnr(s, axis);
        if (snr >= 2.0)
            scored.emplace_back(snr * std::sqrt(c.score), axis);
    }
    // One path is crossed by several of the strongest lines of change, each refined onto it a
    // little differently: the one with the most change under it is the path (kept the first
    // found, a line 0.6° and 5 px off it lost the tip in 261 frames of 512).
    std::vector<PathLine> paths;
    for (LineCandidate c : strongestLines(changeSums, 32)) {
        const std::optional<NeedleAxis> rough = clipped(ridgeSums, c);
        std::optional<PathLine> path = rough ? refinePath(change, change, kFlatPlateau, *rough, s.width, s.height) : std::nullopt;
        if (!path)
            continue;
        // Ranked by the ridge under the line it was found from, as the ridge's own lines are.
        path->ridge = ridgeUnder(c);
        const auto same = std::find_if(paths.begin(), paths.end(), [&](const PathLine& p) { return alike(p.axis, path->axis); });
        if (same == paths.end())
            paths.push_back(*path);
        else if (path->changeOnPath > same->changeOnPath)
            *same = {path->axis, path->changeOnPath, std::max(path->ridge, same->ridge)};
    }
    // The lines along which a shaft stands out of the mean most (a faint needle on a grain as
    // fine as it: the ridge's lines are the grain's), refined onto the shaft's own sign.
    std::vector<std::pair<double, NeedleAxis>> shafts;
    cv::Mat departure;
    const LineSums shaftSums = shaftLineSums(mean, departure);
    cv::resize(departure, departure, mean.size(), 0, 0, cv::INTER_LINEAR);
    for (const LineCandidate& c : strongestLines(shaftSums, kShaftLines)) {
        const std::optional<NeedleAxis> rough = clipped(shaftSums, c);
        if (!rough)
            continue;
        const Strip line(*rough, s.width, s.height, 0);
        cv::Mat along;
        cv::remap(departure, along, line.mapX, line.mapY, cv::INTER_LINEAR);
        const cv::Mat shaft = cv::sum(along)[0] < 0 ? cv::Mat(-departure) : departure;
        const NeedleAxis axis = shaftBehindTip(s, refineAxis(shaft, *rough));
        // Ranked as a line of change is (what it shows moving, and the ridge under it), and
        // tracked even when that ranks it below the lines kept: a faint needle's ridge is low
        // and its tip's edge barely moves in single frames (246810 case 10: 17th of 17).
        shafts.emplace_back(std::max(movingEdgeSnr(s, axis), 2.0) * std::sqrt(sumAlong(ridgeSums, axis)), axis);
        scored.push_back(shafts.back());
    }
    std::vector<std::pair<double, std::pair<double, NeedleAxis>>> pathsByChange;  // (change on the path, (score, axis))
    for (const PathLine& p : paths) {
        // A path of change is evidence of a tip of its own, where single frames are too noisy
        // to show its edge (15 frames/s MJPEG, needle 32 grey levels under noise of 21: 0.9 σ
        // on its path, which the sync then followed to within a frame).
        const NeedleAxis axis = shaftBehindTip(s, p.axis);
        scored.emplace_back(std::max(movingEdgeSnr(s, axis), 3.0) * std::sqrt(p.ridge), axis);
        pathsByChange.emplace_back(p.changeOnPath, scored.back());
    }
    std::sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // The region the operator drew (if any) says where the needle is: lines found in the
    // whole picture (a part of a line is too short to find it reliably) that cross it.
    auto crosses = [&](const NeedleAxis& axis) {
        for (double t = 0; t <= 1.0; t += 0.01)
            if (roi.contains(axis.pointAt(t).toPoint()))
                return true;
        return false;
    };
    if (!roi.isEmpty() && std::any_of(scored.begin(), scored.end(), [&](const auto& c) { return crosses(c.second); })) {
        auto outside = [&](const auto& c) { return !crosses(c.second); };
        scored.erase(std::remove_if(scored.begin(), scored.end(), outside), scored.end());
        shafts.erase(std::remove_if(shafts.begin(), shafts.end(), outside), shafts.end());
    }
    // Refined lines that ended up alike count once.
    std::vector<NeedleAxis> out;
    auto keep = [&](double score, const NeedleAxis& axis, double angle_deg, double distance_px) {
        if (std::any_of(out.begin(), out.end(), [&](const NeedleAxis& o) { return alike(o, axis, angle_deg, distance_px); }))
            return;
        out.push_back(axis);
        if (scores)
            scores->push_back(score);
    };
    for (const auto& [score, axis] : scored)
        if (int(out.size()) < maxCount)
            keep(score, axis, 5.0, 6.0);
    // A line of the ridge, found on a copy a third as wide, may cross a faint shaft at a few
    // degrees, where the line the shaft itself gives lies along it (probe seed 187716 case 15:
    // 3.0° and 0.1° off the needle); both are tracked.
    for (const auto& [score, axis] : shafts)
        keep(score, axis, 1.0, 3.0);
    // The paths with the most change under them are tracked too, when they ranked lower: a
    // faint needle's ridge is low, and the lines across a clock's row of digits rank above it
    // (probe seed 161803 case 0: the needle's path, 192 units of change against about 100 along
    // the clock's row, ranked below 16 lines through the clock and the counter).
    std::sort(pathsByChange.begin(), pathsByChange.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; k < pathsByChange.size() && k < kMostChangePaths; ++k) {
        const auto& [score, axis] = pathsByChange[k].second;
        if (roi.isEmpty() || crosses(axis))
            keep(score, axis, 5.0, 6.0);
    }
    // Burnt-in digits that change outweigh a short path in the sums of change (probe seed 820417
    // case 5: a tip moving ±11 px, the 32 strongest lines of change all through a clock and a
    // counter or along the rows of an MJPEG's blocks, none on the needle). With the patches of
    // change set aside, the three lines of change with a moving edge and the most change on their
    // path that no line kept is alike are tracked too, and so are the short streaks of change
    // (streaksOfChange). Not two: a needle at −92° in a 320x240 MPEG-4 picture with a counter
    // and a clock left a path with 21.5 units of change on it and an edge 7 times its noise,
    // third of the four such lines; no line tracked was the needle, and the sync was 245 frames
    // off (slow-small probe seed 287761 case 14). With the digits set aside, how much a pixel
    // changes says where the path's middle is (refinePath): such a path lies on the needle, and
    // is alike another line only within 1° and 3 px, as the shafts' lines are (slow-small probe
    // seed 5 case 9: a line from the ridge 2.3° off the needle, its track lost; the path's line,
    // 0.2° off, had been dropped as alike it).
    const cv::Mat patches = changingPatches(change);
    PictureChange apart{change.clone(), picture.measured.clone()};
    apart.counted.setTo(0.0f, patches);
    apart.measured.setTo(0.0f, patches);
    std::vector<std::pair<double, std::pair<double, NeedleAxis>>> apartByChange;
    auto addApart = [&](const NeedleAxis& rough, double ridgeThere, double lengthPerWidth) {
        const std::optional<PathLine> path = refinePath(apart.counted, apart.measured, 0.0, rough, s.width, s.height, lengthPerWidth);
        if (!path)
            return;
        const NeedleAxis axis = shaftBehindTip(s, path->axis);
        const double snr = movingEdgeSnr(s, axis);
        if (snr >= 2.0)
            apartByChange.emplace_back(path->changeOnPath, std::pair{snr * std::sqrt(ridgeThere), axis});
    };
    for (const LineCandidate& c : strongestLines(lineSums(apart.counted), 32))
        if (const std::optional<NeedleAxis> rough = clipped(ridgeSums, c))
            addApart(*rough, ridgeUnder(c), kPathLengthPerWidth);
    for (const NeedleAxis& rough : streaksOfChange(apart.counted, s.width, s.height))
        addApart(rough, sumAlong(ridgeSums, rough), kStreakLengthPerWidth);
    std::sort(apartByChange.begin(), apartByChange.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::size_t added = 0;
    for (const auto& [onPath, scoredAxis] : apartByChange) {
        if (added == kMostApartPaths)
            break;
        const std::size_t before = out.size();
        if (roi.isEmpty() || crosses(scoredAxis.second))
            keep(scoredAxis.first, scoredAxis.second, 1.0, 3.0);
        added += out.size() - before;
    }
    return out;
}

std::optional<NeedleAxis> detectNeedleAxis(FrameReader& reader, QRect roi, int sampleFrames)
{
    const std::vector<NeedleAxis> c = needleAxisCandidates(reader, roi, 1, sampleFrames);
    if (c.empty())
        return std::nullopt;
    return c.front();
}

namespace {

// What each sample of a needle strip shows behind the tip and ahead of it (the shaft or what
// it covers, and the picture it has not reached), learnt from sampled frames in which the tip
// was clearly on either side of it; NaN where no side is known.
struct TipSides {
    std::vector<double> behind, ahead;
    double noise = 1.0;  // of the strip's middle, per sample and frame
};

constexpr int kSideClear = 4, kSideFrames = 3;
constexpr std::size_t kSideReach = 32;

// `middles`: the strip's middle in sampled frames; `tips`: the tip found in each.
TipSides learnTipSides(const std::vector<std::vector<double>>& middles, const std::vector<double>& tips)
{
    TipSides s;
    if (middles.empty())
        return s;
    s.noise = robustSigma(middles);
    const std::size_t n = middles.front().size();
    s.behind.assign(n, kNaN);
    s.ahead.assign(n, kNaN);
    std::vector<double> b, a;
    for (std::size_t i = 0; i < n; ++i) {
        b.clear();
        a.clear();
        for (std::size_t k = 0; k < middles.size(); ++k) {
            if (tips[k] > double(i) + kSideClear)
                b.push_back(middles[k][i]);
            else if (tips[k] < double(i) - kSideClear)
                a.push_back(middles[k][i]);
        }
        if (int(b.size()) >= kSideFrames)
            s.behind[i] = median(b);
        if (int(a.size()) >= kSideFrames)
            s.ahead[i] = median(a);
    }
    // Beyond the tip's furthest reach in the sampled frames the shaft was never seen, and
    // short of its nearest the picture without it: there the needle is taken to stand out
    // of what it covers as it does at the nearest sample where both were seen.
    std::vector<double> contrast(n, kNaN);
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(s.behind[i]) && std::isfinite(s.ahead[i]))
            contrast[i] = s.behind[i] - s.ahead[i];
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isfinite(s.behind[i]) == std::isfinite(s.ahead[i]))
            continue;
        double nearest = kNaN;
        for (std::size_t d = 1; d <= kSideReach && !std::isfinite(nearest); ++d) {
            if (i >= d && std::isfinite(contrast[i - d]))
                nearest = contrast[i - d];
            else if (i + d < n && std::isfinite(contrast[i + d]))
                nearest = contrast[i + d];
        }
        if (!std::isfinite(nearest))
            continue;
        if (std::isfinite(s.ahead[i]))
            s.behind[i] = s.ahead[i] + nearest;
        else
            s.ahead[i] = s.behind[i] - nearest;
    }
    return s;
}

// The tip in a window of samples around `centre`, where the shares of the way from ahead to
// behind that its samples have come put it; nullopt where a sample barely changes with the
// tip or is not known on either side. `framed`: the window begins behind the tip and ends
// ahead of it.
constexpr int kRefineWindow = 8;
struct Shares {
    double at = kNaN;
    bool framed = false;
};

std::optional<Shares> sharesAround(const TipSides& sides, const std::vector<double>& middle, double centre)
{
    const int n = int(middle.size());
    const int lo = int(std::lround(centre)) - kRefineWindow, hi = int(std::lround(centre)) + kRefineWindow;
    if (lo < 0 || hi >= n)
        return std::nullopt;
    constexpr int quarter = kRefineWindow / 2;
    double sum = 0.0, first = 0.0, last = 0.0;
    for (int i = lo; i <= hi; ++i) {
        const double b = sides.behind[std::size_t(i)], a = sides.ahead[std::size_t(i)];
        if (!std::isfinite(b) || !std::isfinite(a) || std::abs(b - a) < 4.0 * sides.noise)
            return std::nullopt;
        const double share = std::clamp((middle[std::size_t(i)] - a) / (b - a), -0.5, 1.5);
        sum += share;
        if (i < lo + quarter)
            first += share / quarter;
        else if (i > hi - quarter)
            last += share / quarter;
    }
    return Shares{double(lo) - 0.5 + sum, first > 0.7 && last < 0.3};
}

// The tip found at `rough` in `middle`, measured again against what the strip shows on either
// side of a tip: the share of the way from ahead to behind that each sample has come, summed
// over a window, is how far into the window the tip stands. The edge detector's own peak is
// pulled by a textured background to the nearest of its edges (grain of 4 px, 12 grey levels,
// under a needle 35 bright: up to 6 px off, by position, the same at every pass); the shares
// are not, since the background is in both references. The window is moved onto what it
// measured until it reads as behind, then ahead; `rough` where it cannot be.
double tipAgainstSides(const TipSides& sides, const std::vector<double>& middle, double rough)
{
    if (sides.behind.size() != middle.size())
        return rough;
    double at = rough;
    for (int pass = 0; pass < 4; ++pass) {
        const std::optional<Shares> next = sharesAround(sides, middle, at);
        if (!next)
            return rough;
        const double moved = std::abs(next->at - at);
        at = next->at;
        if (std::abs(at - rough) > kRefineWindow)
            return rough;
        // Two windows a sample apart may read a tenth of a pixel apart, by turns.
        if (next->framed && moved < 0.5)
            return at;
    }
    return rough;
}

// The samples of a strip not to read, asked for as the stretch `stretch` (in samples): that
// stretch, widened over the samples either side whose edge response changes from one sampled
// frame to the next (`g`) more than twice as much as the strip's usually does, and then by a
// tip's reach. What held a track there may reach further: a counter's other digits, whose
// edges held it again just past a stretch of one digit (probe seed 577215 case 14).
std::vector<char> unreadAbout(const AxisStretch& stretch, const std::vector<std::vector<double>>& g)
{
    const int n = g.empty() ? 0 : int(g.front().size());
    std::vector<double> spread(std::size_t(n), 0.0), column;
    for (int i = kStep; i < n - kStep; ++i) {
        column.clear();
        for (const std::vector<double>& frame : g)
            column.push_back(frame[std::size_t(i)]);
        const double middle = median(column);
        for (double& v : column)
            v = std::abs(v - middle);
        spread[std::size_t(i)] = median(column);
    }
    const double usual = median(std::vector<double>(spread.begin() + std::min(n, kStep), spread.end() - std::min(n, kStep)));
    auto changing = [&](int i) { return i >= 0 && i < n && spread[std::size_t(i)] > 2.0 * usual; };
    int from = std::clamp(int(std::floor(stretch.from_px)), 0, n), to = std::clamp(int(std::ceil(stretch.to_px)), -1, n - 1);
    while (changing(from - 1))
        --from;
    while (changing(to + 1))
        ++to;
    std::vector<char> out(std::size_t(n), 0);
    for (int i = std::max(0, from - int(kAwayFromTip)); i <= std::min(n - 1, to + int(kAwayFromTip)); ++i)
        out[std::size_t(i)] = 1;
    return out;
}

// One axis being tracked: its strip, what is always there, the noise and the tip's sign.
struct AxisTracker {
    NeedleStrip strip;
    std::vector<double> still;
    std::vector<double> background;  // of the strip's shaft profile (shaftBackground)
    double sigma = 1.0;
    int polarity = 1;
    bool gated = false;  // the tip is where a shaft ends (TipModel)
    double frame_s = 1.0 / 30.0;  // the video's usual frame interval
    double last = kNaN;  // last tip position (profile samples)
    double lastTime_s = kNaN;
    double velocity = 0.0;  // profile samples per second, over the last few sightings
    int lost = 0;        // frames since it was last seen
    std::vector<double> strengths;
    std::vector<double> slopes;  // grey levels per sample along the middle at each decided tip
    std::vector<std::pair<double, double>> recent;  // (time, position) of the last sightings in a row
    TipSides sides;

    NeedleAxis axis;  // as given, or turned to point from the shaft to the tip

    AxisTracker(const NeedleAxis& given, const FrameSamples& s, double frameDuration_s, const std::optional<AxisStretch>& notRead)
        : strip(given, s.width, s.height), frame_s(frameDuration_s > 0 ? frameDuration_s : 1.0 / 30.0), axis(given)
    {
        if (strip.length < 20)
            return;
        std::vector<StripProfile> profiles = sampleStrip(strip, s);
        std::optional<AxisStretch> blind = notRead;
        // A line drawn by the operator may point either way (found ones are turned already).
        if (shaftFromFarEnd(profiles)) {
            axis = NeedleAxis(given.p2(), given.p1());
            strip = NeedleStrip(axis, s.width, s.height);
            profiles = sampleStrip(strip, s);
            if (blind)
                blind = AxisStretch{given.length() - blind->to_px, given.length() - blind->from_px};
        }
        std::vector<std::vector<double>> g;
        for (const StripProfile& p : profiles)
            g.push_back(gradient(p.middle));
        withoutNoisierFrames(profiles, g);
        if (blind)
            unread = unreadAbout({blind->from_px - strip.origin, blind->to_px - strip.origin}, g);
        sigma = robustSigma(g);
        TipModel model = tipModel(profiles, g, sigma);
        polarity = model.polarity;
        gated = model.gated;
        still = unreadWhereAsked(std::move(model.still));
        auto tipsSeen = [&] {
            std::vector<double> at(profiles.size(), kNaN);
            for (std::size_t k = 0; k < profiles.size(); ++k) {
                const Peak p = findTip(g[k], profiles[k].shaft, still, polarity, gated, sigma);
                if (std::isfinite(p.position) && p.strength > 5.0 * sigma)
                    at[k] = p.position;
            }
            return at;
        };
        const std::vector<double> firstSeenAt = tipsSeen();
        still = unreadWhereAsked(staticPartAwayFromTips(g, polarity, firstSeenAt, std::move(still)));
        background = shaftBackground(profiles, firstSeenAt);
        for (StripProfile& p : profiles)
            withoutBackground(p);
        std::vector<std::vector<double>> middles;
        std::vector<double> tips;
        const std::vector<double> seenAt = tipsSeen();
        for (std::size_t k = 0; k < profiles.size(); ++k)
            if (std::isfinite(seenAt[k])) {
                tips.push_back(seenAt[k]);
                middles.push_back(profiles[k].middle);
            }
        sides = learnTipSides(middles, tips);
        // The edge detector's tips are pulled by a textured background (probe seed 246810
        // case 6: 2.9 px behind the truth at rest, 0.6 px ahead while moving), and sides
        // learnt from them take some of the shaft for the picture ahead of it where the tip
        // rests: measured against them, the tip read 0.9 px behind at rest and 0.1 px ahead
        // while moving, and the sync was 1.2 frames off. Learnt again from the tips measured
        // against them, they are not (one pass; a second moves the tips by hundredths).
        for (std::size_t k = 0; k < tips.size(); ++k)
            tips[k] = tipAgainstSides(sides, middles[k], tips[k]);
        sides = learnTipSides(middles, tips);
        course = TipPath(strip.length, 48, frame_s);
        everyFrame.emplace(still, sigma);
    }

    // FrameSamples where the caller asked for no tip to be read: nothing there stands above what is
    // always there (+inf), so no tip is found and the course gains nothing there.
    std::vector<char> unread;
    std::vector<double> unreadWhereAsked(std::vector<double> stillEdges) const
    {
        for (std::size_t i = 0; i < unread.size() && i < stillEdges.size(); ++i)
            if (unread[i])
                stillEdges[i] = std::numeric_limits<double>::infinity();
        return stillEdges;
    }

    void withoutBackground(StripProfile& p) const
    {
        if (p.shaft.size() == background.size())
            for (std::size_t i = 0; i < background.size(); ++i)
                p.shaft[i] -= background[i];
    }

    // How strong the tip's edge has been lately. In a clean picture the noise is a fraction
    // of a grey level and coding artefacts along the shaft (block edges, ringing) stand
    // many σ out of it; the tip stands out far more. A tip hidden for long may come back
    // fainter (other background), so the memory fades while it is lost.
    double typicalStrength() const
    {
        if (strengths.size() < 5)
            return 0.0;
        const std::size_t k = std::min<std::size_t>(strengths.size(), 25);
        const double m = median(std::vector<double>(strengths.end() - std::ptrdiff_t(k), strengths.end()));
        return lost > 8 ? m * std::pow(0.9, lost - 8) : m;
    }

    // The tip in this frame: searched near where it should be by now (a faint tip in heavy
    // noise beats the noise nearby more easily than the noise of the whole line), everywhere
    // when it has been lost for a while. A fast needle moves further between two frames than
    // the search reaches around its last place, so the search follows its velocity.
    // NaN when no edge stands clearly out of the noise and like the tip seen so far.
    // `repeated`: the index calls the picture a repeat of the one before; taken only when
    // the tip has not moved either (the index judges the whole picture, in which a thin
    // needle is a few hundred pixels: a clean, smoothly coded video of a fast needle gets
    // most frames flagged).
    // The tip as the edge detector found it, and measured against the strip's sides.
    struct Sighting {
        double found = kNaN, measured = kNaN;
        double strength = 0.0;  // of the edge found, in grey levels
    };

    // One frame, kept until the tip's course decides where the tip was in it.
    struct Seen {
        StripProfile profile;
        std::vector<double> g;
        Sighting sighting;
    };
    TipPath course{1};
    std::deque<Seen> undecided;

    // What is always there, learnt again over every frame as it is decided (static_edges.h says
    // why), and each decided frame's edge response about its tip, to read the tip there again
    // against it at the end.
    struct AboutTip {
        int peak = -1;  // the sample the tip was read at; -1 when none was
        std::array<float, 5> edge{};  // in the tip's sign, samples peak-2 ... peak+2
    };
    std::optional<StaticEdges> everyFrame;
    std::vector<AboutTip> aboutTips;

    Sighting decideAndLearn(const Seen& seen, int at)
    {
        const Sighting tip = decide(seen, at);
        double slope = kNaN;
        if (std::isfinite(tip.found)) {
            const std::size_t p = std::size_t(std::lround(std::max(0.0, tip.found)));
            const std::vector<double>& m = seen.profile.middle;
            if (p >= 1 && p + 1 < m.size())
                slope = 0.5 * std::abs(m[p + 1] - m[p - 1]);
        }
        slopes.push_back(slope);
        AboutTip about;
        if (everyFrame && std::isfinite(tip.found)) {
            everyFrame->add(seen.g, polarity, tip.found, kAwayFromTip);
            const int peak = int(std::lround(tip.found));
            if (peak >= 2 && peak + 2 < int(seen.g.size())) {
                about.peak = peak;
                for (int j = -2; j <= 2; ++j)
                    about.edge[std::size_t(j + 2)] = float(polarity * seen.g[std::size_t(peak + j)]);
            }
        }
        aboutTips.push_back(about);
        return tip;
    }

    // The tips decided, `found` (one per decided frame, in order, along the axis: the strip's
    // samples plus `origin`), read again at the end against what is always there as every frame
    // shows it: the peak within a sample of where it was read, to a fraction of a sample as before.
    void readAgain(std::vector<double>& found, double origin) const
    {
        if (!everyFrame || found.size() != aboutTips.size())
            return;
        const std::vector<double> floor = everyFrame->estimate(int(kFramesAway));
        const int n = int(floor.size());
        for (std::size_t k = 0; k < found.size(); ++k) {
            const AboutTip& about = aboutTips[k];
            if (about.peak < 0 || !std::isfinite(found[k]))
                continue;
            auto v = [&](int j) { return double(about.edge[std::size_t(j + 2)]) - floor[std::size_t(about.peak + j)]; };
            int best = 0;
            for (int j : {-1, 1})
                if (v(j) > v(best))
                    best = j;
            const int b = about.peak + best;
            if (cutOffAtEnd(b, n))
                continue;
            found[k] = origin + double(b) + peakOffset(v(best - 1), v(best), v(best + 1));
        }
    }

    // Each frame is looked at on its own (locate), and the tip's course through the frames
    // (TipPath) says where it was a few dozen frames later (decide). Returns the frame decided
    // by this one, the frames in order.
    std::optional<Sighting> next(const cv::Mat& gray, double time_s, bool repeated)
    {
        Seen seen;
        seen.profile = strip.sample(gray);
        withoutBackground(seen.profile);
        seen.g = gradient(seen.profile.middle);
        seen.sighting = locate(seen.profile, seen.g, time_s, repeated);
        const std::optional<int> at = course.push(edgeScores(seen));
        undecided.push_back(std::move(seen));
        if (!at)
            return std::nullopt;
        const Sighting decided = decideAndLearn(undecided.front(), *at);
        undecided.pop_front();
        return decided;
    }

    // The frames still undecided at the end of the video.
    std::vector<Sighting> rest()
    {
        std::vector<Sighting> out;
        for (int at : course.finish()) {
            out.push_back(decideAndLearn(undecided.front(), at));
            undecided.pop_front();
        }
        return out;
    }

    // How much each sample of one frame looks like the tip, in units of the noise: an edge
    // above what is always there, and where a shaft is seen, as far as the shaft ends there.
    // Where the frame alone shows the tip clearly, its course passes near it (within what a
    // textured background pulls the edge detector, 8 samples): the course counts no frame for
    // more than TipPath::kScoreCap, and the changing digits of a frame counter on the line
    // score as high in every frame (probe seed 531911 case 6: the course sat on them in 337 of
    // 584 frames, the tip 6 σ and more in 534). Away from it a sample scores the least a frame
    // can, however strong its edge; not a hard bound: on a line with no needle, what stands
    // out in single frames jumps about faster than any course.
    std::vector<double> edgeScores(const Seen& seen) const
    {
        std::vector<double> out(seen.g.size(), 0.0);
        const bool clear = clearlySeen(seen.sighting);
        for (std::size_t i = 2; i + 3 < seen.g.size(); ++i) {
            if (clear && std::abs(double(i) - seen.sighting.found) > 8.0)
                continue;  // set below; the gate's medians were a tenth of a sync's time
            const double v = polarity * seen.g[i] - still[i];
            // The gate only lowers a score, and below 1 σ it changes little.
            out[i] = (gated && v > sigma ? gatedStrength(seen.profile.shaft, polarity, sigma, int(i), v) : v) / sigma;
        }
        if (clear)
            for (std::size_t i = 0; i < out.size(); ++i)
                if (std::abs(double(i) - seen.sighting.found) > 8.0)
                    out[i] = -TipPath::kScoreCap;
        return out;
    }

    // An edge no noise along the strip makes (its strongest is about 3 σ).
    bool clearlySeen(const Sighting& s) const { return std::isfinite(s.found) && s.strength >= 6.0 * sigma; }

    // Whether the course passed within 3 samples of the tip, in the last frames that showed
    // the tip clearly on their own (at most 50).
    std::deque<bool> courseAgreed;

    // The tip in a frame, given where its course through the frames puts it (`at`, in whole
    // samples). A faint tip in heavy noise (2-3 σ, an edge of noise elsewhere on the strip as
    // high) is lost or mistaken in many frames looked at alone, and its course finds it (probe
    // seed 4711 case 8: 93 of 283 frames masked along the true line, the sync off). An edge
    // found alone is kept where it is clear or where the course agrees; else the edge on the
    // course, where it stands 2 σ out of the noise, as long as the course has kept to the
    // tip where it was clear. A tip may move faster than the course's velocities (16 samples
    // a frame at 30 frames/s), and there the course is noise.
    Sighting decide(const Seen& seen, int at)
    {
        const Sighting& alone = seen.sighting;
        const Peak onCourse = findTip(seen.g, seen.profile.shaft, still, polarity, gated, sigma, at - 2, at + 2);
        const bool agree = std::isfinite(alone.found) && std::abs(alone.found - onCourse.position) <= 3.0;
        if (clearlySeen(alone)) {
            courseAgreed.push_back(agree);
            if (courseAgreed.size() > 50)
                courseAgreed.pop_front();
            return alone;
        }
        const auto agreed = std::count(courseAgreed.begin(), courseAgreed.end(), true);
        const bool trusted = courseAgreed.size() < 5 || double(agreed) >= 0.8 * double(courseAgreed.size());
        if (agree || !trusted)
            return alone;
        if (!std::isfinite(onCourse.position) || !(onCourse.strength >= 2.0 * sigma))
            return {};
        return {onCourse.position, tipAgainstSides(sides, seen.profile.middle, onCourse.position), onCourse.strength};
    }

    Sighting locate(const StripProfile& profile, const std::vector<double>& g, double time_s, bool repeated)
    {
        const int n = int(g.size());
        int lo = 2, hi = n - 3;
        const bool near = std::isfinite(last) && lost < 8;
        if (near) {
            const double ahead = std::isfinite(lastTime_s) ? velocity * (time_s - lastTime_s) : 0.0;
            const double expected = last + ahead;
            const double w = 24 + 8 * lost + 0.5 * std::abs(ahead);
            lo = std::clamp(int(expected - w), 2, n - 3);
            hi = std::clamp(int(expected + w), 2, n - 3);
        }
        const Peak tip = findTip(g, profile.shaft, still, polarity, gated, sigma, lo, hi);
        const double bestV = tip.strength;
        const double needed = std::max((near ? 3.5 : 5.0) * sigma, 0.25 * typicalStrength() * sigma);
        if (!std::isfinite(tip.position) || !(bestV > needed)) {
            ++lost;
            if (lost >= 8) {
                velocity = 0.0;
                recent.clear();
            }
            return {};
        }
        strengths.push_back(bestV / sigma);
        const double found = tip.position;
        const bool repeat = repeated && std::isfinite(last) && std::abs(found - last) < 0.5;
        if (!repeat)
            updateVelocity(time_s, found);
        last = found;
        lastTime_s = time_s;
        lost = 0;
        return {found, tipAgainstSides(sides, profile.middle, found), bestV};
    }

    // The velocity as the straight line through the last few sightings, not from the last
    // two alone: a variable-rate file's timestamps may sit a millisecond apart for frames a
    // frame apart (a writer's rounding), and two such points make any velocity.
    void updateVelocity(double time_s, double found)
    {
        recent.emplace_back(time_s, found);
        while (recent.size() > 4 || (recent.size() > 1 && time_s - recent.front().first > 0.3))
            recent.erase(recent.begin());
        const double span = recent.back().first - recent.front().first;
        if (recent.size() < 2 || span < 0.5 * frame_s) {
            velocity = 0.0;
            return;
        }
        double mt = 0, mx = 0;
        for (const auto& [t, x] : recent) {
            mt += t;
            mx += x;
        }
        mt /= double(recent.size());
        mx /= double(recent.size());
        double stt = 0, stx = 0;
        for (const auto& [t, x] : recent) {
            stt += (t - mt) * (t - mt);
            stx += (t - mt) * (x - mx);
        }
        // The line lags a needle that speeds up; the newest step says where it is going.
        const double fitted = stt > 0 ? stx / stt : 0.0;
        const auto& p = recent[recent.size() - 2];
        const double dt = time_s - p.first;
        velocity = dt >= 0.5 * frame_s ? 0.5 * (fitted + (found - p.second) / dt) : fitted;
    }
};

// How much a track `d` scatters about its own smooth course while the tip moves (by more than
// 3 px over the 7 frames around, by `course`): the median distance of each such point from the
// quadratic through it and its three neighbours on either side (Savitzky-Golay, 7 points).
// Infinite when there is no such point. At rest a texture pulls the edge detector the same way
// in every frame, so only the moving frames tell a steady track from one the texture bends.
double jitterWhileMoving(const std::vector<double>& d, const std::vector<double>& course)
{
    static constexpr std::array<double, 7> kSmooth{-2.0 / 21, 3.0 / 21, 6.0 / 21, 7.0 / 21, 6.0 / 21, 3.0 / 21, -2.0 / 21};
    std::vector<double> off;
    for (std::size_t k = 3; k + 3 < d.size(); ++k) {
        if (!(std::abs(course[k + 3] - course[k - 3]) > 3.0))
            continue;
        double smooth = 0.0;
        for (std::size_t j = 0; j < kSmooth.size(); ++j)
            smooth += kSmooth[j] * d[k + j - 3];
        if (std::isfinite(smooth))
            off.push_back(std::abs(d[k] - smooth));
    }
    return off.empty() ? std::numeric_limits<double>::infinity() : median(off);
}

// Isolated jumps (a noise peak elsewhere on the strip) against their neighbours: masked.
// What the neighbours say a point should be is the median of three guesses in time (the
// line through the nearest point on each side, and each side's two nearest extended), so
// that a needle moving many pixels a frame is no jump and one bad neighbour does not decide.
void maskJumps(const std::vector<double>& t, std::vector<double>& d)
{
    std::vector<std::size_t> finite;
    for (std::size_t i = 0; i < d.size(); ++i)
        if (std::isfinite(d[i]))
            finite.push_back(i);
    std::vector<double> cleaned = d;
    auto line = [&](std::size_t a, std::size_t b, double at) {
        const double dt = t[b] - t[a];
        return std::abs(dt) > 1e-9 ? d[a] + (d[b] - d[a]) * (at - t[a]) / dt : 0.5 * (d[a] + d[b]);
    };
    for (std::size_t k = 2; k + 2 < finite.size(); ++k) {
        const std::size_t i = finite[k];
        const std::size_t p1 = finite[k - 1], p2 = finite[k - 2], n1 = finite[k + 1], n2 = finite[k + 2];
        // Neighbours far away in time say little about this frame.
        if (t[n1] - t[p1] > 0.5)
            continue;
        const double guess = median({line(p1, n1, t[i]), line(p2, p1, t[i]), line(n1, n2, t[i])});
        const double step = std::max(std::abs(d[n1] - d[i]), std::abs(d[i] - d[p1]));
        const double sideSteps = std::min(std::abs(d[p1] - d[p2]), std::abs(d[n2] - d[n1]));
        // A jump leaves both neighbours far behind while they move little themselves.
        if (std::abs(d[i] - guess) > 10.0 + sideSteps && step > 10.0 + sideSteps)
            cleaned[i] = kNaN;
    }
    d = cleaned;
}

}  // namespace

std::vector<std::optional<NeedleAxis>> settledOnFaintShafts(const FrameSamples& s, const std::vector<NeedleAxis>& axes)
{
    const cv::Mat mean = framesMean(s);
    std::vector<std::optional<NeedleAxis>> out;
    for (const NeedleAxis& axis : axes) {
        const NeedleAxis loose = settleOnShaft(mean, axis, 3.0);
        if (settleOnShaft(mean, axis) == axis && loose != axis)
            out.emplace_back(loose);
        else
            out.emplace_back();
    }
    return out;
}

std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress, const std::atomic_bool* cancel,
                                      const std::vector<std::optional<AxisStretch>>& notRead)
{
    return trackNeedles(reader, sampleFrames(reader, 40), axes, progress, cancel, notRead);
}

std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const FrameSamples& s, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress, const std::atomic_bool* cancel,
                                      const std::vector<std::optional<AxisStretch>>& notRead)
{
    const FrameIndex& index = reader.index();
    const cv::Mat mean = framesMean(s);
    std::vector<AxisTracker> trackers;
    std::vector<NeedleTrack> out(axes.size());
    std::vector<std::vector<double>> measured(axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) {
        trackers.emplace_back(settleOnShaft(mean, axes[a]), s, index.frameDuration(),
                              a < notRead.size() ? notRead[a] : std::nullopt);
        if (trackers.back().strip.length < 20)
            throw VideoError(index.path, nb::TrDevices::tr("the needle line lies outside the picture"));
        out[a].axis = trackers.back().axis;
    }
    // A frame's tip, once decided, along the axis from its p1.
    auto record = [&](std::size_t a, const AxisTracker::Sighting& tip) {
        out[a].displacement_px.push_back(tip.found + trackers[a].strip.origin);
        measured[a].push_back(tip.measured + trackers[a].strip.origin);
    };
    const int first = s.span.first, n = s.span.last + 1;
    PictureMemoryMeter memory;
    for (int i = first; i < n && !(cancel && cancel->load()); ++i) {
        // Frames the index calls duplicates are tracked too, at their own time: a slow
        // needle in a clean, smoothly coded picture changes too little between frames to
        // tell from a repeat (whole runs of frames get flagged), and a real repeat only shows
        // its tip one frame late, which the fit over all frames absorbs.
        const FrameInfo& info = index.frames[std::size_t(i)];
        const std::optional<cv::Mat> shown = reader.grayUnlessDamaged(i);
        if (!shown) {
            for (NeedleTrack& t : out)
                ++t.damaged;
            continue;  // in a damaged stretch of the file: left out, as a dropped frame
        }
        const cv::Mat& gray = *shown;
        memory.add(gray);
        for (std::size_t a = 0; a < axes.size(); ++a) {
            out[a].time_s.push_back(info.time_s);
            if (const std::optional<AxisTracker::Sighting> tip = trackers[a].next(gray, info.time_s, info.duplicate))
                record(a, *tip);
        }
        if (progress && (i - first) % 50 == 0)
            progress(i - first, n - first);
    }
    for (std::size_t a = 0; a < axes.size(); ++a) {
        for (const AxisTracker::Sighting& tip : trackers[a].rest())
            record(a, tip);
        trackers[a].readAgain(out[a].displacement_px, trackers[a].strip.origin);
        maskJumps(out[a].time_s, out[a].displacement_px);
        maskJumps(out[a].time_s, measured[a]);
        // Measured against the strip's sides, the tip is freed of a still texture's pull (probe
        // seed 4711, two linear strokes on grain: 0.36 and 0.38 px of scatter against 0.47 and
        // 0.43), but where the picture ahead of it moves (the simulator's imaging view, tissue
        // the needle pushes along) the sides do not hold and the measure scatters (0.29
        // against 0.23; 1.1 px from the truth against 0.29): the clearly steadier is kept.
        const std::vector<double>& found = out[a].displacement_px;
        if (jitterWhileMoving(measured[a], found) < 0.9 * jitterWhileMoving(found, found))
            out[a].displacement_px = std::move(measured[a]);
        const auto& d = out[a].displacement_px;
        out[a].masked = int(std::count_if(d.begin(), d.end(), [](double v) { return !std::isfinite(v); }));
        out[a].edgeSnr = median(trackers[a].strengths);
        out[a].coding = memory.coding();
        std::vector<double> moving;
        const auto& sl = trackers[a].slopes;
        for (std::size_t k = 2; k + 2 < d.size() && k < sl.size(); ++k)
            if (std::isfinite(sl[k]) && std::isfinite(d[k - 2]) && std::isfinite(d[k + 2]) && std::abs(d[k + 2] - d[k - 2]) >= 1.0)
                moving.push_back(sl[k]);
        if (moving.size() >= 10)
            out[a].coding.edgeSlope_grey_per_px = median(moving);
    }
    return out;
}

NeedleTrack trackNeedle(FrameReader& reader, const NeedleAxis& axis, const std::function<void(int, int)>& progress,
                        const std::atomic_bool* cancel)
{
    return trackNeedles(reader, {axis}, progress, cancel).front();
}

}  // namespace nb::video
