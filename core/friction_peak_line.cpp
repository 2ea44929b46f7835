#include "friction_peak_line.h"

#include "statistics.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

// Just past the top speed: close enough that the tissue has not begun to move back (its
// spring-back grows with the deceleration, near zero here), wide enough to average noise.
constexpr double kNearTop = 0.98;
// The samples a little slower than that, still slowing down, tell whether it had come to rest.
constexpr double kSlowerAfter = 0.90;
constexpr std::size_t kMinSamples = 5;
// The rest's two quarters may differ by this much of the force besides the noise.
constexpr double kFlat = 0.005;
// Peak speeds closer than this ratio do not make a line.
constexpr double kMinSpeedRatio = 1.2;

struct LineFit {
    double intercept = 0.0, slope = 0.0, seIntercept = 0.0, seSlope = 0.0;
};

std::optional<LineFit> fitLine(const std::vector<double>& x, const std::vector<double>& y)
{
    const std::size_t n = x.size();
    if (n < 2)
        return std::nullopt;
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= double(n);
    my /= double(n);
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (!(sxx > 0.0))
        return std::nullopt;
    LineFit l;
    l.slope = sxy / sxx;
    l.intercept = my - l.slope * mx;
    if (n > 2) {
        double rss = 0;
        for (std::size_t i = 0; i < n; ++i)
            rss += std::pow(y[i] - l.intercept - l.slope * x[i], 2);
        const double s2 = rss / double(n - 2);
        l.seSlope = std::sqrt(s2 / sxx);
        l.seIntercept = std::sqrt(s2 * (1.0 / double(n) + mx * mx / sxx));
    }
    return l;
}

// The window round each top is a stretch of consecutive samples (a stroke); the tissue may
// still be arriving at the plate in its first part (it reaches the plate at the top speed:
// liver 3 with a 2.5 mm gap, the force 5.7 mN short there and settling 10-30 ms on). The
// later half in time of every stretch is the rest; it is flat when its two quarters agree
// (pooled over the strokes), else the force is still rising (arriving) or falling (a
// break-away of tissue carried through the top).
struct TopTail {
    std::vector<double> rest;          // the force less b times the speed, over the later halves
    std::vector<std::size_t> samples;  // theirs
    // Medians: a stroke cut short at the run's end (one sample, far off) must not count.
    double quarterMedians[2] = {0.0, 0.0};
    std::size_t quarterCounts[2] = {0, 0};
};

template <typename Residual>
TopTail settledTail(const std::vector<std::size_t>& window, int gap, Residual residual)
{
    TopTail tail;
    std::vector<double> quarter[2];
    std::size_t first = 0;
    for (std::size_t k = 1; k <= window.size(); ++k) {
        // Samples apart by less than the smoothing window belong to one stroke: the
        // acceleration's sign flickers at a flat top.
        if (k < window.size() && window[k] - window[k - 1] <= std::size_t(gap))
            continue;
        const double from = double(window[first]), to = double(window[k - 1]);
        const double half = (from + to) / 2.0, threeQuarters = (half + to) / 2.0;
        for (std::size_t j = first; j < k; ++j) {
            const double at = double(window[j]);
            if (at < half)
                continue;
            const double r = residual(window[j]);
            tail.rest.push_back(r);
            tail.samples.push_back(window[j]);
            quarter[at < threeQuarters ? 0 : 1].push_back(r);
        }
        first = k;
    }
    for (int q : {0, 1}) {
        tail.quarterCounts[q] = quarter[q].size();
        tail.quarterMedians[q] = median(quarter[q]);
    }
    return tail;
}

}  // namespace

RunPeaks peakPoints(const ConditionedSignals& c, const FrictionOptions& options, const FrictionFit& fit)
{
    RunPeaks peaks;
    const std::size_t n = c.v_m_s.size();
    const std::size_t trim = std::size_t(std::max(0, options.trimSamples));
    if (n < 2 * trim + 20)
        return peaks;
    const int w = std::max(1, c.window);
    const std::vector<double>& v = c.v_m_s;
    const std::vector<double>& a = c.a_m_s2;
    const std::vector<double>& f = c.force_N;
    const double mass = options.estimateMass ? 0.0 : options.mass_kg;
    const double noise_N = c.noise_N;

    for (int sign : {1, -1}) {
        const std::optional<double> fastest = topSpeed(v, sign, trim, n - trim, 10 * kMinSamples);
        if (!fastest)
            continue;
        const double arriving = sign > 0 ? fit.arrivingAboveP_m_s : fit.arrivingAboveN_m_s;
        const double top = std::min(*fastest, arriving);
        // The sliding slope takes the needle's own slowing out of the force over the window
        // (liver 3 at 0.66 Hz: 11 mN across it), so that what is left is flat once at rest.
        const double slope = sign > 0 ? fit.model.bp_Ns_per_m : fit.model.bn_Ns_per_m;
        const double b = std::isfinite(slope) && slope > 0.0 ? slope : 0.0;
        double sumAfter = 0;
        std::size_t after = 0;
        std::vector<std::size_t> window;
        for (std::size_t i = trim; i < n - trim; ++i) {
            if (v[i] * a[i] > 0.0 || sign * v[i] < kSlowerAfter * top || sign * v[i] > arriving)
                continue;
            if (sign * v[i] < kNearTop * top) {
                sumAfter += f[i] - mass * a[i];
                ++after;
                continue;
            }
            window.push_back(i);
        }
        if (window.size() < kMinSamples || after < kMinSamples || !std::isfinite(sumAfter))
            continue;
        const TopTail tail = settledTail(window, w, [&](std::size_t i) { return sign * (f[i] - mass * a[i]) - b * std::fabs(v[i]); });
        if (tail.rest.size() < kMinSamples)
            continue;
        double sumV = 0;
        for (std::size_t i : tail.samples)
            sumV += std::fabs(v[i]);
        const double speed = sumV / double(tail.samples.size());
        // The median: a stroke whose tissue settles later than the others must not pull the
        // point down.
        PeakPoint p{speed, sign * (median(tail.rest) + b * speed), tail.samples.size()};
        const double effective = double(std::min(tail.rest.size(), after)) / double(w);
        const double tolerance = 4.0 * noise_N / std::sqrt(std::max(1.0, effective)) + 0.01 * std::fabs(p.force_N);
        // Resting against the plate, the force falls as soon as the needle slows; if it is
        // higher a little later, the tissue had not come to rest at the top.
        const double rise = sign * (sumAfter / double(after) - p.force_N);
        // The difference of two medians over `fewer / w` independent samples each.
        const std::size_t fewer = std::min(tail.quarterCounts[0], tail.quarterCounts[1]);
        const double quarterTolerance =
            4.0 * noise_N * std::sqrt(2.0 / std::max(1.0, double(fewer) / double(w))) + kFlat * std::fabs(p.force_N);
        const bool flat = fewer > 0 && std::fabs(tail.quarterMedians[1] - tail.quarterMedians[0]) <= quarterTolerance;
        p.settled = flat && rise <= tolerance;
        (sign > 0 ? peaks.positive : peaks.negative) = p;
    }
    return peaks;
}

void checkAgainstFit(RunPeaks& peaks, const FrictionFit& fit)
{
    auto check = [&](std::optional<PeakPoint>& p, bool positive) {
        if (!p)
            return;
        const double onLine = positive ? fit.model.Cp_N + fit.model.bp_Ns_per_m * p->speed_m_s
                                       : -fit.model.Cn_N - fit.model.bn_Ns_per_m * p->speed_m_s;
        if (std::fabs(p->force_N - onLine) > 0.015 * std::fabs(onLine))
            p->settled = false;
    };
    check(peaks.positive, true);
    check(peaks.negative, false);
}

std::optional<PeakSpeedLine> peakSpeedLine(std::span<const RunPeaks> runs)
{
    // Each direction on its own: a run whose tissue settled at the top going in but not
    // coming out still gives its inward point.
    auto direction = [&](bool positive) -> std::optional<std::pair<LineFit, std::pair<double, double>>> {
        std::vector<double> speed, force;
        for (const RunPeaks& r : runs) {
            const std::optional<PeakPoint>& p = positive ? r.positive : r.negative;
            if (!p || !p->settled)
                continue;
            speed.push_back(positive ? p->speed_m_s : -p->speed_m_s);  // signed: F = -Cn + bn·v with v < 0
            force.push_back(p->force_N);
        }
        // Two points fit any line exactly and leave it no error to judge departures by.
        if (speed.size() < 3)
            return std::nullopt;
        const auto [lo, hi] = std::minmax_element(speed.begin(), speed.end(), [](double l, double r) { return std::fabs(l) < std::fabs(r); });
        const double slow = std::fabs(*lo), fast = std::fabs(*hi);
        if (!(slow > 0.0 && fast >= kMinSpeedRatio * slow))
            return std::nullopt;
        const auto l = fitLine(speed, force);
        if (!l)
            return std::nullopt;
        return std::pair{*l, std::pair{slow, fast}};
    };
    const auto lp = direction(true);
    const auto ln = direction(false);
    if (!lp || !ln)
        return std::nullopt;
    PeakSpeedLine line;
    line.model.Cp_N = lp->first.intercept;
    line.model.bp_Ns_per_m = lp->first.slope;
    line.model.Cn_N = -ln->first.intercept;
    line.model.bn_Ns_per_m = ln->first.slope;
    line.model.Dp_N = line.model.Dn_N = 0.0;
    line.model.band_m_s = 0.0;
    line.seCp_N = lp->first.seIntercept;
    line.seBp_Ns_per_m = lp->first.seSlope;
    line.seCn_N = ln->first.seIntercept;
    line.seBn_Ns_per_m = ln->first.seSlope;
    std::size_t used = 0;
    for (const RunPeaks& r : runs)
        used += (r.positive && r.positive->settled) || (r.negative && r.negative->settled);
    line.runs = used;
    line.slowest_m_s = std::min(lp->second.first, ln->second.first);
    line.fastest_m_s = std::max(lp->second.second, ln->second.second);
    return line;
}

LineDeparture departureFromLine(const FrictionFit& fit, const PeakSpeedLine& line)
{
    LineDeparture d;
    auto one = [](double run, double ref, double seRef, double* percent) {
        *percent = ref != 0.0 ? 100.0 * (run - ref) / std::fabs(ref) : 0.0;
        const double diff = std::fabs(run - ref);
        return diff > 0.05 * std::fabs(ref) && diff > 3.0 * seRef;
    };
    const bool p = one(fit.model.Cp_N, line.model.Cp_N, line.seCp_N, &d.Cp_percent);
    const bool n = one(fit.model.Cn_N, line.model.Cn_N, line.seCn_N, &d.Cn_percent);
    d.significant = p || n;
    return d;
}

}  // namespace nb
