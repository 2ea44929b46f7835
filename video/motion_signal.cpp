#include "motion_signal.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace nb::video {

MotionSignal computeMotionSignal(FrameReader& reader, QRect roi, const std::function<void(int, int)>& progress,
                                 const std::atomic_bool* cancel)
{
    const FrameIndex& index = reader.index();
    const cv::Rect frame(0, 0, index.width, index.height);
    cv::Rect r = roi.isEmpty() ? frame : cv::Rect(roi.x(), roi.y(), roi.width(), roi.height()) & frame;
    if (r.area() == 0)
        r = frame;
    MotionSignal out;
    cv::Mat previous;
    double previousTime = 0.0;
    const int n = index.size();
    for (int i = 0; i < n && !(cancel && cancel->load()); ++i) {
        const FrameInfo& info = index.frames[std::size_t(i)];
        if (info.duplicate) {
            out.time_s.push_back(info.time_s);
            out.value.push_back(std::numeric_limits<double>::quiet_NaN());
            continue;
        }
        const DecodedFrame f = reader.read(i);
        cv::Mat roiImage = f.image(r & cv::Rect(0, 0, f.image.cols, f.image.rows));
        cv::Mat gray;
        cv::cvtColor(roiImage, gray, cv::COLOR_BGR2GRAY);
        cv::Mat small;
        cv::GaussianBlur(gray, small, cv::Size(5, 5), 1.2);
        small.convertTo(small, CV_32F);
        if (!previous.empty() && previous.size() == small.size()) {
            // Count the pixels that changed clearly more than the picture's noise (estimated
            // from the median change), so a thin needle moving in a noisy fluoro picture
            // still stands out and the measure grows with the distance moved.
            cv::Mat diff = cv::abs(small - previous);
            cv::Mat sample;
            cv::resize(diff, sample, cv::Size(std::max(1, diff.cols / 4), std::max(1, diff.rows / 4)), 0, 0, cv::INTER_NEAREST);
            std::vector<float> v(sample.begin<float>(), sample.end<float>());
            std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
            const double sigma = 1.4826 * v[v.size() / 2];
            cv::Mat changed = diff > std::max(6.0 * sigma, 6.0);
            const double dt = std::max(1e-6, f.time_s - previousTime);
            out.time_s.push_back(0.5 * (f.time_s + previousTime));
            out.value.push_back(double(cv::countNonZero(changed)) / double(changed.total()) / dt);
        }
        previous = small;
        previousTime = f.time_s;
        if (progress && i % 50 == 0)
            progress(i, n);
    }
    return out;
}

}  // namespace nb::video
