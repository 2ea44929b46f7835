#pragma once
// Finding the needle's line in a video: the straight ridge (bright or dark) along which an
// edge moves from frame to frame, or the path of change a tip draws where no shaft stands out
// (lines summed across sampled frames, refined at full resolution, ranked by how clearly an edge
// moves along them, with the changing digits of burnt-in clocks and counters set apart).

#include "frame_samples.h"
#include "needle_axis.h"

#include <QRect>
#include <optional>
#include <utility>
#include <vector>

namespace nb::video {

// Finds the needle's axis in `reader`'s video from `sampleFrames` frames spread over it,
// inside `roi` when it is not empty. nullopt when nothing moves along a line. Throws VideoError.
std::optional<NeedleAxis> detectNeedleAxis(FrameReader& reader, QRect roi = {}, int sampleFrames = 40);

// The likeliest needle axes, best first (at most `maxCount`, and after them the few lines along
// which a shaft stands out most of the frames' mean, and the two paths of a tip with the most
// change under them, when they ranked lower); `scores` (may be null) gets how clearly each
// looks like a needle (a moving edge on a straight ridge).
std::vector<NeedleAxis> needleAxisCandidates(FrameReader& reader, QRect roi = {}, int maxCount = 4, int sampleFrames = 40,
                                             std::vector<double>* scores = nullptr);
// `spares` (may be null) gets (score, line) of lines that look less like a needle and are alike
// none returned, worth tracking when none of those explains the recording: the lines along which
// a shaft stands out of the frames' mean after the few taken, and the short streaks of change
// (a tip's path) too short or too faint to be taken.
std::vector<NeedleAxis> needleAxisCandidates(const FrameSamples& samples, QRect roi = {}, int maxCount = 4,
                                             std::vector<double>* scores = nullptr,
                                             std::vector<std::pair<double, NeedleAxis>>* spares = nullptr);

}  // namespace nb::video
