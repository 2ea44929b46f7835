#pragma once
// A motion signal from the video: how much the picture changes inside a region the user
// drew, per second, between consecutive distinct frames. Duplicate frames (a recorder
// repeating a picture) would read as "no motion" and are masked (NaN) instead.

#include "frame_reader.h"

#include <QRect>
#include <atomic>
#include <functional>
#include <vector>

namespace nb::video {

struct MotionSignal {
    std::vector<double> time_s;  // video time, midway between the two frames compared
    std::vector<double> value;   // mean absolute grey change per second; NaN when masked
};

// Reads every frame of `reader` in order. An empty or out-of-frame `roi` means the whole
// frame. Throws VideoError.
MotionSignal computeMotionSignal(FrameReader& reader, QRect roi = {},
                                 const std::function<void(int, int)>& progress = {},
                                 const std::atomic_bool* cancel = nullptr);

}  // namespace nb::video
