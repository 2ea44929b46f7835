#pragma once
// Friction identification (models.md section 5, eqs. 16-26): the modified Karnopp model
// from sinusoidal runs through a tissue slab, by linear least squares, with the mass either
// estimated (eq. 19) or known and removed (eq. 21).

#include "models.h"
#include "plate_give.h"
#include "run.h"

#include <QString>
#include <QStringList>
#include <optional>
#include <limits>
#include <span>
#include <vector>

namespace nb {

struct FrictionOptions {
    double thickness_mm = 0.0;                  // length of needle in tissue; > 0
    // The zero-velocity band is found in the data (estimateBand_m_s) unless one is given
    // (estimateBand false, band_m_s): every fit of a run, the command's, a session's analysis
    // and the plan report, gives the same numbers (the analysis kept a fixed ±2.5 mm/s).
    double band_m_s = 0.005;                    // zero-velocity band (±band/2), when given
    bool estimateBand = true;
    double mass_kg = kNeedleHolderMass_kg;      // removed from the force (eq. 21)...
    bool estimateMass = false;                  // ...or estimated with the friction (eq. 19)
    double smoothing_s = 0.02;                  // moving-average window
    // The tissue's velocity at each of the run's samples (m/s, the needle's axis and sign; NaN
    // where unmeasured), e.g. from the imaging video (core/tissue_trace.h). Given, C and b are
    // fitted against the relative velocity, as the model is written: a slab creeping back
    // against its plate all through the slide moves the force like a larger C (liver 3 at
    // 0.34 Hz: Cp 26 % high, from force and position alone). Samples without it are left out
    // of the sliding line; through each slide it is smoothed (tissueOverSlide, tissue_trace.h).
    // Empty: the tissue is taken to rest while the needle slides.
    std::vector<double> tissueVelocity_m_s;
    double tissueStep_s = 0.0;                  // the time between its measurements (a frame)
    int trimSamples = 100;                      // dropped at each end (filter edges)
};

// One direction's peak: the mean needle speed and force (the holder's mass removed, as
// measured: negative for - motion) over the samples just past the top speed
// (core/friction_peak_line.h: the line through several runs' peaks).
struct PeakPoint {
    double speed_m_s = 0.0;
    double force_N = 0.0;
    std::size_t samples = 0;
    // False when the force went on rising well past the top speed, or changed between the
    // quarters of the tops' later halves: the tissue was still carried or arriving at the
    // plate there (wide band, large gap, short stroke), so the point is not on the sliding
    // line and the line leaves it out.
    bool settled = true;
};
struct RunPeaks {
    std::optional<PeakPoint> positive, negative;
};
struct FrictionFit {
    KarnoppModel model;              // C, b from sliding samples; D from sticking ones
    KarnoppPerLength perLength;      // divided by the thickness in m
    double thickness_mm = 0.0;       // the length of needle in tissue used
    std::optional<double> massEstimate_kg;  // eq. 19 only
    double frequency_hz = 0.0;       // metadata `frequency_hz`, else estimated from position
    double rms_N = 0.0;              // of the sliding-sample residuals
    std::size_t positiveSamples = 0, negativeSamples = 0;
    bool relativeVelocity = false;   // C and b against the needle's velocity relative to the tissue's
    double band_m_s = 0.0;           // the band used (whole width), given or found
    bool bandEstimated = false;
    double bandSlowingDown_m_s = 0.0;  // found band before turning points (band_m_s: the wider)
    // Standard errors (N, N·s/m): the noise's, widened for the smoothing (neighbouring samples share
    // noise), and how far each moves when the sliding line may bend (its shape, which the noise
    // does not show), in quadrature.
    double seCp_N = 0.0, seCn_N = 0.0, seBp_Ns_per_m = 0.0, seBn_Ns_per_m = 0.0;
    // D's (N): the spread of the break-aways it averages over the root of their number; NaN
    // with fewer than two. breakawaysP/N: how many.
    double seDp_N = std::numeric_limits<double>::quiet_NaN(), seDn_N = std::numeric_limits<double>::quiet_NaN();
    std::size_t breakawaysP = 0, breakawaysN = 0;
    // Values that cannot be physical (b < 0, C < 0, |D| below C, D of the wrong sign) or that
    // the run does not determine (b's standard error above a quarter of it, and its C),
    // one sentence each; empty when all are plausible. Such values are not results.
    QStringList notPhysical;
    QStringList notPhysicalValues;   // which: "Cp", "Cn", "bp", "bn", "Dp", "Dn"
    // Where D came from: "phase a" (labels) or "velocity band" (the band around each turning
    // point); D_p averages the largest force of the stretches followed by + motion, D_n the
    // smallest of those followed by - motion; "none" when a direction has no such stretch.
    QString staticSource;
    RunPeaks peaks;                  // top-speed points, checked against this fit
    // A compliant slab springs back off the plate as the friction on it falls (the needle
    // slowing), by Ḟ/k: the relative velocity exceeds the needle's there. The fit then takes
    // F = C + b·(v - Ḟ/k) and reports b/k in s per direction (0: not shown by the run, the
    // plain line). k = b / springBack is the slab's stiffness against the plate, N/m.
    double springBackP_s = 0.0, springBackN_s = 0.0;
    // Each direction's slab give against its plate, read where the tissue is carried into it
    // (core/plate_give.h), where the run shows one that explains its sliding force: the sliding
    // line is then written in the needle's velocity less the resting tissue's, driven by that
    // give (restingTissueVelocity). Never read when a tissue trace is given.
    std::optional<PlateGive> plateGiveP, plateGiveN;
    // Each direction's sliding residual (rms) over the force's noise: about 1 when the line
    // explains the force; above 2 its C and b are flagged as not determined. The larger of the
    // line's through the samples it is fitted to and the one through those the force-rate check
    // left out as well (friction_fit.cpp, steadilySliding).
    double residualToNoiseP = 0.0, residualToNoiseN = 0.0;
    // The needle speeds (m/s, magnitudes) of each direction's sliding samples: C is the line
    // carried from there down to zero speed.
    // How far C moves (a fraction of C, signed) when each direction's sliding line may bend
    // (a v² term): beyond 5 % (and two standard errors) C and b are flagged as not determined.
    double bendShiftCp = 0.0, bendShiftCn = 0.0;
    double slidingFromP_m_s = 0.0, slidingToP_m_s = 0.0, slidingFromN_m_s = 0.0, slidingToN_m_s = 0.0;
    // Needle speeds (m/s, magnitudes) above which, slowing down from the top, the tissue was still
    // arriving at the plate: the force short of the sliding line there. Those samples are left
    // out of the line and of the peak point; infinite where the run shows no such thing.
    double arrivingAboveP_m_s = std::numeric_limits<double>::infinity();
    double arrivingAboveN_m_s = std::numeric_limits<double>::infinity();
};

// `phases`: one phase name per sample ("a", "b1", "b2", "c" or empty), e.g. from a labels
// file (phasePerSample) or the run's `phase` column; when given, C and b come from phase c
// and D from phase a. Without phases (empty list and no `phase` column) the velocity band
// decides. Throws FitError (too few samples, no motion, a direction missing, bad thickness).
FrictionFit fitFriction(const Run& run, const FrictionOptions& options, const QStringList& phases = {});

// The zero-velocity band (whole widths, m/s) of a sinusoidal run, found where the sliding
// line stops explaining the force: the lines are fitted to the clearly sliding samples (above
// 80 % of the peak speed) and extended towards zero speed one step (1/40 of the peak) at a
// time while the samples there follow them, by direction and apart for speeding up and
// slowing down; a step that departs from the line by more than its noise and 2 % of C is
// where sticking begins on that side. Throws FitError.
struct BandEstimate {
    double speedingUp_m_s = 0.0;   // after a turning point (the tissue carried along)
    double slowingDown_m_s = 0.0;  // before one
};
BandEstimate estimateBand(const Run& run, const FrictionOptions& options);
double estimateBand_m_s(const Run& run, const FrictionOptions& options);  // the wider of the two

// The thesis's conditioning (models.md 5, step 1): position and force smoothed with a moving
// average of `smoothing_s`, velocity and acceleration differentiated from the smoothed position
// and smoothed again. SI units.
struct ConditionedSignals {
    int window = 1;                       // samples in the moving average
    std::vector<double> x_m, v_m_s, a_m_s2, force_N;
    double noise_N = 0.0;                 // of the smoothed force (robust, from the raw samples)
};
ConditionedSignals conditionSignals(const Run& run, double smoothing_s);

// A direction's top speed (m/s, a magnitude) over samples [from, to) of a velocity: the 99.5th
// percentile of the speeds moving that way, not the single fastest (one noisy sample must not
// set it); nullopt with fewer than `fewest` such samples.
std::optional<double> topSpeed(const std::vector<double>& v_m_s, int sign, std::size_t from, std::size_t to, std::size_t fewest);

// Frequency of a sinusoidal position signal from its mean crossings; 0 when fewer than
// two crossings.
double estimateFrequency(const Run& run);

// Tables 4/5 layout: mean and sample standard deviation of the per-length values.
struct FrictionGroup {
    double frequency_hz = 0.0;       // mean frequency of the group (0 for "overall")
    std::size_t runs = 0;
    KarnoppPerLength mean, stdDev;   // NaN where too few runs give the value
    QStringList leftOut;             // values some member runs flagged and did not count for
    std::optional<double> massEstimateMean_kg, massEstimateStdDev_kg;
};
// Runs whose frequencies lie within 5 % of each other form a group; sorted by frequency.
std::vector<FrictionGroup> groupByFrequency(std::span<const FrictionFit> fits);
FrictionGroup overall(std::span<const FrictionFit> fits);

}  // namespace nb
