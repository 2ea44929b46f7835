#pragma once
// What is always there in a needle strip's edge response (a textured background's own edges),
// learnt over every frame of the video as the tracker decides where each frame's tip is: the
// low (15 %) percentile per sample over the frames whose tip is away from it. The tracker's
// start-up learns it from a few dozen sampled frames, of which only those with the tip
// elsewhere count; where the tip rests through most of the video that is a dozen, and the
// percentile of a dozen values is off by 0.4 σ of the noise, the same in every frame. Beside a
// resting tip that pulls its edge by half a pixel one way or the other for the whole rest
// (probe seed 187716 case 8: 0.46 px short through the first rest of a 1.4 mm/s stroke, where
// half a pixel is two frames). Gathered in a histogram per sample, so that an hour's video
// needs no more memory than a minute's.

#include <cstdint>
#include <vector>

namespace nb::video {

class StaticEdges {
public:
    // `first`: the start-up's estimate per sample; `sigma`: the edge response's noise.
    StaticEdges(std::vector<double> first, double sigma);

    // One frame's edge response, taken in the tip's sign (`polarity`, ±1), whose tip is at `tip`
    // (samples; NaN when not found, and the frame then says nothing). Samples within `reach` of
    // the tip are left out.
    void add(const std::vector<double>& edge, int polarity, double tip, double reach);

    // Per sample, the low percentile over the frames added; the first estimate where fewer
    // than `minFrames` frames had their tip away.
    std::vector<double> estimate(int minFrames) const;

private:
    static constexpr int kBins = 120;
    static constexpr double kBinsPerSigma = 10.0;
    static constexpr double kBelowFirst_sigma = 6.0;  // where the lowest bin starts

    std::vector<double> first_;
    double binWidth_;
    std::vector<std::uint32_t> counts_;  // kBins per sample, the end bins hold what lies beyond
    std::vector<std::uint32_t> frames_;  // per sample
};

}  // namespace nb::video
