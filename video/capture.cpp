#include "capture.h"

#include <QByteArray>
#include <QFile>

#include <mutex>

namespace nb::video {

namespace {

// OpenCV takes FFmpeg's options for opening a file only from this variable, read at each
// open; a value the user gave comes after ours and so wins.
void readAviInIndexOrder()
{
    static std::once_flag once;
    std::call_once(once, [] {
        const QByteArray given = qgetenv("OPENCV_FFMPEG_CAPTURE_OPTIONS");
        qputenv("OPENCV_FFMPEG_CAPTURE_OPTIONS", given.isEmpty() ? QByteArray("fflags;sortdts") : "fflags;sortdts|" + given);
    });
}

}  // namespace

bool openCapture(cv::VideoCapture& cap, const QString& path)
{
    readAviInIndexOrder();
    return cap.open(QFile::encodeName(path).toStdString(), cv::CAP_FFMPEG);
}

QStringList ffprobeReadOptions() { return {QStringLiteral("-fflags"), QStringLiteral("+sortdts")}; }

}  // namespace nb::video
