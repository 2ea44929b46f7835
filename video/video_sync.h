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
    bool codedOnce = false;           // the operator says nobody coded the file again (PictureCoding::codedOnce)
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

// `done` (from syncVideoToRun with the same index, run and marks) fitted again as `options` say
// the video was coded, without tracking it again. Which line is the needle, and which pass over
// a damaged file is kept, go by how well each track explains the recording with no coder's lag
// (SyncResult::trackConfidence), which the coding does not change.
VideoSync refitVideoSync(VideoSync done, const FrameIndex& index, const Run& run, const VideoSyncOptions& options);

}  // namespace nb::video
