#pragma once
// A needle going into an organ on the bench (models.md 3-6): capsule stiffness up to a
// seeded puncture, surface relaxation, cutting, friction per length of needle in tissue with
// stick-slip (pre-sliding spring + modified Karnopp), internal structures, the diamond tip's
// pre-puncture event and optional bone. Positions in the world frame (mm), forces in N,
// positive when the tissue pushes back.

#include "devices/sim/capsule_design.h"
#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"

#include <random>
#include <vector>

namespace nb::devices::sim {

class OrganTissue {
public:
    OrganTissue(const TissuePreset& preset, const RigConfig& config, std::mt19937_64& rng);
    // Advances by dt to time t with the tip at `tip_mm` moving at `v_mm_s`; returns the force.
    double step(double t, double dt, double tip_mm, double v_mm_s, GroundTruth& truth);
    double surface_mm() const { return surface_; }
    double plannedPunctureDepth_mm() const { return punctureDepth_; }
    int site() const { return site_; }
    const CapsuleDesign& design() const { return design_; }
    double stiffnessScale() const { return scale_; }

private:
    struct Structure {
        double depth_mm;   // in tissue, from the (relaxed) surface
        double force_N;    // gives way at this force
        bool broken = false;
    };
    double capsuleForce(double x) const;
    TissuePreset p_;
    CapsuleDesign design_;
    int site_;
    double scale_ = 1.0;          // this run's stiffness relative to the site's
    double contact_;              // x_s1, world mm
    double punctureDepth_;        // past contact, seeded
    std::optional<double> bone_;  // world mm
    double surface_;
    bool contacted_ = false, punctured_ = false, preEvent_ = false, relaxed_ = false, boneHit_ = false;
    double x2_ = 0.0, tp_ = 0.0, maxDepth_ = 0.0;
    double bristle_mm_ = 0.0;
    bool stuck_ = true;
    std::vector<Structure> structures_;  // sorted by depth
    std::size_t firstIntact_ = 0;
    bool diamond_;
};

}  // namespace nb::devices::sim
