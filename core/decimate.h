#pragma once
// Point reduction for drawing: at most a handful of samples per pixel column, chosen so the
// drawn line keeps every peak. A 10 kHz recording has far more samples than a plot has
// pixels, and QCPCurve (force vs position) draws every point it is given.

#include <cstddef>
#include <span>
#include <vector>

namespace nb {

// Indices into time-ordered samples, in increasing order, that keep the shape of every
// channel in `channels` when the time span [t0, t1] is drawn `columns` pixels wide: per
// column the first and last sample and each channel's minimum and maximum. One sample on
// each side of the span is kept so the line runs to the plot's edges.
// `time` must be non-decreasing; every channel has time.size() values.
std::vector<std::size_t> minMaxIndices(std::span<const double> time,
                                       std::span<const std::span<const double>> channels,
                                       double t0, double t1, int columns);

// Gathers `source[i]` for each index (the reduced series to hand to the plot).
void gather(std::span<const double> source, std::span<const std::size_t> indices, std::vector<double>& out);

}  // namespace nb
