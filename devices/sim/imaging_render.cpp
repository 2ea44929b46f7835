#include "imaging_render.h"
#include "core/tr.h"

#include "video/video_error.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace nb::devices::sim {

std::vector<double> tissuePositions(const Run& run, double play_mm)
{
    if (const auto* column = run.numericColumn(QStringLiteral("tissue_position_mm"))) {
        bool usable = std::any_of(column->begin(), column->end(), [](double v) { return std::isfinite(v); });
        if (usable)
            return *column;
    }
    // Backlash: the tissue stays within ±play/2 of the needle, and stays put otherwise.
    std::vector<double> out(run.size());
    double tissue = run.size() ? run.position_mm.front() : 0.0;
    const double rest = tissue;
    for (std::size_t i = 0; i < run.size(); ++i) {
        const double rel = run.position_mm[i] - rest;
        const double offset = tissue - rest;
        if (rel > offset + 0.5 * play_mm)
            tissue = rest + rel - 0.5 * play_mm;
        else if (rel < offset - 0.5 * play_mm)
            tissue = rest + rel + 0.5 * play_mm;
        out[i] = tissue - rest;  // displacement from rest
    }
    return out;
}

ImagingRenderer::ImagingRenderer(const Run& run, const ImagingOptions& options) : run_(run), o_(options)
{
    if (run.size() == 0)
        return;
    tissue_ = tissuePositions(run);
    // A tissue_position_mm column is absolute; the derived one is a displacement.
    if (run.numericColumn(QStringLiteral("tissue_position_mm")) && !tissue_.empty()) {
        const double rest = tissue_.front();
        for (double& v : tissue_)
            v = std::isfinite(v) ? v - rest : 0.0;
    }
    const auto [lo, hi] = std::minmax_element(run.position_mm.begin(), run.position_mm.end());
    minPos_ = *lo;
    thickness_mm_ = run.metadata.number(QStringLiteral("thickness_mm")).value_or(30.0);
    const bool sine = run.metadata.value(QStringLiteral("protocol"), QString()) == QLatin1String("friction");
    // On the platform the needle has passed fully through the slab (its tip moves below it);
    // elsewhere it enters from above.
    surface_mm_ = sine ? *lo - thickness_mm_ - 4.0 : *lo + 0.25 * (*hi - *lo);
    minPos_ = std::min(minPos_, surface_mm_ - 4.0);
    const double span = std::max(*hi, surface_mm_ + thickness_mm_) - minPos_ + 10.0;
    ppm_ = (o_.height - 60) / std::max(span, 1.0);
    textureRows_ = o_.height * 3;
    texture_.resize(std::size_t(textureRows_) * 64);
    std::mt19937 rng(o_.seed);
    std::normal_distribution<double> n(0.0, 18.0);
    double smooth = 0.0;
    for (auto& px : texture_) {
        smooth = 0.6 * smooth + 0.4 * n(rng);
        px = static_cast<unsigned char>(std::clamp(105.0 + smooth, 0.0, 255.0));
    }
}

double ImagingRenderer::interpolate(const std::vector<double>& v, double t) const
{
    const auto& ts = run_.time_s;
    if (ts.empty() || v.empty())
        return 0.0;
    if (t <= ts.front())
        return v.front();
    if (t >= ts.back())
        return v.back();
    const auto it = std::upper_bound(ts.begin(), ts.end(), t);
    const std::size_t i = std::size_t(it - ts.begin());
    const double w = (t - ts[i - 1]) / std::max(1e-12, ts[i] - ts[i - 1]);
    return v[i - 1] + w * (v[i] - v[i - 1]);
}

double ImagingRenderer::needleAt(double t) const { return interpolate(run_.position_mm, t); }
double ImagingRenderer::tissueAt(double t) const { return interpolate(tissue_, t); }

void ImagingRenderer::render(double t, int frameNumber, cv::Mat& out) const
{
    out.create(o_.height, o_.width, CV_8UC1);
    out.setTo(cv::Scalar(35));
    const int paneW = o_.width / 3;
    const int top = 30;
    auto y = [&](double mm) { return int(std::lround(top + (mm - minPos_ + 5.0) * ppm_)); };
    const double tissue = tissueAt(t);
    const double needle = needleAt(t);
    const int slabTop = y(surface_mm_ + tissue), slabBottom = y(surface_mm_ + thickness_mm_ + tissue);
    const int shift = int(std::lround(tissue * ppm_));
    for (int p = 0; p < 3; ++p) {
        const int x0 = p * paneW;
        const int cx = x0 + paneW / 2;
        // Tissue speckle moves with the tissue; each pane is a different slice of it.
        for (int row = std::max(0, slabTop); row < std::min(o_.height, slabBottom); ++row) {
            const int tr_ = ((row - shift) % textureRows_ + textureRows_) % textureRows_;
            unsigned char* dst = out.ptr<unsigned char>(row);
            for (int x = x0 + 12; x < x0 + paneW - 12; ++x)
                dst[x] = texture_[std::size_t(tr_) * 64 + std::size_t((x * 7 + p * 23) % 64)];
        }
        // The constraining plates, with a hole for the needle.
        const int plateTop = y(surface_mm_) - 6, plateBottom = y(surface_mm_ + thickness_mm_) + 2;
        for (int py : {plateTop, plateBottom}) {
            cv::rectangle(out, cv::Rect(x0 + 8, py, paneW / 2 - 16, 4), cv::Scalar(200), cv::FILLED);
            cv::rectangle(out, cv::Rect(cx + 8, py, paneW / 2 - 16, 4), cv::Scalar(200), cv::FILLED);
        }
        // The needle: in the middle slice fully, in the others a faint partial-volume trace.
        const int tip = y(needle);
        const int level = p == 1 ? 245 : 70;
        cv::line(out, cv::Point(cx, 0), cv::Point(cx, tip), cv::Scalar(level), p == 1 ? 3 : 2);
        cv::line(out, cv::Point(x0 + paneW - 1, 0), cv::Point(x0 + paneW - 1, o_.height), cv::Scalar(90), 1);
    }
    cv::Mat noise(out.size(), CV_16SC1);
    cv::RNG rng(std::uint64_t(o_.seed) * 1000003u + std::uint64_t(frameNumber));
    rng.fill(noise, cv::RNG::NORMAL, 0.0, o_.noise);
    cv::Mat noisy;
    out.convertTo(noisy, CV_16SC1);
    noisy += noise;
    noisy.convertTo(out, CV_8UC1);
}

QString imagingVideoTypeProblem(const QString& path)
{
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext == QLatin1String("avi") || ext == QLatin1String("mkv") || ext == QLatin1String("mp4"))
        return {};
    return nb::TrDevices::tr("unknown video type '.%1' (use .avi, .mkv or .mp4)").arg(ext);
}

ImagingTruth renderImagingVideo(const Run& run, const QString& path, const ImagingOptions& options)
{
    if (run.size() < 2)
        throw nb::video::VideoError(path, nb::TrDevices::tr("the run has too few samples to render"));
    const QString ext = QFileInfo(path).suffix().toLower();
    std::vector<int> fourccs;
    if (ext == QLatin1String("avi"))
        fourccs = {cv::VideoWriter::fourcc('M', 'J', 'P', 'G')};
    else if (ext == QLatin1String("mkv"))
        fourccs = {cv::VideoWriter::fourcc('F', 'F', 'V', '1'), cv::VideoWriter::fourcc('M', 'J', 'P', 'G')};
    else if (ext == QLatin1String("mp4"))
        fourccs = {cv::VideoWriter::fourcc('a', 'v', 'c', '1'), cv::VideoWriter::fourcc('m', 'p', '4', 'v')};
    else
        throw nb::video::VideoError(path, imagingVideoTypeProblem(path));
    cv::VideoWriter writer;
    for (int fourcc : fourccs) {
        try {
            if (writer.open(path.toStdString(), cv::CAP_FFMPEG, fourcc, options.fps, cv::Size(options.width, options.height), false))
                break;
        } catch (const cv::Exception&) {
        }
    }
    if (!writer.isOpened())
        throw nb::video::VideoError(path, nb::TrDevices::tr("cannot write a video here (folder missing or not writable, or no encoder)"));
    ImagingRenderer renderer(run, options);
    ImagingTruth truth;
    truth.offset_s = options.leadIn_s - run.time_s.front();
    truth.fps = options.fps;
    const double end = run.time_s.back() - run.time_s.front() + options.leadIn_s + options.tail_s;
    const int frames = int(std::ceil(end * options.fps));
    // A video that starts after the recording began (a negative lead-in) has frames only while
    // the run is still there to show.
    if (frames <= 0) {
        writer.release();
        QFile::remove(path);
        throw nb::video::VideoError(path, nb::TrDevices::tr("the video would start %1 s after the recording began, after its end (%2 s)")
                                              .arg(-options.leadIn_s)
                                              .arg(run.time_s.back() - run.time_s.front()));
    }
    cv::Mat image;
    for (int k = 0; k < frames; ++k) {
        if (options.cancelled && options.cancelled()) {
            writer.release();
            QFile::remove(path);
            return truth;  // frames 0
        }
        const double recordingTime = run.time_s.front() + k / options.fps - options.leadIn_s;
        renderer.render(recordingTime, k, image);
        writer.write(image);
    }
    writer.release();
    truth.frames = frames;
    if (!QFileInfo(path).exists() || QFileInfo(path).size() == 0)
        throw nb::video::VideoError(path, nb::TrDevices::tr("the video could not be written"));
    return truth;
}

}  // namespace nb::devices::sim
