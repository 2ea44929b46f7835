#include "phase_correlation.h"

#include <opencv2/imgproc.hpp>

#include <cfloat>
#include <cmath>

namespace nb::video {

namespace {

// The magnitude of each element of a CCS-packed 2D spectrum, at the element's real place
// (its imaginary place 0), as OpenCV's phaseCorrelate divides by it.
void magnitudeOf(const cv::Mat& p, cv::Mat& m)
{
    m.create(p.size(), CV_32F);
    m.setTo(0);
    const int rows = p.rows, cols = p.cols;
    // The first column (and the last, for an even width) is a column's own packed spectrum:
    // real at its ends, pairs between them.
    for (int k = 0; k < (cols % 2 ? 1 : 2); ++k) {
        const int c = k == 0 ? 0 : cols - 1;
        m.at<float>(0, c) = std::abs(p.at<float>(0, c));
        if (rows % 2 == 0)
            m.at<float>(rows - 1, c) = std::abs(p.at<float>(rows - 1, c));
        for (int j = 1; j <= rows - 2; j += 2) {
            const double re = p.at<float>(j, c), im = p.at<float>(j + 1, c);
            m.at<float>(j, c) = float(std::sqrt(re * re + im * im));
        }
    }
    const int j1 = cols - (cols % 2 == 0 ? 1 : 0);
    for (int r = 0; r < rows; ++r) {
        const float* s = p.ptr<float>(r);
        float* d = m.ptr<float>(r);
        for (int j = 1; j < j1; j += 2)
            d[j] = float(std::sqrt(double(s[j]) * s[j] + double(s[j + 1]) * s[j + 1]));
    }
}

// A size the transform is quick at, and even: OpenCV's phaseCorrelate reads zero shift half a
// pixel off along an odd side (its middle is at half the side, its zero shift at the integer
// below), and a tracker that moves its reference on adds that half pixel up (a region 121 px
// high pads to 125).
int evenTransformSize(int n)
{
    int m = cv::getOptimalDFTSize(n);
    while (m % 2 != 0)
        m = cv::getOptimalDFTSize(m + 1);
    return m;
}

}  // namespace

Spectrum spectrumOf(const cv::Mat& picture)
{
    CV_Assert(picture.type() == CV_32FC1);
    const int rows = evenTransformSize(picture.rows), cols = evenTransformSize(picture.cols);
    cv::Mat padded = picture;
    if (rows != picture.rows || cols != picture.cols)
        cv::copyMakeBorder(picture, padded, 0, rows - picture.rows, 0, cols - picture.cols, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    Spectrum s;
    cv::dft(padded, s.ccs, cv::DFT_REAL_OUTPUT);
    return s;
}

cv::Point2d phaseShift(const Spectrum& a, const Spectrum& b, double* response)
{
    CV_Assert(!a.empty() && a.ccs.size() == b.ccs.size());
    cv::Mat p, m, c;
    cv::mulSpectrums(a.ccs, b.ccs, p, 0, true);
    magnitudeOf(p, m);
    cv::divSpectrums(p, m, c, 0, false);
    cv::idft(c, c);
    // OpenCV moves zero shift to the middle (a circular shift by half the picture) and takes
    // the peak's centroid over 5x5 pixels there, clipped at that picture's edges; here the
    // same in place.
    cv::Point peak;
    cv::minMaxLoc(c, nullptr, nullptr, nullptr, &peak);
    const int xMid = c.cols / 2, yMid = c.rows / 2;
    const cv::Point centred((peak.x + xMid) % c.cols, (peak.y + yMid) % c.rows);
    const int r0 = std::max(0, centred.y - 2), r1 = std::min(c.rows - 1, centred.y + 2);
    const int c0 = std::max(0, centred.x - 2), c1 = std::min(c.cols - 1, centred.x + 2);
    double sx = 0.0, sy = 0.0, sum = 0.0;
    for (int y = r0; y <= r1; ++y) {
        const float* row = c.ptr<float>((y - yMid + c.rows) % c.rows);
        for (int x = c0; x <= c1; ++x) {
            const double v = row[(x - xMid + c.cols) % c.cols];
            sx += double(x) * v;
            sy += double(y) * v;
            sum += v;
        }
    }
    if (response)
        *response = sum / (double(c.rows) * double(c.cols));
    sum += DBL_EPSILON;
    return {double(c.cols) / 2.0 - sx / sum, double(c.rows) / 2.0 - sy / sum};
}

}  // namespace nb::video
