#include "picture_memory.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace nb::video {

void PictureMemoryMeter::add(const cv::Mat& gray)
{
    if (gray.empty() || gray.type() != CV_8UC1)
        return;
    cv::Mat sampled(gray.rows / 2, gray.cols / 2, CV_8UC1);
    for (int y = 0; y < sampled.rows; ++y) {
        const std::uint8_t* from = gray.ptr<std::uint8_t>(2 * y);
        std::uint8_t* to = sampled.ptr<std::uint8_t>(y);
        for (int x = 0; x < sampled.cols; ++x)
            to[x] = from[2 * x];
    }
    if (!before_.empty() && before_.size() != sampled.size())
        usable_ = 0;
    // A picture repeated whole (a variable-rate file's duplicate) is no picture of the coder's:
    // left out, the frames either side follow each other.
    else if (!before_.empty() && cv::norm(sampled, before_, cv::NORM_INF) == 0.0)
        return;
    if (usable_ >= 2) {
        for (int y = 0; y < sampled.rows; ++y) {
            const std::uint8_t* f0 = sampled.ptr<std::uint8_t>(y);
            const std::uint8_t* f1 = before_.ptr<std::uint8_t>(y);
            const std::uint8_t* f2 = beforeThat_.ptr<std::uint8_t>(y);
            for (int x = 0; x < sampled.cols; ++x) {
                const int a = int(f0[x]) - int(f1[x]), b = int(f1[x]) - int(f2[x]);
                const std::size_t bin = std::size_t(std::max(std::abs(a), std::abs(b)));
                count_[bin] += 1.0;
                squares_[bin] += double(a * a);
                products_[bin] += double(a * b);
                changes_[std::size_t(std::abs(a))] += 1.0;
            }
        }
    }
    beforeThat_ = before_;
    before_ = sampled;
    ++usable_;
}

PictureCoding PictureMemoryMeter::coding() const
{
    double total = 0.0;
    for (double c : changes_)
        total += c;
    if (total < 1000.0)
        return {};
    double below = 0.0;
    std::size_t median = 0;
    while (median < changes_.size() && below + changes_[median] < 0.5 * total)
        below += changes_[median++];
    // σ of a difference from its median absolute value (half a grey level for the rounding).
    const double spread = 1.4826 * double(median) + 0.5;
    double n = 0.0, aa = 0.0, ab = 0.0;
    for (std::size_t bin = 0; bin < count_.size() && double(bin) < 5.0 * spread; ++bin) {
        n += count_[bin];
        aa += squares_[bin];
        ab += products_[bin];
    }
    if (!(aa > 0.0) || n < 1000.0)
        return {};
    PictureCoding out;
    out.memory = std::clamp(1.0 + 2.0 * ab / aa, 0.0, kMostMeasurableMemory);
    // Most pixels shown again exactly: the coder dropped the camera's noise, and what is left to
    // read is only its coarsest changes, which any coder passes. Every MPEG-4 video of a quiet
    // camera (noise 3 grey) read 0.93 whatever its coder held (bold probe seeds 31001, 32001):
    // the memory is at least the most the meter reads.
    if (median == 0)
        out.memory = kMostMeasurableMemory;
    // The pictures' own noise: for noise correlated ρ from one picture to the next, a difference
    // of two has variance 2σ²(1 − ρ). The coder of core/picture_lag.h holds a pixel until it
    // passes, so the camera's noise is shown whole and this is also the camera's σ. (Read as a
    // smoothing that keeps ρ of the picture before, the camera's σ came out √((1 + ρ)/(1 − ρ))
    // times this: 6 times at ρ = 0.95, where H.264 veryfast drops nearly all of a quiet camera's
    // noise, and the lag 4 to 6 frames where it was 0.3 to 1.5; slow-small seed 771, cases 2, 4, 8.)
    out.noise_grey = std::sqrt(aa / n / (2.0 * (1.0 - out.memory)));
    return out;
}

}  // namespace nb::video
