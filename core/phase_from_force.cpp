#include "phase_reading.h"

#include "models.h"
#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>

namespace nb::phase_reading {

namespace {

struct SlidingLine {
    double c0_N = 0.0, b_Ns_per_m = 0.0, rms_N = 0.0;
    bool ok = false;
};

// The sliding line of one direction, F = c0 + b·v, as the line most of the force follows:
// in c the force tracks it over a long stretch while the needle slows, whereas the
// break-away peaks are brief and a rise to the plate is steep. Lines are fitted over short
// stretches of time (`window` samples) and scored by how many samples lie on them, within
// the force's noise (`noise_N`, after smoothing). The force held at static friction (the
// tissue stuck again while the needle, inside a wide band, slows to its turning point) is a
// line too, flat at D: a line at the strongest force even at the slowest speed used is left
// out (sliding friction is below static) unless no other line is followed for long. An
// upper envelope of the force, drawn before, was pulled up by those peaks and holds where
// the band is wide and the needle not much faster than it (83 % and 82 % on bench_accuracy
// --seed 634001 phase cases 4 and 21).
SlidingLine slidingLine(const std::vector<double>& f, const std::vector<double>& v_mm_s, int dir, double minSpeed_mm_s,
                        double noise_N, std::size_t window)
{
    // From where the needle slows down: c is every stroke's last phase, up to the turning
    // point, so the force follows the line there. While the needle speeds up the tissue may
    // still slide through the plate's gap behind it (a light slab slipping at a fast
    // reversal), the force short of the line by b times the tissue's speed: in one thin slab
    // at 0.97 Hz, a third of the run, enough to draw the line flat through it. Every sample
    // when too few slow down (a constant speed).
    const std::size_t step = std::max<std::size_t>(1, window / 5), last = f.size() - 1;
    auto samples = [&](bool slowingOnly) {
        std::vector<std::size_t> out;
        for (std::size_t i = 0; i < f.size(); ++i)
            if (dir * v_mm_s[i] >= minSpeed_mm_s &&
                (!slowingOnly || std::abs(v_mm_s[std::min(last, i + step)]) < std::abs(v_mm_s[i >= step ? i - step : 0])))
                out.push_back(i);
        return out;
    };
    std::vector<std::size_t> use = samples(true);
    if (use.size() < 2 * window)
        use = samples(false);
    SlidingLine line;
    if (use.size() < 2 * window)
        return line;
    double tolerance_N = 3.0 * noise_N, strongest_N = 0.0;
    {
        // The carried tissue pulls through its inertia only, near zero: samples below a
        // quarter of the strongest force (static friction, at most a few times the sliding
        // force) are left out.
        std::vector<double> levels;
        for (std::size_t i : use)
            levels.push_back(dir * f[i]);
        const std::size_t at98 = levels.size() * 98 / 100;
        std::nth_element(levels.begin(), levels.begin() + std::ptrdiff_t(at98), levels.end());
        strongest_N = levels[at98];
        tolerance_N = std::max(tolerance_N, 0.01 * strongest_N);  // the line is not quite straight
        std::vector<std::size_t> upper;
        for (std::size_t i : use)
            if (dir * f[i] >= 0.25 * strongest_N)
                upper.push_back(i);
        use.swap(upper);
    }
    if (use.size() < 2 * window)
        return line;
    auto fit = [&](const std::vector<std::size_t>& idx, std::size_t from, std::size_t to) {
        double sv = 0, sf = 0, svv = 0, svf = 0;
        for (std::size_t j = from; j < to; ++j) {
            const double vi = v_mm_s[idx[j]] / 1000.0;
            sv += vi;
            sf += f[idx[j]];
            svv += vi * vi;
            svf += vi * f[idx[j]];
        }
        const double k = double(to - from), det = k * svv - sv * sv;
        SlidingLine l;
        l.b_Ns_per_m = std::abs(det) > 1e-18 ? std::max(0.0, (k * svf - sv * sf) / det) : 0.0;  // damping is not negative
        l.c0_N = (sf - l.b_Ns_per_m * sv) / k;
        l.ok = true;
        return l;
    };
    auto residual = [&](const SlidingLine& l, std::size_t i) { return std::abs(f[i] - l.c0_N - l.b_Ns_per_m * v_mm_s[i] / 1000.0); };
    auto onLine = [&](const SlidingLine& l) { return [&, l](std::size_t i) { return residual(l, i) <= tolerance_N; }; };
    auto inliers = [&](const SlidingLine& l) {
        std::vector<std::size_t> in;
        std::copy_if(use.begin(), use.end(), std::back_inserter(in), onLine(l));
        return in;
    };
    SlidingLine mostFollowed, mostFollowedBelowStatic;
    std::size_t most = 0, mostBelowStatic = 0;
    for (std::size_t s = 0; s + window <= use.size(); s += window / 2) {
        if (use[s + window - 1] - use[s] != window - 1)
            continue;  // not one stretch of time
        const SlidingLine l = fit(use, s, s + window);
        const std::size_t count = std::size_t(std::count_if(use.begin(), use.end(), onLine(l)));
        if (count > most) {
            most = count;
            mostFollowed = l;
        }
        // At the strongest force even at the slowest speed used: flat at D, the hold.
        const bool atStatic = dir * l.c0_N + l.b_Ns_per_m * minSpeed_mm_s / 1000.0 >= 0.9 * strongest_N;
        if (!atStatic && count > mostBelowStatic) {
            mostBelowStatic = count;
            mostFollowedBelowStatic = l;
        }
    }
    line = mostBelowStatic >= 2 * window ? mostFollowedBelowStatic : mostFollowed;
    for (int refit = 0; refit < 3 && line.ok; ++refit) {
        const std::vector<std::size_t> in = inliers(line);
        if (in.size() < window)
            break;
        line = fit(in, 0, in.size());
    }
    if (line.ok) {
        std::vector<double> r;
        for (std::size_t i : inliers(line))
            r.push_back(residual(line, i));
        if (!r.empty()) {
            std::nth_element(r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2), r.end());
            line.rms_N = 1.4826 * r[r.size() / 2];
        }
    }
    return line;
}

// The force's noise after a moving average over `smoothedSamples`: from the second
// differences of the raw force (a smooth force has almost none, noise σ·√6).
double smoothedForceNoise(const Run& run, int smoothedSamples)
{
    std::vector<double> d2;
    for (std::size_t i = 1; i + 1 < run.size(); ++i)
        d2.push_back(std::abs(run.force_N[i - 1] - 2.0 * run.force_N[i] + run.force_N[i + 1]));
    if (d2.empty())
        return 0.0;
    std::nth_element(d2.begin(), d2.begin() + std::ptrdiff_t(d2.size() / 2), d2.end());
    return 1.4826 * d2[d2.size() / 2] / std::sqrt(6.0) / std::sqrt(double(smoothedSamples));
}

// Where a tissue creeping into the plate's soft part comes to rest, read from the force's
// shortfall below the sliding line (`shortfall_N` at `t_s`, the needle at `speed_mm_s`): b times
// the creep's speed (eq. 15: the relative velocity is the needle's less the tissue's), too small
// to read sample by sample, but settling as the creep does. Fitted as an exponential over a
// level (what the line misses of the force), the tissue rests from the first sample where the
// fitted creep is a twentieth of the needle's speed, the rest laterRest reads in the picture.
// The creep and where it rests; nullopt unless the fit shows a creep: τ from half the force
// smoothing's spread (a smoothed stop reads τ of about a quarter of it) to under a quarter of
// the stretch (longer is the line missing the force's curve), a shortfall three times the
// smoothed noise, and more than a tenth of a millimetre left to creep (∫shortfall/b: less is
// the slab stopping against the stiff part, and a pixel or less at the imaging view's scale).
std::optional<Creep> creepRest(const std::vector<double>& t_s, const std::vector<double>& speed_mm_s, const std::vector<double>& shortfall_N,
                               double b_Ns_per_m, double noise_N, double smoothing_s)
{
    if (t_s.size() < 2 || !(b_Ns_per_m > 0.0))
        return std::nullopt;
    const double longest_s = 0.25 * (t_s.back() - t_s.front());
    const SettlingFit f = fitSettlingFrom(t_s, shortfall_N, t_s.front(), 0.002, longest_s, 60);
    const double creep0_N = f.d0 - f.rest, creepLeft_mm = 1000.0 * creep0_N * f.tau_s / b_Ns_per_m;
    if (!(creepLeft_mm > 0.1 && creep0_N > 3.0 * noise_N && f.tau_s < longest_s && f.tau_s >= 0.5 * smoothing_s))
        return std::nullopt;
    for (std::size_t i = 0; i < t_s.size(); ++i)
        if (f.at(t_s[i]) - f.rest <= 0.05 * b_Ns_per_m * speed_mm_s[i] / 1000.0)
            return Creep{i, f, b_Ns_per_m};
    return std::nullopt;
}

// The time a jump in the force takes once smoothed (the smoothing spreads an instant over about
// 20 ms).
constexpr double kJump_s = 0.03;
// The run's first moments, where the stage starts at speed (see firstStrokeCarried).
constexpr double kStartTransient_s = 0.05;
// Where the force is held at static friction, the tissue resting on the plate sticks again for
// moments that pull the force down by more than half (to 38 % of it for 50 ms, every 0.2-0.4 s;
// liver3 at 0.08 Hz, a needle never faster than 1.6 times the band: each withdrawal's c ended
// at the last such dip, 1.9 s late, seed 9306 case 16 of a random draw at the matrix's edge,
// 80.1 %). The tissue carried before c pulls the force down for far longer.
constexpr double kHeldDip_s = 0.08;
// How much the needle must slow over a rise of the force for it to be the soft part's push (see
// the break-away on the stiff part).
constexpr double kSlowing = 0.95;
// A first stroke whose strongest force stays under this share of what its direction's whole
// strokes reach never released the tissue.
constexpr double kReleased = 0.8;

}  // namespace

bool carriedThroughout(const Run& run, const std::vector<double>& v_mm_s)
{
    const std::size_t n = run.size();
    std::vector<double> speeds;
    for (double x : v_mm_s)
        speeds.push_back(std::abs(x));
    if (speeds.size() < 100)
        return false;
    std::nth_element(speeds.begin(), speeds.begin() + std::ptrdiff_t(speeds.size() * 95 / 100), speeds.end());
    const double moving = 0.1 * speeds[speeds.size() * 95 / 100];
    std::vector<double> depth;
    for (std::size_t i = 0; i < n; ++i)
        if (std::abs(v_mm_s[i]) > moving)
            depth.push_back(run.position_mm[i]);
    if (depth.size() < 100)
        return false;
    std::sort(depth.begin(), depth.end());
    const double lo = depth[depth.size() / 100], hi = depth[depth.size() - 1 - depth.size() / 100];
    const int bins = std::clamp(int(depth.size() / 100), 5, 20);
    if (!(hi > lo))
        return false;
    std::vector<double> sum[2], count[2];
    for (int d : {0, 1}) {
        sum[d].assign(std::size_t(bins), 0.0);
        count[d].assign(std::size_t(bins), 0.0);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (std::abs(v_mm_s[i]) <= moving || run.position_mm[i] < lo || run.position_mm[i] >= hi)
            continue;
        const auto b = std::size_t(std::clamp(int((run.position_mm[i] - lo) / (hi - lo) * bins), 0, bins - 1));
        const int d = v_mm_s[i] > 0 ? 0 : 1;
        sum[d][b] += run.force_N[i];
        count[d][b] += 1.0;
    }
    std::vector<double> difference;
    for (std::size_t b = 0; b < std::size_t(bins); ++b)
        if (count[0][b] >= 10 && count[1][b] >= 10)
            difference.push_back(sum[0][b] / count[0][b] - sum[1][b] / count[1][b]);
    if (difference.size() < std::size_t(bins) / 2 + 1)
        return false;
    const double sigma = smoothedForceNoise(run, 1);
    double largest = 0.0;
    for (double x : difference)
        largest = std::max(largest, std::abs(x));
    std::nth_element(difference.begin(), difference.begin() + std::ptrdiff_t(difference.size() / 2), difference.end());
    return std::abs(difference[difference.size() / 2]) < 2.0 * sigma && largest < std::max(6.0 * sigma, 0.02);
}

namespace {

// The force less what a tissue carried by the needle gives over stroke `h`, sample by sample.
// Carried, the tissue pulls with its inertia only: a straight line over depth (m·a, and a sine's
// acceleration follows its depth), fitted over the stroke's middle third, where the needle is
// fastest and the plates farthest, leaving out what strays from it (the plate left behind at
// the turning point still pushing) by more than four times the residuals' spread, or `floor_N`.
auto lessCarried(const Run& run, const std::vector<double>& force, const HalfCycle& h, double floor_N)
{
    const std::size_t third = (h.end - h.start) / 3;
    std::vector<std::size_t> use;
    for (std::size_t i = h.start + third; i < h.end - third; ++i)
        use.push_back(i);
    double c0 = 0.0, c1 = 0.0;
    {
        std::vector<double> f;
        for (std::size_t i : use)
            f.push_back(force[i]);
        c0 = median(f);
    }
    for (int pass = 0; pass < 5; ++pass) {
        std::vector<double> residual;
        for (std::size_t i : use)
            residual.push_back(std::abs(force[i] - c0 - c1 * run.position_mm[i]));
        const double tolerance_N = std::max((pass == 0 ? 3.0 : 4.0) * robustSigma(residual), floor_N);
        double sx = 0, sf = 0, sxx = 0, sxf = 0, k = 0;
        for (std::size_t j = 0; j < use.size(); ++j) {
            if (residual[j] > tolerance_N)
                continue;
            const double x = run.position_mm[use[j]], f = force[use[j]];
            sx += x, sf += f, sxx += x * x, sxf += x * f, k += 1;
        }
        const double det = k * sxx - sx * sx;
        if (k < 10 || std::abs(det) < 1e-12)
            break;
        c1 = (k * sxf - sx * sf) / det;
        c0 = (sf - c1 * sx) / k;
    }
    return [&run, &force, c0, c1](std::size_t i) { return force[i] - c0 - c1 * run.position_mm[i]; };
}

}  // namespace

bool stuckThroughTurn(const Run& run, const std::vector<double>& force, const HalfCycle& h, const HalfCycle& next, double noise_N)
{
    if (h.end != next.start || h.end - h.start < 30 || next.end - next.start < 30)
        return false;
    // The carried force is a line only nearly (3 mN: a few per cent of the least push seen).
    const double floor_N = std::max(3.0 * noise_N, 0.003);
    const auto offIn = lessCarried(run, force, h, floor_N), offOut = lessCarried(run, force, next, floor_N);
    const std::size_t middleIn = (h.start + h.end) / 2, middleOut = (next.start + next.end) / 2;
    double top_N = 0.0;
    for (std::size_t i = middleIn; i < h.end; ++i)
        top_N = std::max(top_N, std::abs(offIn(i)));
    for (std::size_t i = next.start; i < middleOut; ++i)
        top_N = std::max(top_N, std::abs(offOut(i)));
    // The plate's push must stand clear of the noise, and the carried level near zero beside it
    // (a tissue sliding the whole stroke has no carried stretch to measure from).
    if (!(top_N > 10.0 * floor_N) || std::abs(force[middleIn] - offIn(middleIn)) >= 0.25 * top_N ||
        std::abs(force[middleOut] - offOut(middleOut)) >= 0.25 * top_N)
        return false;
    std::size_t in = middleIn;
    while (in < h.end && std::abs(offIn(in)) <= 0.15 * top_N)
        ++in;
    std::size_t out = middleOut;
    while (out > next.start && std::abs(offOut(out)) <= 0.15 * top_N)
        --out;
    // A push from the middle on is no carried stretch measured before it: the tissue met the
    // plate at once, and the line through the middle third drawn partly through the push.
    if (in >= h.end || out <= next.start || in - middleIn < (h.end - h.start) / 10 || middleOut - out < (next.end - next.start) / 10)
        return false;
    // From where the push is clear back to its foot, where it starts.
    while (in > middleIn && std::abs(offIn(in - 1)) > 0.07 * top_N)
        --in;
    while (out < middleOut && std::abs(offOut(out + 1)) > 0.07 * top_N)
        ++out;
    // Within 3 %: on random draws the depths read this way come within 0.06 mm of the true slide
    // there. A slab thrown back off the plate at a fast reversal slips back about as far as it slid
    // in, its push ending 4.6 % of the reach from where it began (liver2 at 0.95 Hz, 55 mm/s,
    // 0.67 mm slid; seed 4713 case 28 at short reach).
    const double reach_mm = h.direction * (run.position_mm[h.end] - run.position_mm[in]);
    const double slid_mm = h.direction * (run.position_mm[out] - run.position_mm[in]);
    return reach_mm > 0.0 && std::abs(slid_mm) < 0.03 * reach_mm;
}

std::optional<FrictionFit> slidingLines(const Run& run)
{
    try {
        FrictionOptions o;
        o.thickness_mm = run.metadata.number(QStringLiteral("thickness_mm")).value_or(30.0);
        o.estimateBand = true;
        return fitFriction(run, o, QStringList(qsizetype(run.size()), QString()));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

bool firstStrokeCarried(const Run& run, const std::vector<double>& force, const std::vector<double>& v_mm_s,
                        const std::vector<const HalfCycle*>& strokes, const FrictionFit& lines)
{
    if (strokes.size() < 5)
        return false;
    const HalfCycle& first = *strokes.front();
    const KarnoppModel& m = lines.model;
    auto along = [&](std::size_t i, const HalfCycle& h) { return h.direction * force[i]; };
    auto sliding = [&](std::size_t i, const HalfCycle& h) {
        return h.direction > 0 ? m.Cp_N + m.bp_Ns_per_m * v_mm_s[i] / 1000.0 : m.Cn_N - m.bn_Ns_per_m * v_mm_s[i] / 1000.0;
    };
    // The stage starts at speed and the tissue, at rest, slides until friction has brought it
    // up to the needle's. A light slab, or a fast start, takes longer than kStartTransient_s
    // (90 ms for a 13 mm prostate slab at 30 mm/s): it has caught up where the force first falls
    // to the carried tissue's, under half the sliding line, within the stroke's first third.
    double caughtUp_s = run.time_s.front() + kStartTransient_s;
    const std::size_t firstThird = first.start + (first.end - first.start) / 3;
    for (std::size_t i = first.start; i < firstThird; ++i)
        if (run.time_s[i] >= caughtUp_s) {
            if (along(i, first) < 0.5 * sliding(i, first))
                break;
            caughtUp_s = run.time_s[i + 1];
        }
    if (caughtUp_s >= run.time_s[firstThird])
        caughtUp_s = run.time_s.front() + kStartTransient_s;  // still sliding: whatever the force does, not a start
    auto started = [&](std::size_t i) { return run.time_s[i] >= caughtUp_s; };
    auto strongest_N = [&](const HalfCycle& h) {
        double top = -std::numeric_limits<double>::infinity();
        for (std::size_t i = h.start; i < h.end; ++i)
            if (started(i))
                top = std::max(top, along(i, h));
        return top;
    };
    std::vector<double> tops;
    for (std::size_t k = 1; k + 1 < strokes.size(); ++k)
        if (strokes[k]->direction == first.direction)
            tops.push_back(strongest_N(*strokes[k]));
    if (tops.size() < 2)
        return false;
    std::nth_element(tops.begin(), tops.begin() + std::ptrdiff_t(tops.size() / 2), tops.end());
    if (!(strongest_N(first) < kReleased * tops[tops.size() / 2]))
        return false;
    const double slidingMost_N = std::max(std::abs(m.Cp_N), std::abs(m.Cn_N));
    const double tolerance_N = std::clamp(3.0 * lines.rms_N, 0.1 * slidingMost_N, 0.25 * slidingMost_N);
    double carried_N = 0.0, slidingSum_N = 0.0;
    for (std::size_t i = first.start; i < first.end; ++i) {
        if (!started(i))
            continue;
        if (along(i, first) - sliding(i, first) >= -tolerance_N)
            return false;
        if (run.time_s[i] < caughtUp_s + kStartTransient_s) {
            carried_N += along(i, first);
            slidingSum_N += sliding(i, first);
        }
    }
    return slidingSum_N > 0.0 && carried_N < 0.5 * slidingSum_N;
}

std::vector<double> forceLessHolder(const Run& run, const std::vector<double>& v, int half)
{
    const std::size_t n = run.size();
    std::vector<double> force(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i >= std::size_t(half) ? i - half : 0, b = std::min(n - 1, i + half);
        double sum = 0;
        for (std::size_t k = a; k <= b; ++k)
            sum += run.force_N[k];
        const double acc = (v[b] - v[a]) / 1000.0 / std::max(1e-9, run.time_s[b] - run.time_s[a]);
        force[i] = sum / double(b - a + 1) - kNeedleHolderMass_kg * acc;
    }
    return force;
}

PhaseLines phaseLines(const Run& run, const std::vector<double>& force, const std::vector<double>& v, double fastest, double rate, int half)
{
    PhaseLines out;
    std::optional<FrictionFit>& lines = out.fit;
    lines = slidingLines(run);
    if (lines) {
        const double c[2] = {lines->model.Cp_N, lines->model.Cn_N}, b[2] = {lines->model.bp_Ns_per_m, lines->model.bn_Ns_per_m};
        const double top[2] = {lines->slidingToP_m_s, lines->slidingToN_m_s};
        for (int d : {0, 1}) {
            out.heldLevel_N[d] = c[d] + b[d] * top[d];
            out.held[d] = out.heldLevel_N[d] > 0.0 && std::abs(b[d]) * top[d] <= 0.05 * out.heldLevel_N[d];
        }
        const double minSpeed = std::max(1000.0 * lines->bandSlowingDown_m_s / 2.0, 0.2 * fastest);
        const std::size_t window = std::max<std::size_t>(10, std::size_t(0.05 * rate));  // 50 ms
        out.noise_N = smoothedForceNoise(run, 2 * half + 1);
        const SlidingLine up = slidingLine(force, v, 1, minSpeed, out.noise_N, window), down = slidingLine(force, v, -1, minSpeed, out.noise_N, window);
        // A direction with no sliding at all: the force follows no line with C > 0 there (the
        // search finds none) and the fit's C and b are not above zero by two standard errors. A
        // plate gap nearly as wide as the stroke: the slab, carried across it, pulls on the needle
        // only with its inertia, meets the plate near the turning point and is taken back before
        // it breaks away, or slides for a moment only. The fit's line through that force (C < 0,
        // or near 0 with errors larger than itself) read most of each stroke as c (17.7 to
        // 66.2 %; random draws over the command line at short reach, seed 4711: 8 runs of 40).
        // Where the search finds a line, the fit's errors are only the sliding's brevity: a
        // stroke that slides briefly slides (seed 9191 at the matrix's edge: 4 runs read 4 to 14
        // points worse as carried). A b above its errors counts only with a C not clearly below
        // zero: a thin heavy slab carried to the plate pulls ahead as the needle speeds up and
        // holds back as it slows, a line rising with speed from below zero (C −0.17 ± 0.03 N;
        // seed 9503 case 15 at short reach, c read from mid-stroke on: 62.4 %).
        auto slides = [](double c_N, double seC_N, double b, double seB) { return c_N > 2.0 * seC_N || (b > 2.0 * seB && !(c_N < -2.0 * seC_N)); };
        const bool fitSlides[2] = {slides(lines->model.Cp_N, lines->seCp_N, lines->model.bp_Ns_per_m, lines->seBp_Ns_per_m),
                                   slides(lines->model.Cn_N, lines->seCn_N, lines->model.bn_Ns_per_m, lines->seBn_Ns_per_m)};
        out.neverSlid[0] = !(up.ok && up.c0_N > 0.0) && !fitSlides[0];
        out.neverSlid[1] = !(down.ok && down.c0_N < 0.0) && !fitSlides[1];
        // The other direction's line, where one never slid, may be a level rather than a line
        // (b = 0: slidingLine clamps a force that does not rise with speed to a level) with the fit
        // seeing no sliding there either: the force held at static friction against the plate
        // near the turning point, not sliding. Sliding acts on both directions alike, through the
        // same tissue; the slab turned back at both plates (random draws at short reach: 65.8 %
        // and 66.3 % read the level as c, seeds 4713 case 1 and 4711 case 0; at the matrix's edge
        // 50.2 %, seed 6060 case 32).
        const bool level[2] = {up.ok && up.b_Ns_per_m == 0.0, down.ok && down.b_Ns_per_m == 0.0};
        for (int d : {0, 1})
            if (out.neverSlid[1 - d] && level[d] && !fitSlides[d])
                out.neverSlid[d] = true;
        if (up.ok && down.ok) {
            lines->model.Cp_N = up.c0_N;
            lines->model.bp_Ns_per_m = up.b_Ns_per_m;
            lines->model.Cn_N = -down.c0_N;
            lines->model.bn_Ns_per_m = down.b_Ns_per_m;
            lines->rms_N = std::max(up.rms_N, down.rms_N);
        }
        // A held direction's line is the force held at D, flat. Where the search for lines
        // finds none with C > 0 there, what it found is the rise to the plate.
        if (out.held[0] && !(lines->model.Cp_N > 0.0)) {
            lines->model.Cp_N = out.heldLevel_N[0];
            lines->model.bp_Ns_per_m = 0.0;
        }
        if (out.held[1] && !(lines->model.Cn_N > 0.0)) {
            lines->model.Cn_N = out.heldLevel_N[1];
            lines->model.bn_Ns_per_m = 0.0;
        }
    }
    return out;
}

StrokeBounds boundsFromForce(const HalfCycle& h, const ForceReading& f, const SuggestOptions& o)
{
    const Run& run = f.run;
    const std::vector<double>& v = f.v;
    const std::vector<double>& force = f.force;
    const std::optional<FrictionFit>& lines = f.lines.fit;
    const bool held = f.lines.held[h.direction > 0 ? 0 : 1];  // this direction's force held at static friction
    const double noise_N = f.lines.noise_N;
    const int half = f.half;
    const double rate = f.rate;
    std::size_t aEnd = h.start, cStart = h.start, b2Start = h.start;
    std::optional<Creep> creep;  // the force read the tissue creeping to rest on the plate's soft part
    std::optional<std::size_t> brokeAway;  // where the force jumped to static friction, the tissue carried until then
    // A jump that reaches `level` at sample `at`: where it starts (kJump_s before, not before
    // `floor`) and its middle, where `level` has risen half of it.
    auto jumpInto = [&](std::size_t at, std::size_t floor, auto level) {
        std::size_t before = at;
        while (before > floor && run.time_s[at] - run.time_s[before - 1] <= kJump_s)
            --before;
        std::size_t middle = before;
        while (middle < at && level(middle) - level(before) < 0.5 * (level(at) - level(before)))
            ++middle;
        return std::make_pair(before, middle);
    };
    if (lines) {
        // c: the force follows the sliding line (relative velocity = needle velocity)
        // from here to the turning point.
        const KarnoppModel& m = lines->model;
        auto line = [&](std::size_t i) {
            const double vi = v[i] / 1000.0;
            return h.direction > 0 ? m.Cp_N + m.bp_Ns_per_m * vi : -m.Cn_N + m.bn_Ns_per_m * vi;
        };
        auto over = [&](std::size_t i) { return h.direction * (force[i] - line(i)); };  // above the line, along the stroke
        // Noise decides, within bounds: a tenth to a quarter of the sliding force.
        const double sliding = std::max(std::abs(m.Cp_N), std::abs(m.Cn_N));
        const double tolerance = std::clamp(3.0 * lines->rms_N, 0.1 * sliding, 0.25 * sliding);
        // Just before the turning point the needle is slower than the band and the force
        // leaves the line although the tissue still rests: scanned from before that.
        std::size_t last = h.end;
        const double slowest = 1000.0 * lines->bandSlowingDown_m_s / 2.0;
        while (last > h.start + 1 && std::abs(v[last - 1]) < slowest)
            --last;
        // A stroke may end with the needle stopping while still fast instead of slowing into
        // a turning point (the run's last, often partial, stroke): in its last tenth the
        // needle keeps more than half its top speed.
        bool stopsFast = false;
        if (last > h.start + 10) {
            double top = 0.0, lastTenth = 0.0;
            for (std::size_t i = h.start; i < last; ++i) {
                top = std::max(top, std::abs(v[i]));
                if (i >= last - (last - h.start) / 10)
                    lastTenth = std::max(lastTenth, std::abs(v[i]));
            }
            stopsFast = lastTenth > 0.5 * top;
        }
        // Backwards while the force follows the line; a few stray samples (noise) do not
        // end c, a run of them does. The samples nearest the turning point may still be
        // off the line (a slow needle inside the band): they do not end the search
        // before it has begun.
        cStart = last;
        int off = 0;
        bool onLine = false;
        for (std::size_t i = last; i > h.start; --i) {
            // Off the line while the needle is still fast, before any sample on it: the
            // stroke ended without the tissue coming to rest (the last, often partial,
            // stroke stopped mid-way): no c here, whatever the force does earlier (the
            // tissue leaving the plate behind pushes near the line after a turning point).
            if (!onLine && stopsFast && std::abs(v[i - 1]) > 2.0 * slowest &&
                h.direction * (force[i - 1] - line(i - 1)) < -tolerance &&
                std::size_t(++off) >= std::max<std::size_t>(25, (last - h.start) / 10))
                break;
            // Above the line decides nothing: the tissue still stuck, pressed to the plate
            // up to static friction (a), or resting there while the needle, slower than the
            // band, is held (c).
            const double off_N = h.direction * (force[i - 1] - line(i - 1));
            if (off_N > tolerance)
                continue;
            if (off_N >= -tolerance) {
                off = 0;
                onLine = true;
                cStart = i - 1;
            } else if (held && off_N >= -0.5 * std::abs(line(i - 1))) {
                continue;  // stuck again against the plate for a moment: still at rest there
            } else if (onLine && ++off >= 5 && (!held || run.time_s[cStart] - run.time_s[i - 1] > kHeldDip_s)) {
                break;
            }
        }
        if (cStart == last)
            cStart = h.end;
        // The tissue comes to rest only after it has broken away: a peak clearly above the
        // line (static friction) followed by the line means c starts after that peak (the
        // soft first contact with the plate can bring the force close to the line before).
        // The first such peak: later ones may be the tissue stuck again as the needle
        // slows into the band before the turning point.
        if (cStart < last) {
            std::size_t above = 0;
            for (std::size_t i = cStart; i < last; ++i) {
                above = h.direction * (force[i] - line(i)) > tolerance ? above + 1 : 0;
                if (above < 3)  // a peak, not a stray sample
                    continue;
                std::size_t after = i + 1;
                while (after < last && h.direction * (force[after] - line(after)) > tolerance)
                    ++after;
                std::size_t onAfter = 0, end = after;
                for (; end < last && h.direction * (force[end] - line(end)) <= tolerance; ++end)
                    onAfter += std::abs(force[end] - line(end)) <= tolerance;
                // A peak is brief: longer above the line than on it afterwards is the line
                // lying too low under a sliding force, not a break-away.
                const std::size_t peakLength = after - (i + 1 - above);
                if (onAfter >= std::max<std::size_t>({10, (last - after) / 5, peakLength})) {
                    while (after < last && std::abs(force[after] - line(after)) > tolerance)
                        ++after;
                    cStart = after;
                    break;
                }
                // Where the needle is not much faster than the band, the sliding force is
                // seen only briefly and the line found may lie below it: the force falling
                // back from the peak and staying down is the break-away all the same.
                // Measured from the line, not in force: as the needle slows to its turning
                // point the line falls with it, and so does a force that merely stays a little
                // above a line drawn too steep (a thin slab at 0.95 Hz, most of whose c was
                // read as b2 that way).
                std::size_t top = i, fall = i, down = 0;
                for (; fall < last && over(top) - over(fall) <= 2.0 * tolerance; ++fall)
                    if (over(fall) > over(top))
                        top = fall;
                for (std::size_t j = fall; j < last && over(top) - over(j) > tolerance; ++j)
                    ++down;
                if (fall < last && down >= std::max<std::size_t>(10, fall - (i + 1 - above))) {
                    cStart = fall;
                    break;
                }
                // Neither back on the line nor down from the peak, and the peak reached by a
                // jump from a force that was rising along the stroke while the needle slowed:
                // that was no sliding (C + b·v falls as the needle slows), but the plate's
                // soft part pushing back through a tissue still carried, across the line.
                // The tissue broke away where it met the stiff part, whose losses act at
                // once, and stopped there (b2): a runs to the jump (bench_accuracy --seed
                // 31337 phase case 4: a read as ending 120 ms early, at the soft part). A
                // peak the force reaches from the line, falling as the needle slows, is the
                // tissue at rest stuck again as the needle slows into the band: c stands.
                // Only where the peak is the stroke's highest: static friction caps the
                // force while the tissue is stuck.
                std::size_t reached = i + 1 - above;
                while (reached + 1 < fall && over(reached) < 0.9 * over(top))
                    ++reached;
                const auto [before, middle] = jumpInto(reached, cStart, over);
                bool highest = true;
                for (std::size_t j = h.start; j < last && highest; ++j)
                    highest = over(j) <= over(top) + tolerance;
                const double rise_N = over(reached) - over(before);
                const double pushed_N = h.direction * (force[before] - force[cStart]);
                const bool slowing = std::abs(v[before]) < std::abs(v[cStart]);
                if (highest && slowing && pushed_N >= tolerance && rise_N >= std::max(3.0 * tolerance, 0.6 * over(top))) {
                    brokeAway = middle;
                    std::size_t back = reached;
                    while (back < last && over(back) > tolerance)
                        ++back;
                    cStart = back;
                }
                break;
            }
        }
        // The force back within the tolerance of the line is not yet the tissue at rest: on
        // a thin slab it creeps on into the plate's soft part for a while (creepRest), up to
        // where the needle slows into the band (the tissue may stick again there). A creep
        // that slow is on the soft part, b1: against the stiff part the tissue stops at once,
        // so b2, if any, was too brief to tell.
        std::size_t fitEnd = last;
        while (fitEnd > cStart && std::abs(v[fitEnd - 1]) < 2.0 * slowest)
            --fitEnd;
        // Nor past where the tissue sticks again (the force back above the line by more than
        // its tolerance, after the break-away's peak and the creep's shortfall below it): the
        // settling's level would bend to meet that jump.
        std::size_t fallFrom = cStart;
        while (fallFrom + 1 < fitEnd && over(fallFrom + 1) >= over(fallFrom))
            ++fallFrom;
        bool under = false;
        for (std::size_t i = fallFrom; i < fitEnd; ++i) {
            if (under && over(i) > tolerance) {
                fitEnd = i;
                break;
            }
            under = under || over(i) < 0.0;
        }
        if (cStart + 10 < fitEnd && !held) {
            std::vector<double> ts, speed, shortfall;
            for (std::size_t i = cStart; i < fitEnd; ++i) {
                ts.push_back(run.time_s[i]);
                speed.push_back(std::abs(v[i]));
                shortfall.push_back(-over(i));
            }
            creep = creepRest(ts, speed, shortfall, h.direction > 0 ? m.bp_Ns_per_m : m.bn_Ns_per_m, noise_N, double(2 * half + 1) / rate);
            if (creep && creep->rest > 0)
                cStart += creep->rest;
            else
                creep.reset();
        }
        // a: the tissue is carried with the needle (static friction) and pulls on it only
        // through its inertia, well below the sliding line, until it meets the plate
        // ahead: from there the plate's reaction drives the force up to the line. a ends
        // where the force rises from that low level for the last time before c, or, when
        // the tissue still sticks there (the force overshoots the line and drops back
        // when it breaks away: static friction above dynamic), at that peak.
        auto level = [&](std::size_t i) { return h.direction * force[i] / std::max(1e-9, std::abs(line(i))); };
        // The valley: backwards from c to the lowest level, stopping where the force
        // climbs again towards the turning point (the tissue leaving the plate behind
        // pushes while it relaxes) or turns to the previous direction's sign.
        std::size_t valley = cStart, climb = h.start;
        double lowest = std::numeric_limits<double>::infinity();
        for (std::size_t i = cStart; i > h.start; --i) {
            const double l = level(i - 1);
            if (l > lowest + 0.3)
                climb = i - 1;
            if (l < 0.0 || l > lowest + 0.3)
                break;
            if (l < lowest) {
                lowest = l;
                valley = i - 1;
            }
        }
        // Unless what the force climbs to there is the tissue held at static friction
        // after a at its low level: the force jumps to D as the tissue meets the plate,
        // holds while it slips over the plate's soft part (b1), drops back and closes on
        // the line (c). The valley above is then that drop; a ended before the hold, where
        // the peak below finds it. D lies above the sliding line at low speeds; at high
        // ones (C + b·v grows with speed) it may lie just below it, and then only a jump
        // tells the hold (the tissue meets the plate in an instant, which the smoothing
        // spreads over about 20 ms) from the tissue left behind at the turning point
        // pushing back, which rises gradually.
        if (climb > h.start) {
            std::size_t start = climb;
            double top = 0.0;
            while (start > h.start && level(start - 1) >= 0.5 * lowest)
                top = std::max(top, level(--start));
            // Low: the tissue carried, near zero force; not the push of the plate left behind
            // at the turning point (the other direction's sign).
            std::size_t low = 0;
            for (std::size_t i = start; i > h.start && level(i - 1) < 0.5 * lowest && level(i - 1) > -0.2; --i)
                ++low;
            std::size_t reached = start;
            while (reached < climb && level(reached) < 0.9 * top)
                ++reached;
            const bool jumped = run.time_s[reached] - run.time_s[start] <= 0.03;
            if ((top > 1.05 || (top > 0.9 && jumped)) && low >= std::max<std::size_t>(10, (climb - start) / 2)) {
                valley = start - 1;
                lowest = std::max(0.0, level(valley));
            }
        }
        aEnd = valley;
        const double risen = std::max(0.0, lowest) + 0.35 * (1.0 - std::max(0.0, lowest));
        while (aEnd < cStart && level(aEnd) < risen)
            ++aEnd;
        if (cStart >= h.end)
            aEnd = h.end;  // the force never reached the sliding line: the tissue was carried throughout
        std::size_t peak = aEnd;
        for (std::size_t i = aEnd; i < cStart; ++i)
            if (h.direction * force[i] - std::abs(line(i)) > h.direction * force[peak] - std::abs(line(peak)))
                peak = i;
        if (peak < cStart && h.direction * force[peak] - std::abs(line(peak)) > std::max(tolerance, 0.1 * std::abs(line(peak)))) {
            // While stuck the force cannot exceed static friction: the tissue slips where it
            // first reaches the peak's level. A plateau there (the force held at D while the
            // tissue slips slowly over the plate's soft part, b1, which the picture hardly
            // shows) belongs to b.
            const double peakLevel_N = h.direction * force[peak] - std::max(3.0 * lines->rms_N, 0.03 * std::abs(force[peak]));
            while (peak > aEnd && h.direction * force[peak - 1] >= peakLevel_N)
                --peak;
            aEnd = peak;
        }
        // The same break-away where the line found is static friction itself (a direction
        // held there, the needle inside the band, seed 9191 case 6 of a random draw): the
        // jump to it does not stand above it, and the rise across the soft part was read as
        // b1. Found here as the stroke's first arrival at its strongest force, by a jump,
        // after a force that rose without falling while the needle slowed. A tissue sliding
        // over the soft part (b1, its force rising too as it slows) broke away before,
        // reaching static friction first, and fell from it to sliding; or, where sliding
        // friction at speed stands above static friction (liver 3 past 20 mm/s), its force
        // rose on through it. The needle must slow clearly over the rise: near its top
        // speed that rise is the tissue sliding (bench_accuracy --seed 9001 phase case 22,
        // 36 mm/s: 94.9 % read as 93.5 % without that). And the jump must reach above
        // the line where the rise ended (static friction above sliding), unless the line is
        // static friction itself: a sliding force rising with the relative velocity reaches
        // the line, and the stiff part's jump lands on it (--seed 777 phase case 2, liver3
        // at 0.95 Hz: 94.5 % read as 91.3 % without that).
        if (!brokeAway && aEnd < cStart) {
            double strongest_N = -std::numeric_limits<double>::infinity();
            for (std::size_t j = h.start; j < last; ++j)
                strongest_N = std::max(strongest_N, h.direction * force[j]);
            std::size_t first = aEnd;
            while (first < last && h.direction * force[first] < strongest_N - tolerance)
                ++first;
            if (first >= last)  // never there before the needle slows into the band
                first = aEnd;
            auto along = [&](std::size_t i) { return h.direction * force[i]; };
            const auto [before, middle] = jumpInto(first, aEnd, along);
            const double jump_N = h.direction * (force[first] - force[before]);
            const double pushed_N = h.direction * (force[before] - force[aEnd]);
            bool reachedBefore = false, fell = false;
            for (std::size_t j = h.start; j < aEnd && !reachedBefore; ++j)
                reachedBefore = h.direction * force[j] >= strongest_N - tolerance;
            double risen_N = -std::numeric_limits<double>::infinity();
            for (std::size_t j = aEnd; j <= before && !fell; ++j) {
                risen_N = std::max(risen_N, h.direction * force[j]);
                fell = risen_N - h.direction * force[j] > tolerance;
            }
            if (!reachedBefore && !fell && first < last && first <= cStart + (first - before) && before > aEnd &&
                pushed_N >= tolerance && std::abs(v[before]) <= kSlowing * std::abs(v[aEnd]) && jump_N >= 3.0 * tolerance &&
                (held || strongest_N - h.direction * line(before) > tolerance)) {
                brokeAway = middle;
                cStart = std::max(cStart, first);
            }
        }
        if (brokeAway)
            aEnd = *brokeAway;
        // b1/b2: the tissue bears on the plate progressively, then fully (the force
        // closes on the line, models.md 5: the relative velocity grows); b2 once the gap
        // to the line has closed to a quarter of what it was when the tissue met the plate.
        // After a break-away on the stiff part, b2 at once.
        const double gap0 = aEnd < cStart ? std::abs(force[aEnd] - line(aEnd)) : 0.0;
        b2Start = brokeAway ? aEnd : cStart;
        while (!creep && !brokeAway && b2Start > aEnd && std::abs(force[b2Start - 1] - line(b2Start - 1)) <= 0.25 * gap0)
            --b2Start;
    } else {
        while (aEnd < h.end && std::abs(v[aEnd]) < o.zeroBand_mm_s / 2)
            ++aEnd;
        const std::size_t len = h.end - h.start;
        std::vector<double> mid(run.force_N.begin() + std::ptrdiff_t(h.start + len * 3 / 10),
                                run.force_N.begin() + std::ptrdiff_t(h.start + len * 7 / 10));
        std::nth_element(mid.begin(), mid.begin() + std::ptrdiff_t(mid.size() / 2), mid.end());
        const double plateau = mid.empty() ? run.force_N[h.start] : mid[mid.size() / 2];
        const double step = std::abs(run.force_N[h.start] - plateau);
        cStart = aEnd;
        while (cStart < h.end && std::abs(run.force_N[cStart] - plateau) > o.settledFraction * step)
            ++cStart;
        b2Start = aEnd + (cStart - std::min(cStart, aEnd)) / 2;
    }
    return {aEnd, b2Start, cStart, creep};
}

}  // namespace nb::phase_reading
