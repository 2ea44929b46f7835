// How much of each decoded picture a coder carried over from the one before, measured on the
// picture's noise (PictureMemoryMeter), and how far behind the tip that shows a slow motion
// (pictureTrail; core/picture_lag.h). Pictures made here: a fixed grain with fresh noise
// in each frame, as they are, through a first-order carry-over of known memory, and encoded
// by the ffmpeg tool as MJPEG (every picture afresh) and MPEG-4 part 2 (each from the one before).
#include "core/picture_lag.h"
#include "video/frame_index.h"
#include "video/frame_reader.h"
#include "video/picture_memory.h"
#include "video_fixtures.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace {

constexpr int kWidth = 320, kHeight = 240;
constexpr double kNoise = 6.0;

// The fixed picture: grain of 4 px squares around grey 110.
cv::Mat grain()
{
    cv::RNG rng(2024);
    cv::Mat squares(kHeight / 4, kWidth / 4, CV_32F), out;
    rng.fill(squares, cv::RNG::NORMAL, 110.0, 20.0);
    cv::resize(squares, out, cv::Size(kWidth, kHeight), 0, 0, cv::INTER_NEAREST);
    return out;
}

// `frames` pictures of the grain with fresh noise of σ `noise`, each carried over from the one
// before with `memory` (0: as the camera saw it), in 8 bits.
std::vector<cv::Mat> pictures(int frames, double memory, std::uint64_t seed, double noise = kNoise)
{
    const cv::Mat still = grain();
    cv::RNG rng(seed);
    std::vector<cv::Mat> out;
    cv::Mat shown;
    for (int k = 0; k < frames; ++k) {
        cv::Mat fresh(kHeight, kWidth, CV_32F);
        rng.fill(fresh, cv::RNG::NORMAL, 0.0, noise);
        const cv::Mat seen = still + fresh;
        shown = shown.empty() ? seen : memory * shown + (1.0 - memory) * seen;
        cv::Mat bytes;
        shown.convertTo(bytes, CV_8U);
        out.push_back(bytes);
    }
    return out;
}

// The noise as the pictures show it: each pixel's spread about its mean over the frames.
double noiseShown(const std::vector<cv::Mat>& frames)
{
    cv::Mat sum = cv::Mat::zeros(frames.front().size(), CV_64F), squares = sum.clone(), f;
    for (const cv::Mat& frame : frames) {
        frame.convertTo(f, CV_64F);
        sum += f;
        squares += f.mul(f);
    }
    const double n = double(frames.size());
    const cv::Mat variance = (squares - sum.mul(sum) / n) / (n - 1.0);
    return std::sqrt(cv::mean(variance)[0]);
}

nb::PictureCoding measured(const std::vector<cv::Mat>& frames)
{
    nb::video::PictureMemoryMeter meter;
    for (const cv::Mat& f : frames)
        meter.add(f);
    return meter.coding();
}

struct Coded {
    nb::PictureCoding coding;
    double noiseShown = 0.0;
    nb::MotionCoding motion = nb::MotionCoding::Unknown;  // as the file's index names its codec
};

// The pictures encoded by the ffmpeg tool with `codec` (its arguments), decoded back through
// NeedleBench's reader and measured; nullopt when the tool failed.
std::optional<Coded> throughCoder(const QStringList& codec, const QString& name, double noise = kNoise)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    QProcess ffmpeg;
    ffmpeg.start(QStringLiteral("ffmpeg"), QStringList{"-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "gray", "-s",
                                                       QStringLiteral("%1x%2").arg(kWidth).arg(kHeight), "-r", "25", "-i", "-"}
                                               << codec << path);
    if (!ffmpeg.waitForStarted())
        return std::nullopt;
    for (const cv::Mat& f : pictures(120, 0.0, 77, noise))
        ffmpeg.write(reinterpret_cast<const char*>(f.data), qint64(f.total()));
    ffmpeg.closeWriteChannel();
    if (!ffmpeg.waitForFinished(60000) || ffmpeg.exitCode() != 0)
        return std::nullopt;
    const nb::video::FrameIndex index = nb::video::buildFrameIndex(path);
    nb::video::FrameReader reader(index);
    nb::video::PictureMemoryMeter meter;
    std::vector<cv::Mat> decoded;
    for (int i = 0; i < index.size(); ++i) {
        cv::Mat gray;
        cv::cvtColor(reader.read(i).image, gray, cv::COLOR_BGR2GRAY);
        meter.add(gray);
        decoded.push_back(gray);
    }
    return Coded{meter.coding(), noiseShown(decoded), nb::motionCodingOf(index.codec)};
}

}  // namespace

class TestPictureMemory : public QObject {
    Q_OBJECT

private slots:
    // Fresh noise in every picture: nothing carried over, and the noise is the camera's.
    void freshNoiseCarriesNothing()
    {
        const nb::PictureCoding c = measured(pictures(60, 0.0, 1));
        qInfo("memory %.3f, noise %.2f grey levels (drawn %.1f)", c.memory, c.noise_grey, kNoise);
        QVERIFY2(c.memory < 0.03, qPrintable(QString::number(c.memory)));
        QVERIFY2(std::abs(c.noise_grey - kNoise) < 0.1 * kNoise, qPrintable(QString::number(c.noise_grey)));
    }

    // Each picture 0.4 of the one before and 0.6 of what the camera saw: memory 0.4, and the
    // noise as the pictures show it, σ·√((1 − ρ)/(1 + ρ)), the spread the lag model is given
    // (core/picture_lag.h: the coder holds, and what it shows spreads as it does).
    void aCarryOverOfKnownMemory()
    {
        const std::vector<cv::Mat> frames = pictures(60, 0.4, 2);
        const nb::PictureCoding c = measured(frames);
        const double shown = noiseShown(frames);
        qInfo("memory %.3f (made 0.4), noise %.2f grey levels (in the pictures %.2f, drawn %.1f)", c.memory, c.noise_grey, shown,
              kNoise);
        QVERIFY2(std::abs(c.memory - 0.4) < 0.04, qPrintable(QString::number(c.memory)));
        QVERIFY2(std::abs(c.noise_grey - shown) < 0.1 * shown, qPrintable(QString::number(c.noise_grey)));
        QVERIFY2(c.noise_grey < 0.8 * kNoise, qPrintable(QString::number(c.noise_grey)));
    }

    // A picture repeated whole is no sample of the coder: left out, it changes nothing (taken,
    // its differences of zero would read as memory).
    void repeatsAreLeftOut()
    {
        std::vector<cv::Mat> frames = pictures(60, 0.0, 3);
        nb::video::PictureMemoryMeter meter;
        for (std::size_t k = 0; k < frames.size(); ++k) {
            meter.add(frames[k]);
            if (k % 5 == 0)
                meter.add(frames[k].clone());
        }
        QVERIFY2(meter.coding().memory < 0.03, qPrintable(QString::number(meter.coding().memory)));
    }

    // Real coders at their usual settings: MJPEG codes every picture afresh; MPEG-4 part 2
    // (ffmpeg's mpeg4 at -q:v 5) codes each from the one before and drops much of the noise.
    void realCoders()
    {
        if (!nb::test::haveFfmpeg())
            QFAIL("the ffmpeg tool is missing (scripts/install-deps.sh installs it): the coders cannot be measured");
        const auto mjpeg = throughCoder({"-c:v", "mjpeg", "-q:v", "5", "-pix_fmt", "yuvj420p"}, QStringLiteral("noise.avi"));
        const auto mpeg4 = throughCoder({"-c:v", "mpeg4", "-q:v", "5"}, QStringLiteral("noise4.avi"));
        QVERIFY(mjpeg && mpeg4);
        qInfo("MJPEG memory %.3f noise %.2f (shown %.2f); MPEG-4 memory %.3f noise %.2f (shown %.2f); drawn %.1f",
              mjpeg->coding.memory, mjpeg->coding.noise_grey, mjpeg->noiseShown, mpeg4->coding.memory, mpeg4->coding.noise_grey,
              mpeg4->noiseShown, kNoise);
        QVERIFY2(mjpeg->coding.memory < 0.05, qPrintable(QString::number(mjpeg->coding.memory)));
        // The files name their coders, and with them how finely each follows motion.
        QCOMPARE(mjpeg->motion, nb::MotionCoding::Intra);
        QCOMPARE(mpeg4->motion, nb::MotionCoding::HalfPixel);
        QVERIFY2(mpeg4->coding.memory > 0.2, qPrintable(QString::number(mpeg4->coding.memory)));
        // Either coder's quantiser drops part of the noise; what is measured is what is shown.
        for (const Coded* c : {&*mjpeg, &*mpeg4})
            QVERIFY2(std::abs(c->coding.noise_grey - c->noiseShown) < 0.15 * c->noiseShown, qPrintable(QString::number(c->coding.noise_grey)));
    }

    // A quiet camera (noise of 2 grey levels) through MPEG-4: the coder shows most pixels again
    // exactly and drops the noise it would read the memory from. Read from the few changes it
    // passes, the memory came out 0.93 for every such video whatever the coder held; it is at
    // least the most the meter reads.
    void aQuietCameraReadsAtTheTop()
    {
        if (!nb::test::haveFfmpeg())
            QFAIL("the ffmpeg tool is missing (scripts/install-deps.sh installs it): the coders cannot be measured");
        const auto quiet = throughCoder({"-c:v", "mpeg4", "-q:v", "5"}, QStringLiteral("quiet.avi"), 2.0);
        const auto mjpeg = throughCoder({"-c:v", "mjpeg", "-q:v", "5", "-pix_fmt", "yuvj420p"}, QStringLiteral("quiet.mjpeg.avi"), 2.0);
        QVERIFY(quiet && mjpeg);
        qInfo("noise of 2 grey levels: MPEG-4 memory %.3f, MJPEG %.3f", quiet->coding.memory, mjpeg->coding.memory);
        QCOMPARE(quiet->coding.memory, nb::kMostMeasurableMemory);
        QVERIFY2(mjpeg->coding.memory < 0.3, qPrintable(QString::number(mjpeg->coding.memory)));
    }

    // The trail (core/picture_lag.h): none for a coder that codes every picture afresh or where
    // nothing was measured; for a faint edge it grows with the memory; for a bold one it is half
    // the quantiser's threshold over the edge's slope, smaller for a coder that moves by quarter
    // pixels, whose video may yet have been coded by halves first, unless the operator says not.
    void trailFollowsTheCoder()
    {
        using nb::MotionCoding;
        QCOMPARE(nb::motionCodingOf(QStringLiteral("h264")), MotionCoding::QuarterPixel);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("avc1")), MotionCoding::QuarterPixel);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("FMP4")), MotionCoding::HalfPixel);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("mpeg4")), MotionCoding::HalfPixel);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("MJPG")), MotionCoding::Intra);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("dvvideo")), MotionCoding::Intra);
        QCOMPARE(nb::motionCodingOf(QStringLiteral("")), MotionCoding::Unknown);

        auto trail = [](double memory, double edge, MotionCoding motion) { return nb::pictureTrail({memory, 5.0, edge, motion}); };
        QCOMPARE(trail(0.6, 4.0, MotionCoding::Intra).most_px, 0.0);
        QCOMPARE(nb::pictureTrail({0.6, 0.0, 4.0, MotionCoding::HalfPixel}).most_px, 0.0);  // nothing measured
        // Faint: the memory's trail, as large for any coder; more memory, more trail.
        const nb::PictureTrail faint = trail(0.4, 2.0, MotionCoding::HalfPixel);
        QVERIFY(std::abs(faint.likely_px() - (0.04 + 0.53 * 0.4)) < 1e-9 && faint.uncertainty_px() == faint.residual_px);
        QVERIFY(trail(0.8, 2.0, MotionCoding::HalfPixel).likely_px() > faint.likely_px());
        // Bold: less the bolder, and a coder by quarter pixels is known only within the range
        // from its own trail to that of one by halves.
        const nb::PictureTrail half = trail(0.9, 14.0, MotionCoding::HalfPixel);
        const nb::PictureTrail quarter = trail(0.9, 14.0, MotionCoding::QuarterPixel);
        QVERIFY(std::abs(half.likely_px() - 3.5 / 14.0) < 1e-9);
        QVERIFY(trail(0.9, 20.0, MotionCoding::HalfPixel).likely_px() < half.likely_px());
        QVERIFY(quarter.least_px < 0.1 && std::abs(quarter.most_px - half.most_px) < 1e-9);
        QVERIFY(trail(0.9, 14.0, MotionCoding::Unknown).most_px == quarter.most_px);
        // Said to be coded once, by quarter pixels: its own trail alone, known as closely as one
        // coded once by halves. Said of a coder by halves, or of one not known, it changes nothing.
        auto once = [](double memory, double edge, MotionCoding motion) {
            nb::PictureCoding c{memory, 5.0, edge, motion};
            c.codedOnce = true;
            return nb::pictureTrail(c);
        };
        const nb::PictureTrail quarterOnce = once(0.9, 14.0, MotionCoding::QuarterPixel);
        QVERIFY(std::abs(quarterOnce.least_px - 0.75 / 14.0) < 1e-9 && quarterOnce.most_px == quarterOnce.least_px);
        QVERIFY(quarterOnce.uncertainty_px() < quarter.uncertainty_px());
        QCOMPARE(quarterOnce.residual_px, half.residual_px);
        QVERIFY(std::abs(once(0.4, 2.0, MotionCoding::QuarterPixel).likely_px() - (0.04 + 0.53 * 0.4)) < 1e-9);
        const nb::PictureTrail halfOnce = once(0.9, 14.0, MotionCoding::HalfPixel), unknownOnce = once(0.9, 14.0, MotionCoding::Unknown);
        QVERIFY(halfOnce.least_px == half.least_px && halfOnce.most_px == half.most_px && halfOnce.residual_px == half.residual_px);
        const nb::PictureTrail unknown = trail(0.9, 14.0, MotionCoding::Unknown);
        QVERIFY(unknownOnce.least_px == unknown.least_px && unknownOnce.most_px == unknown.most_px && unknownOnce.residual_px == unknown.residual_px);
        QCOMPARE(once(0.6, 4.0, MotionCoding::Intra).most_px, 0.0);
        // Only the range a first coder may hide behind quarter pixels is one saying so would close.
        QVERIFY(quarter.narrowsIfCodedOnce && !quarterOnce.narrowsIfCodedOnce && !half.narrowsIfCodedOnce && !unknown.narrowsIfCodedOnce);
        // At the top of the meter the memory says only "at least": a faint edge may trail far
        // more than the memory gives, up to what its edge allows.
        const nb::PictureTrail top = trail(nb::kMostMeasurableMemory, 4.0, MotionCoding::HalfPixel);
        QVERIFY(top.most_px > 0.04 + 0.53 * nb::kMostMeasurableMemory && top.most_px <= 3.5 / 4.0 + 1e-9);
        QVERIFY(std::isfinite(trail(nb::kMostMeasurableMemory, 0.0, MotionCoding::Unknown).most_px));
        QVERIFY(std::isfinite(trail(0.5, std::nan(""), MotionCoding::Unknown).most_px));
    }
};

QTEST_GUILESS_MAIN(TestPictureMemory)
#include "test_picture_memory.moc"
