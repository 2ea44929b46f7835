#include "organ_tissue.h"

#include <algorithm>
#include <cmath>

namespace nb::devices::sim {

namespace {
constexpr double kBone_N_per_mm = 40.0;
// Pre-sliding stiffness of the tissue around the needle, per metre in tissue: sets how far
// the tissue is dragged along (stick) before it slips.
constexpr double kBristle_N_per_mm_per_m = 40.0;
// Run-to-run scatter of the capsule's stiffness at one site (relative).
constexpr double kSiteStiffnessSd = 0.01;
constexpr double kBand_m_s = 0.005;

double lognormalForce(std::mt19937_64& rng, double mean, double max)
{
    const double sigma = 0.5;
    std::lognormal_distribution<double> d(std::log(mean) - sigma * sigma / 2.0, sigma);
    return std::clamp(d(rng), 0.2 * mean, max);
}

double solveStiffness(const StiffnessModel& s, double force)
{
    // a2 x^2 + a1 x - F = 0, positive root.
    if (s.a2_N_per_mm2 <= 0.0)
        return force / std::max(s.a1_N_per_mm, 1e-9);
    return (-s.a1_N_per_mm + std::sqrt(s.a1_N_per_mm * s.a1_N_per_mm + 4.0 * s.a2_N_per_mm2 * force)) /
           (2.0 * s.a2_N_per_mm2);
}
}  // namespace

OrganTissue::OrganTissue(const TissuePreset& preset, const RigConfig& config, std::mt19937_64& rng)
    : p_(preset), design_(designCapsule(preset, config.tip)), site_(CapsuleDesign::siteOf(config.seed)),
      contact_(config.surface_mm), surface_(config.surface_mm), diamond_(config.tip == Tip::Diamond)
{
    std::normal_distribution<double> n01(0.0, 1.0);
    punctureDepth_ = design_.siteDepth_mm[std::size_t(site_)];
    scale_ = std::clamp(1.0 + kSiteStiffnessSd * n01(rng), 0.95, 1.05);
    if (config.boneDepth_mm)
        bone_ = contact_ + *config.boneDepth_mm;

    std::uniform_real_distribution<double> u01(0.0, 1.0);
    if (p_.capsule) {
        // Internal structures after the capsule: a Poisson process in depth.
        double d = punctureDepth_ * p_.relaxFraction;
        while (d < 250.0) {
            d += -std::log(1.0 - u01(rng)) / p_.internalEvents_per_mm;
            structures_.push_back({d, lognormalForce(rng, p_.internalForceMean_N, p_.internalForceMax_N)});
        }
    } else {
        // Capsule removed: the needle loads one structure after another (Table 3).
        double d = 0.0;
        while (d < 250.0) {
            const double f = lognormalForce(rng, p_.internalForceMean_N, p_.internalForceMax_N);
            structures_.push_back({d, f});
            d += solveStiffness(p_.stiffness, f) + 0.2 + 1.3 * u01(rng);
        }
    }
}

double OrganTissue::capsuleForce(double x) const
{
    return scale_ * design_.force(x, punctureDepth_);
}

double OrganTissue::step(double t, double dt, double tip, double v_mm_s, GroundTruth& truth)
{
    double force = 0.0;
    if (!contacted_ && tip >= contact_) {
        contacted_ = true;
        truth.contact_mm = contact_;
        truth.contact_s = t;
        truth.events.push_back({QStringLiteral("contact"), t, tip, 0.0});
        if (!p_.capsule) {
            // No capsule to puncture: the needle is in the tissue from contact on.
            punctured_ = true;
            x2_ = contact_;
            tp_ = t;
        }
    }
    if (contacted_ && !punctured_) {
        const double x = tip - contact_;
        surface_ = std::max(contact_, tip);
        if (diamond_ && !preEvent_ && x >= kPreEventFraction * punctureDepth_) {
            preEvent_ = true;
            truth.events.push_back({QStringLiteral("pre_puncture"), t, tip, capsuleForce(x)});
        }
        if (x >= punctureDepth_) {
            punctured_ = true;
            x2_ = tip;
            tp_ = t;
            truth.puncture_mm = tip;
            truth.puncture_s = t;
            truth.punctureForce_N = capsuleForce(x);
            truth.relaxed_mm = contact_ + p_.relaxFraction * (x2_ - contact_);
            truth.events.push_back({QStringLiteral("puncture"), t, tip, truth.punctureForce_N});
        } else {
            force += capsuleForce(x);
        }
    }
    if (punctured_) {
        if (p_.capsule) {
            const double r = p_.relaxFraction + (1.0 - p_.relaxFraction) * std::exp(-(t - tp_) / p_.relaxTime_s);
            surface_ = contact_ + (x2_ - contact_) * r;
            if (!relaxed_ && t - tp_ >= 4.0 * p_.relaxTime_s) {
                relaxed_ = true;
                truth.relaxed_s = t;
                truth.events.push_back({QStringLiteral("relaxed"), t, tip, 0.0});
            }
        }
        const double depth = tip - surface_;  // needle length in tissue, mm
        const double length_m = std::max(0.0, depth) / 1000.0;
        const double v = v_mm_s / 1000.0;

        // Cutting: only while the tip advances into tissue it has not cut yet.
        if (tip > maxDepth_) {
            if (v_mm_s > 0.05)
                force += p_.cutting_N;
            maxDepth_ = tip;
        }

        // Friction with stick-slip: a pre-sliding spring until static friction gives.
        if (length_m > 0.0) {
            const KarnoppModel k = p_.friction.forLength(length_m, kBand_m_s);
            const double kb = kBristle_N_per_mm_per_m * length_m;
            double f = 0.0;  // always set below; GCC cannot see that stuck_ flips between the two branches
            if (stuck_) {
                bristle_mm_ += v_mm_s * dt;
                f = kb * bristle_mm_;
                if (f > k.Dp_N || f < k.Dn_N)
                    stuck_ = false;
            }
            if (!stuck_) {
                f = std::fabs(v) < kBand_m_s / 2.0 ? std::clamp(kb * bristle_mm_, k.Dn_N, k.Dp_N) : k(v, 0.0);
                bristle_mm_ = f / kb;
                if (std::fabs(v) < kBand_m_s / 2.0)
                    stuck_ = true;
            }
            force += f;
        } else {
            bristle_mm_ = 0.0;
            stuck_ = true;
        }

        // Internal structures: local build-up, then they give way.
        while (firstIntact_ < structures_.size() && structures_[firstIntact_].broken)
            ++firstIntact_;
        for (std::size_t i = firstIntact_; i < structures_.size() && structures_[i].depth_mm <= depth; ++i) {
            Structure& s = structures_[i];
            if (s.broken)
                continue;
            const double x = depth - s.depth_mm;
            const double f = p_.capsule ? p_.internalStiffness_N_per_mm * x : p_.stiffness(x);
            if (f >= s.force_N) {
                s.broken = true;
                truth.events.push_back({QStringLiteral("internal_puncture"), t, tip, f});
            } else {
                force += f;
            }
        }
    }
    if (bone_ && tip > *bone_) {
        if (!boneHit_) {
            boneHit_ = true;
            truth.events.push_back({QStringLiteral("bone_contact"), t, tip, force});
        }
        force += kBone_N_per_mm * (tip - *bone_);
    }
    return force;
}

}  // namespace nb::devices::sim
