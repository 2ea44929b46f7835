#include "picture_lag.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

double upperTail(double z) { return 0.5 * std::erfc(z / std::sqrt(2.0)); }

// z with upperTail(z) = p, for p in (0, 0.5]: Abramowitz and Stegun 26.2.23 (within 4.5e-4),
// then two Newton steps.
double upperQuantile(double p)
{
    const double t = std::sqrt(-2.0 * std::log(p));
    double z = t - (2.515517 + 0.802853 * t + 0.010328 * t * t) / (1.0 + 1.432788 * t + 0.189269 * t * t + 0.001308 * t * t * t);
    for (int i = 0; i < 2; ++i)
        z += (upperTail(z) - p) / (std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI));
    return z;
}

}  // namespace

double pictureLag_frames(const PictureCoding& c, double change_grey)
{
    constexpr double kMostLag = 10.0;
    if (!(c.memory > 0.0) || !(c.noise_grey > 0.0) || !std::isfinite(change_grey))
        return 0.0;
    // The noise passes with probability 1 − memory: beyond ±threshold.
    const double noisePass = 1.0 - std::min(c.memory, kMostModelledMemory);
    const double t = upperQuantile(0.5 * noisePass);
    const double z = std::abs(change_grey) / c.noise_grey;
    // The coder compares the camera's picture with the one it last showed, so a steady motion's
    // difference grows by `change` each frame it is not shown: passed after k frames with
    // probability pass(k·z). Shown afresh after K frames, the pictures in between are 0 … K−1
    // frames stale: (K−1)/2 on average, weighed by K, E[K(K−1)/2]/E[K] = Σ k·S(k) / Σ S(k) with
    // S(k) = P(K > k). For a change of nothing that is the noise's own (1 − pass)/pass. Beyond
    // 60 frames S falls as it did at the 60th (at most that fast: later frames pass more easily).
    auto pass = [&](double accumulated) { return upperTail(t - accumulated) + upperTail(t + accumulated); };
    double survive = 1.0, stale = 0.0, frames = 1.0, q = 0.0;
    for (int k = 1; k <= 60 && survive > 1e-9; ++k) {
        q = 1.0 - pass(k * z);
        survive *= q;
        stale += k * survive;
        frames += survive;
    }
    if (survive > 1e-9 && q < 1.0) {
        const double k = 60.0, tail = q / (1.0 - q);
        stale += survive * (k * tail + tail / (1.0 - q));
        frames += survive * tail;
    }
    return std::min(kMostLag, stale / frames);
}

}  // namespace nb
