#include "settling_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace nb {

double SettlingFit::at(double t_s) const
{
    return t_s < t0_s ? d0 + v * (t_s - t0_s) : rest + (d0 - rest) * std::exp(-(t_s - t0_s) / tau_s);
}

double SettlingFit::speedAt(double t_s) const
{
    return t_s < t0_s ? v : (rest - d0) / tau_s * std::exp(-(t_s - t0_s) / tau_s);
}

SettlingFit fitSettlingAt(const std::vector<double>& t, const std::vector<double>& d, const std::vector<double>& w, double t0, double tau,
                          double lo, double hi)
{
    // The normal equations of the model, linear in (d0, v, rest) for this onset and τ.
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < lo || t[i] > hi)
            continue;
        Eigen::Vector3d x;
        if (t[i] < t0) {
            x << 1.0, t[i] - t0, 0.0;
        } else {
            const double e = std::exp(-(t[i] - t0) / tau);
            x << e, 0.0, 1.0 - e;
        }
        r += w[i] * d[i] * x;
        m += w[i] * x * x.transpose();
    }
    SettlingFit f;
    // No samples on one side of the onset (or none at all): d0, v and rest are not determined.
    if (!(std::abs(m.determinant()) > 1e-12))
        return f;
    const Eigen::Vector3d p = m.inverse() * r;
    f.t0_s = t0, f.tau_s = tau, f.d0 = p(0), f.v = p(1), f.rest = p(2);
    f.sse = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < lo || t[i] > hi)
            continue;
        const double model = f.at(t[i]);
        f.sse += w[i] * (d[i] - model) * (d[i] - model);
    }
    return f;
}

SettlingFit fitSettling(const std::vector<double>& t, const std::vector<double>& d, const std::vector<double>& w, double t0From,
                        double t0To, double t0Step, double tauFrom, double tauTo, double tauFactor, double lo, double hi)
{
    SettlingFit best;
    for (double t0 = t0From; t0 <= t0To + 1e-12; t0 += t0Step)
        for (double tau = tauFrom; tau <= tauTo * (1 + 1e-9); tau *= tauFactor) {
            const SettlingFit f = fitSettlingAt(t, d, w, t0, tau, lo, hi);
            if (f.sse < best.sse)
                best = f;
        }
    return best;
}

SettlingFit fitSettlingFrom(const std::vector<double>& t, const std::vector<double>& d, double t0, double tauFrom, double tauTo, int steps)
{
    SettlingFit best;
    const std::size_t n = std::min(t.size(), d.size());
    std::vector<double> decay(n);
    for (int k = 0; k < steps; ++k) {
        const double tau = tauFrom * std::pow(tauTo / tauFrom, double(k) / std::max(1, steps - 1));
        // d = rest + (d0 − rest)·decay: a straight line in decay.
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < n; ++i) {
            decay[i] = std::exp(-std::max(0.0, t[i] - t0) / tau);
            sx += decay[i], sy += d[i], sxx += decay[i] * decay[i], sxy += decay[i] * d[i];
        }
        const double m = double(n), den = m * sxx - sx * sx;
        if (std::abs(den) < 1e-12)
            continue;
        const double slope = (m * sxy - sx * sy) / den, offset = (sy - slope * sx) / m;
        double sse = 0;
        for (std::size_t i = 0; i < n; ++i)
            sse += std::pow(offset + slope * decay[i] - d[i], 2);
        if (sse < best.sse)
            best.sse = sse, best.t0_s = t0, best.tau_s = tau, best.d0 = offset + slope, best.v = 0.0, best.rest = offset;
    }
    return best;
}

}  // namespace nb
