#include "friction_peak_line.h"


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

}  // namespace

RunPeaks peakPoints(const ConditionedSignals& c, const FrictionOptions& options, double arrivingAboveP_m_s, double arrivingAboveN_m_s)
{
    RunPeaks peaks;
    const std::size_t n = c.v_m_s.size();
    const std::size_t trim = std::size_t(std::max(0, options.trimSamples));
    if (n < 2 * trim + 20)
        return peaks;
    const int w = c.window;
    const std::vector<double>& v = c.v_m_s;
    const std::vector<double>& a = c.a_m_s2;
    const std::vector<double>& f = c.force_N;
    const double mass = options.estimateMass ? 0.0 : options.mass_kg;
    const double noise_N = c.noise_N;

    for (int sign : {1, -1}) {
        const std::optional<double> fastest = topSpeed(v, sign, trim, n - trim, 10 * kMinSamples);
        if (!fastest)
            continue;
        const double arriving = sign > 0 ? arrivingAboveP_m_s : arrivingAboveN_m_s;
        const double top = std::min(*fastest, arriving);
        double sumV = 0, sumF = 0, sumAfter = 0;
        std::size_t count = 0, after = 0;
        std::vector<double> atTop;
        for (std::size_t i = trim; i < n - trim; ++i) {
            if (v[i] * a[i] > 0.0 || sign * v[i] < kSlowerAfter * top || sign * v[i] > arriving)
                continue;
            if (sign * v[i] < kNearTop * top) {
                sumAfter += f[i] - mass * a[i];
                ++after;
                continue;
            }
            sumV += std::fabs(v[i]);
            sumF += f[i] - mass * a[i];
            atTop.push_back(f[i] - mass * a[i]);
            ++count;
        }
        if (count < kMinSamples || after < kMinSamples || !std::isfinite(sumF) || !std::isfinite(sumAfter))
            continue;
        // The median: a stroke whose tissue arrives at the plate just at the top adds a few
        // samples below the line, which must not pull the point down.
        const auto mid = atTop.begin() + std::ptrdiff_t(atTop.size() / 2);
        std::nth_element(atTop.begin(), mid, atTop.end());
        PeakPoint p{sumV / double(count), *mid, count};
        // Resting against the plate, the force falls as soon as the needle slows; if it is
        // higher a little later, the tissue had not come to rest at the top.
        const double rise = sign * (sumAfter / double(after) - p.force_N);
        const double effective = double(std::min(count, after)) / double(std::max(1, w));
        p.settled = rise <= 4.0 * noise_N / std::sqrt(std::max(1.0, effective)) + 0.01 * std::fabs(p.force_N);
        (sign > 0 ? peaks.positive : peaks.negative) = p;
    }
    return peaks;
}

void checkAgainstFit(RunPeaks& peaks, const FrictionFit& fit)
{
    auto check = [&](std::optional<PeakPoint>& p, bool positive) {
        if (!p)
            return;
        const QStringList own = positive ? QStringList{QStringLiteral("Cp"), QStringLiteral("bp")}
                                         : QStringList{QStringLiteral("Cn"), QStringLiteral("bn")};
        for (const QString& name : own)
            if (fit.notPhysicalValues.contains(name))
                p->settled = false;
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
    auto one = [](double run, double seRun, double ref, double seRef, double* percent) {
        *percent = ref != 0.0 ? 100.0 * (run - ref) / std::fabs(ref) : 0.0;
        const double diff = std::fabs(run - ref);
        return diff > 0.05 * std::fabs(ref) && diff > 3.0 * std::hypot(seRun, seRef);
    };
    const bool p = one(fit.model.Cp_N, fit.seCp_N, line.model.Cp_N, line.seCp_N, &d.Cp_percent);
    const bool n = one(fit.model.Cn_N, fit.seCn_N, line.model.Cn_N, line.seCn_N, &d.Cn_percent);
    d.significant = p || n;
    return d;
}

}  // namespace nb
