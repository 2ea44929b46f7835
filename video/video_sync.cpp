#include "video_sync.h"

#include "frame_reader.h"
#include "motion_signal.h"

#include <algorithm>

namespace nb::video {

VideoSync syncVideoToRun(const FrameIndex& index, const Run& run, const VideoSyncOptions& options,
                         const std::function<void(int, int)>& progress, const std::atomic_bool* cancel)
{
    VideoSync out;
    out.frames = index.size();
    FrameReader reader(index, 8);
    std::optional<NeedleAxis> axis = options.axis;
    const bool detected = !axis;
    if (!axis)
        axis = detectNeedleAxis(reader, options.roi);
    if (axis) {
        out.track = trackNeedle(reader, *axis, progress, cancel);
        out.track.axisDetected = detected;
        out.result = synchroniseDisplacement({out.track.time_s, out.track.displacement_px}, needlePosition(run),
                                             index.frameDuration(), options.sync);
        return out;
    }
    // No needle to follow: the old, weaker comparison, never confident enough to accept.
    const MotionSignal m = computeMotionSignal(reader, options.roi, progress, cancel);
    out.result = synchronise({m.time_s, m.value}, needleSpeed(run), options.sync);
    out.result.method = QStringLiteral("picture motion vs needle speed (no needle found)");
    out.result.confidence = std::min(out.result.confidence, 0.9 * kSyncAcceptConfidence);
    return out;
}

}  // namespace nb::video
