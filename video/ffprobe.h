#pragma once
// The ffprobe tool, run once per video: what the frame index needs of the container, its video
// streams and the first one's packets, in one listing. Its start-up (loading FFmpeg's
// libraries) costs more than listing a short video's packets, and each index asked it four
// times, twice for the same packets.

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace nb::video {

std::optional<QByteArray> runFfprobe(const QStringList& args, int timeout_ms = 300000);

// `path` as ffprobe's input, never read as an option or a protocol: a video named "-x.avi"
// was taken for an option, and its index lost its codec and keyframes.
QString ffprobeInput(const QString& path);

struct ProbedStream {
    int index = -1;            // the stream's number in the file
    QString codec;             // e.g. "h264"
    int width = 0, height = 0;
    double avgRate = 0.0;      // frames/s, 0 when not given
    double realRate = 0.0;     // ffprobe's r_frame_rate
    double start_s = 0.0;      // the stream's start time in the file
    int reorderFrames = 0;     // has_b_frames
    bool coverPicture = false; // an attached picture, not a video
};

struct ProbedPacket {
    std::optional<double> pts_s;  // presentation time in the file; none where it says N/A (AVI)
    bool keyframe = false;
};

struct FfprobeListing {
    std::vector<ProbedStream> videoStreams;  // in the file's order, each once (not again from a program)
    std::vector<ProbedPacket> packets;       // the first video stream's, in decoding order
};

// nullopt when ffprobe is missing or fails (a file without video lists none).
std::optional<FfprobeListing> listVideo(const QString& path);

}  // namespace nb::video
