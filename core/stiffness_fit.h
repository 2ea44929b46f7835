#pragma once
// Capsule stiffness fits (models.md section 4, eq. 11 and Table 2): f = a1·x + a2·x² with
// x the depth past contact in mm, per run and pooled, and the cubic and the nonlinear
// spring x/(a·x + b) as alternatives.

#include "events.h"
#include "models.h"
#include "run.h"

#include <span>
#include <vector>

namespace nb {

// The pre-puncture samples of one run: depth past contact [mm] and zeroed force [N].
struct StiffnessSegment {
    std::vector<double> depth_mm;
    std::vector<double> force_N;
};

// Samples from contact to puncture, offset removed.
StiffnessSegment stiffnessSegment(const Run& run, const InsertionEvents& events);

struct QuadraticStiffnessFit {
    StiffnessModel model;  // a1, a2 (a0 = 0)
    double rms_N = 0.0, r2 = 0.0;
};
struct CubicStiffnessFit {
    double a1_N_per_mm = 0.0, a2_N_per_mm2 = 0.0, a3_N_per_mm3 = 0.0;
    double rms_N = 0.0, r2 = 0.0;
};
// f = x / (a·x + b): a [1/N], b [mm/N].
struct SpringStiffnessFit {
    double a_per_N = 0.0, b_mm_per_N = 0.0;
    double rms_N = 0.0, r2 = 0.0;
    bool converged = false;
};

struct StiffnessFit {
    QuadraticStiffnessFit quadratic;
    CubicStiffnessFit cubic;
    SpringStiffnessFit spring;
    std::size_t samples = 0;
};

// Throws FitError for fewer than 4 samples.
StiffnessFit fitStiffness(const StiffnessSegment& segment);

struct StiffnessSummary {
    std::vector<StiffnessFit> runs;
    StiffnessFit pooled;               // all runs' points at once (what the thesis reports)
    StiffnessModel meanOfRuns;         // mean of per-run a1, a2
    StiffnessModel stdDevOfRuns;       // their sample standard deviations
};
StiffnessSummary fitStiffnessRuns(std::span<const StiffnessSegment> segments);

}  // namespace nb
