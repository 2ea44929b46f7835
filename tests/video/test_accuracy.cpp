// The accuracy targets of issue 13 on a small matrix drawn at random (the seed is printed;
// NB_ACCURACY_SEED repeats a draw): real simulated runs, real encoded videos, the real sync
// pipeline; synthetic friction runs through the real fit. bench/bench_accuracy prints the
// full table.
#include "support/accuracy_seed.h"
#include "support/case_share.h"
#include "video/accuracy_matrix.h"
#include "video/video_fixtures.h"

#include "core/sync.h"

#include <QTemporaryDir>
#include <QtTest>

#include <opencv2/videoio.hpp>

#include <cstring>

using namespace nb::accuracy;

class TestAccuracy : public QObject {
    Q_OBJECT

    unsigned seed_ = 0;

    // `tipInPlainSight`: the tip shows in every frame, so the tracker must follow it through
    // (nearly) all of them, not only through enough of them for the fit to get by.
    void expectSynchronised(const SyncCase& c, bool tipInPlainSight = true)
    {
        QTemporaryDir dir;
        const SyncOutcome o = runSyncCase(c, QStringLiteral(NB_EXECUTABLE), dir.path());
        qInfo("%s: error %.2f frames, confidence %.2f, %.1f %% of frames without a tip", qPrintable(c.describe()), o.errorFrames,
              o.confidence, 100 * o.maskedFraction);
        QVERIFY2(o.ok, qPrintable(c.describe() + QStringLiteral(": ") + o.problem));
        QVERIFY2(o.errorFrames <= 1.0, qPrintable(c.describe()));
        QVERIFY2(o.acceptable, qPrintable(c.describe()));
        if (tipInPlainSight)
            QVERIFY2(o.maskedFraction < 0.03, qPrintable(c.describe()));
    }

private slots:
    void initTestCase()
    {
        // bench_accuracy draws a fresh matrix every time; its misses are findings.
        seed_ = nb::test::accuracySeed(371381u, "accuracy matrix seed");
    }

    void syncWithinAFrameAndHonest()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        std::mt19937 rng(seed_);
        QTemporaryDir dir;
        const std::vector<SyncCase> cases = drawSyncCases(rng, 8, true);
        int within1 = 0, ran = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (!nb::test::caseInShare(i))
                continue;
            ++ran;
            const SyncOutcome o = runSyncCase(cases[i], QStringLiteral(NB_EXECUTABLE), dir.filePath(QStringLiteral("c%1").arg(i)));
            qInfo("%s: error %.2f frames, confidence %.2f", qPrintable(cases[i].describe()), o.errorFrames, o.confidence);
            QVERIFY2(o.ok, qPrintable(cases[i].describe() + QStringLiteral(": ") + o.problem));
            within1 += o.errorFrames <= 1.0;
            QVERIFY2(o.errorFrames <= 2.0, qPrintable(cases[i].describe()));
            if (o.errorFrames > 1.0)
                QVERIFY2(!o.acceptable, qPrintable(QStringLiteral("a miss offered for acceptance: ") + cases[i].describe()));
        }
        // 95 % of eight: at most one case between one and two frames.
        QVERIFY(within1 >= ran - 1);
    }

    // Classes of video the matrix once missed, each its own case so that a draw without them
    // still checks them. A needle at 1 Hz crossing a clean, smoothly coded picture (24 px a
    // frame; H.264 smooths the noise to a fraction of a grey level, and the index, judging the
    // whole picture, calls most frames repeats): the tracker lost the tip and followed a coding
    // artefact on the shaft (seed 198523, 25 frames off).
    void fastNeedleInCleanH264()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.sine = true;
        c.frequency_hz = 1.0;
        c.amplitude_mm = 6.0;
        c.cycles = 6;
        c.offset_s = -1.7;
        c.drift = 0.0015;
        c.look = Look::Plain;
        c.codec = Codec::H264;
        c.seed = 4522;  // even: 25 frames/s
        expectSynchronised(c);
    }

    // A slow steady insertion (1.2 mm/s, needle at 30 degrees, H.264 with B-frames) whose
    // video starts mid-stroke and sees its stop: one moment to time it by, so a clock drift
    // cannot be told from the scale. The search kept the drift the tracking noise favoured
    // (-0.43 % for a true +0.067 %) and the offset was 1.07 frames off with confidence 0.98
    // (bench_accuracy --seed 715541, case 17 of its draw).
    void steadyStrokeSeenFromItsMiddle()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        std::mt19937 rng(715541);
        const std::vector<SyncCase> cases = drawSyncCases(rng, 20, false);
        QCOMPARE(cases.size(), std::size_t(20));
        QVERIFY(!cases[17].sine && std::abs(cases[17].velocity_mm_s - 1.2) < 0.05);
        expectSynchronised(cases[17]);
    }

    // A variable-rate file whose writer rounded the timestamps to a 25 Hz clock, 1 ms apart
    // where two frames met: two sightings 1 ms apart made a velocity of thousands of pixels
    // a second and the tracker lost the tip in every other stretch (seed 629754).
    void roundedVariableRateTimestamps()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.sine = true;
        c.frequency_hz = 0.6;
        c.amplitude_mm = 8.0;
        c.cycles = 4;
        c.offset_s = 1.2;
        c.drift = 0.0008;
        c.look = Look::VariableRate;
        c.codec = Codec::H264;
        c.timestampClock_hz = 25;
        c.seed = 2917;  // odd: pictures at 30000/1001 frames/s
        expectSynchronised(c);
    }

    // Heavy noise, low contrast, a needle reaching from the top edge to the middle, at rest
    // for most of the video: the noise, summed along the picture's long diagonals, outweighed
    // the needle's line and no needle was found at all (seed 586261, 1004 frames off).
    void noisyNeedleAcrossHalfThePicture()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.sine = false;
        c.velocity_mm_s = 6.0;
        c.depth_mm = 30.0;
        c.offset_s = 13.5;
        c.drift = 0.0007;
        c.look = Look::NoisyLowContrast;
        c.codec = Codec::Dv;
        c.width = 720;
        c.height = 480;
        c.seed = 4013;  // a needle at 96 deg, darker than the background
        expectSynchronised(c);
    }

    // A thin needle 30 grey levels bright on grainy tissue whose grain (4 px, 25 levels) is as
    // strong, 1024x768 MJPEG: in the mean picture the grain's own lines outrank the shaft, and
    // the needle's line was not among those tried (error 37.7 frames, confidence 0). Its tip's
    // path, the one long thin line along which the picture changes, finds it (0.03 frames,
    // confidence 0.98). Ten angles (seeds): 8 within a frame and accepted, 2 within a frame at
    // confidence 0 (half their frames without a tip); before, none accepted. Look::Speckle is
    // not drawn by the matrix.
    void faintNeedleOnGrainyTissue()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.frequency_hz = 0.4;
        c.amplitude_mm = 8.0;
        c.cycles = 3;
        c.offset_s = 7.2;
        c.drift = 0.001;
        c.look = Look::Speckle;
        c.codec = Codec::Mjpeg;
        c.width = 1024;
        c.height = 768;
        c.seed = 5531;
        expectSynchronised(c, false);  // the grain hides the tip in some frames (9 %)
    }

    // A single needle advancing along its own axis, its line crossing the burnt-in clock at
    // the top left (the shaft runs through it) and the frame counter at the bottom right
    // (beyond the tip). The digits change every frame with edges 2-3 times the tip's: the
    // tracker followed them, and the sync missed by 75-165 frames at confidence 0 (seeds
    // 956579, 271526, 167008). No region of interest is given.
    void needleLineAcrossBurntInClock()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.sine = false;
        c.velocity_mm_s = 6.0;
        c.depth_mm = 24.0;
        c.offset_s = 6.5;
        c.drift = 0.001;
        c.look = Look::Overlays;
        c.codec = Codec::H264;
        c.seed = 16;  // a needle at 52.5 deg through the clock's seconds; even: 25 frames/s
        expectSynchronised(c);

        // The same crossing in a sine run, coded frame by frame.
        c.sine = true;
        c.frequency_hz = 0.4;
        c.amplitude_mm = 7.0;
        c.cycles = 3;
        c.offset_s = 2.3;
        c.codec = Codec::Mjpeg;
        c.seed = 3;  // 53 deg; odd: 30000/1001 frames/s
        expectSynchronised(c);
    }

    // The clock on the shaft and the counter beyond the tip, whatever the needle's angle: in
    // heavy noise, a dark needle, where the gaps between the white digits are darker than
    // the strokes beside them and looked like the end of a dark shaft; and a bright needle on
    // a dark picture, whose text has the shaft's own sign.
    void overlaysOnTheNeedleLine()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.overlaysOnNeedleLine = true;
        c.sine = true;
        c.frequency_hz = 0.5;
        c.amplitude_mm = 8.0;
        c.cycles = 3;
        c.offset_s = 1.1;
        c.drift = 0.0012;
        c.look = Look::NoisyLowContrast;
        c.codec = Codec::Mjpeg;
        c.seed = 1;  // 54 deg, darker than the background; odd: 30000/1001 frames/s
        expectSynchronised(c);

        c.sine = false;
        c.velocity_mm_s = 5.0;
        c.depth_mm = 20.0;
        c.offset_s = 4.0;
        c.look = Look::Angle30;
        c.codec = Codec::H264;
        c.seed = 10;  // even: 25 frames/s
        expectSynchronised(c);
    }

    // A video begun long before the run (14 s at rest, then a 3 s sine at 1 Hz): in the 40
    // frames spread over it to find the needle, its tip rested in all but 7, counted as what
    // is always there, and the needle's line was passed over (a line along the shaft's edge
    // was taken: 11.9 frames off, confidence 0; in the plain look 1.5 frames off).
    void videoBegunLongBeforeTheRun()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        NB_SKIP_OUTSIDE_CASE_SHARE();
        SyncCase c;
        c.sine = true;
        c.frequency_hz = 1.0;
        c.amplitude_mm = 6.0;
        c.cycles = 3;
        c.offset_s = 14.0;
        c.drift = 0.0005;
        c.look = Look::Rendered;
        c.codec = Codec::Mjpeg;
        c.seed = 7;  // odd: 30000/1001 frames/s
        expectSynchronised(c);
        c.look = Look::Plain;
        expectSynchronised(c);
    }

    // The matrix's encoder keeps every frame of a picture whose first grey values read "ID3"
    // and a tag's size: ffmpeg skipped that many bytes of frames (seed 546418, sync case 2).
    void encoderKeepsFramesThatBeginLikeAnId3Tag()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is not installed");
        std::vector<cv::Mat> frames;
        for (int k = 0; k < 40; ++k)
            frames.emplace_back(48, 64, CV_8UC1, cv::Scalar(100 + k));
        const unsigned char tag[10] = {'I', 'D', '3', 4, 0, 0, 0, 0, 0x60, 0};  // version 4, no flags, a size of 12288 bytes (syncsafe)
        std::memcpy(frames.front().data, tag, sizeof tag);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("id3.avi"));
        const QString problem = encodeConstantRate(frames, Codec::Mjpeg, 25.0, path);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        cv::VideoCapture video(path.toStdString());
        QVERIFY(video.isOpened());
        int read = 0;
        cv::Mat frame;
        while (video.read(frame))
            ++read;
        QCOMPARE(read, 40);
    }

    void frictionFindsItsBand()
    {
        std::mt19937 rng(seed_ + 1);
        for (const FrictionCase& c : drawFrictionCases(rng, 10)) {
            const FrictionOutcome o = runFrictionCase(c);
            const QString what = QStringLiteral("%1 Hz, band ±%2 mm/s").arg(c.frequency_hz).arg(c.band_mm_s);
            QVERIFY2(o.ok, qPrintable(what + QStringLiteral(": ") + o.problem));
            QVERIFY2(o.errC < 0.05, qPrintable(what + QStringLiteral(": C off by %1").arg(o.errC)));
            QVERIFY2(o.errB < 0.15, qPrintable(what + QStringLiteral(": b off by %1").arg(o.errB)));
            QVERIFY2(!o.flagged, qPrintable(what));
        }
    }
};

QTEST_GUILESS_MAIN(TestAccuracy)
#include "test_accuracy.moc"
