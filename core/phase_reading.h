#pragma once
// How suggested phase labels read a friction run (label_suggest.cpp): from the force, one
// stroke at a time (phase_from_force.cpp), and from the tissue's motion in the imaging video
// (phase_from_picture.cpp). Internal to core.

#include "friction_fit.h"
#include "label_suggest.h"
#include "run.h"
#include "settling_fit.h"
#include "signal.h"
#include "tissue_motion.h"

#include <QString>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace nb::phase_reading {

using nb::HalfCycle;  // core/signal.h

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

// The imaging video's view of the tissue, the same for every stroke.
struct PictureView {
    const TissueMotion* tissue = nullptr;
    double noise_mm_s = 0.0;   // the picture's velocity noise (pictureNoise_mm_s)
    double frameHalf_s = 0.0;
    bool trusted = false;      // it agrees with the force where the force is plain (pictureTrusted)
    QString source;            // what labels the picture placed were suggested from
};

// From the force (phase_from_force.cpp).

// Whether the force shows sliding friction at all: sliding adds C·sgn(ẋ) (models.md 5), so at
// one depth the force going in stands above the force coming out by about Cp + |Cn|, while a
// slab carried the whole time (a stroke shorter than the plate's gap) pushes back only with
// its inertia and the plate's spring, the same both ways at a depth. Over bins of depth along
// the moving samples (`v_mm_s`), the force in minus the force out: the slab was carried
// throughout when that difference is within the raw force's noise in the middle bin (twice
// σ) and in every bin (six σ, and 20 mN: a tenth of the least sliding friction a slab of a few
// millimetres gives). False when too few samples fill both directions of a bin.
bool carriedThroughout(const Run& run, const std::vector<double>& v_mm_s);

// The sliding lines F = C + b·v of the run (friction_fit.h, its band found in the data, no
// phases used); nullopt when the fit fails.
std::optional<FrictionFit> slidingLines(const Run& run);

// Whether the run's first stroke, from the centre, never released the tissue (a throughout):
// it may reach only the plate's soft part. The tissue breaks away only where the force reaches
// static friction, which the run's whole strokes of that direction show as their strongest
// force: the first stroke stays well below it (kReleased), and below the sliding line everywhere
// (the tissue never slides). Its first moments are left out, where the stage starts at speed and
// the tissue slips in the gap until it has caught up with the needle, which is no phase (50 ms at
// least, until the force first falls under half the sliding line, within the stroke's first
// third); but it must be carried from there (the force well below the sliding line), not go on
// sliding. `force` is the smoothed force, `strokes` the run's strokes in order.
bool firstStrokeCarried(const Run& run, const std::vector<double>& force, const std::vector<double>& v_mm_s,
                        const std::vector<const HalfCycle*>& strokes, const FrictionFit& lines);

// Whether the tissue stayed stuck to the needle through the turning point between stroke `h` and
// the `next`: pressed on the plate and back, it never slid. The tissue meets the plate at one of
// its own positions (the gap), so the needle's depth where the plate starts to push going in and
// where it stops coming out differ by exactly how far the needle slid through the tissue in
// between. Read from `force` (forceLessHolder) against the force the carried tissue gives in
// each stroke's middle third; stuck when that slide is within 3 % of the needle's travel from
// where the push began to the turning point. `noise_N` is the smoothed force's.
bool stuckThroughTurn(const Run& run, const std::vector<double>& force, const HalfCycle& h, const HalfCycle& next, double noise_N);

// The force less the needle holder's inertia, lightly smoothed (a moving average over 2·half + 1 samples).
std::vector<double> forceLessHolder(const Run& run, const std::vector<double>& v, int half);

// The run's PhaseLines: `force` from forceLessHolder (over 2·half + 1 samples), `v` the needle's
// velocity and `fastest` its top speed (mm/s), `rate` the samples per second.
PhaseLines phaseLines(const Run& run, const std::vector<double>& force, const std::vector<double>& v, double fastest, double rate, int half);

// One stroke's phases as the force reads them (models.md 5).
StrokeBounds boundsFromForce(const HalfCycle& h, const ForceReading& f, const SuggestOptions& o);

// From the picture (phase_from_picture.cpp).

// The picture's velocity noise: most of the time the tissue rests (c), so a low
// quantile of its measured speed is the noise the picture adds. Where it is carried most
// of the time (a plate gap nearly as wide as the stroke) that quantile is a speed, so the
// reading-to-reading jitter bounds it too: the second differences of a smooth motion are
// small, those of noise σ·√6.
double pictureNoise_mm_s(const TissueMotion* tissue);

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
bool pictureTrusted(const Run& run, const TissueMotion* tissue, double videoNoise_mm_s, const SuggestOptions& o);

// The picture's say on a stroke's bounds as the force read them (`b`, changed in place); `t0`
// and `t1` are where the stroke starts and where the next one starts. Returns what the labels
// were suggested from.
QString placeByPicture(const HalfCycle& h, double t0, double t1, StrokeBounds& b, const PictureView& p, const ForceReading& f,
                       const QString& forceSource, const SuggestOptions& o);

}  // namespace nb::phase_reading
