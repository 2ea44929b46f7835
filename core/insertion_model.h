#pragma once
// The summed insertion model (models.md sections 3, 6, 7; eq. 7 and eq. 27): stiffness up
// to puncture, then a constant cutting force plus friction growing with the length of needle
// in tissue. Simulates a run from parameters and compares it with a recording (Fig. 38).

#include "models.h"
#include "run.h"

#include <span>

namespace nb {

// Eq. 27: no cutting before puncture, a constant afterwards while the tip advances into
// tissue beyond x_s3 (a withdrawing needle cuts nothing).
struct CuttingModel {
    double force_N = 0.0858;  // the thesis's estimate (Table 3, blunt tip: an over-estimate)
    double operator()(bool punctured, double tip_mm, double surface_mm, double velocity_m_s) const
    {
        return punctured && tip_mm > surface_mm && velocity_m_s > 0.0 ? force_N : 0.0;
    }
};

struct InsertionModel {
    StiffnessModel stiffness;
    double contact_mm = 0.0;          // x_s1: tip position at contact
    double punctureDepth_mm = 0.0;    // x_s2 - x_s1
    double relaxation_mm = 0.0;       // x_s2 - x_s3: how far the surface springs back
    CuttingModel cutting;
    KarnoppPerLength friction;        // per length of needle in tissue
    double band_m_s = 0.005;

    double puncture_mm() const { return contact_mm + punctureDepth_mm; }
    double surfaceAfterPuncture_mm() const { return puncture_mm() - relaxation_mm; }
};

// A run (time_s, position_mm, force_N) with the model's force along the given trajectory.
// Velocity comes from differentiating position. Sizes must match (FitError otherwise).
Run simulateInsertion(const InsertionModel& model, std::span<const double> time_s,
                      std::span<const double> position_mm);

// RMS of recorded - simulated force, the simulation interpolated onto the recording's time
// stamps within their common time range. Throws FitError when the runs do not overlap.
double rmsDistance(const Run& simulated, const Run& recorded);

}  // namespace nb
