#pragma once
// Labels suggested from a run together with its imaging video: the one path behind
// `needlebench labels suggest --video` and Review's Suggest labels. Friction runs get their
// phases from the tissue's motion in the picture (the relative velocity that defines them,
// models.md 5); insertion runs get the relaxation from the organ surface's spring-back.
// Where the picture gives nothing, the suggestion from force and position stands and
// `problem` says why, so the caller can tell the operator.

#include "core/labels.h"
#include "core/run.h"
#include "core/sync.h"
#include "core/tissue_motion.h"
#include "frame_index.h"

#include <atomic>
#include <functional>
#include <optional>

namespace nb::video {

struct VideoLabels {
    Labels labels;        // the whole suggestion (from force and position where the video gave nothing)
    bool phases = false;  // friction phases, else events
    bool videoUsed = false;
    QString problem;      // why the video added nothing; empty when it added something
    // Insertion runs whose surface was read: "" when a relaxation was suggested, else why not.
    std::optional<QString> relaxationProblem;
    std::optional<TissueMotion> tissue;  // friction runs: the tissue's velocity that was used
    bool cancelled = false;
};

// Whether the run's suggestion is friction phases (its protocol, or, when it names none, what
// `suggested` = suggestLabels(run) holds) rather than events.
bool suggestsPhases(const Run& run, const Labels& suggested);

// `mapping`: the video's clock against the recording's (its offset and drift, found before).
// `name` names the video in each label's comment. Never throws: a video that cannot be read
// is a `problem`. `progress(done, total)` counts the frames read; `cancel` stops early (the
// answer is then the suggestion from force and position, `cancelled` set).
VideoLabels suggestLabelsWithVideo(const Run& run, const FrameIndex& index, const TimelineMapping& mapping, const QString& name,
                                   const std::function<void(int, int)>& progress = {}, const std::atomic_bool* cancel = nullptr);

}  // namespace nb::video
