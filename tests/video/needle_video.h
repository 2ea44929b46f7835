#pragma once
// Needle videos made by the tests: a bright thin needle entering from beyond the picture's
// edge, its tip where a function of the frame puts it, on fixed grain with noise of its own in
// each frame (MJPEG through OpenCV); written, indexed and tracked.
#include "video/frame_index.h"
#include "video/frame_reader.h"
#include "video/needle_axis_finder.h"
#include "video/needle_tracker.h"

#include <QTemporaryDir>
#include <QtTest>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace nb::needle_video {

constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 480, kHeight = 360, kFrames = 90;

// Where the tip is in frame k, along the needle from the picture's centre (px).
inline double tipAt(int frame)
{
    return 50.0 * std::sin(2.0 * kPi * frame / 60.0);
}

struct NeedleVideo {
    double towardsTip_deg = 0.0;  // the needle's direction, from the shaft to the tip (image y down)
    bool clockOnShaft = false;    // changing digits burnt in across the line, behind the tip's travel
    bool counterAhead = false;    // a frame counter in a black box burnt in on the line, 110 px ahead of the travel's centre
    int noisierFrame = -1;        // one frame with four times the noise (coded worse than the rest)
    bool tissueCarried = false;   // the grain moves along with the needle by a third of its travel
    double clockScale = 0.7;      // of the clock's font (OpenCV's Hershey simplex)
    double contrast = 35.0;       // of the shaft over the background, grey levels
    double noise = 5.0;           // each frame's own, grey levels (σ)
    double grain = 12.0;          // of the fixed background, grey levels (σ of 4 px squares)
    int width = kWidth, height = kHeight;
    double travelCentre = 0.0;    // of the tip's travel, along the needle from the picture's centre (px)
    double (*tip)(int frame) = tipAt;  // where the tip is in each frame (before travelCentre)
    std::uint64_t grainSeed = 12345;   // of the background's grain
    int frames = kFrames;
};

inline QPointF direction(const NeedleVideo& v)
{
    return {std::cos(v.towardsTip_deg * kPi / 180.0), std::sin(v.towardsTip_deg * kPi / 180.0)};
}

// A bright thin needle (a smooth profile `contrast` grey levels over the background, ending
// softly at the tip) entering from beyond the picture's edge, on fixed grain of 4 px with noise
// of its own in each frame; MJPEG through OpenCV.
inline QString writeNeedleVideo(const QString& path, const NeedleVideo& v)
{
    cv::theRNG().state = v.grainSeed;
    cv::Mat grains(v.height / 4 + 1, v.width / 4 + 1, CV_32F), grain;
    cv::randn(grains, 0.0, v.grain);
    cv::resize(grains, grain, cv::Size(grains.cols * 4, grains.rows * 4), 0, 0, cv::INTER_NEAREST);
    grain = grain(cv::Rect(0, 0, v.width, v.height)).clone();
    const QPointF u = direction(v);
    cv::Mat along(v.height, v.width, CV_32F), shaft(v.height, v.width, CV_32F);
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x) {
            const double dx = x - v.width / 2.0, dy = y - v.height / 2.0;
            const double across = -dx * u.y() + dy * u.x();
            along.at<float>(y, x) = float(dx * u.x() + dy * u.y());
            shaft.at<float>(y, x) = float(v.contrast * std::exp(-0.5 * across * across / (1.5 * 1.5)));
        }
    cv::VideoWriter writer(path.toStdString(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0, cv::Size(v.width, v.height));
    if (!writer.isOpened())
        return QStringLiteral("OpenCV cannot write MJPEG to %1").arg(path);
    for (int k = 0; k < v.frames; ++k) {
        cv::Mat tissue = grain;
        if (v.tissueCarried) {
            const double shift = v.tip(k) / 3.0;
            const cv::Mat move = (cv::Mat_<double>(2, 3) << 1, 0, shift * u.x(), 0, 1, shift * u.y());
            cv::warpAffine(grain, tissue, move, grain.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
        }
        cv::Mat frame = 100.0 + tissue, ending, noise(v.height, v.width, CV_32F), bytes, bgr;
        cv::exp(along - v.tip(k) - v.travelCentre, ending);
        frame += shaft / (1.0 + ending);
        cv::randn(noise, 0.0, k == v.noisierFrame ? 4.0 * v.noise : v.noise);
        frame += noise;
        frame.convertTo(bytes, CV_8U);
        if (v.clockOnShaft) {
            const std::string clock = QStringLiteral("10:00:%1.%2").arg(k / 30, 2, 10, QLatin1Char('0')).arg(k % 30 * 33, 3, 10, QLatin1Char('0')).toStdString();
            int base = 0;
            const int thickness = int(std::lround(2.0 * v.clockScale / 0.7));
            const cv::Size size = cv::getTextSize(clock, cv::FONT_HERSHEY_SIMPLEX, v.clockScale, thickness, &base);
            const double halfAlong = std::abs(u.x()) * size.width / 2.0 + std::abs(u.y()) * size.height / 2.0;
            const QPointF centre = QPointF(v.width / 2.0, v.height / 2.0) - u * (60.0 + halfAlong);
            cv::putText(bytes, clock, cv::Point(int(centre.x() - size.width / 2.0), int(centre.y() + size.height / 2.0)),
                        cv::FONT_HERSHEY_SIMPLEX, v.clockScale, cv::Scalar(250), thickness);
        }
        if (v.counterAhead) {
            // As ffmpeg's drawtext draws one: white digits on a black box.
            const std::string counter = std::to_string(k);
            int base = 0;
            const cv::Size size = cv::getTextSize(counter, cv::FONT_HERSHEY_SIMPLEX, 0.8, 2, &base);
            const QPointF centre = QPointF(v.width / 2.0, v.height / 2.0) + u * (v.travelCentre + 110.0);
            const cv::Point corner(int(centre.x() - size.width / 2.0), int(centre.y() + size.height / 2.0));
            cv::rectangle(bytes, cv::Rect(corner.x - 4, corner.y - size.height - 4, size.width + 8, size.height + base + 8),
                          cv::Scalar(0), cv::FILLED);
            cv::putText(bytes, counter, corner, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(250), 2);
        }
        cv::cvtColor(bytes, bgr, cv::COLOR_GRAY2BGR);
        writer.write(bgr);
    }
    return {};
}

// `v` written into `dir` and indexed; nothing, and `problem` says why, when it cannot be.
inline std::optional<nb::video::FrameIndex> writtenAndIndexed(const QTemporaryDir& dir, const NeedleVideo& v, QString* problem)
{
    if (!dir.isValid()) {
        *problem = QStringLiteral("no temporary folder");
        return std::nullopt;
    }
    const QString path = dir.filePath(QStringLiteral("needle.avi"));
    *problem = writeNeedleVideo(path, v);
    if (!problem->isEmpty())
        return std::nullopt;
    return nb::video::buildFrameIndex(path);
}

// `v` written, indexed and its tip tracked along a line drawn across the picture's middle, left
// to right; nothing, and `problem` says why, when the video cannot be made.
inline std::optional<nb::video::NeedleTrack> trackedAcrossTheMiddle(const NeedleVideo& v, QString* problem)
{
    QTemporaryDir dir;
    const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, problem);
    if (!index)
        return std::nullopt;
    nb::video::FrameReader reader(*index);
    const nb::video::NeedleAxis drawn(QPointF(10.0, kHeight / 2.0), QPointF(kWidth - 10.0, kHeight / 2.0));
    return nb::video::trackNeedle(reader, drawn);
}

inline double median(std::vector<double> x)
{
    std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(x.size() / 2), x.end());
    return x[x.size() / 2];
}

}  // namespace nb::needle_video
