#pragma once
// Suggested labels from the data, a starting point the operator corrects:
// - sinusoidal (friction) runs: turning points split the motion into half-cycles
//   (insertion: needle going deeper, withdrawal: coming back); in each (models.md 5), a
//   runs from the turning point while the tissue is carried with the needle (the force well
//   below the sliding line), b1/b2 while it bears on the plate (the force rising to the
//   line), c from where the force follows the sliding line (tissue at rest) to the end;
// - linear (stiffness) runs: contact, puncture and internal punctures from core/events.h
//   on the "events" point track; relaxation only from the imaging video (the force does not
//   show when the surface has sprung back: core/surface_relaxation.h).

#include "labels.h"
#include "run.h"
#include "surface_relaxation.h"
#include "tissue_motion.h"

namespace nb {

struct SuggestOptions {
    double zeroBand_mm_s = 5.0;   // Δv, the thesis's 0.005 m/s: |v| < Δv/2 counts as zero
    double settledFraction = 0.15;  // c starts once the force is this close to its plateau
};

// Protocol from the metadata ("friction" → phases) or, without one, from the motion
// (several turning points → phases, else events). Never throws: a run with nothing to
// suggest gives no labels.
Labels suggestLabels(const Run& run, const SuggestOptions& options = {});

Labels suggestPhaseLabels(const Run& run, const SuggestOptions& options = {});
// With the tissue's motion from the imaging video (null: without): a and c from the
// relative velocity it gives, b1/b2 from the force; each label's comment says which.
Labels suggestPhaseLabels(const Run& run, const TissueMotion* tissue, const SuggestOptions& options = {});

Labels suggestEventLabels(const Run& run);
// With the organ surface's motion from the imaging video (measured one or more ways; none:
// no relaxation): relaxation where the surface has come to rest after the puncture, from the
// trace with the largest believable spring-back (one that loses the surface reads it short).
// `relaxationProblem` (may be null) says why
// there is none when traces were given.
Labels suggestEventLabels(const Run& run, const std::vector<SurfaceTrace>& surfaces, QString* relaxationProblem = nullptr);

}  // namespace nb
