#pragma once
// Every video NeedleBench reads is opened here, through OpenCV's FFmpeg backend, the same way.
//
// An AVI keeps no time per chunk: read on, FFmpeg numbers its chunks one frame each and, where a
// stretch of the file is overwritten, looks for the next chunk header and counts on. A zeroed
// stretch of an MJPEG AVI then indexed clean, four frames missing and every frame after them
// numbered 0.13 s early, while a seek (through the file's own index) found them at their true
// times. Read in the order of its index (FFmpeg's "sortdts" flag, which only its AVI reader
// heeds), every chunk keeps its place and the overwritten ones are refused, as damage is in
// other files.

#include <QString>
#include <QStringList>
#include <opencv2/videoio.hpp>

namespace nb::video {

// Opens `path`; false when FFmpeg cannot. OpenCV's own exceptions pass through.
bool openCapture(cv::VideoCapture& cap, const QString& path);

// The same reading for the ffprobe tool: its options before the input.
QStringList ffprobeReadOptions();

}  // namespace nb::video
