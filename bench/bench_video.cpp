// Frame-exact seeking against OpenCV's plain seek (CAP_PROP_POS_FRAMES) on the same file in
// the same run, and one-frame-back steps from the cache.
//   bench_video [FILE]   (without FILE: makes a 640x480 H.264 file, keyframes 90 apart,
//                         B-frames, with the ffmpeg tool)
#include "video/frame_index.h"
#include "video/frame_index_store.h"
#include "video/frame_reader.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <opencv2/videoio.hpp>

#include <algorithm>
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
