#pragma once
// Something carried at a steady speed that, from an onset t0, settles exponentially towards
// rest: d(t) = d0 + v·(t − t0) before t0, rest + (d0 − rest)·exp(−(t − t0)/τ) after it. The
// organ's surface springing back after the puncture (surface_relaxation.h) and the tissue
// slowing on the plate (label_suggest.cpp) both move so, and are both read off the picture
// as a fit over all their frames rather than frame by frame, where noise would decide.

#include <limits>
#include <vector>

namespace nb {

struct SettlingFit {
    double sse = std::numeric_limits<double>::infinity();  // weighted; infinite: no fit
    double t0_s = 0, tau_s = 0;
    double d0 = 0, v = 0, rest = 0;  // value at the onset, speed before it, value at rest
    // Where the settling meets something stiff and stops short of `rest` (infinite: it does not).
    double stop_s = std::numeric_limits<double>::infinity();

    double at(double t_s) const;
    double speedAt(double t_s) const;  // d'(t)
};

// Weighted least squares of d0, v and rest for one onset and τ (linear in those three), over
// the samples with lo ≤ t ≤ hi. The window is the caller's, the same for every onset tried,
// so that the sums of squares compare.
SettlingFit fitSettlingAt(const std::vector<double>& t_s, const std::vector<double>& d, const std::vector<double>& weight, double t0_s,
                          double tau_s, double lo_s, double hi_s);

// The best fit over onsets t0From, t0From + t0Step, … ≤ t0To and τ = tauFrom, tauFrom·tauFactor,
// … ≤ tauTo.
SettlingFit fitSettling(const std::vector<double>& t_s, const std::vector<double>& d, const std::vector<double>& weight, double t0From_s,
                        double t0To_s, double t0Step_s, double tauFrom_s, double tauTo_s, double tauFactor, double lo_s, double hi_s);

// With the onset known and nothing carried before it (v = 0; samples before t0 count as at d0):
// d0 and rest by least squares, τ the best of `steps` values spaced evenly in log from tauFrom
// to tauTo.
SettlingFit fitSettlingFrom(const std::vector<double>& t_s, const std::vector<double>& d, double t0_s, double tauFrom_s, double tauTo_s,
                            int steps);

// As fitSettlingFrom, but the settling may also stop short, all at once, at any of `stops_s`
// (it meets something stiff on its way to rest); each stop is tried with each τ, and so is
// not stopping at all.
SettlingFit fitSettlingFromOrStop(const std::vector<double>& t_s, const std::vector<double>& d, double t0_s, double tauFrom_s,
                                  double tauTo_s, int steps, const std::vector<double>& stops_s);

}  // namespace nb
