#include "phase_reading.h"

#include "labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nb::phase_reading {

namespace {

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
// the needle's within 5 %, as phase c's fit of C and b takes it. Or from where the curve stops
// short, all at once, if it does: a tissue slowing on the plate's soft part meets its stiff
// part still moving and stops there. Fitted without that stop, the curve bends too soon to
// stay flat after it, and puts the rest (and the tissue's travel left) too early (liver5 at
// 0.93 Hz, ±3.1 mm on a 15 mm slab: c called 3 frames early in one stroke, now within a frame).
// `direction` is the stroke's.
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
    std::vector<double> stops_s;
    for (double stop_s = from_s + 0.25 * frame_s; stop_s < t.back(); stop_s += 0.25 * frame_s)
        stops_s.push_back(stop_s);
    const SettlingFit f = fitSettlingFromOrStop(t, y, from_s, tauLo_s, tauHi_s, 60, stops_s);
    const double end_mm = f.at(t.back());
    // No settling: the tissue moving backwards, or still under way at ten frames.
    if (!(end_mm - f.d0 > 0.0) || f.tau_s >= tauHi_s || f.tau_s < 0.5 * frame_s)
        return std::nullopt;
    const double at_s = std::max(c_s, from_s);
    if ((end_mm - f.at(at_s)) * tissue.px_per_mm < kLeft_px || f.speedAt(at_s) * tissue.px_per_mm * frame_s < kMoving_px)
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

constexpr double kTrustSum_px = 3.0;  // how far the needle moves the picture in a reading that tests it
// Clear readings a picture needs where the force is plain before it may overrule the force: one
// that gives fewer (its noise above a slow needle's motion) is unchecked, not trusted.
constexpr int kMinJudged = 10;

}  // namespace

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

bool pictureTrusted(const Run& run, const TissueMotion* tissue, double videoNoise_mm_s, const SuggestOptions& o)
{
    bool videoTrusted = tissue != nullptr;
    if (tissue && tissue->px_per_mm > 0.0 && tissue->time_s.size() > 1) {
        const double frame_s = (tissue->time_s.back() - tissue->time_s.front()) / double(tissue->time_s.size() - 1);
        const QStringList plain = phasePerSample(suggestPhaseLabels(run, nullptr, o), tissue->time_s);
        int judged = 0, agreed = 0, impossible = 0, impossibleBeyondNoise = 0, judgedInA = 0, carriedInA = 0;
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
            // Backwards, or faster than half again the needle, by more than `margin`; the ratio's
            // own noise is the reading's over the needle's speed.
            auto impossibleBy = [&](double margin) { return ratio < -0.25 - margin || ratio > 1.5 + margin; };
            impossible += impossibleBy(0.0);
            impossibleBeyondNoise += impossibleBy(videoNoise_mm_s / std::sqrt(double(r.pairs)) / std::abs(r.needle_mm_s()));
            if (p == QLatin1String("a")) {
                ++judgedInA;
                carriedInA += carried;
            }
        }
        const bool seesCarried = judgedInA < kMinJudged / 2 || 2 * carriedInA >= judgedInA;
        // A slow needle moves the picture a pixel or two a frame, and single readings scatter
        // past what a tissue can do by their own noise (liver5 at 0.34 Hz, ±2.7 mm: 6 % of
        // them, the force wrong by 0.2 s in every stroke and the picture right; seed 9303 case
        // 4 at the matrix's edge, 82.7 % from the force). That is no garbled picture where it
        // sees the tissue carried nearly everywhere the force has it so. A noisy one that sees
        // it carried in 72 % of them stays unchecked (bench_accuracy --seed 612302 phase case
        // 0, heavy noise: 98.5 % from the force, 93.4 % had it been trusted).
        const bool seesCarriedClearly = judgedInA >= kMinJudged && carriedInA >= 0.8 * judgedInA;
        videoTrusted = judged >= kMinJudged && (agreed >= 0.9 * judged || (impossible <= 0.04 * judged && seesCarried) ||
                                                (impossibleBeyondNoise <= 0.04 * judged && seesCarriedClearly));
    }
    return videoTrusted;
}

QString placeByPicture(const HalfCycle& h, double t0, double t1, StrokeBounds& b, const PictureView& p, const ForceReading& f,
                       const QString& forceSource, const SuggestOptions& o)
{
    const Run& run = f.run;
    const std::vector<double>& v = f.v;
    const std::optional<FrictionFit>& lines = f.lines.fit;
    const TissueMotion* tissue = p.tissue;
    const double videoNoise_mm_s = p.noise_mm_s, frameHalf_s = p.frameHalf_s;
    const bool videoTrusted = p.trusted;
    const QString& videoSource = p.source;
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
    bool behindOnSharedFrames = false;
    double lastFollow = t0, lastMoving = t0, lastClearFollow = t0;
    const double frame_s = 2.0 * frameHalf_s;
    std::optional<double> reference_mm;
    double carried_mm = 0.0;
    int steps = 0;
    double pendingCatchUpEnd_s = std::numeric_limits<double>::infinity();  // where the frames of a first reading carried again end
    const double bandEdge_mm_s = lines ? 1000.0 * lines->bandSlowingDown_m_s / 2.0 : o.zeroBand_mm_s / 2.0;
    double peak_s = t0, top_mm_s = 0.0;  // where the needle is fastest, and how fast
    for (std::size_t i = h.start; i < h.end; ++i)
        if (h.direction * v[i] > top_mm_s)
            top_mm_s = h.direction * v[i], peak_s = run.time_s[i];
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
        // point, still c. That happens only as the needle slows into the band: while it
        // still speeds up (before its top speed), or keeps half its top speed, a tissue
        // carried again has caught up after a slip, whatever band the force found. Where the
        // tissue is carried most of the stroke (a plate gap nearly the stroke's width) the
        // sliding line is drawn from little, and the band found can be wider than the needle
        // ever goes (±15 mm/s for a top speed of 30: liver5 at 0.68 Hz, ±7 mm, a 5.7 mm gap;
        // a ended at the slip in every stroke moving in, and in the first, 56 %).
        const bool carriedClearly = clear && vtk >= 0.8 * vn && vtk <= 1.5 * vn &&
                                    (vn >= 2.0 * bandEdge_mm_s || r.to_s <= peak_s || vn >= 0.5 * top_mm_s);
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
        // reading that holds it, so the second must be over frames of its own. Or so far
        // behind that it would be even with those shared frames carried in full: near the
        // turning point, where the needle moves the picture little, the second reading adds
        // up pairs back into the first's, and the stroke may end before a third (liver2 at
        // 0.93 Hz, ±4.5 mm: the tissue seen stopping in each withdrawal, read as carried to
        // the turning point).
        if (!firstBehind) {
            if ((clear && vtk < 0.5 * vn) || shortfall_mm > noise_mm + 0.4 * needle_mm) {
                const bool ownFrames = r.from_s >= pendingBehindEnd_s - 1e-9;
                auto behindBeyondShared = [&] {
                    if (!clear)
                        return false;
                    // The pairs of frames of the first reading within this one.
                    const double shared = std::clamp(std::round((pendingBehindEnd_s - r.from_s) / frame_s), 0.0, double(r.pairs));
                    return vtk < 0.5 * vn * (r.pairs - shared) / r.pairs;
                };
                if (pendingBehind && (ownFrames || behindBeyondShared())) {
                    behindOnSharedFrames = !ownFrames;
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
    // Confirmed on shared frames only as far as the picture then sees the tissue rest: a stop
    // not seen at rest may be the picture a frame behind a tissue still moving, and without a
    // rest to place c by, the force's c would be given up for none (liver1 at 0.57 Hz, the
    // rendered view coded as DV: 4 of 6 withdrawals lost their c).
    if (behindOnSharedFrames && !cWindow)
        firstBehind.reset();
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

}  // namespace nb::phase_reading
