#include "capsule_design.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace nb::devices::sim {

namespace {
constexpr double kPreEventDecay_mm = 0.4;
constexpr double kMaxPreEventDrop_N = 0.08;
// Quantiles of the standard normal at the middle of five equal strata: the sites sample the
// specimen's spread of puncture depths evenly.
constexpr std::array<double, CapsuleDesign::kSites> kSiteZ{-0.841621, -0.253347, 0.0, 0.253347, 0.841621};

double tent(double x, double depth)
{
    const double w = CapsuleDesign::kTentFraction * depth;
    const double u = std::clamp((x - (depth - w)) / w, 0.0, 1.0);
    return u * u * u;
}
}  // namespace

double CapsuleDesign::force(double x, double depth) const
{
    double f = base(x) + tent_N * tent(x, depth);
    const double xPre = kPreEventFraction * depth;
    if (diamond && x > xPre)
        f -= preEventDrop_N(depth) * std::exp(-(x - xPre) / kPreEventDecay_mm);
    return f;
}

double CapsuleDesign::preEventDrop_N(double depth) const
{
    return std::min(kMaxPreEventDrop_N, 0.25 * table(kPreEventFraction * depth));
}

CapsuleDesign designCapsule(const TissuePreset& preset, Tip tip)
{
    CapsuleDesign d;
    d.table = preset.stiffness;
    d.base = preset.stiffness;
    d.diamond = tip == Tip::Diamond;
    for (int k = 0; k < CapsuleDesign::kSites; ++k)
        d.siteDepth_mm[std::size_t(k)] = preset.punctureDepth_mm * (1.0 + preset.punctureDepthSd * kSiteZ[std::size_t(k)]);
    if (!preset.capsule)
        return d;

    // The pooled least-squares quadratic (no intercept) over every site's loading, sampled
    // evenly in depth as a constant-velocity insertion is: normal matrix N, and the fit's
    // response to each part of the force.
    Eigen::Matrix2d N = Eigen::Matrix2d::Zero();
    Eigen::Matrix<double, 2, 3> R = Eigen::Matrix<double, 2, 3>::Zero();  // to x, x², tenting
    Eigen::Vector2d dip = Eigen::Vector2d::Zero();
    CapsuleDesign dipOnly = d;
    dipOnly.base = {};
    dipOnly.tent_N = 0.0;
    double meanDepth = 0.0, meanDepth2 = 0.0, meanDipAtPuncture = 0.0;
    constexpr int kPoints = 4000;
    for (const double depth : d.siteDepth_mm) {
        const double h = depth / kPoints;
        for (int i = 0; i < kPoints; ++i) {
            const double x = (i + 0.5) * h;
            const Eigen::Vector2d phi(x, x * x);
            N += h * phi * phi.transpose();
            R.col(0) += h * phi * x;
            R.col(1) += h * phi * x * x;
            R.col(2) += h * phi * tent(x, depth);
            dip += h * phi * dipOnly.force(x, depth);
        }
        meanDepth += depth / CapsuleDesign::kSites;
        meanDepth2 += depth * depth / CapsuleDesign::kSites;
        meanDipAtPuncture += dipOnly.force(depth, depth) / CapsuleDesign::kSites;
    }
    const Eigen::Matrix<double, 2, 3> P = N.ldlt().solve(R);
    const Eigen::Vector2d q = N.ldlt().solve(dip);
    const Eigen::Vector2d target(preset.stiffness.a1_N_per_mm, preset.stiffness.a2_N_per_mm2);

    Eigen::Matrix3d M;
    M.topRows<2>() = P;
    M.row(2) << meanDepth, meanDepth2, 1.0;
    Eigen::Vector3d rhs;
    rhs << target - q, preset.punctureForce_N - meanDipAtPuncture;
    Eigen::Vector3d b = M.fullPivLu().solve(rhs);
    if (b(2) < 0.0) {
        // The table's force is already on (or under) its curve: no tenting.
        b.head<2>() = P.leftCols<2>().fullPivLu().solve(target - q);
        b(2) = 0.0;
    }
    d.base = {b(0), b(1)};
    d.tent_N = b(2);
    return d;
}

}  // namespace nb::devices::sim
