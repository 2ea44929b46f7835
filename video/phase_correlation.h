#pragma once
// Phase correlation from pictures' spectra kept between matches. cv::phaseCorrelate transforms
// both of its pictures at every call; a tracker that matches each picture twice (against a
// reference and against the picture before) transforms each of them four times over, and
// OpenCV 4.6 took 14-19 ms a call at 480x360 where its three transforms take 4.5 ms.

#include <opencv2/core.hpp>

namespace nb::video {

// A picture's Fourier transform (CCS-packed, of the picture zero-padded to an even size the
// transform is quick at).
struct Spectrum {
    cv::Mat ccs;
    bool empty() const { return ccs.empty(); }
};

// picture: one channel, 32-bit float.
Spectrum spectrumOf(const cv::Mat& picture);

// What cv::phaseCorrelate(a, b, cv::noArray(), response) gives for the pictures of a and b:
// the shift of b against a, to a fraction of a pixel, and the peak's response (1 for a
// picture against itself); where OpenCV pads a side to an odd size, without its half pixel.
// a and b are of pictures of the same size.
cv::Point2d phaseShift(const Spectrum& a, const Spectrum& b, double* response = nullptr);

}  // namespace nb::video
