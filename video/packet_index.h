#pragma once
// The frame index from the container's packets, without decoding a frame's picture: the
// `ffprobe` tool lists every video packet's presentation time and keyframe flag (a few
// seconds for an hour of H.264 where decoding takes minutes). Frame 0 is decoded once for
// the decoder's time origin; the reader checks every later frame's time against the index
// as it decodes it (frame_reader.h), so a wrong entry shows, not a wrong frame. What it
// cannot know without decoding: which frames repeat the previous picture (duplicates stay
// unflagged, and a warning says so).

#include "ffprobe.h"
#include "frame_index.h"

#include <optional>

namespace nb::video {

// nullopt when ffprobe is missing or the file's packets carry no usable times (then build
// the index by decoding). Throws VideoError when the file cannot be opened at all.
std::optional<FrameIndex> buildFrameIndexFromPackets(const QString& path);
// The same from the file's listing (listVideo, ffprobe.h), made once for every use.
std::optional<FrameIndex> buildFrameIndexFromPackets(const QString& path, const FfprobeListing& listing);

}  // namespace nb::video
