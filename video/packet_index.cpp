#include "packet_index.h"
#include "orientation.h"
#include "capture.h"

#include "ffprobe.h"
#include "video_error.h"

#include "core/tr.h"

#include <QFileInfo>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>

namespace nb::video {

std::optional<FrameIndex> buildFrameIndexFromPackets(const QString& path)
{
    if (!QFileInfo(path).isFile())
        throw VideoError(path, nb::TrDevices::tr("no such file"));
    const std::optional<FfprobeListing> listing = listVideo(path);
    if (!listing)
        return std::nullopt;
    return buildFrameIndexFromPackets(path, *listing);
}

std::optional<FrameIndex> buildFrameIndexFromPackets(const QString& path, const FfprobeListing& listing)
{
    if (listing.videoStreams.empty())
        return std::nullopt;
    const ProbedStream& stream = listing.videoStreams.front();
    FrameIndex index;
    index.path = path;
    index.codec = stream.codec;
    index.width = stream.width;
    index.height = stream.height;
    index.fpsNominal = stream.avgRate > 0 ? stream.avgRate : stream.realRate;
    if (index.width <= 0 || index.height <= 0)
        return std::nullopt;
    struct Packet {
        double pts;
        bool key;
    };
    std::vector<Packet> list;
    bool timed = true;
    for (const ProbedPacket& p : listing.packets) {
        timed = timed && p.pts_s.has_value();
        list.push_back({p.pts_s ? *p.pts_s - stream.start_s : 0.0, p.keyframe});
    }
    if (list.empty())
        return std::nullopt;
    if (!timed) {
        // AVI stores no per-packet time: one packet a frame at the container's rate.
        if (!(index.fpsNominal > 0))
            return std::nullopt;
        for (std::size_t k = 0; k < list.size(); ++k)
            list[k].pts = double(k) / index.fpsNominal;
    }
    // Packets come in decoding order; frames are shown in presentation order.
    std::stable_sort(list.begin(), list.end(), [](const Packet& a, const Packet& b) { return a.pts < b.pts; });
    // The decoder's time of frame 0 (AVI with B-frames reports every frame late by its delay):
    // the reader compares decoded times with the index through it.
    cv::VideoCapture cap;
    if (!openCapture(cap, path))
        throw VideoError(path, nb::TrDevices::tr("no frame could be decoded (truncated or corrupt file?)"));
    // A damaged start (the decoder refuses the first packets) is passed over, as the reader does
    // later. Its first frame then is not the first packet's: with times from the packets, the
    // origin is the first packet's (the decoder's and ffprobe's times count from the stream's
    // start alike); the first frame decoded would put every frame that much late.
    int refused = 0;
    while (!cap.grab())
        if (++refused > std::min(kRefusedPacketsTried, int(list.size())))
            throw VideoError(path, nb::TrDevices::tr("no frame could be decoded (truncated or corrupt file?)"));
    const double first = refused > 0 && timed ? list.front().pts : cap.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    turnIndexUpright(index, takeRotation(cap));
    index.containerFrames = int(list.size());
    index.frames.reserve(list.size());
    for (const Packet& p : list) {
        FrameInfo f;
        f.time_s = p.pts - list.front().pts;
        f.keyframe = p.key;
        if (!index.frames.empty() && f.time_s <= index.frames.back().time_s)
            index.timestampsMonotonic = false;
        index.frames.push_back(f);
    }
    index.timeOrigin_s = first;
    index.frames.front().keyframe = true;
    index.keyframesKnown = true;
    index.fromPackets = true;
    index.updateStats();
    index.warnings = indexWarnings(index);
    return index;
}

}  // namespace nb::video
