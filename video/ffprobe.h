#pragma once
// The ffprobe tool, run once: its standard output, or nothing when it is missing, fails or
// takes longer than `timeout_ms`. The keyframe probe and the packet index both ask it.

#include <QByteArray>
#include <QStringList>
#include <optional>

namespace nb::video {

std::optional<QByteArray> runFfprobe(const QStringList& args, int timeout_ms = 300000);

// `path` as ffprobe's input, never read as an option or a protocol: a video named "-x.avi"
// was taken for an option, and its index lost its codec and keyframes.
QString ffprobeInput(const QString& path);

}  // namespace nb::video
