#pragma once
// Synchronising a video to a run, the one way the command line, the demo and the review
// window all do it: find the needle's axis (or take the operator's), track the tip along
// it, and fit the tracked displacement to the recorded position (sync.h). When no needle
// can be found the picture's motion is compared with the needle's speed instead, and the
// answer never reaches the accept threshold.

#include "core/run.h"
#include "core/sync.h"
#include "frame_index.h"
#include "needle_tracker.h"

#include <QRect>
#include <atomic>
#include <functional>
#include <optional>

namespace nb::video {

struct VideoSyncOptions {
    QRect roi;                        // where to look for the needle; empty: everywhere
    std::optional<NeedleAxis> axis;   // the needle's line, when the operator drew it
    SyncOptions sync;
};

struct VideoSync {
    SyncResult result;
    NeedleTrack track;                // empty when the fallback was used
    int frames = 0;
    FrameSpan tracked;                // the frames looked at (those the offsets tried can reach)
};

// Throws VideoError (the file) and std::invalid_argument (nothing to compare).
VideoSync syncVideoToRun(const FrameIndex& index, const Run& run, const VideoSyncOptions& options = {},
                         const std::function<void(int, int)>& progress = {},
                         const std::atomic_bool* cancel = nullptr);

}  // namespace nb::video
