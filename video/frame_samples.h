#pragma once
// Frames spread over a video, in grey, from which the line finder and the tracker learn what
// is always there and what changes. Sampling seeks through the file (on H.264 with a keyframe
// every 250 frames it decodes about as much as two passes over the video): a caller that both
// finds lines and tracks them samples once and gives both the same frames.

#include "frame_reader.h"

#include <opencv2/core.hpp>

#include <vector>

namespace nb::video {

struct FrameSamples {
    std::vector<cv::Mat> gray;
    int width = 0, height = 0;
    FrameSpan span;  // the frames sampled from, which trackNeedles tracks
};

// `count` frames spread evenly over `span` of the video (all of it by default), and as many
// again over the stretch in which the picture changes, when that is a small part of it.
// Throws VideoError.
FrameSamples sampleFrames(FrameReader& reader, int count = 40, FrameSpan span = {});

}  // namespace nb::video
