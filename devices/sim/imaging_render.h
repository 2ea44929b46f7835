#pragma once
// The imaging view of a simulated run: what the CT-fluoro console's monitor would have shown
// (models.md 1: 29.97 frames/s, three slice panes, the needle visible mainly in the middle
// one). Grey, noisy: a tissue slab between two plates that moves with the rig's phases, and
// the needle. Used to exercise synchronisation and labelling without a scanner.

#include "core/run.h"

#include <QString>

#include <functional>
#include <vector>

namespace cv {
class Mat;
}

namespace nb::devices::sim {

struct ImagingOptions {
    double fps = 30000.0 / 1001.0;
    double leadIn_s = 0.0;  // the video starts this long before the recording (negative: after it began)
    double tail_s = 0.5;    // and runs on this long after it
    int width = 720;
    int height = 480;
    double noise = 10.0;    // grey levels, standard deviation per pixel and frame
    unsigned seed = 1;
    // Asked before each frame: true stops the rendering, and the part written is removed
    // (Ctrl+C during a long video went unheard and the command ended 0).
    std::function<bool()> cancelled;
};

struct ImagingTruth {
    double offset_s = 0.0;  // video time minus recording time
    int frames = 0;         // 0 when cancelled: nothing is left of the video
    double fps = 0.0;
};

// The tissue's position per sample (mm, same frame as position_mm): the run's
// tissue_position_mm column when it has one; otherwise derived: the tissue is carried by
// the needle (static friction) until it takes up the play against a plate, as on the
// friction platform.
std::vector<double> tissuePositions(const Run& run, double play_mm = 1.5);

// Renders the view at recording time t (before the start and after the end the rig is at
// rest). `frameNumber` seeds the noise.
class ImagingRenderer {
public:
    ImagingRenderer(const Run& run, const ImagingOptions& options);
    void render(double recordingTime_s, int frameNumber, cv::Mat& out) const;
    double needleAt(double t) const;
    double tissueAt(double t) const;

private:
    double interpolate(const std::vector<double>& v, double t) const;
    const Run& run_;
    ImagingOptions o_;
    std::vector<double> tissue_;
    double minPos_ = 0.0, ppm_ = 4.0, surface_mm_ = 0.0, thickness_mm_ = 30.0;
    std::vector<unsigned char> texture_;  // tissue speckle, rows follow the tissue
    int textureRows_ = 0;
};

// Writes the whole video (codec from the extension: .avi MJPEG, .mkv FFV1, .mp4 H.264 or
// MPEG-4 Part 2). Throws VideoError naming the file.
ImagingTruth renderImagingVideo(const Run& run, const QString& path, const ImagingOptions& options = {});

// Why renderImagingVideo cannot write a video of `path`'s type (.avi, .mkv, .mp4), or empty:
// for a command to check before it records the run the video shows.
QString imagingVideoTypeProblem(const QString& path);

}  // namespace nb::devices::sim
