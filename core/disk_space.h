#pragma once
// Free space on the disk a file goes to: checked before a recording starts and watched
// while it runs, so that the operator hears of a filling disk before rows are lost.

#include <QString>
#include <optional>

namespace nb {

// Bytes that may still be written on the file system holding `path` (a file, or the folder
// it will be created in); nullopt when the file system cannot tell.
std::optional<qint64> freeBytes(const QString& path);

// Seconds until `free_bytes` are used up at `bytes_per_s`; +infinity when nothing is written.
double secondsUntilFull(qint64 free_bytes, double bytes_per_s);

// A recording is refused below this much free space (a few seconds at 10 kHz).
inline constexpr qint64 kMinFreeBytesToRecord = 1 << 20;
// The operator is warned when the disk will be full within this time at the current rate.
inline constexpr double kLowSpaceWarning_s = 60.0;

}  // namespace nb
