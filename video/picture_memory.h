#pragma once
// Measures how much of each decoded picture an inter-frame coder carried over from the one
// before (core/picture_lag.h says why that makes a faint motion late), from the picture's noise:
// for fresh noise, successive differences f(k) − f(k−1) and f(k−1) − f(k−2) correlate at −½,
// and for noise a coder carries on with memory ρ at −(1 − ρ)/2, whatever still picture lies
// under it. What moves or changes (the needle, a counter's digits) is a few pixels of many and
// is left out as beyond five noise widths.

#include "core/picture_lag.h"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>

namespace nb::video {

class PictureMemoryMeter {
public:
    // The next decoded frame, in grey (8 bits). A picture identical to the one before (a
    // variable-rate file's duplicate) is left out.
    void add(const cv::Mat& gray);
    // memory and noise_grey (PictureCoding's edge slope is the tracker's); zeros until three
    // frames have been seen.
    PictureCoding coding() const;

private:
    cv::Mat before_, beforeThat_;  // sampled pictures, every other pixel each way
    int usable_ = 0;               // frames in a row of one size
    // By the larger of the two differences' sizes (grey levels): how many pixels, Σa², Σa·b.
    std::array<double, 256> count_{}, squares_{}, products_{};
    std::array<double, 256> changes_{};  // |a| alone, for its median
};

}  // namespace nb::video
