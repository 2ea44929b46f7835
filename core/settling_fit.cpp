#include "settling_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace nb {

double SettlingFit::at(double t_s) const
{
    t_s = std::min(t_s, stop_s);
    return t_s < t0_s ? d0 + v * (t_s - t0_s) : rest + (d0 - rest) * std::exp(-(t_s - t0_s) / tau_s);
}

double SettlingFit::speedAt(double t_s) const
{
    if (t_s >= stop_s)
        return 0.0;
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

namespace {

// Every point of the grid by fitSettlingAt: two exponentials a sample a point.
SettlingFit fitSettlingPointByPoint(const std::vector<double>& t, const std::vector<double>& d, const std::vector<double>& w,
                                    const std::vector<double>& onsets, const std::vector<double>& taus, double lo, double hi)
{
    SettlingFit best;
    for (double t0 : onsets)
        for (double tau : taus) {
            const SettlingFit f = fitSettlingAt(t, d, w, t0, tau, lo, hi);
            if (f.sse < best.sse)
                best = f;
        }
    return best;
}

}  // namespace

SettlingFit fitSettling(const std::vector<double>& t, const std::vector<double>& d, const std::vector<double>& w, double t0From,
                        double t0To, double t0Step, double tauFrom, double tauTo, double tauFactor, double lo, double hi)
{
    std::vector<double> onsets, taus;
    for (double t0 = t0From; t0 <= t0To + 1e-12; t0 += t0Step)
        onsets.push_back(t0);
    for (double tau = tauFrom; tau <= tauTo * (1 + 1e-9); tau *= tauFactor)
        taus.push_back(tau);
    if (!std::is_sorted(t.begin(), t.end()) || !std::is_sorted(onsets.begin(), onsets.end()))
        return fitSettlingPointByPoint(t, d, w, onsets, taus, lo, hi);

    // The samples in the window, their times from lo.
    std::vector<double> at, T, D, W;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= lo && t[i] <= hi)
            at.push_back(t[i]), T.push_back(t[i] - lo), D.push_back(d[i]), W.push_back(w[i]);
    const std::size_t n = T.size();
    if (n == 0)
        return {};
    // The sums over the samples before an onset, as prefix sums: the straight line's part of
    // the normal equations for any onset, from five numbers.
    std::vector<double> sw(n + 1, 0.0), swt(n + 1, 0.0), swtt(n + 1, 0.0), swd(n + 1, 0.0), swdt(n + 1, 0.0);
    double swdd = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sw[i + 1] = sw[i] + W[i];
        swt[i + 1] = swt[i] + W[i] * T[i];
        swtt[i + 1] = swtt[i] + W[i] * T[i] * T[i];
        swd[i + 1] = swd[i] + W[i] * D[i];
        swdt[i + 1] = swdt[i] + W[i] * D[i] * T[i];
        swdd += W[i] * D[i] * D[i];
    }
    // After the onset, exp(−(t − t0)/τ) = exp(−(t_k − t0)/τ)·exp(−(t − t_k)/τ), t_k the first
    // sample at or after the onset: for each τ, sums from each sample on, of factors no larger
    // than one (no overflow however small τ is), make every onset's sums one exponential more.
    // A grid point costs a few multiplications, not two exponentials a sample.
    std::vector<double> se(n), see(n), sde(n);
    double bestSse = std::numeric_limits<double>::infinity();
    std::size_t bestOnset = 0, bestTau = 0;
    for (std::size_t j = 0; j < taus.size(); ++j) {
        const double tau = taus[j];
        se[n - 1] = W[n - 1], see[n - 1] = W[n - 1], sde[n - 1] = W[n - 1] * D[n - 1];
        for (std::size_t k = n - 1; k-- > 0;) {
            const double q = std::exp(-(T[k + 1] - T[k]) / tau);
            se[k] = W[k] + q * se[k + 1];
            see[k] = W[k] + q * q * see[k + 1];
            sde[k] = W[k] * D[k] + q * sde[k + 1];
        }
        std::size_t k = 0;
        for (std::size_t o = 0; o < onsets.size(); ++o) {
            const double t0 = onsets[o], t0r = t0 - lo;
            while (k < n && at[k] < t0)
                ++k;
            const double g = k < n ? std::exp(-(at[k] - t0) / tau) : 0.0;
            const double e = k < n ? g * se[k] : 0.0, ee = k < n ? g * g * see[k] : 0.0, de = k < n ? g * sde[k] : 0.0;
            const double after = sw[n] - sw[k], afterD = swd[n] - swd[k];
            Eigen::Matrix3d m;
            m(0, 0) = sw[k] + ee;
            m(0, 1) = m(1, 0) = swt[k] - t0r * sw[k];
            m(1, 1) = swtt[k] - 2.0 * t0r * swt[k] + t0r * t0r * sw[k];
            m(0, 2) = m(2, 0) = e - ee;
            m(2, 2) = after - 2.0 * e + ee;
            m(1, 2) = m(2, 1) = 0.0;
            const Eigen::Vector3d r(swd[k] + de, swdt[k] - t0r * swd[k], afterD - de);
            if (!(std::abs(m.determinant()) > 1e-12))
                continue;
            const Eigen::Vector3d p = m.inverse() * r;
            // Least squares: the residual's sum of squares is Σw·d² − p·r.
            const double sse = std::max(0.0, swdd - p.dot(r));
            // Ties go to the earlier onset, then the shorter τ, as point by point.
            if (sse < bestSse || (sse == bestSse && (o < bestOnset || (o == bestOnset && j < bestTau))))
                bestSse = sse, bestOnset = o, bestTau = j;
        }
    }
    if (!std::isfinite(bestSse))
        return {};
    // The winner's parameters and sum of squares as fitSettlingAt gives them.
    return fitSettlingAt(t, d, w, onsets[bestOnset], taus[bestTau], lo, hi);
}

SettlingFit fitSettlingFromOrStop(const std::vector<double>& t, const std::vector<double>& d, double t0, double tauFrom, double tauTo,
                                  int steps, const std::vector<double>& stops)
{
    SettlingFit best;
    const std::size_t n = std::min(t.size(), d.size());
    std::vector<double> decay(n);
    std::vector<double> ends{std::numeric_limits<double>::infinity()};
    ends.insert(ends.end(), stops.begin(), stops.end());
    for (int k = 0; k < steps; ++k) {
        const double tau = tauFrom * std::pow(tauTo / tauFrom, double(k) / std::max(1, steps - 1));
        for (const double stop : ends) {
            // d = rest + (d0 − rest)·decay: a straight line in decay.
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            for (std::size_t i = 0; i < n; ++i) {
                decay[i] = std::exp(-std::max(0.0, std::min(t[i], stop) - t0) / tau);
                sx += decay[i], sy += d[i], sxx += decay[i] * decay[i], sxy += decay[i] * d[i];
            }
            const double m = double(n), den = m * sxx - sx * sx;
            if (std::abs(den) < 1e-12)
                continue;
            const double slope = (m * sxy - sx * sy) / den, offset = (sy - slope * sx) / m;
            double sse = 0;
            for (std::size_t i = 0; i < n; ++i)
                sse += std::pow(offset + slope * decay[i] - d[i], 2);
            if (sse < best.sse) {
                best.sse = sse, best.t0_s = t0, best.tau_s = tau, best.d0 = offset + slope, best.v = 0.0, best.rest = offset;
                best.stop_s = stop;
            }
        }
    }
    return best;
}

SettlingFit fitSettlingFrom(const std::vector<double>& t, const std::vector<double>& d, double t0, double tauFrom, double tauTo, int steps)
{
    return fitSettlingFromOrStop(t, d, t0, tauFrom, tauTo, steps, {});
}

}  // namespace nb
