#pragma once
// The thesis's force models (models.md sections 3-6) as plain functions. Units: mm, s, N
// unless a name says otherwise. Shared by the fits, the simulated rig and the validation view.

#include <cmath>

namespace nb {

constexpr double kGravity_m_s2 = 9.81;
constexpr double kNeedleHolderMass_kg = 0.087;  // thesis: needle holder with needle

// Capsule stiffness before puncture (eq. 11): f(x) = a1 x + a2 x^2, x = depth past contact [mm].
struct StiffnessModel {
    double a1_N_per_mm = 0.0;
    double a2_N_per_mm2 = 0.0;
    double operator()(double x_mm) const { return x_mm <= 0.0 ? 0.0 : a1_N_per_mm * x_mm + a2_N_per_mm2 * x_mm * x_mm; }
};

// Modified Karnopp friction (eq. 15). C and D are forces [N], b is [N s/m]; velocity in m/s.
// Dn is a signed (negative) limit; `applied` is F_a, the sum of the non-friction forces.
struct KarnoppModel {
    double Cp_N = 0.0, Cn_N = 0.0;       // dynamic (Coulomb) friction, magnitudes
    double bp_Ns_per_m = 0.0, bn_Ns_per_m = 0.0;  // viscous damping
    double Dp_N = 0.0, Dn_N = 0.0;       // static friction limits, Dn < 0
    double band_m_s = 0.005;             // zero-velocity band width (±band/2)

    double operator()(double velocity_m_s, double applied_N) const
    {
        const double half = band_m_s / 2.0;
        if (velocity_m_s <= -half)
            return -Cn_N + bn_Ns_per_m * velocity_m_s;  // C_n sgn(v) with v < 0
        if (velocity_m_s <= 0.0)
            return std::fmax(Dn_N, applied_N);
        if (velocity_m_s < half)
            return std::fmin(Dp_N, applied_N);
        return Cp_N + bp_Ns_per_m * velocity_m_s;
    }
};

// Friction per unit length of needle in tissue (Tables 4/5): C, D in N/m, b in N s/m^2.
struct KarnoppPerLength {
    double Cp_N_per_m = 0.0, Cn_N_per_m = 0.0;
    double bp_Ns_per_m2 = 0.0, bn_Ns_per_m2 = 0.0;
    double Dp_N_per_m = 0.0, Dn_N_per_m = 0.0;

    KarnoppModel forLength(double length_m, double band_m_s = 0.005) const
    {
        return {Cp_N_per_m * length_m, Cn_N_per_m * length_m, bp_Ns_per_m2 * length_m,
                bn_Ns_per_m2 * length_m, Dp_N_per_m * length_m, Dn_N_per_m * length_m, band_m_s};
    }
};

// Eq. 6: force from the load cell voltage. d in V/g (the calibration slope), v0 the voltage
// at bias (tare).
inline double forceFromVolts(double volts, double v0, double slope_V_per_g)
{
    return (volts - v0) * kGravity_m_s2 / (1000.0 * slope_V_per_g);
}

}  // namespace nb
