#pragma once
// Suggested labels from the data, a starting point the operator corrects:
// - sinusoidal (friction) runs: turning points split the motion into half-cycles
//   (insertion: needle going deeper, withdrawal: coming back); in each, phase a runs from the
//   turning point while the speed is inside the zero band (needle and tissue stuck), c from
//   where the force has settled to the end, and b1, b2 split what lies between;
// - linear (stiffness) runs: contact, puncture, relaxation and internal punctures from
//   core/events.h on the "events" point track.

#include "labels.h"
#include "run.h"

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

Labels suggestEventLabels(const Run& run);

}  // namespace nb
