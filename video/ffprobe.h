#pragma once
// The ffprobe tool, run once: its standard output, or nothing when it is missing, fails or
// takes longer than `timeout_ms`. The keyframe probe and the packet index both ask it.

#include <QByteArray>
#include <QStringList>
#include <optional>

namespace nb::video {

std::optional<QByteArray> runFfprobe(const QStringList& args, int timeout_ms = 300000);

}  // namespace nb::video
