#include "packet_index.h"
#include "orientation.h"

#include "ffprobe.h"
#include "video_error.h"

#include "core/tr.h"

#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>

namespace nb::video {

namespace {


double rate(const QByteArray& fraction)
{
    const QList<QByteArray> p = fraction.trimmed().split('/');
    bool ok1 = false, ok2 = true;
    const double num = p.value(0).toDouble(&ok1);
    const double den = p.size() > 1 ? p[1].toDouble(&ok2) : 1.0;
    return ok1 && ok2 && den > 0 ? num / den : 0.0;
}

}  // namespace

std::optional<FrameIndex> buildFrameIndexFromPackets(const QString& path)
{
    if (!QFileInfo(path).isFile())
        throw VideoError(path, nb::TrDevices::tr("no such file"));
    const auto stream = runFfprobe({QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"), QStringLiteral("v:0"),
                               QStringLiteral("-show_entries"),
                               QStringLiteral("stream=codec_name,width,height,avg_frame_rate,r_frame_rate,start_time"),
                               QStringLiteral("-of"), QStringLiteral("default=noprint_wrappers=1"), ffprobeInput(path)});
    if (!stream)
        return std::nullopt;
    FrameIndex index;
    index.path = path;
    double start = 0.0, avg = 0.0, real = 0.0;
    for (const QByteArray& line : stream->split('\n')) {
        const int eq = line.indexOf('=');
        if (eq < 0)
            continue;
        const QByteArray key = line.left(eq), value = line.mid(eq + 1).trimmed();
        if (key == "codec_name")
            index.codec = QString::fromUtf8(value);
        else if (key == "width")
            index.width = value.toInt();
        else if (key == "height")
            index.height = value.toInt();
        else if (key == "avg_frame_rate")
            avg = rate(value);
        else if (key == "r_frame_rate")
            real = rate(value);
        else if (key == "start_time")
            start = value.toDouble();
    }
    index.fpsNominal = avg > 0 ? avg : real;
    if (index.width <= 0 || index.height <= 0)
        return std::nullopt;
    const auto packets = runFfprobe({QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"), QStringLiteral("v:0"),
                                QStringLiteral("-show_entries"), QStringLiteral("packet=pts_time,flags"), QStringLiteral("-of"),
                                QStringLiteral("csv=p=0"), ffprobeInput(path)});
    if (!packets)
        return std::nullopt;
    struct Packet {
        double pts;
        bool key;
    };
    std::vector<Packet> list;
    bool timed = true;
    for (const QByteArray& line : packets->split('\n')) {
        const QList<QByteArray> f = line.trimmed().split(',');
        if (f.size() < 2 || f[0].isEmpty())
            continue;
        bool ok = false;
        const double t = f[0].toDouble(&ok);
        timed = timed && ok;
        list.push_back({ok ? t - start : 0.0, f[1].startsWith('K')});
    }
    if (list.empty())
        return std::nullopt;
    if (!timed) {
        // AVI stores no per-packet time: one packet a frame at the container's rate.
        if (!(index.fpsNominal > 0))
            return std::nullopt;
        for (std::size_t k = 0; k < list.size(); ++k)
            list[k].pts = double(k) / index.fpsNominal;
    }
    // Packets come in decoding order; frames are shown in presentation order.
    std::stable_sort(list.begin(), list.end(), [](const Packet& a, const Packet& b) { return a.pts < b.pts; });
    // The decoder's time of frame 0 (AVI with B-frames reports every frame late by its delay):
    // the reader compares decoded times with the index through it.
    cv::VideoCapture cap(path.toStdString(), cv::CAP_FFMPEG);
    if (!cap.isOpened())
        throw VideoError(path, nb::TrDevices::tr("no frame could be decoded (truncated or corrupt file?)"));
    // A damaged start (the decoder refuses the first packets) is passed over, as the reader does
    // later. Its first frame then is not the first packet's: with times from the packets, the
    // origin is the first packet's (the decoder's and ffprobe's times count from the stream's
    // start alike); the first frame decoded would put every frame that much late.
    int refused = 0;
    while (!cap.grab())
        if (++refused > std::min(kRefusedPacketsTried, int(list.size())))
            throw VideoError(path, nb::TrDevices::tr("no frame could be decoded (truncated or corrupt file?)"));
    const double first = refused > 0 && timed ? list.front().pts : cap.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    turnIndexUpright(index, takeRotation(cap));
    index.containerFrames = int(list.size());
    index.frames.reserve(list.size());
    for (const Packet& p : list) {
        FrameInfo f;
        f.time_s = p.pts - list.front().pts;
        f.keyframe = p.key;
        if (!index.frames.empty() && f.time_s <= index.frames.back().time_s)
            index.timestampsMonotonic = false;
        index.frames.push_back(f);
    }
    index.timeOrigin_s = first;
    index.frames.front().keyframe = true;
    index.keyframesKnown = true;
    index.fromPackets = true;
    index.updateStats();
    index.warnings = indexWarnings(index);
    return index;
}

}  // namespace nb::video
