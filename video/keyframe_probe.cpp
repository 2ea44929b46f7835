#include "keyframe_probe.h"
#include "ffprobe.h"

#include <algorithm>

namespace nb::video {

ProbeResult probeKeyframes(const FfprobeListing& listing)
{
    ProbeResult r;
    r.videoStreams = 0;
    // Every video stream counts but a cover picture; the first is the one OpenCV decodes.
    for (const ProbedStream& s : listing.videoStreams) {
        if (s.coverPicture || r.videoStreams++ > 0)
            continue;
        r.codec = s.codec;
        r.reorderFrames = s.reorderFrames;
        r.start_s = s.start_s;  // OpenCV reports time relative to the stream's start
    }
    bool untimed = false;
    for (const ProbedPacket& p : listing.packets) {
        if (!p.pts_s) {  // "N/A" (AVI without timestamps): no usable time
            untimed = true;
            continue;
        }
        r.packets_s.push_back(*p.pts_s - r.start_s);
        if (p.keyframe)
            r.keyframes_s.push_back(*p.pts_s - r.start_s);
    }
    std::sort(r.packets_s.begin(), r.packets_s.end());  // listed in decoding order
    if (untimed)
        r.packets_s.clear();  // some packets' times unknown: not every packet's time
    return r;
}

std::optional<ProbeResult> probeKeyframes(const QString& path)
{
    const std::optional<FfprobeListing> listing = listVideo(path);
    if (!listing)
        return std::nullopt;
    return probeKeyframes(*listing);
}

}  // namespace nb::video
