#include "surface_relaxation.h"

#include "settling_fit.h"
#include "statistics.h"
#include "tr.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

constexpr double kCarried_s = 0.3;       // before the onset: the surface carried by the needle
constexpr double kMinSettle_s = 1.5;     // after it: at least this long, and 8 τ
constexpr double kMaxSettle_s = 6.0;
constexpr double kMinTau_s = 0.003, kMaxTau_s = 2.0;
constexpr double kRelaxedTaus = 4.0;     // 98.2 % of the spring-back done
// A spring-back must stand this far out of the trace's noise (and move at least a pixel or
// two) before it is believed, and the exponential must explain most of the motion after it.
constexpr double kMinAmplitudeNoise = 8.0, kMinAmplitude_px = 1.5;
constexpr double kMinExplained = 0.8;
// It springs back at most to where it was touched (x_s3 ≥ x_s1), with some slack for the
// contact's time and an organ that overshoots a little.
constexpr double kMaxSpringBackOfCarried = 1.25;

}  // namespace

std::optional<SpringBack> fitSpringBack(const SurfaceTrace& trace, double puncture_s, double contact_s, QString* problem,
                                        double search_s)
{
    auto fail = [&](const QString& why) -> std::optional<SpringBack> {
        if (problem)
            *problem = why;
        return std::nullopt;
    };
    const std::vector<double>& t = trace.time_s;
    const std::vector<double>& d = trace.displacement_px;
    const std::size_t n = std::min(t.size(), d.size());
    if (n < 10 || !std::isfinite(puncture_s))
        return fail(nb::TrCore::tr("too few frames to follow the surface"));
    if (puncture_s < t.front() || puncture_s > t[n - 1])
        return fail(nb::TrCore::tr("the video does not show the puncture"));
    // The trace's noise, from its second differences (robust: the spring-back's few fast frames
    // are outliers there).
    std::vector<double> second;
    for (std::size_t i = 1; i + 1 < n; ++i)
        if (std::abs(t[i] - puncture_s) < 3.0)
            second.push_back(std::abs(d[i + 1] - 2 * d[i] + d[i - 1]));
    const double noise = noiseFromSecondDifferences(std::move(second));
    // The spring-back's onset: where the motion over a few frames changes most from the
    // motion over the few before (the surface carried one way, then springing back the other;
    // over one frame a slow spring-back's first step is hardly larger than the noise, and a
    // fast needle carries the surface further in a few frames than a slow spring-back moves).
    constexpr std::size_t kSpan = 3;
    std::size_t onset = 0;
    double largest = -1.0;
    for (std::size_t i = kSpan + 1; i + kSpan - 1 < n; ++i) {
        if (std::abs(t[i] - puncture_s) > search_s)
            continue;
        const double after = d[i + kSpan - 1] - d[i - 1], before = d[i - 1] - d[i - 1 - kSpan];
        if (std::abs(after - before) > largest) {
            largest = std::abs(after - before);
            onset = i;
        }
    }
    if (largest < 0.0)
        return fail(nb::TrCore::tr("no frames near the puncture"));
    const double frame_s = (t[n - 1] - t.front()) / double(n - 1);
    // The onset lies before the frames that moved most (a late onset leaves the first frame
    // after it a short step, and noise may shift the largest motion by a frame or two): coarse
    // grid from four frame intervals before to one after, then finer.
    const double from = t[onset >= 4 ? onset - 4 : 0], to = t[std::min(n - 1, onset + 1)];
    double settle = kMinSettle_s;
    std::vector<double> w(n, 1.0);
    const double step = std::max(1e-4, (to - from) / 60.0);
    auto fitOnce = [&](double lo, double hi) {
        const SettlingFit coarse = fitSettling(t, d, w, from, to, step, kMinTau_s, kMaxTau_s, 1.04, lo, hi);
        return fitSettling(t, d, w, std::max(from, coarse.t0_s - step), std::min(to, coarse.t0_s + step), step / 10.0, coarse.tau_s / 1.05,
                           coarse.tau_s * 1.05, 1.004, lo, hi);
    };
    SettlingFit f;
    for (int round = 0; round < 3; ++round) {
        f = fitOnce(from - kCarried_s, to + settle);
        if (!std::isfinite(f.sse) || 8.0 * f.tau_s <= settle || settle >= kMaxSettle_s)
            break;
        settle = std::min(kMaxSettle_s, 8.0 * f.tau_s);
    }
    // Frames far off the fit count less (Tukey's biweight), twice over: a repeated frame the
    // capture put out again (the previous picture at a later time) or a frame the tracker
    // misread lies far off while the surface moves fast, and would bend τ. A frame that moved
    // from the one before may be off by what the fit moves in half a frame there besides: the
    // first frames after the onset move fast, and a fit whose onset is a fraction of a frame off
    // lies several pixels off them; weighed by the noise alone, the frame straddling the onset
    // was dropped and the fit moved its onset 1.4 frames later with a shorter τ, 0.065 s for
    // 0.080 (bench_accuracy --seed 4455667 relaxation case 4: the relaxation 1.8 frames early).
    // A repeated frame did not move, and is weighed by the noise (seed 31415 case 7: one at the
    // onset, kept, read τ 0.061 s for 0.080).
    for (int round = 0; round < 2 && std::isfinite(f.sse); ++round) {
        const double lo = from - kCarried_s, hi = to + settle;
        std::vector<double> residual(n, 0.0), absolute;
        for (std::size_t i = 0; i < n; ++i) {
            if (t[i] < lo || t[i] > hi)
                continue;
            const double model = f.at(t[i]);
            residual[i] = d[i] - model;
            absolute.push_back(std::abs(residual[i]));
        }
        const double scale = 4.685 * std::max({robustSigma(absolute), noise, 0.05});
        for (std::size_t i = 0; i < n; ++i) {
            const bool moved = i > 0 && std::abs(d[i] - d[i - 1]) > 3.0 * noise;
            const double halfFrame = moved ? 0.5 * std::abs(f.at(t[i] + 0.5 * frame_s) - f.at(t[i] - 0.5 * frame_s)) : 0.0;
            const double u = residual[i] / (scale + halfFrame);
            w[i] = std::abs(u) < 1.0 ? (1 - u * u) * (1 - u * u) : 0.0;
        }
        const SettlingFit robust = fitOnce(lo, hi);
        if (!std::isfinite(robust.sse))
            break;
        f = robust;
    }
    if (!std::isfinite(f.sse))
        return fail(nb::TrCore::tr("the surface's motion around the puncture could not be fitted"));
    SpringBack s;
    s.onset_s = f.t0_s;
    s.tau_s = f.tau_s;
    s.amplitude_px = std::abs(f.d0 - f.rest);
    s.noise_px = noise;
    s.relaxed_s = puncture_s + kRelaxedTaus * f.tau_s;
    if (s.amplitude_px < std::max(kMinAmplitude_px, kMinAmplitudeNoise * noise))
        return fail(nb::TrCore::tr("the surface's spring-back (%1 px) does not stand out of the picture's noise (%2 px)")
                        .arg(s.amplitude_px, 0, 'f', 1)
                        .arg(noise, 0, 'f', 2));
    // Springing back goes against the way the needle carried the surface; motion that goes on
    // the same way (the needle's own, or a surface still carried) is not a spring-back. Said
    // first: such a fit's slow settling would otherwise read as a video that ends too soon.
    if (f.v * (f.d0 - f.rest) < 0.0 && std::abs(f.v) * kCarried_s > 2.0 * noise + kMinAmplitude_px)
        return fail(nb::TrCore::tr("nothing springs back after the puncture: the picture goes on moving the way the needle carried it"));
    if (s.relaxed_s > t[n - 1] + frame_s)
        return fail(nb::TrCore::tr("the video ends before the surface has come to rest"));
    // How much of the motion after the onset the settling explains.
    double mean = 0.0, count = 0.0, sse = 0.0, sst = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        if (t[i] >= f.t0_s && t[i] <= f.t0_s + settle)
            mean += w[i] * d[i], count += w[i];
    mean /= std::max(1e-9, count);
    for (std::size_t i = 0; i < n; ++i)
        if (t[i] >= f.t0_s && t[i] <= f.t0_s + settle) {
            const double model = f.at(t[i]);
            sse += w[i] * (d[i] - model) * (d[i] - model);
            sst += w[i] * (d[i] - mean) * (d[i] - mean);
        }
    if (count < 4 || !(sst > 0.0) || 1.0 - sse / sst < kMinExplained)
        return fail(nb::TrCore::tr("the surface's motion after the puncture is not a spring-back that settles"));
    if (f.tau_s >= kMaxTau_s / 1.05)
        return fail(nb::TrCore::tr("the surface does not come to rest within %1 s").arg(kMaxTau_s * kRelaxedTaus, 0, 'f', 0));
    if (std::isfinite(contact_s) && contact_s < f.t0_s && contact_s >= t.front()) {
        // Where the surface was at the contact: the frames within a frame of it.
        std::vector<double> atContact;
        for (std::size_t i = 0; i < n; ++i)
            if (std::abs(t[i] - contact_s) <= frame_s)
                atContact.push_back(d[i]);
        s.carried_px = (f.d0 - median(atContact)) * (f.d0 > f.rest ? 1.0 : -1.0);
        if (!atContact.empty() && s.amplitude_px > kMaxSpringBackOfCarried * s.carried_px + 2.0 * noise + kMinAmplitude_px)
            return fail(nb::TrCore::tr("the surface springs back further (%1 px) than it was carried since the contact (%2 px): "
                                       "the picture lost the surface")
                            .arg(s.amplitude_px, 0, 'f', 1)
                            .arg(s.carried_px, 0, 'f', 1));
    }
    return s;
}

}  // namespace nb
