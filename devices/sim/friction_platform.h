#pragma once
// The friction platform (models.md 5, Figs. 31-32): a tissue slab of set thickness between
// two plates with holes, the needle passed fully through it and moved sinusoidally. The slab
// is a mass that moves with the needle while static friction holds (phase a), slips when the
// plate's reaction exceeds it (b1), presses fully against the plate while the tissue at the
// hole still moves (b2), and comes to rest (c: relative velocity = needle velocity).
// Units inside: m, m/s, N.

#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"

namespace nb::devices::sim {

class FrictionPlatform {
public:
    // The plate's law against the slab past its free travel: soft over its first kSoft_mm,
    // stiff beyond (the knee at kSoft_N_per_m · kSoft_mm), critically damped in contact.
    static constexpr double kSoft_mm = 1.0, kSoft_N_per_m = 200.0, kStiff_N_per_m = 5000.0;

    FrictionPlatform(const TissuePreset& preset, const RigConfig& config);
    // Needle velocity/acceleration in mm/s, mm/s^2; returns the force on the needle.
    double step(double t, double dt, double v_mm_s, double a_mm_s2, GroundTruth& truth);
    double slab_mm() const { return y_ * 1000.0; }
    char phase() const { return phase_; }
    TruePhase truePhase() const;
    // Closes the open phase at time t (end of motion or of the run).
    void closePhases(double t, GroundTruth& truth);

private:
    double plateForce(double y, double vy) const;
    void enter(char phase, double t, GroundTruth& truth);
    KarnoppModel k_;
    double band_m_s_;      // Δv, the whole width of the zero band
    double m_;
    double gap_, w1_ = kSoft_mm / 1000.0, k1_ = kSoft_N_per_m, k2_ = kStiff_N_per_m, damping_, dampingB1_;
    double y_ = 0.0, vy_ = 0.0;
    bool stuck_ = true;
    char phase_ = 0;
    double phaseStart_ = 0.0;
    int dir_ = 0;          // sign of the needle velocity since the last turning point
    double lastMoving_ = 0.0;
};

}  // namespace nb::devices::sim
