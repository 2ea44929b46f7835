// Frame-exact seeking against OpenCV's plain seek (CAP_PROP_POS_FRAMES) on the same file in
// the same run, and one-frame-back steps from the cache.
//   bench_video [FILE]   (without FILE: makes a 640x480 H.264 file, keyframes 90 apart,
//                         B-frames, with the ffmpeg tool)
#include "video/frame_index.h"
#include "video/frame_index_store.h"
#include "video/frame_reader.h"
#include "video/packet_index.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

static double percentile(std::vector<double> v, double p)
{
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    QString file = argc > 1 ? QString::fromLocal8Bit(argv[1]) : dir.filePath(QStringLiteral("bench.mp4"));
    if (argc <= 1) {
        const int rc = QProcess::execute(QStringLiteral("ffmpeg"),
                                         {"-v", "error", "-y", "-f", "lavfi", "-i", "testsrc2=size=640x480:rate=30",
                                          "-t", "60", "-c:v", "libx264", "-g", "90", "-bf", "2", "-pix_fmt", "yuv420p", file});
        if (rc != 0) {
            std::fprintf(stderr, "cannot make the test file with ffmpeg\n");
            return 1;
        }
    }
    QElapsedTimer clock;
    clock.start();
    const nb::video::FrameIndex index = nb::video::buildFrameIndex(file);
    std::printf("file: %s, %d frames, %dx%d, keyframes known: %s\n", qPrintable(file), index.size(), index.width,
                index.height, index.keyframesKnown ? "yes" : "no");
    const double buildMs = double(clock.elapsed());
    std::printf("index build: %.0f ms (%.2f ms/frame)\n", buildMs, buildMs / index.size());
    {
        // From the packets (ffprobe), the way long videos are indexed; checked against the
        // decoded index frame by frame.
        clock.restart();
        const auto packets = nb::video::buildFrameIndexFromPackets(file);
        const double packetMs = double(clock.elapsed());
        if (!packets) {
            std::printf("packet index: not available (no ffprobe?)\n");
        } else {
            int same = 0;
            for (int i = 0; i < std::min(packets->size(), index.size()); ++i)
                same += std::abs(packets->frames[std::size_t(i)].time_s - index.frames[std::size_t(i)].time_s) < 1e-3
                        && packets->frames[std::size_t(i)].keyframe == index.frames[std::size_t(i)].keyframe;
            const double duration_s = index.duration_s();
            std::printf("packet index: %.0f ms for %d frames (%.3f ms/frame, %.0fx faster than decoding); %d of %d frames "
                        "agree with the decoded index (time and keyframe)\n",
                        packetMs, packets->size(), packetMs / packets->size(), buildMs / std::max(packetMs, 1.0), same, index.size());
            // A ten times longer file by stream copy (no re-encoding), for a fairer
            // extrapolation to an hour (the tool's start-up is paid once).
            QFile list(dir.filePath(QStringLiteral("ten.txt")));
            if (list.open(QIODevice::WriteOnly)) {
                for (int k = 0; k < 10; ++k)
                    list.write(QStringLiteral("file '%1'\n").arg(file).toUtf8());
                list.close();
            }
            const QString ten = dir.filePath(QStringLiteral("ten.mp4"));
            if (QProcess::execute(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-f", "concat", "-safe", "0", "-i", list.fileName(),
                                                             "-c", "copy", ten}) == 0) {
                clock.restart();
                const auto longer = nb::video::buildFrameIndexFromPackets(ten);
                const double tenMs = double(clock.elapsed());
                const double tenDuration = longer ? longer->duration_s() : 0.0;
                if (longer && tenDuration > 0)
                    std::printf("packet index of %.0f s of video: %.0f ms; one hour of 640x480 H.264 extrapolated: %.1f s "
                                "(target 10 s)\n", tenDuration, tenMs, tenMs / 1000.0 * 3600.0 / tenDuration);
            }
        }
    }
    {
        // Reopening the same file: the stored index against building it again.
        const QString store = dir.filePath(QStringLiteral("index-store"));
        nb::video::storeFrameIndex(index, store);
        clock.restart();
        const auto stored = nb::video::loadStoredFrameIndex(file, store);
        const double loadMs = double(clock.nsecsElapsed()) / 1e6;
        std::printf("stored index load: %.2f ms for %d frames (%.0fx faster than building it)\n", loadMs,
                    stored ? stored->size() : 0, buildMs / std::max(loadMs, 1e-3));
    }

    std::mt19937 rng(42);
    std::uniform_int_distribution<int> pick(0, index.size() - 1);
    std::vector<int> targets(300);
    for (int& t : targets)
        t = pick(rng);

    cv::VideoCapture plain(file.toStdString(), cv::CAP_FFMPEG);
    nb::video::FrameReader reader(index, 1);
    std::vector<double> plainMs, exactMs;
    cv::Mat m;
    // Interleaved so that machine load hits both alike.
    for (int n : targets) {
        clock.restart();
        plain.set(cv::CAP_PROP_POS_FRAMES, n);
        plain.read(m);
        plainMs.push_back(clock.nsecsElapsed() / 1e6);
        reader.cache().clear();
        clock.restart();
        reader.read(n);
        exactMs.push_back(clock.nsecsElapsed() / 1e6);
    }
    const double p95plain = percentile(plainMs, 0.95), p95exact = percentile(exactMs, 0.95);
    std::printf("random seek, plain OpenCV:  p50 %.2f ms  p95 %.2f ms\n", percentile(plainMs, 0.5), p95plain);
    std::printf("random seek, frame-exact:   p50 %.2f ms  p95 %.2f ms\n", percentile(exactMs, 0.5), p95exact);
    std::printf("p95 ratio exact/plain: %.2f (target <= 1.5)\n", p95exact / p95plain);
    std::printf("reader: %d seeks, %d retries, %d decodes from the start\n", reader.stats().seeks, reader.stats().retries,
                reader.stats().sequentialResets);

    // One frame back after the decoder thread has filled the cache around the cursor.
    nb::video::FrameReader cached(index, 64);
    std::vector<double> backMs, backUncachedMs;
    for (int i = 0; i < 40; ++i) {
        const int n = std::max(12, targets[std::size_t(i)]);
        cached.read(n);
        cached.fillCache(n - 10, n + 10);
        clock.restart();
        cached.read(n - 1);
        backMs.push_back(clock.nsecsElapsed() / 1e6);
        cached.cache().clear();
        cached.read(n);
        clock.restart();
        cached.read(n - 1);
        backUncachedMs.push_back(clock.nsecsElapsed() / 1e6);
    }
    std::printf("one frame back, from cache: p50 %.3f ms  p95 %.3f ms (target < 5 ms)\n", percentile(backMs, 0.5),
                percentile(backMs, 0.95));
    std::printf("one frame back, not cached: p50 %.2f ms  p95 %.2f ms\n", percentile(backUncachedMs, 0.5),
                percentile(backUncachedMs, 0.95));
    return 0;
}
