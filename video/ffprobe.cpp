#include "ffprobe.h"
#include "capture.h"

#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>

#include <algorithm>

namespace nb::video {

std::optional<QByteArray> runFfprobe(const QStringList& args, int timeout_ms)
{
    const QString exe = QStandardPaths::findExecutable(QStringLiteral("ffprobe"));
    if (exe.isEmpty())
        return std::nullopt;
    QProcess p;
    p.start(exe, args);
    if (!p.waitForStarted(5000))
        return std::nullopt;
    if (!p.waitForFinished(timeout_ms)) {
        p.kill();
        p.waitForFinished(1000);
        return std::nullopt;
    }
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
        return std::nullopt;
    return p.readAllStandardOutput();
}

QString ffprobeInput(const QString& path) { return QStringLiteral("file:") + QFileInfo(path).absoluteFilePath(); }

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

std::optional<FfprobeListing> listVideo(const QString& path)
{
    // Compact lines, one a section: "stream|index=0|codec_name=h264|…|disposition:attached_pic=0",
    // "packet|stream_index=0|pts_time=0.040000|flags=K_"; a stream listed inside a program
    // (MPEG-TS) comes as "program|stream|…" and again on its own.
    const auto out = runFfprobe(ffprobeReadOptions() + QStringList{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-select_streams"), QStringLiteral("v"),
                                 QStringLiteral("-show_entries"),
                                 QStringLiteral("stream=index,codec_name,width,height,avg_frame_rate,r_frame_rate,start_time,has_b_frames"
                                                ":stream_disposition=attached_pic:packet=stream_index,pts_time,flags"),
                                 QStringLiteral("-of"), QStringLiteral("compact=p=1"), ffprobeInput(path)});
    if (!out)
        return std::nullopt;
    struct Packet {
        int stream;
        ProbedPacket packet;
    };
    std::vector<Packet> packets;
    FfprobeListing listing;
    for (const QByteArray& line : out->split('\n')) {
        const QList<QByteArray> fields = line.trimmed().split('|');
        const QByteArray& section = fields.front();
        if (section != "packet" && section != "stream")
            continue;
        ProbedStream s;
        Packet p{-1, {}};
        for (const QByteArray& field : fields) {
            const int eq = field.indexOf('=');
            if (eq < 0)
                continue;
            const QByteArray key = field.left(eq), value = field.mid(eq + 1).trimmed();
            bool ok = false;
            if (section == "packet") {
                if (key == "stream_index")
                    p.stream = value.toInt();
                else if (key == "pts_time") {
                    const double t = value.toDouble(&ok);
                    if (ok)
                        p.packet.pts_s = t;
                } else if (key == "flags")
                    p.packet.keyframe = value.startsWith('K');
            } else if (key == "index")
                s.index = value.toInt();
            else if (key == "codec_name")
                s.codec = QString::fromUtf8(value);
            else if (key == "width")
                s.width = value.toInt();
            else if (key == "height")
                s.height = value.toInt();
            else if (key == "avg_frame_rate")
                s.avgRate = rate(value);
            else if (key == "r_frame_rate")
                s.realRate = rate(value);
            else if (key == "start_time") {
                const double t = value.toDouble(&ok);
                if (ok)
                    s.start_s = t;
            } else if (key == "has_b_frames")
                s.reorderFrames = std::clamp(value.toInt(), 0, 16);
            else if (key == "disposition:attached_pic")
                s.coverPicture = value == "1";
        }
        if (section == "packet")
            packets.push_back(p);
        else
            listing.videoStreams.push_back(s);
    }
    std::sort(listing.videoStreams.begin(), listing.videoStreams.end(),
              [](const ProbedStream& a, const ProbedStream& b) { return a.index < b.index; });
    for (const Packet& p : packets)
        if (!listing.videoStreams.empty() && p.stream == listing.videoStreams.front().index)
            listing.packets.push_back(p.packet);
    return listing;
}

}  // namespace nb::video
