#pragma once
// Indexing decodes the whole video (about 2.5 ms a frame here: most of a minute for ten
// minutes of CT-fluoro), so each index is stored and used again for as long as the video file
// is unchanged (same size, same modification time). Stored in the user's cache folder, not
// beside the video, which may sit on a read-only share; a store that cannot be written only
// loses the shortcut.

#include "video/frame_index.h"

#include <optional>
#include <vector>

namespace nb::video {

// QStandardPaths' cache location + "/frame-index", or $NEEDLEBENCH_CACHE_DIR/frame-index.
QString defaultFrameIndexStore();

// The stored index of `videoPath` when the file is unchanged since it was stored; nullopt
// when there is none, it is stale, or it cannot be read.
std::optional<FrameIndex> loadStoredFrameIndex(const QString& videoPath, const QString& storeDir);
// False when it could not be written.
bool storeFrameIndex(const FrameIndex& index, const QString& storeDir);

// The stored index when valid, else buildFrameIndex() and store the result (not when
// cancelled). `fromStore` (may be null) says which. An empty `storeDir` means the default.
FrameIndex loadOrBuildFrameIndex(const QString& path, const IndexProgress& progress = {},
                                 const std::atomic_bool* cancel = nullptr, bool* fromStore = nullptr,
                                 const QString& storeDir = {});

// Each frame's time (video time), from the stored or built index: what exports number frames
// by. Empty, with the reason in `problem`, when the video cannot be read.
std::vector<double> frameTimesOf(const QString& videoPath, QString* problem);

}  // namespace nb::video
