#pragma once
// Real encoded test videos whose frames carry a number in their pixels (a 12-bit stripe
// code across the frame), so a test can tell exactly which frame a decoder returned.

#include <QImage>
#include <QString>
#include <QStringList>
#include <opencv2/core.hpp>
#include <vector>

namespace nb::test {

constexpr int kCodeBits = 12;

// True when the `ffmpeg` tool is on PATH.
bool haveFfmpeg();

struct VideoSpec {
    int width = 320;
    int height = 240;
    QString rate = QStringLiteral("30");  // input frame rate as ffmpeg reads it
    std::vector<int> codes;               // the number shown in each frame, in order
    QStringList encodeArgs;               // e.g. -c:v libx264 -g 30 -bf 2
    QStringList filterArgs;               // e.g. -vf setpts=... -fps_mode passthrough
};

// Encodes `spec` to `path` with the ffmpeg tool; returns an empty string on success, else
// ffmpeg's complaint.
QString writeVideo(const QString& path, const VideoSpec& spec);

// ffmpeg reads raw frames that begin with the bytes "ID3" as an ID3v2 tag and skips as many
// bytes as the next ones give for its size, frames and all: the first 318 frames of a noisy
// picture vanished from a video, which then started 12.7 s late (bench_accuracy --seed 546418,
// sync case 2, an offset 318 frames off at confidence 1). The first grey value of a picture
// (8-bit, one channel) that would begin so is moved by one.
void keepFromReadingAsId3(cv::Mat& firstFrame);

// Writes `from` to `to` with the data of the video packets shown from `t0_s` to `t1_s` overwritten
// (their place and size in the file as ffprobe gives them): a damaged stretch, as a bad copy or
// sector leaves. Returns the packets overwritten (-1 when ffprobe or a file failed).
int writeScratched(const QString& from, const QString& to, double t0_s, double t1_s);

// The same, but each packet keeps its first 8 bytes (an MP4 packet's length and the NAL unit's
// header) and the rest is random bytes drawn from `seed`: the decoder then reads nonsense slices
// instead of skipping the packets, conceals, and gives out pictures it made up, some with the
// times of packets it lost (bench/sync_probe_matrix.py --damage does the same).
int writeScrambled(const QString& from, const QString& to, double t0_s, double t1_s, unsigned seed);

// Writes `from` to `to` with every byte from the first video packet shown from `t0_s` on to the end
// of the last shown by `t1_s` zeroed, headers and all: a stretch of the file overwritten. Returns
// the packets in it (-1 when ffprobe or a file failed).
int writeZeroed(const QString& from, const QString& to, double t0_s, double t1_s);

// Codes 0..n-1.
std::vector<int> sequence(int n);

// Reads the stripe code back (-1 when the stripes are not readable).
int readCode(const cv::Mat& bgr);
int readCode(const QImage& image);

}  // namespace nb::test
