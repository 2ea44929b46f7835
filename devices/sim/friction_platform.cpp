#include "friction_platform.h"

#include <algorithm>
#include <cmath>

namespace nb::devices::sim {

namespace {
constexpr double kMoving_m_s = 2.0e-4;   // below this the needle counts as at a turning point
constexpr double kStopped = 0.05;        // slab speed / needle speed under which the tissue has stopped

QString phaseLabel(char p)
{
    switch (p) {
    case 'a': return QStringLiteral("a");
    case '1': return QStringLiteral("b1");
    case '2': return QStringLiteral("b2");
    case 'c': return QStringLiteral("c");
    }
    return {};
}
}  // namespace

FrictionPlatform::FrictionPlatform(const TissuePreset& preset, const RigConfig& config)
    : k_(preset.friction.forLength(config.thickness_mm / 1000.0, 2.0 * config.stickBand_mm_s / 1000.0)),
      band_m_s_(2.0 * config.stickBand_mm_s / 1000.0),
      m_(preset.tissueMass_kg),
      gap_(config.plateGap_mm / 1000.0),
      damping_(2.0 * std::sqrt(k2_ * preset.tissueMass_kg)),
      dampingB1_(2.0 * std::sqrt(k1_ * preset.tissueMass_kg))
{
}

double FrictionPlatform::plateForce(double y, double vy) const
{
    const double s = std::fabs(y) - gap_;
    if (s <= 0.0)
        return 0.0;
    // b1: the slab comes to bear on the plate progressively; b2: fully against it, stiff.
    const double f = s < w1_ ? k1_ * s : k1_ * w1_ + k2_ * (s - w1_);
    // Critically damped in contact (the tissue's losses bring it to rest against the plate),
    // free in the gap. The soft region carries less than the dynamic friction, so the slab
    // comes to rest fully against the plate (c), not ringing in b1.
    const double losses = (s > w1_ ? damping_ : dampingB1_) * vy;
    return (y > 0 ? f : -f) + losses;
}

TruePhase FrictionPlatform::truePhase() const
{
    switch (phase_) {
    case 'a': return TruePhase::A;
    case '1': return TruePhase::B1;
    case '2': return TruePhase::B2;
    case 'c': return TruePhase::C;
    default: return TruePhase::None;
    }
}

void FrictionPlatform::enter(char phase, double t, GroundTruth& truth)
{
    if (phase == phase_)
        return;
    if (phase_ != 0 && t > phaseStart_)
        truth.phases.push_back({QStringLiteral("phase"), phaseLabel(phase_), phaseStart_, t});
    phase_ = phase;
    phaseStart_ = t;
}

void FrictionPlatform::closePhases(double t, GroundTruth& truth)
{
    enter(0, std::min(t, lastMoving_), truth);
}

double FrictionPlatform::step(double t, double dt, double v_mm_s, double a_mm_s2, GroundTruth& truth)
{
    const double vn = v_mm_s / 1000.0, an = a_mm_s2 / 1000.0;

    // Turning points start a new half-cycle with phase a.
    const int dir = vn > kMoving_m_s ? 1 : vn < -kMoving_m_s ? -1 : 0;
    if (dir != 0) {
        lastMoving_ = t;
        if (dir != dir_) {
            dir_ = dir;
            enter('a', t, truth);
        }
    }

    double force;
    if (stuck_) {
        vy_ = vn;
        y_ += vn * dt;
        force = m_ * an + plateForce(y_, vy_);
        if (force > k_.Dp_N || force < k_.Dn_N) {
            stuck_ = false;
            force = force > 0 ? k_.Dp_N : k_.Dn_N;
            // Phase a ends where the tissue meets the plate ahead and relative motion begins
            // (models.md 5). A slip while the tissue is still leaving the plate behind (its
            // reaction and damping at the reversal) is not that: the tissue is carried on.
            if (phase_ == 'a' && dir_ * y_ > gap_)
                enter('1', t, truth);
        }
    } else {
        const double vrel = vn - vy_;
        const double plate = plateForce(y_, vy_);
        if (std::fabs(vrel) < band_m_s_ / 2.0) {
            // Inside the zero band: sticks again if static friction can carry the slab.
            const double need = m_ * an + plate;
            if (need <= k_.Dp_N && need >= k_.Dn_N) {
                stuck_ = true;
                vy_ = vn;
                y_ += vn * dt;
                return need;
            }
        }
        // Inside the band the friction is static and saturates at D (eq. 15 leaves v = 0
        // itself to either side; the sign of the load decides here).
        force = std::fabs(vrel) < band_m_s_ / 2.0 ? std::clamp(m_ * an + plate, k_.Dn_N, k_.Dp_N) : k_(vrel, 0.0);
        vy_ += (force - plate) / m_ * dt;
        y_ += vy_ * dt;
    }

    if (!stuck_ && dir_ != 0) {
        const double into = dir_ * y_;
        // Sliding already when it reaches the plate ahead: relative motion from there on.
        if (phase_ == 'a' && into > gap_)
            enter('1', t, truth);
        if (phase_ == '1' && into >= gap_ + w1_)
            enter('2', t, truth);
        if ((phase_ == '1' || phase_ == '2') && std::fabs(vy_) < kStopped * std::fabs(vn))
            enter('c', t, truth);
    }
    return force;
}

}  // namespace nb::devices::sim
