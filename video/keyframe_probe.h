#pragma once
// Keyframe times from the `ffprobe` tool (part of Debian's ffmpeg package): OpenCV 4.6 does
// not expose the keyframe flag of its FFmpeg backend. Absent tool or unusable output gives
// nullopt and the index falls back to "frame 0 only".

#include <QString>
#include <optional>
#include <vector>

namespace nb::video {

struct ProbeResult {
    QString codec;                    // e.g. "h264"
    std::vector<double> keyframes_s;  // relative to the stream start, as OpenCV reports time
    std::vector<double> packets_s;    // every packet's time so, in presentation order; empty when some have none
    double start_s = 0.0;             // the stream's start time in the file
    int videoStreams = 1;             // video streams in the file, cover pictures aside
    int reorderFrames = 0;            // the stream's has_b_frames: pictures shown before one they are predicted from
};

struct FfprobeListing;

// From the listing of the file (listVideo, ffprobe.h), or from the file, listed first.
ProbeResult probeKeyframes(const FfprobeListing& listing);
std::optional<ProbeResult> probeKeyframes(const QString& path);

}  // namespace nb::video
