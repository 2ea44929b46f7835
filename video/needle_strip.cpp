#include "needle_strip.h"

#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>

namespace nb::video::strip {

double median(std::vector<double> v) { return medianInPlace(v.begin(), v.end()); }

Strip::Strip(const NeedleAxis& axis, int width, int height, int halfWidth, double sideOffset, QRect within)
{
    const double len = axis.length();
    if (len < 2.0)
        return;
    const double ux = (axis.x2() - axis.x1()) / len, uy = (axis.y2() - axis.y1()) / len;
    const double nx = -uy, ny = ux;
    // Extend the line across the whole picture (or region): the tip may travel past the drawn ends.
    const QRect bounds = within.isEmpty() ? QRect(0, 0, width, height) : within & QRect(0, 0, width, height);
    double s0 = -1e9, s1 = 1e9;
    auto clip = [&](double p, double d, double lo, double hi) {
        if (std::abs(d) < 1e-9) {
            if (p < lo || p > hi)
                s1 = s0;  // parallel to two of the bounds, outside them: nothing to sample
            return;
        }
        double a = (lo - p) / d, b = (hi - p) / d;
        if (a > b)
            std::swap(a, b);
        s0 = std::max(s0, a);
        s1 = std::min(s1, b);
    };
    clip(axis.x1(), ux, bounds.left(), bounds.right());
    clip(axis.y1(), uy, bounds.top(), bounds.bottom());
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

std::vector<double> Strip::profile(const cv::Mat& gray, double smoothing_px) const
{
    cv::Mat sampled, column;
    cv::remap(gray, sampled, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    sampled.convertTo(sampled, CV_32F);
    cv::reduce(sampled, column, 0, cv::REDUCE_AVG);
    if (smoothing_px > 0)
        cv::GaussianBlur(column, column, cv::Size(0, 0), smoothing_px, 0.1);
    return std::vector<double>(column.begin<float>(), column.end<float>());
}

StripProfile NeedleStrip::sample(const cv::Mat& gray, double smoothing_px) const
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

namespace {

// The value `k` values from the lowest of `v` (reordered).
double atRank(std::vector<double>& v, std::size_t k)
{
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

// The low (15 %) percentile of `column` (reordered).
double lowPercentile(std::vector<double>& column) { return atRank(column, column.size() * 15 / 100); }

}  // namespace

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

namespace {

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

}  // namespace

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
             bool gated, double sigma, int lo, int hi)
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

namespace {

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

}  // namespace

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

TipModel tipModel(const std::vector<StripProfile>& profiles, const std::vector<std::vector<double>>& g, double sigma, int shaft)
{
    TipModel m;
    if (shaft == 0)
        shaft = shaftSign(profiles);
    if (shaft != 0) {
        m.shaftSeen = true;
        m.polarity = shaft > 0 ? -1 : 1;
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

ShaftAtEnds shaftAtEnds(const StripProfile& raw, int shaftSign)
{
    const int n = int(raw.shaft.size());
    // To the strip's very end: a tip beyond the last sample it is read at (cutOffAtEnd) but
    // inside the picture is cut off, not out of it.
    const int end = n - 2, from = end - kShaftBehind;
    if (shaftSign == 0 || from < n / 4 + kShaftBehind)
        return {};
    // The first quarter by its median (a clock's digits may cover some of it), the last stretch
    // by its quarter point: a tip on it leaves part of it without shaft.
    auto quantileOf = [&](int a, int b, double q) {
        std::vector<double> v;
        for (int i = a; i < b; ++i)
            v.push_back(shaftSign * raw.shaft[std::size_t(i)]);
        return atRank(v, std::size_t(q * double(v.size() - 1)));
    };
    return {quantileOf(0, n / 4, 0.5), quantileOf(from, end, 0.25)};
}

bool shaftReachesEnd(const ShaftAtEnds& frame, const UsualAtEnd& usual)
{
    return frame.start > 0.0 && frame.end - usual.floor >= std::max(0.5 * frame.start, usual.margin);
}

UsualAtEnd usualShaftAtEnd(const std::vector<ShaftAtEnds>& frames)
{
    std::vector<double> ends;
    for (const ShaftAtEnds& f : frames)
        if (std::isfinite(f.end))
            ends.push_back(f.end);
    if (ends.empty())
        return {};
    const double floor = atRank(ends, ends.size() / 10), quarter = atRank(ends, ends.size() / 4);
    // The noise from the lower frames alone (the tip may be beyond the end in half of them):
    // from the tenth percentile to the quarter point is 0.61 σ, and 8 times that lies 3.6 σ
    // above the noise's mean. Less, and a faint shaft's frames on coarse grain (45 over noise
    // 15, grain 25) were taken for a shaft that runs on, the tip lost through a long rest.
    return {floor, 8.0 * (quarter - floor)};
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

}  // namespace nb::video::strip
