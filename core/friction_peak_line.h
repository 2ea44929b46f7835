#pragma once
// Dynamic friction C and damping b through the peak speeds of several sinusoidal runs of one
// slab (models.md section 5, the thesis's 0.2 / 0.5 / 0.8 Hz protocol).
//
// Why: a plain sliding line through one run assumes the tissue rests in phase c, so that the
// relative velocity is the needle's. A compliant slab does not: as the needle slows, friction
// falls and the tissue springs back off the plate, the relative velocity exceeds the needle's
// and the line tilts (C high, b low; a quarter too high for a slab with C small against b,
// like the thesis's Table 4 liver). fitFriction now follows that give itself; this line is
// the check that needs no model of it. At the top of a stroke the needle does not accelerate and the
// tissue, come to rest against the plate, has not yet begun to spring back: there the force
// is C + b·v with v the needle's own speed, whatever the band and however soft the tissue.
// Runs at different frequencies put that point at different speeds; the line through them
// gives C and b.

#include "friction_fit.h"
#include "run.h"

#include <cmath>
#include <optional>
#include <span>

namespace nb {

// The run's peaks from its conditioned signals, with the fit's trimming and mass (fitFriction
// calls this and keeps them in FrictionFit::peaks). Empty sides when a direction never moves.
// Above the fit's `arrivingAbove*_m_s` the tissue was still arriving at the plate: the top is
// taken below that speed. The fit's b takes the needle's slowing out across the top.
RunPeaks peakPoints(const ConditionedSignals& conditioned, const FrictionOptions& options, const FrictionFit& fit);

// A peak point must also lie on its own run's sliding line (within 1.5 % of its force): one
// below it was taken while the tissue still moved with the needle. Marks such points not
// settled. A run whose C or b the fit flagged (a sliding line bent by the slab's give) is
// checked so too and still gives its point: near the top, where the run's samples are, its line
// holds even where its C, carried far below them to zero speed, does not.
void checkAgainstFit(RunPeaks& peaks, const FrictionFit& fit);

struct PeakSpeedLine {
    KarnoppModel model;          // C and b only; D and the band are not defined by this line
    double seCp_N = 0.0, seCn_N = 0.0, seBp_Ns_per_m = 0.0, seBn_Ns_per_m = 0.0;
    std::size_t runs = 0;        // runs with a settled peak in at least one direction
    double slowest_m_s = 0.0, fastest_m_s = 0.0;  // the peak speeds spanned
};
// Per direction, from the runs whose peak in that direction settled; nullopt when a direction
// has fewer than three such runs (two fit any line exactly, leaving no error to judge a
// departure by) or their peak speeds differ by less than a fifth (an extrapolation from one
// point).
std::optional<PeakSpeedLine> peakSpeedLine(std::span<const RunPeaks> runs);

// How far (percent of the line's value) a run's own C departs from the line's, per direction.
struct LineDeparture {
    double Cp_percent = 0.0, Cn_percent = 0.0;
    // Beyond 5 % and three of the line's standard errors. The run's own standard error does
    // not excuse it: it holds the noise, not the slab's spring-back, which tilts a run's line
    // (liver 3 runs 6-8 % off in C with standard errors of 2 %, their peaks on the line).
    bool significant = false;
};
LineDeparture departureFromLine(const FrictionFit& fit, const PeakSpeedLine& line);

}  // namespace nb
