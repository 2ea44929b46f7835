#include "picture_lag.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

double upperTail(double z) { return 0.5 * std::erfc(z / std::sqrt(2.0)); }

// z with upperTail(z) = p, for p in (0, 0.5].
double upperQuantile(double p)
{
    double lo = 0.0, hi = 10.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (upperTail(mid) > p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

double pictureLag_frames(const PictureCoding& c, double change_grey)
{
    constexpr double kMostLag = 10.0;
    if (!(c.memory > 0.0) || !(c.noise_grey > 0.0) || !std::isfinite(change_grey))
        return 0.0;
    // The noise passes with probability 1 − memory: beyond ±threshold.
    const double noisePass = 1.0 - std::min(c.memory, 0.99);
    const double threshold = c.noise_grey * upperQuantile(0.5 * noisePass);
    const double z = std::abs(change_grey) / c.noise_grey, t = threshold / c.noise_grey;
    const double pass = upperTail(t - z) + upperTail(t + z);
    return std::min(kMostLag, (1.0 - pass) / std::max(pass, 1.0 / (1.0 + kMostLag)));
}

}  // namespace nb
