#pragma once
// Synthetic runs with known parameters for the fit tests and the bench: the thesis's
// models plus Gaussian noise, so every recovered value has a true value to compare with.

#include "core/labels.h"
#include "core/models.h"
#include "core/run.h"

#include <cstdint>
#include <vector>

namespace nb::synthetic {

struct InternalPuncture {
    double depth_mm = 0.0;   // tip position past the main puncture where the peak sits
    double force_N = 0.1;    // rise over the millimetre before it, lost at once
};

// A constant-velocity insertion (models.md sections 3-4, Table 2 liver 1 by default).
struct Insertion {
    double a1_N_per_mm = 0.0480, a2_N_per_mm2 = 0.0052;
    double start_mm = 0.0, contact_mm = 5.0;
    double punctureDepth_mm = 16.57;   // x_s2 - x_s1
    double dropTravel_mm = 0.3;        // the post-puncture drop lasts this much travel
    double relaxation_mm = 3.0;        // x_s2 - x_s3
    double cutting_N = 0.0858;
    double friction_N_per_mm = 0.01;   // friction growth with needle length in tissue
    std::vector<InternalPuncture> internal;
    double end_mm = 35.0;
    double speed_mm_s = 4.0, rate_hz = 500.0;
    double noise_N = 0.006, offset_N = 0.05;
    std::uint32_t seed = 1;

    double puncture_mm() const { return contact_mm + punctureDepth_mm; }
    // The noise-free force (offset excluded) at tip position x.
    double force(double x) const;
};
Run makeInsertion(const Insertion& p);

// A sinusoidal friction run (models.md section 5): x = A sin(2πft), force = m·a +
// Karnopp friction + noise. Inside the zero-velocity band the needle sticks: the tissue
// acts as a stiff spring whose force (the applied force F_a) is clamped to [Dn, Dp].
struct Friction {
    KarnoppModel model{0.20, 0.22, 4.0, 3.5, 0.30, -0.32, 0.005};
    double mass_kg = kNeedleHolderMass_kg;
    double amplitude_mm = 10.0, frequency_hz = 0.5;
    double cycles = 8.0, rate_hz = 500.0;
    double noise_N = 0.004;
    double stickStiffness_N_per_mm = 100.0;
    double encoderStep_mm = 0.0015;    // position quantisation of the encoder
    bool writeFrequency = true;        // `# frequency_hz` metadata
    bool writePhases = true;           // a `phase` column: "a" sticking, "c" sliding
    std::uint32_t seed = 1;
};
Run makeFriction(const Friction& p);

// Labels for a friction run: "a" intervals where it sticks, "c" where it slides, on the
// tracks "insertion" (moving in) and "withdrawal" (moving out).
Labels frictionLabels(const Friction& p);

// Calibration points V = slope·m + intercept with noise, 0..850 g in 25 g steps.
struct CalibrationData {
    std::vector<double> mass_g, voltage_V;
};
CalibrationData makeCalibration(double slope_V_per_g, double intercept_V, double noise_V, std::uint32_t seed);

}  // namespace nb::synthetic
