#include "plate_give.h"

#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nb {

namespace {

// Samples past a stretch's end where its break-away may still lie (a label boundary or the
// first sliding sample falls either side of the force's extreme).
constexpr std::size_t kPast = 5;
constexpr std::size_t kFewestOnLine = 9;
// A slide is left out over this many of the contact's time constants c/k from its start where it
// starts on the soft part or near it (kNearlySoft times the force the give was read to): the
// tissue's way there from where it let go (the plate's knee, the slab's own inertia) is what the
// contact's law alone does not follow (liver 3 at 0.4 Hz: 15 mN off its line at 50 ms, none
// left after 150 ms).
constexpr double kSettlingTimes = 2.0;
constexpr double kNearlySoft = 1.25;

// The median slope over pairs of points (Theil-Sen): the step at contact and the steep part
// past a knee are a minority of a rise and do not lean it as they would a least-squares line.
std::optional<double> medianSlope(const std::vector<double>& x, const std::vector<double>& y)
{
    const std::size_t n = x.size(), stride = std::max<std::size_t>(1, n / 120);
    std::vector<double> slopes;
    for (std::size_t i = 0; i < n; i += stride)
        for (std::size_t j = i + stride; j < n; j += stride)
            if (x[j] != x[i])
                slopes.push_back((y[j] - y[i]) / (x[j] - x[i]));
    if (slopes.size() < 10)
        return std::nullopt;
    return median(std::move(slopes));
}

struct Rise {
    double stiffness_N_per_m, upTo_N, losses_Ns_per_m;
    std::size_t breakAway;     // the sample where the tissue let go
    double depth_m;            // how far into the contact it was there
};

std::optional<Rise> readRise(std::span<const double> x, std::span<const double> v, std::span<const double> smooth,
                             std::span<const double> f, std::size_t from, std::size_t to, int s, double noise_N, std::size_t window)
{
    const std::size_t end = std::min(f.size(), to + kPast);
    if (end <= from)
        return std::nullopt;
    std::size_t peak = from;
    for (std::size_t i = from; i < end; ++i)
        if (s * f[i] > s * f[peak])
            peak = i;
    // Down the rise on the smoothed force, from its own top (up to a window before the sharp
    // one's): the lightly averaged force wiggles with the noise and would stop the walk early.
    std::size_t start = peak;
    for (std::size_t i = peak; i + window > peak && i > from; --i)
        if (s * smooth[i - 1] > s * smooth[start])
            start = i - 1;
    while (start > from && s * smooth[start - 1] < s * smooth[start])
        --start;
    const double free_N = s * f[start];
    if (peak - start < 8 || s * f[peak] - free_N < 10.0 * noise_N)
        return std::nullopt;
    // A rise from a force pulling the other way is the tissue leaving the other plate, which
    // drags on the needle as it unloads: then the stretch never met the plate ahead.
    if (free_N < -0.25 * (s * f[peak] - free_N))
        return std::nullopt;
    // A break-away lets go: the force falls past it, static friction above sliding. A force that
    // only levels off may be the sliding's own rise with speed, which is not the contact's.
    double after = s * f[peak];
    for (std::size_t i = peak + 1; i < std::min(f.size(), peak + window + kPast); ++i)
        after = std::min(after, s * f[i]);
    if (s * f[peak] - after < std::max(10.0 * noise_N, 0.05 * (s * f[peak] - free_N)))
        return std::nullopt;
    std::vector<double> xs, ys;
    for (std::size_t i = start; i <= peak; ++i) {
        xs.push_back(s * x[i]);
        ys.push_back(s * f[i]);
    }
    const std::optional<double> slope = medianSlope(xs, ys);
    if (!slope || !(*slope > 0.0))
        return std::nullopt;
    std::vector<double> offsets;
    for (std::size_t k = 0; k < xs.size(); ++k)
        offsets.push_back(ys[k] - *slope * xs[k]);
    const double intercept = median(offsets);
    auto line = [&](double at) { return intercept + *slope * at; };
    // Contact: the first sample halfway up from the free level to the line. A step there is the
    // contact's losses taking the speed the tissue meets the plate with; at rest they are gone.
    std::size_t contact = 0;
    while (contact + 1 < xs.size() && ys[contact] - free_N < 0.5 * (line(xs[contact]) - free_N))
        ++contact;
    const double step_N = std::max(0.0, line(xs[contact]) - free_N);
    const double speed = std::fabs(v[start + contact]);
    const double losses = speed > 0.0 ? step_N / speed : 0.0;
    const double tolerance = std::max(3.0 * noise_N, 0.05 * (line(xs.back()) - line(xs[contact])));
    std::vector<double> at, held;
    std::size_t last = start;
    for (std::size_t k = contact; k < xs.size(); ++k)
        if (std::fabs(ys[k] - line(xs[k])) <= tolerance) {
            at.push_back(xs[k]);
            held.push_back(ys[k] - losses * std::fabs(v[start + k]) - free_N);
            last = start + k;
        }
    // A rise passed within a few samples is the averaging's shape, not the contact's.
    if (at.size() < kFewestOnLine)
        return std::nullopt;
    const double mx = mean(at), my = mean(held);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < at.size(); ++k) {
        sxy += (at[k] - mx) * (held[k] - my);
        sxx += (at[k] - mx) * (at[k] - mx);
    }
    if (!(sxx > 0.0) || !(sxy > 0.0))
        return std::nullopt;
    const double k = sxy / sxx;
    // From the last sample on the line to the break-away the tissue was still carried, so as
    // deep again as the needle went, unless the force left the line upwards there: then it met
    // the plate's stiff part, which it hardly enters, and let go at the knee.
    bool stiffened = false;
    for (std::size_t i = last + 1; i <= peak; ++i)
        stiffened = stiffened || s * f[i] - line(s * x[i]) > tolerance;
    const double most_N = *std::max_element(held.begin(), held.end());
    const double depth = stiffened ? most_N / k : held.back() / k + std::fabs(x[peak] - x[last]);
    return Rise{k, most_N, losses, peak, depth};
}

}  // namespace

std::optional<PlateGive> plateGive(std::span<const double> x_m, std::span<const double> v_m_s, std::span<const double> smooth_N,
                                   std::span<const double> force_N, std::span<const std::pair<std::size_t, std::size_t>> carried, int sign,
                                   double noise_N, std::size_t window)
{
    std::vector<double> k, upTo, losses;
    std::vector<PlateGive::BreakAway> breakAways;
    for (const auto& [from, to] : carried)
        if (const std::optional<Rise> r = readRise(x_m, v_m_s, smooth_N, force_N, from, to, sign, noise_N, window)) {
            k.push_back(r->stiffness_N_per_m);
            upTo.push_back(r->upTo_N);
            losses.push_back(r->losses_Ns_per_m);
            breakAways.push_back({from, r->breakAway, r->depth_m});
        }
    // A contact the tissue meets on every stroke shows on most of them; a rise read in a few only
    // is something else (the tissue arriving at the plate while it already slips).
    if (k.size() < 2 || 2 * k.size() < carried.size())
        return std::nullopt;
    PlateGive g;
    g.rises = k.size();
    g.stiffness_N_per_m = median(k);
    g.losses_Ns_per_m = median(losses);
    std::vector<double> depths;
    for (const PlateGive::BreakAway& b : breakAways)
        depths.push_back(b.depth_m);
    g.upTo_N = std::max(median(upTo), g.stiffness_N_per_m * median(depths));
    g.breakAways = std::move(breakAways);
    return g;
}

std::vector<double> restingTissueVelocity(const PlateGive& give, std::span<const double> time_s, std::span<const double> v_m_s,
                                          std::span<const double> force_N, int sign)
{
    const std::size_t n = force_N.size();
    std::vector<double> out(n, std::numeric_limits<double>::quiet_NaN());
    const double k = give.stiffness_N_per_m, c = give.losses_Ns_per_m, deepest = give.upTo_N / k;
    for (const PlateGive::BreakAway& b : give.breakAways) {
        const std::size_t from = b.at;
        double s = std::min(b.depth_m, deepest);
        for (std::size_t i = from + 1; i < n && sign * v_m_s[i] > 0.0; ++i) {
            const double dt = time_s[i] - time_s[i - 1];
            const double load = sign * force_N[i];
            // The depth the force would hold the slab at (none once it pulls the slab off the
            // plate), and the slab's way there: at once without losses, else over c/k (the exact
            // step of the linear law for a constant load).
            const double toward = std::clamp(load / k, 0.0, deepest);
            const double next = c > 0.0 ? toward + (s - toward) * std::exp(-k * dt / c) : toward;
            out[i] = dt > 0.0 ? sign * (next - s) / dt : 0.0;
            s = next;
        }
    }
    return out;
}

std::vector<std::size_t> withoutCarried(const std::vector<std::size_t>& rows, const PlateGive& give)
{
    std::vector<std::size_t> kept;
    for (std::size_t i : rows)
        if (std::none_of(give.breakAways.begin(), give.breakAways.end(),
                         [&](const PlateGive::BreakAway& b) { return i >= b.carriedFrom && i <= b.at; }))
            kept.push_back(i);
    return kept;
}

std::vector<std::size_t> withoutSettling(const std::vector<std::size_t>& rows, const PlateGive& give, std::span<const double> time_s,
                                         std::span<const double> v_m_s, std::span<const double> force_N, int sign)
{
    const double settle_s = kSettlingTimes * give.losses_Ns_per_m / give.stiffness_N_per_m;
    std::vector<std::size_t> kept;
    double softFrom = -INFINITY;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::size_t i = rows[r];
        if (sign * v_m_s[i] <= 0.0) {
            kept.push_back(i);
            continue;
        }
        if (r == 0 || rows[r - 1] + 1 != i || sign * v_m_s[rows[r - 1]] <= 0.0)
            softFrom = std::fabs(force_N[i]) <= kNearlySoft * give.upTo_N ? time_s[i] : -INFINITY;
        if (time_s[i] - softFrom >= settle_s)
            kept.push_back(i);
    }
    return kept;
}

}  // namespace nb
