#include "motion_signal.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <limits>

namespace nb::devices {

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
        // Averaging over small blocks keeps real motion and drops most pixel noise.
        cv::Mat small;
        cv::resize(gray, small, cv::Size(std::max(1, gray.cols / 4), std::max(1, gray.rows / 4)), 0, 0, cv::INTER_AREA);
        small.convertTo(small, CV_32F);
        if (!previous.empty() && previous.size() == small.size()) {
            const double dt = std::max(1e-6, f.time_s - previousTime);
            out.time_s.push_back(0.5 * (f.time_s + previousTime));
            out.value.push_back(cv::mean(cv::abs(small - previous))[0] / dt);
        }
        previous = small;
        previousTime = f.time_s;
        if (progress && i % 50 == 0)
            progress(i, n);
    }
    return out;
}

}  // namespace nb::devices
