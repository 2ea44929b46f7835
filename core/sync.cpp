#include "sync.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nb {

namespace {

double valueAt(const TimeSignal& s, double t)
{
    const auto& ts = s.time_s;
    if (ts.empty() || t < ts.front() || t > ts.back())
        return 0.0;
    const auto it = std::lower_bound(ts.begin(), ts.end(), t);
    if (it == ts.begin())
        return s.value.front();
    const std::size_t i = std::size_t(it - ts.begin());
    const double w = (t - ts[i - 1]) / std::max(1e-12, ts[i] - ts[i - 1]);
    return s.value[i - 1] + w * (s.value[i] - s.value[i - 1]);
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    const std::size_t k = std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

}  // namespace

TimeSignal needleSpeed(const Run& run, double smoothing_s)
{
    TimeSignal out;
    const std::size_t n = run.size();
    if (n < 3)
        return out;
    std::vector<double> v(n);
    if (const auto* vel = run.numericColumn(QStringLiteral("velocity_mm_s"))) {
        for (std::size_t i = 0; i < n; ++i)
            v[i] = std::abs((*vel)[i]);
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
            v[i] = std::abs((run.position_mm[b] - run.position_mm[a]) / std::max(1e-9, run.time_s[b] - run.time_s[a]));
        }
    }
    // Moving average over the smoothing window (prefix sums; samples may be uneven).
    std::vector<double> prefix(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        prefix[i + 1] = prefix[i] + (std::isfinite(v[i]) ? v[i] : 0.0);
    out.time_s = run.time_s;
    out.value.resize(n);
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 0; i < n; ++i) {
        while (run.time_s[i] - run.time_s[lo] > smoothing_s / 2)
            ++lo;
        while (hi + 1 < n && run.time_s[hi + 1] - run.time_s[i] <= smoothing_s / 2)
            ++hi;
        hi = std::max(hi, i);
        out.value[i] = (prefix[hi + 1] - prefix[lo]) / double(hi + 1 - lo);
    }
    return out;
}

std::optional<double> motionOnset(const TimeSignal& s, double fraction, double restWindow_s)
{
    std::vector<double> rest, all;
    for (std::size_t i = 0; i < s.time_s.size(); ++i) {
        if (!std::isfinite(s.value[i]))
            continue;
        all.push_back(s.value[i]);
        if (s.time_s[i] - s.time_s.front() <= restWindow_s)
            rest.push_back(s.value[i]);
    }
    if (all.size() < 3 || rest.empty())
        return std::nullopt;
    const double base = percentile(rest, 0.5);
    const double high = percentile(all, 0.95);
    if (high <= base)
        return std::nullopt;
    const double threshold = base + fraction * (high - base);
    for (std::size_t i = 0; i < s.time_s.size(); ++i)
        if (std::isfinite(s.value[i]) && s.value[i] > threshold)
            return s.time_s[i];
    return std::nullopt;
}

std::pair<double, int> correlationAt(const TimeSignal& m, const TimeSignal& speed, double offset_s)
{
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < m.time_s.size(); ++i) {
        const double x = m.value[i];
        if (!std::isfinite(x))
            continue;
        const double y = valueAt(speed, m.time_s[i] - offset_s);
        sx += x;
        sy += y;
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
        ++n;
    }
    if (n < 3)
        return {0.0, n};
    const double cov = sxy - sx * sy / n, vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
    if (vx <= 0 || vy <= 0)
        return {0.0, n};
    return {cov / std::sqrt(vx * vy), n};
}

SyncResult synchronise(const TimeSignal& m, const TimeSignal& speed, const SyncOptions& o)
{
    if (m.time_s.size() < 10 || speed.time_s.size() < 10)
        throw std::invalid_argument("too few samples to synchronise");
    SyncResult r;
    r.onsetOffset_s = [&]() -> std::optional<double> {
        const auto a = motionOnset(m), b = motionOnset(speed);
        if (a && b)
            return *a - *b;
        return std::nullopt;
    }();
    const bool anchored = o.anchorOnOnset && r.onsetOffset_s && std::abs(*r.onsetOffset_s) <= o.maxOffset_s;
    double best = anchored ? *r.onsetOffset_s : 0.0, bestR = -2.0;
    for (double off = -o.maxOffset_s; off <= o.maxOffset_s + 1e-9; off += o.coarseStep_s) {
        const double rr = correlationAt(m, speed, off).first;
        r.curve.emplace_back(off, rr);
        if (anchored && std::abs(off - *r.onsetOffset_s) > o.anchorWindow_s)
            continue;
        if (rr > bestR) {
            bestR = rr;
            best = off;
        }
    }
    // Fine: every millisecond around the coarse peak.
    const double centre = best;
    for (double off = centre - o.coarseStep_s; off <= centre + o.coarseStep_s + 1e-9; off += o.fineStep_s) {
        const double rr = correlationAt(m, speed, off).first;
        if (rr > bestR) {
            bestR = rr;
            best = off;
        }
    }
    r.offset_s = best;
    const auto [rr, pairs] = correlationAt(m, speed, best);
    r.correlation = rr;
    r.pairs = pairs;
    // Confidence: a strong correlation that also agrees with the onsets. Without an onset
    // estimate a periodic signal could lock onto the wrong period: halve it.
    double agreement = 0.5;
    if (r.onsetOffset_s) {
        const double d = (best - *r.onsetOffset_s) / std::max(o.anchorWindow_s, 1e-3);
        agreement = std::exp(-d * d);
    }
    r.confidence = std::clamp(rr, 0.0, 1.0) * agreement;
    return r;
}

}  // namespace nb
