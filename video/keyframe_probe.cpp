#include "keyframe_probe.h"
#include "ffprobe.h"

#include <algorithm>

namespace nb::video {

std::optional<ProbeResult> probeKeyframes(const QString& path)
{
    // Every video stream, to count them (a cover picture is none); the first is the one OpenCV
    // decodes.
    const auto stream = runFfprobe({QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"),
                                       QStringLiteral("v"), QStringLiteral("-show_entries"),
                                       QStringLiteral("stream=codec_name,start_time,has_b_frames:stream_disposition=attached_pic"),
                                       QStringLiteral("-of"), QStringLiteral("default"), ffprobeInput(path)});
    if (!stream)
        return std::nullopt;
    ProbeResult r;
    r.videoStreams = 0;
    double start = 0.0;
    // A stream listed inside a program ([PROGRAM] … [/PROGRAM]: MPEG-TS) is listed again on its
    // own; counted twice, every TS file was said to hold two video streams.
    bool inProgram = false;
    for (const QByteArray& block : stream->split('[')) {
        if (block.startsWith("PROGRAM]"))
            inProgram = true;
        else if (block.startsWith("/PROGRAM]"))
            inProgram = false;
        if (inProgram || !block.startsWith("STREAM]") || block.contains("attached_pic=1"))
            continue;
        if (r.videoStreams++ > 0)
            continue;
        for (const QByteArray& line : block.split('\n')) {
            if (line.startsWith("codec_name="))
                r.codec = QString::fromUtf8(line.mid(11)).trimmed();
            else if (line.startsWith("has_b_frames="))
                r.reorderFrames = std::clamp(line.mid(13).trimmed().toInt(), 0, 16);
            else if (line.startsWith("start_time=")) {
                bool ok = false;
                const double s = line.mid(11).trimmed().toDouble(&ok);
                if (ok)
                    start = s;  // OpenCV reports time relative to the stream's start
            }
        }
    }
    const auto packets = runFfprobe({QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"),
                                        QStringLiteral("v:0"), QStringLiteral("-show_entries"),
                                        QStringLiteral("packet=pts_time,flags"), QStringLiteral("-of"),
                                        QStringLiteral("csv=p=0"), ffprobeInput(path)});
    if (!packets)
        return std::nullopt;
    bool untimed = false;
    for (const QByteArray& line : packets->split('\n')) {
        const QList<QByteArray> f = line.trimmed().split(',');
        if (f.size() < 2)
            continue;
        bool ok = false;
        const double t = f[0].toDouble(&ok);
        if (!ok) {  // "N/A" (AVI without timestamps) is skipped: no usable time
            untimed = true;
            continue;
        }
        r.packets_s.push_back(t - start);
        if (f[1].startsWith('K'))
            r.keyframes_s.push_back(t - start);
    }
    std::sort(r.packets_s.begin(), r.packets_s.end());  // listed in decoding order
    if (untimed)
        r.packets_s.clear();  // some packets' times unknown: not every packet's time
    r.start_s = start;
    return r;
}

}  // namespace nb::video
