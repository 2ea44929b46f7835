#pragma once
// Signal conditioning for the fits: the thesis smooths with a moving average and
// differentiates position for velocity and acceleration.

#include <cstddef>
#include <span>
#include <vector>

namespace nb {

// Centred moving average over `window` samples (odd windows are symmetric; an even window
// is widened by one). Near the ends the window shrinks symmetrically so that no phase shift
// and no zero padding distort the first and last samples.
std::vector<double> movingAverage(std::span<const double> x, int window);

// dx/dt by central differences on the real time stamps (handles uneven sampling), one-sided
// at the ends. Sizes must match; fewer than two samples give zeros.
std::vector<double> derivative(std::span<const double> time_s, std::span<const double> x);

// Moving-average window [samples] covering `seconds` at the run's median sample rate (>= 1).
int windowForDuration(std::span<const double> time_s, double seconds);

// Half-cycles [start, end) of a to-and-fro motion between its turning points, with their
// direction (+1, -1): a new one begins where the velocity `v` crosses zero before it leaves
// ±band/2 the other way (a slow needle's velocity crosses zero many times in the noise as it
// turns). The needle at rest after the last stroke belongs to none.
struct HalfCycle {
    std::size_t start, end;
    int direction;
};
std::vector<HalfCycle> halfCycles(std::span<const double> v, double band);

}  // namespace nb
