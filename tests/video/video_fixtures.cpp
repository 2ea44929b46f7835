#include "video_fixtures.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <opencv2/imgproc.hpp>

#include <cstring>
#include <functional>
#include <optional>
#include <vector>
#include <random>

namespace nb::test {

bool haveFfmpeg() { return !QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty(); }

std::vector<int> sequence(int n)
{
    std::vector<int> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        v[std::size_t(i)] = i;
    return v;
}

static QByteArray frameBytes(int w, int h, int code)
{
    QByteArray gray(w * h, char(16));
    const int bar = w / kCodeBits;
    for (int b = 0; b < kCodeBits; ++b) {
        const bool on = (code >> (kCodeBits - 1 - b)) & 1;
        for (int y = h / 8; y < h - h / 8; ++y)
            for (int x = b * bar + 2; x < (b + 1) * bar - 2; ++x)
                gray[y * w + x] = char(on ? 235 : 16);
    }
    return gray;
}

void keepFromReadingAsId3(cv::Mat& firstFrame)
{
    CV_Assert(firstFrame.type() == CV_8UC1 && firstFrame.isContinuous());
    if (firstFrame.total() >= 3 && std::memcmp(firstFrame.data, "ID3", 3) == 0)
        firstFrame.data[0] += 1;
}

QString writeVideo(const QString& path, const VideoSpec& spec)
{
    QProcess p;
    QStringList args{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y"),
                     QStringLiteral("-f"), QStringLiteral("rawvideo"), QStringLiteral("-pix_fmt"),
                     QStringLiteral("gray"), QStringLiteral("-s"),
                     QStringLiteral("%1x%2").arg(spec.width).arg(spec.height), QStringLiteral("-r"), spec.rate,
                     QStringLiteral("-i"), QStringLiteral("-")};
    args << spec.filterArgs << spec.encodeArgs << path;
    p.start(QStringLiteral("ffmpeg"), args);
    if (!p.waitForStarted(10000))
        return QStringLiteral("ffmpeg did not start");
    for (int code : spec.codes) {
        p.write(frameBytes(spec.width, spec.height, code));
        while (p.bytesToWrite() > 0)
            if (!p.waitForBytesWritten(30000))
                return QStringLiteral("ffmpeg stopped reading: ") + QString::fromUtf8(p.readAllStandardError());
    }
    p.closeWriteChannel();
    if (!p.waitForFinished(120000))
        return QStringLiteral("ffmpeg timed out");
    if (p.exitCode() != 0)
        return QString::fromUtf8(p.readAllStandardError());
    return {};
}

int readCode(const cv::Mat& bgr)
{
    if (bgr.empty())
        return -1;
    cv::Mat gray;
    if (bgr.channels() == 3)
        cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
    else
        gray = bgr;
    const int w = gray.cols, h = gray.rows, bar = w / kCodeBits;
    int code = 0;
    for (int b = 0; b < kCodeBits; ++b) {
        const cv::Rect box(b * bar + bar / 2 - 2, h / 2 - h / 8, 4, h / 4);
        const double m = cv::mean(gray(box))[0];
        if (m > 100 && m < 150)
            return -1;  // neither black nor white: not our stripes
        code = (code << 1) | (m >= 128 ? 1 : 0);
    }
    return code;
}

int readCode(const QImage& image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
    cv::Mat m(rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar*>(rgb.constBits()), size_t(rgb.bytesPerLine()));
    cv::Mat bgr;
    cv::cvtColor(m, bgr, cv::COLOR_RGB2BGR);
    return readCode(bgr);
}

namespace {
struct Packet {
    qint64 pos = 0, size = 0;
};

// The video packets shown from t0_s to t1_s: where they lie in `from` and their size, as ffprobe
// gives them. nullopt when ffprobe fails.
std::optional<std::vector<Packet>> packetsShown(const QString& from, double t0_s, double t1_s)
{
    QProcess probe;
    probe.start(QStringLiteral("ffprobe"), {"-v", "error", "-select_streams", "v:0", "-show_entries", "packet=pts_time,pos,size", "-of", "csv=p=0", from});
    if (!probe.waitForFinished(60000) || probe.exitCode() != 0)
        return std::nullopt;
    std::vector<Packet> packets;
    for (const QByteArray& line : probe.readAllStandardOutput().split('\n')) {
        const QList<QByteArray> f = line.trimmed().split(',');  // pts_time, size, pos
        if (f.size() >= 3 && f[0].toDouble() >= t0_s && f[0].toDouble() <= t1_s)
            packets.push_back({f[2].toLongLong(), f[1].toLongLong()});
    }
    return packets;
}

// `from` written to `to` with the bytes `change` changes; -1 when a file failed.
int rewritten(const QString& from, const QString& to, const std::function<int(QByteArray&)>& change)
{
    QFile in(from), out(to);
    if (!in.open(QIODevice::ReadOnly) || !out.open(QIODevice::WriteOnly))
        return -1;
    QByteArray bytes = in.readAll();
    const int changed = change(bytes);
    return out.write(bytes) == bytes.size() ? changed : -1;
}

// Overwrites the video packets shown from t0_s to t1_s, from byte `kept` of each on, with `fill`.
int overwritePackets(const QString& from, const QString& to, double t0_s, double t1_s, qint64 kept,
                     const std::function<char(qint64)>& fill)
{
    const auto packets = packetsShown(from, t0_s, t1_s);
    if (!packets)
        return -1;
    return rewritten(from, to, [&](QByteArray& bytes) {
        int scratched = 0;
        for (const Packet& p : *packets) {
            if (p.size <= kept)
                continue;
            for (qint64 i = p.pos + kept; i < p.pos + p.size && i < bytes.size(); ++i)
                bytes[i] = fill(i);
            ++scratched;
        }
        return scratched;
    });
}
}  // namespace

int writeScratched(const QString& from, const QString& to, double t0_s, double t1_s)
{
    return overwritePackets(from, to, t0_s, t1_s, 0, [](qint64 i) { return char(0xff ^ (i * 7919 % 251)); });
}

int writeZeroed(const QString& from, const QString& to, double t0_s, double t1_s)
{
    const auto packets = packetsShown(from, t0_s, t1_s);
    if (!packets || packets->empty())
        return -1;
    qint64 first = packets->front().pos, end = 0;
    for (const Packet& p : *packets) {
        first = std::min(first, p.pos);
        end = std::max(end, p.pos + p.size);
    }
    return rewritten(from, to, [&](QByteArray& bytes) {
        for (qint64 i = first; i < end && i < bytes.size(); ++i)
            bytes[i] = 0;
        return int(packets->size());
    });
}

int writeScrambled(const QString& from, const QString& to, double t0_s, double t1_s, unsigned seed)
{
    std::mt19937 rng(seed);
    return overwritePackets(from, to, t0_s, t1_s, 8, [&rng](qint64) { return char(rng() & 0xff); });
}

}  // namespace nb::test
