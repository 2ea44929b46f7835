#pragma once
// Friction phases read off the video (models.md §5), the way the operator reads them: the
// video is synchronised to the run (video_sync.h), the tissue's motion is tracked in a band
// beside the needle, and the phases follow from how the tissue moves against the needle
// (label_suggest.h). A video that cannot be synchronised with confidence gives the
// suggestions from force and position instead, and says so.

#include "core/labels.h"
#include "video_sync.h"

namespace nb::video {

struct VideoPhases {
    Labels labels;
    bool fromVideo = false;
    QString note;          // why the video was not used, when it was not
    SyncResult sync;
};

// Throws VideoError.
VideoPhases suggestPhasesFromVideo(const FrameIndex& index, const Run& run, const VideoSyncOptions& options = {});

}  // namespace nb::video
