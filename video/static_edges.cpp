#include "static_edges.h"

#include <algorithm>
#include <cmath>

namespace nb::video {

StaticEdges::StaticEdges(std::vector<double> first, double sigma)
    : first_(std::move(first)),
      binWidth_(std::max(sigma, 1e-9) / kBinsPerSigma),
      counts_(first_.size() * kBins, 0),
      frames_(first_.size(), 0)
{
}

void StaticEdges::add(const std::vector<double>& edge, int polarity, double tip, double reach)
{
    if (!std::isfinite(tip) || edge.size() != first_.size())
        return;
    for (std::size_t i = 0; i < first_.size(); ++i) {
        // Nor samples that are not read at all (+inf in the first estimate).
        if (std::abs(double(i) - tip) <= reach || !std::isfinite(first_[i]))
            continue;
        const double at = (polarity * edge[i] - first_[i]) / binWidth_ + kBelowFirst_sigma * kBinsPerSigma;
        const int bin = std::clamp(int(std::floor(at)), 0, kBins - 1);
        ++counts_[i * kBins + std::size_t(bin)];
        ++frames_[i];
    }
}

std::vector<double> StaticEdges::estimate(int minFrames) const
{
    std::vector<double> out = first_;
    for (std::size_t i = 0; i < first_.size(); ++i) {
        if (frames_[i] < std::uint32_t(std::max(minFrames, 1)))
            continue;
        // The same rank as lowPercentile's: the value with frames·15/100 below it, placed
        // within its bin by how far into the bin's count that rank falls.
        const double rank = double(frames_[i] * 15 / 100);
        double below = 0.0;
        for (int b = 0; b < kBins; ++b) {
            const double c = counts_[i * kBins + std::size_t(b)];
            if (below + c > rank) {
                const double into = (rank - below + 0.5) / c;
                out[i] = first_[i] + (double(b) + into - kBelowFirst_sigma * kBinsPerSigma) * binWidth_;
                break;
            }
            below += c;
        }
    }
    return out;
}

}  // namespace nb::video
