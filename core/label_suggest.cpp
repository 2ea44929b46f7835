#include "label_suggest.h"

#include "events.h"
#include "friction_fit.h"
#include "models.h"
#include "settling_fit.h"
#include "tr.h"

#include <cstdlib>
#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <optional>

namespace nb {

namespace {

// The needle settling back by more than this after its last stroke counts as a reversal
// (a few encoder counts: the thesis's stage resolves 1.5 µm).
constexpr double kSettleBack_mm = 0.01;

std::vector<double> velocity(const Run& run)
{
    const std::size_t n = run.size();
    std::vector<double> v(n, 0.0);
    if (const auto* col = run.numericColumn(QStringLiteral("velocity_mm_s"))) {
        v = *col;
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
            v[i] = (run.position_mm[b] - run.position_mm[a]) / std::max(1e-9, run.time_s[b] - run.time_s[a]);
        }
    }
    // Light smoothing (about 20 ms) so noise does not make false turning points.
    const double rate = n > 1 ? (n - 1) / std::max(1e-9, run.time_s.back() - run.time_s.front()) : 1.0;
    const int half = std::max(1, int(0.01 * rate));
    std::vector<double> s(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i >= std::size_t(half) ? i - half : 0, b = std::min(n - 1, i + half);
        double sum = 0;
        for (std::size_t k = a; k <= b; ++k)
            sum += v[k];
        s[i] = sum / double(b - a + 1);
    }
    return s;
}

// Half-cycles [start, end) between turning points, with their direction.
struct HalfCycle {
    std::size_t start, end;
    int direction;
};

std::vector<HalfCycle> halfCycles(const std::vector<double>& v, double band)
{
    std::vector<HalfCycle> out;
    int dir = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const int d = v[i] > band / 2 ? 1 : (v[i] < -band / 2 ? -1 : 0);
        if (d == 0 || d == dir)
            continue;
        // The turning point is where the velocity crossed zero before this sample.
        std::size_t turn = i;
        while (turn > start && v[turn - 1] * d > 0)
            --turn;
        if (dir != 0)
            out.push_back({start, turn, dir});
        start = turn;
        dir = d;
    }
    if (dir != 0) {
        std::size_t end = v.size();
        while (end > start + 1 && std::abs(v[end - 1]) < band / 2)
            --end;  // the needle at rest after the last stroke belongs to no phase
        out.push_back({start, end, dir});
    }
    return out;
}

}  // namespace

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

// Whether the force shows sliding friction at all: sliding adds C·sgn(ẋ) (models.md 5), so at
// one depth the force going in stands above the force coming out by about Cp + |Cn|, while a
// slab carried the whole time (a stroke shorter than the plate's gap) pushes back only with
// its inertia and the plate's spring, the same both ways at a depth. Over bins of depth along
// the moving samples (`v_mm_s`), the force in minus the force out: the slab was carried
// throughout when that difference is within the raw force's noise in the middle bin (twice
// σ) and in every bin (six σ, and 20 mN: a tenth of the least sliding friction a slab of a few
// millimetres gives). False when too few samples fill both directions of a bin.
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

// The needle's position at the first sample at or after `t` (the last sample after the run).
double positionAtTime(const Run& run, double t)
{
    const auto at = std::lower_bound(run.time_s.begin(), run.time_s.end(), t);
    return run.position_mm[std::min(run.size() - 1, std::size_t(at - run.time_s.begin()))];
}

// How far the needle must move the picture in one pair of frames for the tissue's motion in it
// to read true (pictureReading).
constexpr double kClearPair_px = 1.5;

// One reading of the picture against the needle, over one or a few pairs of frames.
struct PictureReading {
    double from_s = 0.0, to_s = 0.0;       // recording time it spans
    double needle_mm = 0.0, tissue_mm = 0.0;  // displacements over it
    int pairs = 0;
    bool clear = false;  // the needle moved the picture clearly: its speed reads true
    double mid_s() const { return 0.5 * (from_s + to_s); }
    double needle_mm_s() const { return needle_mm / std::max(1e-9, to_s - from_s); }
    double tissue_mm_s() const { return tissue_mm / std::max(1e-9, to_s - from_s); }
};

// The reading that ends with pair of frames k: that pair alone where the needle moved the
// picture clearly in it (1.5 px, and four times the picture's noise), else added up with the
// pairs before it (none before `since_s` or the needle's last turning point, at most eight)
// until it has moved it `sum_px`. The tracker's shifts are differences of positions measured
// against a reference, so their sum over a few frames has about the noise of one: a slow
// needle is judged over a few frames, not left unjudged.
PictureReading pictureReading(const Run& run, const TissueMotion& tissue, std::size_t k, double since_s, double noise_mm_s,
                              double frameHalf_s, double sum_px = kClearPair_px)
{
    constexpr int kMaxPairs = 8;
    PictureReading r;
    r.to_s = tissue.time_s[k] + frameHalf_s;
    for (std::size_t j = k + 1; j-- > 0 && r.pairs < kMaxPairs;) {
        const double from = tissue.time_s[j] - frameHalf_s;
        if (from < since_s - 1e-9 || !std::isfinite(tissue.velocity_mm_s[j]))
            break;
        if (r.pairs > 0 && (positionAtTime(run, r.from_s) - positionAtTime(run, from)) * r.needle_mm < 0.0)
            break;  // not across a turning point
        r.from_s = from;
        r.tissue_mm += tissue.velocity_mm_s[j] * 2.0 * frameHalf_s;
        ++r.pairs;
        r.needle_mm = positionAtTime(run, r.to_s) - positionAtTime(run, r.from_s);
        const double moved = std::abs(r.needle_mm);
        r.clear = tissue.px_per_mm > 0.0 && moved * tissue.px_per_mm >= (r.pairs == 1 ? kClearPair_px : sum_px) &&
                  moved / (r.to_s - r.from_s) >= 4.0 * noise_mm_s / std::sqrt(double(r.pairs));
        if (r.clear)
            break;
    }
    return r;
}

// Where the tissue, slowing on the plate after it fell behind the needle at `from_s`, comes to
// rest, when that is later than `c_s`, where the readings one by one put it. On a thin slab
// the tissue creeps into the plate's soft part for several frames at a tenth to a third of
// the needle's speed: single readings, a pixel or so off, cannot tell that creep from rest,
// and the force, already near the sliding line, cannot either. The whole settling can: the
// tissue's displacement in the picture from `from_s` to the turning point `to_s` is fitted as
// y(t) = y_end - A·exp(-(t - from_s)/tau), and the tissue is at rest from where its fitted
// speed is a twentieth of the needle's (`needle_mm_s`, by time), the relative velocity then
// the needle's within 5 %, as phase c's fit of C and b takes it. `direction` is the stroke's.
// nullopt, and `c_s` stands, unless the picture shows the settling: at `c_s` the tissue still
// has 1.5 px to go and moves a pixel a frame, and it takes half a frame or more (a faster stop
// is over within the pair of frames that placed `c_s`).
template <class NeedleSpeed>
std::optional<double> laterRest(const TissueMotion& tissue, double from_s, double to_s, double c_s, int direction,
                                double frame_s, const NeedleSpeed& needle_mm_s)
{
    constexpr double kLeft_px = 1.5, kMoving_px = 1.0, kAtRest = 0.05;
    std::vector<double> t, y;
    double moved_mm = 0.0;
    for (std::size_t k = 0; k < tissue.time_s.size() && k < tissue.velocity_mm_s.size(); ++k) {
        const double end_s = tissue.time_s[k] + 0.5 * frame_s;
        if (end_s <= from_s || end_s > to_s || !std::isfinite(tissue.velocity_mm_s[k]))
            continue;
        if (t.empty()) {
            t.push_back(tissue.time_s[k] - 0.5 * frame_s);
            y.push_back(0.0);
        }
        moved_mm += direction * tissue.velocity_mm_s[k] * frame_s;
        t.push_back(end_s);
        y.push_back(moved_mm);
    }
    if (t.size() < 6 || !(tissue.px_per_mm > 0.0))
        return std::nullopt;
    // tau over a grid from a third of a frame to ten frames.
    const double tauLo_s = frame_s / 3.0, tauHi_s = 10.0 * frame_s;
    const SettlingFit f = fitSettlingFrom(t, y, from_s, tauLo_s, tauHi_s, 60);
    // No settling: the tissue moving backwards, or still under way at ten frames.
    if (!(f.rest - f.d0 > 0.0) || f.tau_s >= tauHi_s || f.tau_s < 0.5 * frame_s)
        return std::nullopt;
    const double at_s = std::max(c_s, from_s);
    if ((f.rest - f.at(at_s)) * tissue.px_per_mm < kLeft_px || f.speedAt(at_s) * tissue.px_per_mm * frame_s < kMoving_px)
        return std::nullopt;
    // The curve must also be what the frames after `c_s` show: a tissue carried at the needle's
    // speed that stops within a frame is fitted by a curve with a tau of a frame or two, which
    // still creeps on after the stop (liver3 at 0.81 Hz, a 30 mm slab: c placed 60-80 ms late
    // in most strokes, seed 518445 phase case 11). The frames after it show half the creep left.
    const auto after = std::lower_bound(t.begin(), t.end(), at_s);
    if (after == t.end() || after + 1 == t.end())
        return std::nullopt;
    const std::size_t j = std::size_t(after - t.begin());
    const double shown_mm = y.back() - y[j], curve_mm = f.at(t.back()) - f.at(t[j]);
    if (shown_mm < 0.5 * curve_mm)
        return std::nullopt;
    for (double rest_s = at_s; rest_s < to_s; rest_s += 0.001)
        if (f.speedAt(rest_s) <= kAtRest * std::abs(needle_mm_s(rest_s)))
            return rest_s;
    return std::nullopt;
}

// A creep read from the force (creepRest).
struct Creep {
    std::size_t rest = 0;  // index of the first sample at rest
    SettlingFit shortfall;  // of the force below the line
    double b_Ns_per_m = 0.0;
    // How far the tissue creeps on after `t_s`: the shortfall over the level is b times the creep's speed.
    double leftAfter_mm(double t_s) const
    {
        return 1000.0 * std::max(0.0, shortfall.at(t_s) - shortfall.rest) * shortfall.tau_s / b_Ns_per_m;
    }
};

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

// Whether the picture shows too little of the creep the force read (`creep`) between `from_s`
// and `to_s` for it to have been there: where the creep stands out of the picture's noise
// (`noise_mm_s`, each reading's) four times over and moves it half a pixel, the frames show
// under half of it (slow motion reads short in the picture, not by half).
bool creepUnseen(const TissueMotion& tissue, const Creep& creep, double from_s, double to_s, int direction, double frame_s,
                 double noise_mm_s)
{
    const double expected_mm = creep.leftAfter_mm(from_s) - creep.leftAfter_mm(to_s);
    double shown_mm = 0.0;
    int readings = 0;
    for (std::size_t k = 0; k < tissue.time_s.size() && k < tissue.velocity_mm_s.size(); ++k)
        if (tissue.time_s[k] - 0.5 * frame_s >= from_s - 1e-9 && tissue.time_s[k] + 0.5 * frame_s <= to_s + 1e-9 &&
            std::isfinite(tissue.velocity_mm_s[k])) {
            shown_mm += direction * tissue.velocity_mm_s[k] * frame_s;
            ++readings;
        }
    if (readings == 0 || !(tissue.px_per_mm > 0.0) || expected_mm * tissue.px_per_mm < 0.5 ||
        expected_mm < 4.0 * noise_mm_s * frame_s * std::sqrt(double(readings)))
        return false;
    return shown_mm < 0.5 * expected_mm;
}

// The time a jump in the force takes once smoothed (the smoothing spreads an instant over about
// 20 ms).
constexpr double kJump_s = 0.03;
// The run's first moments, where the stage starts at speed (see firstStrokeCarried).
constexpr double kStartTransient_s = 0.05;
// How much the needle must slow over a rise of the force for it to be the soft part's push (see
// the break-away on the stiff part).
constexpr double kSlowing = 0.95;
// A first stroke whose strongest force stays under this share of what its direction's whole
// strokes reach never released the tissue.
constexpr double kReleased = 0.8;
constexpr double kTrustSum_px = 3.0;  // how far the needle moves the picture in a reading that tests it
// Clear readings a picture needs where the force is plain before it may overrule the force: one
// that gives fewer (its noise above a slow needle's motion) is unchecked, not trusted.
constexpr int kMinJudged = 10;

// The sliding lines F = C + b·v of the run (friction_fit.h, its band found in the data, no
// phases used); nullopt when the fit fails.
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

// Whether the run's first stroke, from the centre, never released the tissue (a throughout):
// it may reach only the plate's soft part. The tissue breaks away only where the force reaches
// static friction, which the run's whole strokes of that direction show as their strongest
// force: the first stroke stays well below it (kReleased), and below the sliding line everywhere
// (the tissue never slides). Its first moments are left out, where the stage starts at speed and
// the tissue may slip for a moment in the gap, which is no phase; but it must be carried once the
// stage is at speed (the force well below the sliding line), not go on sliding. `force` is the
// smoothed force, `strokes` the run's strokes in order.
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
    auto started = [&](std::size_t i) { return run.time_s[i] - run.time_s.front() >= kStartTransient_s; };
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
        if (run.time_s[i] - run.time_s.front() < 2.0 * kStartTransient_s) {
            carried_N += along(i, first);
            slidingSum_N += sliding(i, first);
        }
    }
    return slidingSum_N > 0.0 && carried_N < 0.5 * slidingSum_N;
}

    // The picture's velocity noise: most of the time the tissue rests (c), so a low
    // quantile of its measured speed is the noise the picture adds. Where it is carried most
    // of the time (a plate gap nearly as wide as the stroke) that quantile is a speed, so the
    // reading-to-reading jitter bounds it too: the second differences of a smooth motion are
    // small, those of noise σ·√6.
double pictureNoise_mm_s(const TissueMotion* tissue)
{
    double videoNoise_mm_s = 0.0;
    if (tissue) {
        std::vector<double> speeds, jitter;
        const std::vector<double>& tv = tissue->velocity_mm_s;
        for (std::size_t k = 0; k < tv.size(); ++k) {
            if (std::isfinite(tv[k]))
                speeds.push_back(std::abs(tv[k]));
            if (k >= 1 && k + 1 < tv.size() && std::isfinite(tv[k - 1]) && std::isfinite(tv[k]) && std::isfinite(tv[k + 1]))
                jitter.push_back(std::abs(tv[k - 1] - 2.0 * tv[k] + tv[k + 1]));
        }
        if (!speeds.empty()) {
            std::nth_element(speeds.begin(), speeds.begin() + std::ptrdiff_t(speeds.size() / 4), speeds.end());
            videoNoise_mm_s = speeds[speeds.size() / 4];
        }
        if (jitter.size() >= 10) {
            std::nth_element(jitter.begin(), jitter.begin() + std::ptrdiff_t(jitter.size() / 2), jitter.end());
            videoNoise_mm_s = std::min(videoNoise_mm_s, 1.4826 * jitter[jitter.size() / 2] / std::sqrt(6.0));
        }
    }
    return videoNoise_mm_s;
}

// A picture to be trusted where it disagrees with the force must first agree with it
// where the force is plain: moving with the needle in the force's a, resting in its c,
// wherever the picture moves clearly (over several frames, 3 px: a picture that drops and
// repeats frames is off by a frame's motion at times, a third of a 1.5 px reading; the
// boundaries below want the finer time). Below nine in ten it is too unclear to judge
// (noise, blur, a wrong clock) and leaves the force's phases as they are, unless hardly
// any of its clear readings (one in 25) are ones the tissue cannot give: moving backwards
// against the needle, or faster than it. A garbled picture or a clock three frames wrong
// reads those often, of either sign, while a clear one that disagrees with the force is
// the force placing a boundary wrong (the tissue slowing on the plate, or slipping at a
// fast reversal, reads in between carried and resting: possible, and no objection). But
// a picture blind to the motion reads the tissue at rest wherever it looks, and that too is
// possible: it must show the tissue carried in at least half of the force's a, which the
// force tells well (the tissue, pulled along, holds it far below the sliding line). The
// force's c may be wrong for most of a stroke (a plate gap nearly as wide as the stroke: 1
// of 56 readings at rest, rightly), its a not (seed 424242 phase case 20, a blurred picture
// with little texture at 1.5 px/mm: not one of 19 readings in the force's a carried, 3 of 75
// impossible; trusted, it cut every a short, 74.3 % against the force's 94.6 %).
bool pictureTrusted(const Run& run, const TissueMotion* tissue, double videoNoise_mm_s, const SuggestOptions& o)
{
    bool videoTrusted = tissue != nullptr;
    if (tissue && tissue->px_per_mm > 0.0 && tissue->time_s.size() > 1) {
        const double frame_s = (tissue->time_s.back() - tissue->time_s.front()) / double(tissue->time_s.size() - 1);
        const QStringList plain = phasePerSample(suggestPhaseLabels(run, nullptr, o), tissue->time_s);
        int judged = 0, agreed = 0, impossible = 0, judgedInA = 0, carriedInA = 0;
        for (std::size_t k = 0; k < tissue->time_s.size() && k < tissue->velocity_mm_s.size(); ++k) {
            const PictureReading r = pictureReading(run, *tissue, k, run.time_s.front(), videoNoise_mm_s, 0.5 * frame_s, kTrustSum_px);
            if (!r.clear)
                continue;
            const QString& p = plain[qsizetype(k) - r.pairs / 2];
            if (p != QLatin1String("a") && p != QLatin1String("c"))
                continue;
            const double ratio = r.tissue_mm / r.needle_mm;
            ++judged;
            // Carried: with the needle, not faster; resting: still, not moving backwards.
            const bool carried = ratio >= 0.5 && ratio <= 1.5, resting = std::abs(ratio) < 0.25;
            agreed += p == QLatin1String("a") ? carried : resting;
            impossible += ratio < -0.25 || ratio > 1.5;
            if (p == QLatin1String("a")) {
                ++judgedInA;
                carriedInA += carried;
            }
        }
        const bool seesCarried = judgedInA < kMinJudged / 2 || 2 * carriedInA >= judgedInA;
        videoTrusted = judged >= kMinJudged && (agreed >= 0.9 * judged || (impossible <= 0.04 * judged && seesCarried));
    }
    return videoTrusted;
}

// The force less the needle holder's inertia, lightly smoothed (a moving average over 2·half + 1 samples).
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

// The run's sliding lines as the phases read them: the friction fit's (band found in the data,
// no phases used), each direction's line replaced by the one most of the force follows
// (slidingLine), and what the lines say of each direction (0: insertion, 1: withdrawal).
struct PhaseLines {
    std::optional<FrictionFit> fit;  // nullopt when the fit fails
    // A direction whose needle never leaves the zero band holds the force at static friction
    // once the tissue meets the plate: the fitted line is flat, at D (it changes by less than
    // 5 % over the speeds), and the tissue, stuck again against the plate for a moment, lets
    // the force dip below it.
    bool held[2] = {false, false};
    double heldLevel_N[2] = {0.0, 0.0};
    bool neverSlid[2] = {false, false};  // a direction whose force shows no sliding at all (phaseLines)
    double noise_N = 0.0;  // the smoothed force's
};

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
        // search finds none) and the fit's C and b are not above zero by two standard errors. A plate gap
        // nearly as wide as the stroke: the slab, carried across it, pulls on the needle only
        // with its inertia, meets the plate near the turning point and is taken back before it
        // breaks away, or slides for a moment only. The fit's line through that force (C < 0,
        // or near 0 with errors larger than itself) read most of each stroke as c (17.7 to
        // 66.2 %; random draws over the command line at short reach, seed 4711: 8 runs of 40).
        // Where the search finds a line, the fit's errors are only the sliding's brevity: a
        // stroke that slides briefly slides (seed 9191 at the matrix's edge: 4 runs read 4 to 14
        // points worse as carried).
        auto slides = [](double c_N, double seC_N, double b, double seB) { return c_N > 2.0 * seC_N || b > 2.0 * seB; };
        out.neverSlid[0] = !(up.ok && up.c0_N > 0.0) && !slides(lines->model.Cp_N, lines->seCp_N, lines->model.bp_Ns_per_m, lines->seBp_Ns_per_m);
        out.neverSlid[1] = !(down.ok && down.c0_N < 0.0) && !slides(lines->model.Cn_N, lines->seCn_N, lines->model.bn_Ns_per_m, lines->seBn_Ns_per_m);
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

// Where a stroke's phases change: sample indices into the run where a ends, b2 starts and c
// starts (each the stroke's end where that phase is absent).
struct StrokeBounds {
    std::size_t aEnd = 0, b2Start = 0, cStart = 0;
    std::optional<Creep> creep;  // the force read the tissue creeping to rest on the plate's soft part
};

// What every stroke is read from.
struct ForceReading {
    const Run& run;
    const std::vector<double>& v;      // the needle's velocity, mm/s
    const std::vector<double>& force;  // less the holder's inertia, over 2·half + 1 samples (forceLessHolder)
    int half = 1;
    double rate = 0.0;  // samples per second
    const PhaseLines& lines;
};

// One stroke's phases as the force reads them (models.md 5).
StrokeBounds boundsFromForce(const HalfCycle& h, const ForceReading& f, const SuggestOptions& o)
{
    const Run& run = f.run;
    const std::vector<double>& v = f.v;
    const std::vector<double>& force = f.force;
    const std::optional<FrictionFit>& lines = f.lines.fit;
    const bool* held = f.lines.held;
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
            } else if (held[h.direction > 0 ? 0 : 1] && off_N >= -0.5 * std::abs(line(i - 1))) {
                continue;  // stuck again against the plate for a moment: still at rest there
            } else if (onLine && ++off >= 5) {
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
        if (cStart + 10 < fitEnd && !held[h.direction > 0 ? 0 : 1]) {
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
                (held[h.direction > 0 ? 0 : 1] || strongest_N - h.direction * line(before) > tolerance)) {
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

// The imaging video's view of the tissue, the same for every stroke.
struct PictureView {
    const TissueMotion* tissue = nullptr;
    double noise_mm_s = 0.0;   // the picture's velocity noise (pictureNoise_mm_s)
    double frameHalf_s = 0.0;
    bool trusted = false;      // it agrees with the force where the force is plain (pictureTrusted)
};

// The picture's say on a stroke's bounds as the force read them (`b`, changed in place); `t0`
// and `t1` are where the stroke starts and where the next one starts. Returns what the labels
// were suggested from.
QString placeByPicture(const HalfCycle& h, double t0, double t1, StrokeBounds& b, const PictureView& p, const ForceReading& f,
                       const QString& forceSource, const SuggestOptions& o)
{
    const Run& run = f.run;
    const std::vector<double>& v = f.v;
    const std::optional<FrictionFit>& lines = f.lines.fit;
    const TissueMotion* tissue = p.tissue;
    const double videoNoise_mm_s = p.noise_mm_s, frameHalf_s = p.frameHalf_s;
    const bool videoTrusted = p.trusted;
    const QString videoSource = QStringLiteral("suggested from the tissue's motion in %1 (timed by force and position)").arg(tissue->source);
    std::size_t &aEnd = b.aEnd, &cStart = b.cStart, &b2Start = b.b2Start;
    const std::optional<Creep>& creep = b.creep;
    QString source = forceSource;
    // The picture measures the relative velocity itself, one value per pair of frames:
    // a while the tissue keeps up with the needle, c once it has stopped. It decides
    // between which frames each boundary lies; the force, sampled far finer, places
    // it there when it agrees, and is overruled when it does not.
    const std::size_t forceA = aEnd, forceC = std::min(cStart, h.end);
    // a ends between the last pair of frames in which the tissue had kept up with the
    // needle since the turning point (its displacement equal to the needle's, within
    // the picture's noise) and the first in which it has fallen behind; c starts
    // between the last in which it still moved and the first in which it rests.
    // Displacements, not speeds, for a: a slow needle moves the picture by a fraction
    // of a pixel per frame, too little to judge frame by frame.
    std::optional<std::pair<double, double>> aWindow, cWindow;
    std::optional<double> firstBehind, pendingBehind, pendingRest;
    double pendingBehindEnd_s = t0;  // where the frames of the pending reading end
    bool followed = false, measured = false, anyClear = false, wasNotResting = false;
    double lastFollow = t0, lastMoving = t0, lastClearFollow = t0;
    const double frame_s = 2.0 * frameHalf_s;
    std::optional<double> reference_mm;
    double carried_mm = 0.0;
    int steps = 0;
    double pendingCatchUpEnd_s = std::numeric_limits<double>::infinity();  // where the frames of a first reading carried again end
    const double bandEdge_mm_s = lines ? 1000.0 * lines->bandSlowingDown_m_s / 2.0 : o.zeroBand_mm_s / 2.0;
    for (std::size_t k = 0; k < tissue->time_s.size() && k < tissue->velocity_mm_s.size(); ++k) {
        const double tk = tissue->time_s[k];
        if (tk - frameHalf_s < t0 || tk >= t1 || !std::isfinite(tissue->velocity_mm_s[k]))
            continue;
        const PictureReading r = pictureReading(run, *tissue, k, t0, videoNoise_mm_s, frameHalf_s);
        const double vn = h.direction * r.needle_mm_s(), vtk = h.direction * r.tissue_mm_s();
        const double noiseHere_mm_s = videoNoise_mm_s / std::sqrt(double(r.pairs));
        const double at_s = r.mid_s();  // the reading stands for the pair of frames around here
        if (!reference_mm)
            reference_mm = positionAtTime(run, tk - frameHalf_s);
        carried_mm += h.direction * tissue->velocity_mm_s[k] * frame_s;
        ++steps;
        const double needle_mm = h.direction * (positionAtTime(run, tk + frameHalf_s) - *reference_mm);
        // Kept up: within the noise and a sixth of the travel; fallen behind: by more than
        // the noise and 40 % (slow motion reads short in the picture: sub-pixel shifts
        // are pulled towards whole pixels). The tissue never falls behind by more than
        // the needle has moved: a picture that reads it moving backwards reads noise.
        const double noise_mm = 3.0 * videoNoise_mm_s * frame_s * std::sqrt(double(steps));
        const double shortfall_mm = needle_mm - std::max(0.0, carried_mm);
        // Reading by reading where the picture moves clearly (speeds read true), else by
        // the displacement since the turning point.
        const bool clear = r.clear && vn > 0.0;
        anyClear |= clear;
        // Fallen behind, then carried at the needle's speed again before coming to rest:
        // the tissue did not meet the plate, which stops it for the stroke. It slipped
        // (the needle's jump at the run's start, or a reversal faster than static
        // friction can follow) or the picture garbled a frame or two. Counted afresh from
        // there, over two readings of their own frames, each within the needle's speed
        // and the needle clear of the stick band (twice its edge): slower, the tissue at
        // rest on the plate sticks to the needle again and is carried into the turning
        // point, still c.
        const bool carriedClearly = clear && vtk >= 0.8 * vn && vtk <= 1.5 * vn && vn >= 2.0 * bandEdge_mm_s;
        if ((firstBehind || pendingBehind) && carriedClearly) {
            if (r.from_s >= pendingCatchUpEnd_s - 1e-9) {
                firstBehind.reset();
                pendingBehind.reset();
                cWindow.reset();
                pendingRest.reset();
                pendingCatchUpEnd_s = std::numeric_limits<double>::infinity();
                followed = true;
                lastFollow = lastClearFollow = at_s + frameHalf_s;
                reference_mm = positionAtTime(run, tk + frameHalf_s);
                carried_mm = 0.0;
                steps = 0;
                wasNotResting = true;
                continue;
            }
            pendingCatchUpEnd_s = std::min(pendingCatchUpEnd_s, r.to_s);
        } else {
            pendingCatchUpEnd_s = std::numeric_limits<double>::infinity();
        }
        // Two readings in a row decide: one may be a repeated or garbled frame. Readings
        // summed over a few pairs share frames, and one repeated frame pulls down each
        // reading that holds it, so the second must be over frames of its own.
        if (!firstBehind) {
            if ((clear && vtk < 0.5 * vn) || shortfall_mm > noise_mm + 0.4 * needle_mm) {
                if (pendingBehind && r.from_s >= pendingBehindEnd_s - 1e-9) {
                    firstBehind = pendingBehind;
                } else if (!pendingBehind) {
                    pendingBehind = at_s + frameHalf_s;
                    pendingBehindEnd_s = r.to_s;
                }
            } else if ((clear && vtk >= 0.8 * vn) || (needle_mm > 0.0 && shortfall_mm <= noise_mm + 0.15 * needle_mm)) {
                followed = true;
                lastFollow = at_s + frameHalf_s;
                if (clear && vtk >= 0.8 * vn)
                    lastClearFollow = lastFollow;
                pendingBehind.reset();
            }
        }
        if (vn < std::max(o.zeroBand_mm_s / 2, 4.0 * noiseHere_mm_s))
            continue;  // too slow to tell moving from resting
        measured = true;
        const bool resting = vtk < std::max(0.25 * vn, 2.0 * noiseHere_mm_s);
        // From the first reading behind the needle on (a tissue that stops within a
        // frame is behind and resting in the same reading). One reading between resting
        // and clearly moving is noise, two in a row are motion.
        if ((firstBehind || pendingBehind) && !cWindow) {
            const bool moving = !resting && (vtk >= 0.5 * vn || wasNotResting);
            if (moving) {
                lastMoving = std::max(at_s, lastFollow);
                pendingRest.reset();
            } else if (resting && pendingRest) {
                cWindow = std::make_pair(std::max(lastMoving, lastFollow), *pendingRest);
            } else if (resting) {
                pendingRest = at_s;
            }
        } else if (!cWindow) {
            pendingRest.reset();
        }
        wasNotResting = !resting;
    }
    // The tissue slows down once it meets the plate (b1) and still reads as keeping up
    // in the pair of frames it does so: a may have ended a frame before lastFollow.
    if (firstBehind)
        aWindow = std::make_pair(lastFollow - frame_s, cWindow ? cWindow->second : *firstBehind);
    auto sampleAt = [&](double t) {
        return std::size_t(std::lower_bound(run.time_s.begin() + std::ptrdiff_t(h.start), run.time_s.begin() + std::ptrdiff_t(h.end), t) -
                           run.time_s.begin());
    };
    // A frame and a half of slack each side: a value stands for the whole pair of
    // frames, and a picture that is noisy, compressed or repeats frames is off by one.
    const double slack = 3.0 * frameHalf_s;
    auto place = [&](std::size_t fromForce, const std::pair<double, double>& w) {
        const double tf = fromForce < h.end ? run.time_s[fromForce] : t1;
        if (tf >= w.first - slack && tf <= w.second + slack)
            return fromForce;
        return sampleAt(0.5 * (w.first + w.second));
    };
    const std::pair<double, double> aMid = aWindow ? std::make_pair(aWindow->first, *firstBehind) : std::make_pair(t0, t0);
    if (!videoTrusted) {
        source = forceSource + QStringLiteral(" (the tissue's motion in %1 too unclear to judge)").arg(tissue->source);
    } else if (tissue->time_s.empty() || t1 <= tissue->time_s.front() || t0 >= tissue->time_s.back()) {
        // A video started after the recording (or ended before it) has no frame of it.
        source = forceSource + QStringLiteral(" (%1 does not cover this stroke)").arg(tissue->source);
    } else if (!anyClear) {
        // The picture moved less than a pixel or two a frame all through: what it
        // measures reads short and cannot overrule the force.
        source = forceSource + QStringLiteral(" (the tissue moved too little per frame in %1 to judge)").arg(tissue->source);
    } else if (measured && !aWindow && followed) {
        // The tissue kept up with the needle as far as the picture tells. Near the
        // turning point the needle moves the picture too little to tell a tissue at rest
        // from one carried: where the force has the tissue sliding, c stands, though not
        // before the last reading that saw the tissue keep up clearly.
        if (forceC < h.end) {
            aEnd = std::max(forceA, sampleAt(lastClearFollow));
            cStart = std::max(forceC, aEnd);
            // Unless the needle moves the picture less than a clear reading needs
            // (kClearPair_px) from there to its turning point: the picture cannot have
            // seen the tissue rest, and the force cannot tell either (a slab carried onto
            // the plate's soft part presses on it as a resting one would). A stroke within
            // the slab's free travel had a c at every turning point, the needle sliding
            // 0.03-0.1 mm in it (friction_cli_matrix.py --video seed 630281 r0).
            const double left_mm = std::abs(run.position_mm[h.end - 1] - run.position_mm[std::min(cStart, h.end - 1)]);
            if (tissue->px_per_mm > 0.0 && left_mm * tissue->px_per_mm < kClearPair_px)
                aEnd = h.end;
        } else {
            aEnd = h.end;
        }
        source = videoSource;
    } else if (aWindow) {
        aEnd = place(forceA, *aWindow);
        if (aEnd != forceA)
            aEnd = sampleAt(0.5 * (aMid.first + aMid.second));
        // No resting pair of readings: the tissue moved up to the turning point, unless
        // the picture stopped telling (the video ends, or the needle too slow to judge)
        // before the force's c began: then the force's c stands.
        const double forceC_s = forceC < h.end ? run.time_s[forceC] : t1;
        // A picture read reading by reading takes a slow creep for rest: a window before
        // where the force read the creep's end does not overrule it.
        // Unless the frames after the window show under half the creep the force read,
        // where it would stand out of their noise: the force fell short of its line for
        // another reason (liver3 at 0.81 Hz, a 30 mm slab: c placed
        // 80 ms late where the tissue stopped within a frame, seed 518445 phase case 11).
        const bool creepSeen = creep && cWindow && cWindow->second <= forceC_s &&
                               !creepUnseen(*tissue, *creep, cWindow->second, forceC_s, h.direction, frame_s, videoNoise_mm_s);
        cStart = cWindow && !creepSeen ? place(forceC, *cWindow) : (lastMoving > forceC_s + slack ? h.end : forceC);
        // A tissue that settles slowly does so on the plate's soft part (b1): against
        // its stiff part it stops within a frame. So c starts later, and b2, if any, was
        // too brief to see.
        if (cWindow) {
            const auto needle = [&](double t) { return v[std::min(sampleAt(t), h.end - 1)]; };
            const double fromA = run.time_s[std::min(aEnd, h.end - 1)], atC = run.time_s[std::min(cStart, h.end - 1)];
            if (const std::optional<double> rest = laterRest(*tissue, fromA, t1, atC, h.direction, frame_s, needle))
                b2Start = cStart = sampleAt(*rest);
        }
        cStart = std::max(cStart, aEnd);
        if (b2Start < aEnd || b2Start > cStart)
            b2Start = cStart - (cStart - aEnd) / 4;
        source = videoSource;
    }
    return source;
}

}  // namespace

Labels suggestPhaseLabels(const Run& run, const SuggestOptions& o)
{
    return suggestPhaseLabels(run, nullptr, o);
}

Labels suggestPhaseLabels(const Run& run, const TissueMotion* tissue, const SuggestOptions& o)
{
    Labels out;
    if (run.size() < 10)
        return out;
    const std::vector<double> v = velocity(run);
    double fastest = 0.0;
    for (double x : v)
        fastest = std::max(fastest, std::abs(x));
    const double videoNoise_mm_s = pictureNoise_mm_s(tissue);
    const PictureView picture{tissue, videoNoise_mm_s,
                              tissue && tissue->time_s.size() > 1
                                  ? 0.5 * (tissue->time_s.back() - tissue->time_s.front()) / double(tissue->time_s.size() - 1)
                                  : 0.0,
                              tissue && pictureTrusted(run, tissue, videoNoise_mm_s, o)};
    const std::size_t n = run.size();
    const double rate = (n - 1) / std::max(1e-9, run.time_s.back() - run.time_s.front());
    const int half = std::max(1, int(0.01 * rate));
    const std::vector<double> force = forceLessHolder(run, v, half);
    const PhaseLines phaseLinesOfRun = phaseLines(run, force, v, fastest, rate, half);
    const std::optional<FrictionFit>& lines = phaseLinesOfRun.fit;
    const ForceReading reading{run, v, force, half, rate, phaseLinesOfRun};
    const QString forceSource = lines ? QStringLiteral("suggested from force and position")
                                      : QStringLiteral("suggested from position (velocity band)");
    // A stroke slower than the thesis's band (±1 mm at 0.4 Hz tops at 2.5 mm/s) still turns:
    // its turning points are found within half its top speed, not lost in one long label.
    const std::vector<HalfCycle> cycles = halfCycles(v, std::min(o.zeroBand_mm_s, 0.5 * fastest));
    // No sliding anywhere (the force the same going in and out at each depth): the slab was
    // carried by the needle all along, whatever lines the force's noise lets be drawn.
    const bool carried = carriedThroughout(run, v);
    const QString carriedSource = QStringLiteral("suggested from force and position (no friction between directions: the tissue moved with the needle)");
    // A stroke far shorter than the run's usual one is the stage settling (an overshoot when it
    // stops), not a stroke: the tissue cannot break away in it and stays carried (a).
    auto travel_mm = [&](const HalfCycle& h) { return std::abs(run.position_mm[h.end - 1] - run.position_mm[h.start]); };
    double usualTravel_mm = 0.0;
    {
        std::vector<double> travels;
        for (const HalfCycle& h : cycles)
            if (h.end > h.start + 4)
                travels.push_back(travel_mm(h));
        if (!travels.empty()) {
            std::nth_element(travels.begin(), travels.begin() + std::ptrdiff_t(travels.size() / 2), travels.end());
            usualTravel_mm = travels[travels.size() / 2];
        }
    }
    std::vector<const HalfCycle*> strokes;
    for (const HalfCycle& h : cycles)
        if (h.end > h.start + 4)
            strokes.push_back(&h);
    const bool firstCarried = lines && firstStrokeCarried(run, force, v, strokes, *lines);
    const HalfCycle* lastStroke = strokes.empty() ? nullptr : strokes.back();
    for (const HalfCycle* stroke : strokes) {
        const HalfCycle& h = *stroke;
        const QString track = h.direction > 0 ? QStringLiteral("insertion") : QStringLiteral("withdrawal");
        // Up to where the next half-cycle starts, so that the phases tile the run without gaps.
        const double t0 = run.time_s[h.start], t1 = h.end < run.size() ? run.time_s[h.end] : run.time_s.back();
        const bool neverReleased = firstCarried && stroke == strokes.front();
        if (travel_mm(h) < 0.1 * usualTravel_mm || carried || (neverReleased && !tissue)) {
            out.push_back({track, QStringLiteral("a"), t0, t1, carried ? carriedSource : forceSource});
            continue;
        }
        // The first stroke that never released the tissue, and a direction that never slid, are
        // carried throughout as the force reads them; a trusted picture may still say otherwise.
        StrokeBounds b = neverReleased || phaseLinesOfRun.neverSlid[h.direction > 0 ? 0 : 1] ? StrokeBounds{h.end, h.end, h.end, {}}
                                                                                             : boundsFromForce(h, reading, o);
        const QString source = tissue ? placeByPicture(h, t0, t1, b, picture, reading, forceSource, o) : forceSource;
        if (b.aEnd >= h.end) {
            out.push_back({track, QStringLiteral("a"), t0, t1, source});
            continue;
        }
        b.cStart = std::min(std::max(b.cStart, b.aEnd), h.end - 1);
        b.b2Start = std::clamp(b.b2Start, b.aEnd, b.cStart);
        const double ta = run.time_s[std::min(b.aEnd, h.end - 1)], tb = run.time_s[b.b2Start], tc = run.time_s[b.cStart];
        if (ta > t0)
            out.push_back({track, QStringLiteral("a"), t0, ta, source});
        if (tb > ta)
            out.push_back({track, QStringLiteral("b1"), ta, tb, source});
        if (tb < tc)
            out.push_back({track, QStringLiteral("b2"), tb, tc, source});
        if (t1 > tc)
            out.push_back({track, QStringLiteral("c"), tc, t1, source});
    }
    // After the last stroke the needle comes to rest. When it settles back from its last
    // extreme, that is one more turning point and the tissue it holds is carried (a) to the
    // end; otherwise the tissue stays at rest (c).
    if (lastStroke && lastStroke->end < n) {
        const HalfCycle& h = *lastStroke;
        std::size_t extreme = h.start;
        for (std::size_t i = h.start; i < n; ++i)
            if (h.direction * run.position_mm[i] > h.direction * run.position_mm[extreme])
                extreme = i;
        const double back_mm = h.direction * (run.position_mm[extreme] - run.position_mm[n - 1]);
        Label& lastLabel = out.back();
        const double tx = run.time_s[extreme];
        if (back_mm > kSettleBack_mm && tx > lastLabel.start_s && lastLabel.label != QLatin1String("a")) {
            lastLabel.end_s = std::min(lastLabel.end_s, tx);
            const QString track = h.direction > 0 ? QStringLiteral("withdrawal") : QStringLiteral("insertion");
            out.push_back({track, QStringLiteral("a"), lastLabel.end_s, run.time_s.back(), lastLabel.comment});
        } else {
            lastLabel.end_s = run.time_s.back();
        }
    }
    return out;
}

Labels suggestEventLabels(const Run& run) { return suggestEventLabels(run, {}); }

Labels suggestEventLabels(const Run& run, const std::vector<SurfaceTrace>& surfaces, QString* relaxationProblem)
{
    Labels out;
    try {
        const InsertionEvents e = detectEvents(run);
        auto point = [&](const QString& name, double t, const QString& comment) {
            out.push_back({QStringLiteral("events"), name, t, t, comment});
        };
        const QString fromForce = QStringLiteral("suggested from force (event detection)");
        point(QStringLiteral("contact"), e.contact.time_s, fromForce);
        point(QStringLiteral("puncture"), e.puncture.time_s, fromForce);
        // Relaxation only from the picture: the tissue's surface springing back after the
        // puncture (to x_s3, models.md 4) takes a few tenths of a second, and the force does
        // not show when it is done (the end of its drop, a few milliseconds after the
        // puncture, is not it). Its duration comes from the video; it is counted from the
        // force's puncture, so that the clocks' residual offset does not enter.
        const SurfaceTrace* best = nullptr;
        std::optional<SpringBack> fit;
        QStringList problems;
        for (const SurfaceTrace& surface : surfaces) {
            QString problem;
            const std::optional<SpringBack> s = fitSpringBack(surface, e.puncture.time_s, e.contact.time_s, &problem);
            if (!s)
                problems << (surface.source.isEmpty() ? problem : surface.source + QStringLiteral(": ") + problem);
            // A trace that loses the surface reads its motion short: the larger spring-back wins.
            else if (!fit || s->amplitude_px > fit->amplitude_px)
                fit = s, best = &surface;
        }
        if (fit)
            point(QStringLiteral("relaxation"), fit->relaxed_s,
                  QStringLiteral("suggested from the surface's spring-back in %1 (4 tau after the puncture, tau %2 s, %3 px)")
                      .arg(best->source)
                      .arg(fit->tau_s, 0, 'f', 3)
                      .arg(fit->amplitude_px, 0, 'f', 1));
        else if (relaxationProblem && !surfaces.empty())
            *relaxationProblem = problems.join(QStringLiteral("; "));
        for (const RunEvent& p : e.internalPunctures)
            point(QStringLiteral("internal puncture"), p.time_s, fromForce);
        std::stable_sort(out.begin(), out.end(), [](const Label& a, const Label& b) { return a.start_s < b.start_s; });
    } catch (const std::exception&) {
        // No puncture found (or too few samples): nothing to suggest.
        if (!surfaces.empty() && relaxationProblem)
            *relaxationProblem = nb::TrCore::tr("no puncture found in the force");
    }
    return out;
}

Labels suggestLabels(const Run& run, const SuggestOptions& options)
{
    const QString protocol = run.metadata.value(QStringLiteral("protocol"), QString());
    if (protocol == QLatin1String("friction"))
        return suggestPhaseLabels(run, options);
    if (!protocol.isEmpty())
        return suggestEventLabels(run);
    // No protocol named: several turning points mean a sinusoid.
    const Labels phases = suggestPhaseLabels(run, options);
    const auto turns = std::count_if(phases.begin(), phases.end(), [](const Label& l) { return l.label == QLatin1String("c"); });
    return turns >= 3 ? phases : suggestEventLabels(run);
}

}  // namespace nb
