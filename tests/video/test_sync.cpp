// Synchronisation: the timeline mapping, and the automatic offset on a video rendered from a
// simulated friction run started a known time after the video (real processes, real files).
#include "core/label_suggest.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "core/sync.h"
#include "needle_video.h"
#include "video/frame_index.h"
#include "video/video_sync.h"
#include "support/needlebench_cli.h"
#include "support/case_share.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

// The needle drawn back 60 px in 3 s after 10 s at rest (30 frames/s): against a recorded
// insertion, a picture that moves the other way (mirrored, or the position's sign reversed).
static double strokeBackwards(int frame)
{
    return 30.0 - 60.0 * std::clamp(frame - 300, 0, 90) / 90.0;
}

// A stroke of 60 px in 3 s after 10 s at rest (30 frames/s); a minute later, the needle drawn
// back (another run in the same video).
static double strokeThenAnotherLater(int frame)
{
    return -30.0 + 60.0 * std::clamp(frame - 300, 0, 90) / 90.0 - 60.0 * std::clamp(frame - 2100, 0, 90) / 90.0;
}

// A clear needle (60 grey levels) in a 320x240 picture, `frames` frames at 30 frames/s.
static nb::needle_video::NeedleVideo plainNeedle(int frames, double (*tip)(int))
{
    nb::needle_video::NeedleVideo v;
    v.width = 320;
    v.height = 240;
    v.contrast = 60.0;
    v.frames = frames;
    v.tip = tip;
    return v;
}

// Recorded at 500 Hz: 0.5 s at rest, an insertion of 15 mm in 3 s, 0.5 s at rest.
static bool writeStrokeRun(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QByteArray csv = "time_s,position_mm,force_N\n";
    for (int i = 0; i <= 2000; ++i) {
        const double t = i * 0.002;
        csv += QByteArray::number(t, 'f', 4) + ',' + QByteArray::number(15.0 * std::clamp((t - 0.5) / 3.0, 0.0, 1.0), 'f', 6) + ",0\n";
    }
    return f.write(csv) == csv.size();
}

static QJsonObject runJson(const QStringList& args, int* code = nullptr)
{
    const nbtest::CliResult r = nbtest::runCli(args, 240000);
    if (code)
        *code = r.code;
    return r.json();
}

class TestSync : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString run_, video_, truth_;

    // The rig's recorded position: `samples` samples of `positionAt` (mm) at 500 Hz.
    static nb::TimeSignal recordedAt500Hz(const std::function<double(double)>& positionAt, int samples)
    {
        nb::TimeSignal p;
        for (int i = 0; i < samples; ++i) {
            p.time_s.push_back(i * 0.002);
            p.value.push_back(positionAt(i * 0.002));
        }
        return p;
    }

    // What the tracker reads in the video: `frames` frames `frame_s` apart, each the tip's
    // pixel position `px` of where the needle was (mm) at the recording time `truth` maps the
    // frame to, with 0.3 px of noise drawn from `seed`.
    static nb::TimeSignal seenInVideo(const std::function<double(double)>& positionAt, const std::function<double(double)>& px,
                                      const nb::TimelineMapping& truth, double frame_s, int frames, unsigned seed)
    {
        nb::TimeSignal picture;
        std::mt19937 rng(seed);
        std::normal_distribution<double> noise(0.0, 0.3);
        for (int k = 0; k < frames; ++k) {
            const double tv = k * frame_s;
            picture.time_s.push_back(tv);
            picture.value.push_back(px(positionAt(truth.toRecording(tv))) + noise(rng));
        }
        return picture;
    }

private slots:
    // One simulated friction run with its rendered video (offset 1.7 s), shared by the tests below.
    void initTestCase()
    {
        run_ = dir_.filePath("fr.csv");
        video_ = dir_.filePath("fr.avi");
        truth_ = dir_.filePath("fr.json");
        int code = -1;
        runJson({"simulate", "--protocol", "friction", "--tissue", "liver7", "--cycles", "3", "--out", run_, "--truth",
                 truth_, "--video", video_, "--video-offset-s", "1.7"},
                &code);
        QCOMPARE(code, 0);
        QFile tf(truth_);
        QVERIFY(tf.open(QIODevice::ReadOnly));
        const QJsonObject truth = QJsonDocument::fromJson(tf.readAll()).object();
        const double offset = truth["video_offset_s"].toDouble();
        QVERIFY(std::abs(offset - 1.7) < 0.01);
        QVERIFY(!truth["phases"].toArray().isEmpty());
    }

    void mapping()
    {
        nb::TimelineMapping m = nb::TimelineMapping::fromEvent(1.5, 4.0);
        QCOMPARE(m.offset_s, 2.5);
        QCOMPARE(m.toVideo(10.0), 12.5);
        QCOMPARE(m.toRecording(12.5), 10.0);
        m.nudge(-3, 1.0 / 30);
        QVERIFY(std::abs(m.offset_s - 2.4) < 1e-12);
        const nb::TimelineMapping d{1.0, 1e-3};
        QVERIFY(std::abs(d.toRecording(d.toVideo(123.0)) - 123.0) < 1e-9);
        QVERIFY(std::abs(d.toVideo(1000.0) - 1002.0) < 1e-9);
        // Two events: a video clock 500 ppm fast, started 0.7 s before the recording.
        const nb::TimelineMapping truth{0.7, 5e-4};
        const auto two = nb::TimelineMapping::fromEvents(2.0, truth.toVideo(2.0), 62.0, truth.toVideo(62.0));
        QVERIFY(two);
        QVERIFY(std::abs(two->drift - 5e-4) < 1e-12);
        QVERIFY(std::abs(two->offset_s - 0.7) < 1e-12);
        QVERIFY(!nb::TimelineMapping::fromEvents(2.0, 2.7, 2.0, 2.8));  // one instant cannot give a rate
    }

    void onsetAndCorrelationOnSynthetic()
    {
        // A half-sine burst of speed starting at 3 s; "video motion" the same, 1.25 s later, noisy.
        nb::TimeSignal speed, motion;
        for (int i = 0; i < 5000; ++i) {
            const double t = i * 0.002;
            speed.time_s.push_back(t);
            speed.value.push_back(t > 3 && t < 8 ? std::abs(std::sin((t - 3) * M_PI)) * 30 : 0.0);
        }
        for (int k = 0; k < 400; ++k) {
            const double tv = k / 29.97;
            const double tr = tv - 1.25;
            motion.time_s.push_back(tv);
            motion.value.push_back((tr > 3 && tr < 8 ? std::abs(std::sin((tr - 3) * M_PI)) : 0.0) + 0.05 * ((k * 7919) % 13) / 13.0);
        }
        motion.value[100] = std::numeric_limits<double>::quiet_NaN();  // a masked duplicate
        const nb::SyncResult r = nb::synchronise(motion, speed);
        QVERIFY2(std::abs(r.offset_s - 1.25) < 0.01, qPrintable(QString::number(r.offset_s)));
        QVERIFY(r.confidence > 0.8);
        QVERIFY(r.onsetOffset_s && std::abs(*r.onsetOffset_s - 1.25) < 0.05);
        // Without the onset anchor the periodic signal may lock a period off; with it, not.
        QVERIFY(!r.curve.empty());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, nb::synchronise({}, speed));
    }

    // A drift shows only between two moments the motion marks: the sync keeps one only where
    // it explains the picture better than none by more than the noise allows. A sinusoid
    // marks many moments and its 0.2 % drift is still found; a steady stroke seen from its
    // middle to its stop (one moment) stays within a frame. (The real video where the drift
    // the noise favoured put it a frame off: test_accuracy steadyStrokeSeenFromItsMiddle.)
    void driftOnlyWhereThePictureShowsOne_data()
    {
        QTest::addColumn<bool>("sine");
        QTest::addColumn<double>("drift");
        QTest::newRow("steady stroke, middle to stop") << false << 6.7e-4;
        QTest::newRow("sinusoid") << true << 2.0e-3;
    }
    void driftOnlyWhereThePictureShowsOne()
    {
        QFETCH(bool, sine);
        QFETCH(double, drift);
        const double offset_s = -2.425, frame_s = 1.0 / 29.97;
        auto positionAt = [&](double t) {
            if (sine)
                return t < 0.5 ? 0.0 : 5.0 * std::sin(2.0 * M_PI * 0.4 * (t - 0.5));
            return 1.174 * std::clamp(t - 0.5, 0.0, 8.0 / 1.174);  // 8 mm at 1.174 mm/s from 0.5 s
        };
        const nb::TimeSignal position = recordedAt500Hz(positionAt, 5000);
        const nb::TimelineMapping truth{offset_s, drift};
        const nb::TimeSignal picture = seenInVideo(positionAt, [](double x_mm) { return 12.0 + 23.9 * x_mm; }, truth, frame_s, 200, 64);
        const nb::SyncResult r = nb::synchroniseDisplacement(picture, position, frame_s);
        double worst = 0.0;
        for (double tv : picture.time_s)
            worst = std::max(worst, std::abs(r.mapping().toRecording(tv) - truth.toRecording(tv)));
        QVERIFY2(worst < frame_s, qPrintable(QStringLiteral("off by %1 frames, drift %2").arg(worst / frame_s).arg(r.drift)));
        if (sine)
            QVERIFY2(std::abs(r.drift - drift) < 5e-4, qPrintable(QString::number(r.drift)));
    }

    // A single steady stroke whose tip the tracker reads up to a pixel ahead along one stretch
    // of the picture and behind along another (grain, a codec's blocks): the drift that made
    // the most of that bias, +0.55 % for a true −0.13 %, put the stroke's end 1.1 frames off
    // at confidence 0.85 (an MPEG-4 video of a needle on grainy tissue). Two events (onset and
    // stop) 4.7 s apart cannot time the clock's rate that finely; the drift must not stand.
    void driftNotTakenFromAReadingBias()
    {
        const double offset_s = 13.486, drift = -1.34e-3, frame_s = 1.0 / 25.0, speed_mm_s = 8.6;
        auto positionAt = [&](double t) { return speed_mm_s * std::clamp(t - 0.5, 0.0, 40.0 / speed_mm_s); };
        const nb::TimeSignal position = recordedAt500Hz(positionAt, 3000);
        const nb::TimelineMapping truth{offset_s, drift};
        // The bias measured along that video's stroke (its residuals against the truth).
        static const std::vector<std::pair<double, double>> bias{{0.0, 0.0},   {2.3, -0.37},  {6.6, -0.28},  {10.9, 0.41},
                                                                 {15.2, 0.57}, {19.5, 0.91},  {23.8, 0.21},  {28.1, 1.06},
                                                                 {32.4, 0.22}, {36.7, 0.76},  {39.8, -0.47}, {40.0, -1.0}};
        auto px = [](double x_mm) {
            double bias_px = bias.back().second;
            for (std::size_t j = 1; j < bias.size(); ++j)
                if (x_mm <= bias[j].first) {
                    const double w = (x_mm - bias[j - 1].first) / (bias[j].first - bias[j - 1].first);
                    bias_px = bias[j - 1].second + w * (bias[j].second - bias[j - 1].second);
                    break;
                }
            return 557.0 - 4.0 * x_mm + bias_px;
        };
        const nb::TimeSignal picture = seenInVideo(positionAt, px, truth, frame_s, 520, 81);
        const nb::SyncResult r = nb::synchroniseDisplacement(picture, position, frame_s);
        double worst = 0.0;
        for (double t = 0.0; t <= 6.0; t += 0.01)
            worst = std::max(worst, std::abs(r.mapping().toVideo(t) - truth.toVideo(t)));
        qInfo("drift %.5f, off by %.2f frames at most, confidence %.2f", r.drift, worst / frame_s, r.confidence);
        QVERIFY2(worst < frame_s || r.confidence < 0.5,
                 qPrintable(QStringLiteral("off by %1 frames at confidence %2, drift %3").arg(worst / frame_s).arg(r.confidence).arg(r.drift)));
    }

    // A video that begins inside a slow stroke shows its stop and nothing else that times it:
    // shifted in time, the rest of the stroke is the same stroke at another intercept. A
    // reading half a pixel behind while the tip moves and half ahead at rest (grain) moves the
    // stop by nearly two frames (probe seed 314159 case 1: 1.8 frames off). Counting every
    // frame of the stroke as timing the offset claimed 0.29 frames and confidence 0.71.
    void aStopAloneTimesTheOffsetLoosely()
    {
        const double offset_s = -3.211, frame_s = 1.0 / 30.0, speed_mm_s = 4.1;
        auto positionAt = [&](double t) { return speed_mm_s * std::clamp(t, 0.0, 6.03); };
        const nb::TimeSignal position = recordedAt500Hz(positionAt, 3091);  // to 6.18 s
        const nb::TimelineMapping truth{offset_s, 0.0};
        auto px = [&](double x_mm) { return 133.0 + 4.0 * x_mm + (x_mm < speed_mm_s * 6.03 - 1e-9 ? -0.5 : 0.5); };
        const nb::TimeSignal picture = seenInVideo(positionAt, px, truth, frame_s, 119, 17);
        const nb::SyncResult r = nb::synchroniseDisplacement(picture, position, frame_s);
        const double off = std::abs(r.offset_s - offset_s) / frame_s;
        qInfo("off by %.2f frames, uncertainty %.2f frames, confidence %.2f", off, r.uncertainty_s / frame_s, r.confidence);
        QVERIFY2(off < 1.0 || r.confidence < 0.5,
                 qPrintable(QStringLiteral("off by %1 frames at confidence %2").arg(off).arg(r.confidence)));
    }

    // A slow motion back and forth whose tip the tracker reads a quarter of a pixel ahead of it
    // one way and behind it the other: to a fit with one intercept, that is the motion shifted
    // in time, and the more frames, the surer that fit is of it (a faint needle drawn with numpy,
    // a sine of 0.12 Hz and ±9.6 px at 25 frames/s read 0.27 px off each way: 1.15 frames late,
    // offered for acceptance at confidence 0.54; here five cycles at 30 frames/s, 1.43 frames
    // late at confidence 0.97). Off by more than a frame, the sync must say it is unsure.
    void aReadingAheadOneWayAndBehindTheOther()
    {
        const double offset_s = 3.922, frame_s = 1.0 / 30.0;
        auto positionAt = [](double t) { return t < 0.5 ? 0.0 : 3.1 * std::sin(2.0 * M_PI * 0.12 * (t - 0.5)); };
        auto speedAt = [](double t) { return t < 0.5 ? 0.0 : std::cos(2.0 * M_PI * 0.12 * (t - 0.5)); };
        const nb::TimeSignal position = recordedAt500Hz(positionAt, 21500);  // five cycles and a bit
        const nb::TimelineMapping truth{offset_s, 0.0};
        nb::TimeSignal picture;
        std::mt19937 rng(29);
        std::normal_distribution<double> noise(0.0, 0.1);
        for (int k = 0; k < 1400; ++k) {
            const double tv = k * frame_s, tr = truth.toRecording(tv);
            const double ahead = std::abs(speedAt(tr)) > 0.05 ? (speedAt(tr) > 0 ? 0.27 : -0.27) : 0.0;
            picture.time_s.push_back(tv);
            picture.value.push_back(300.0 + 3.1 * positionAt(tr) + ahead + noise(rng));
        }
        const nb::SyncResult r = nb::synchroniseDisplacement(picture, position, frame_s);
        double worst = 0.0;
        for (double t = 0.0; t <= 42.0; t += 0.01)
            worst = std::max(worst, std::abs(r.mapping().toVideo(t) - truth.toVideo(t)));
        qInfo("off by %.2f frames at most, confidence %.2f", worst / frame_s, r.confidence);
        QVERIFY2(worst < frame_s || r.confidence < nb::kSyncAcceptConfidence,
                 qPrintable(QStringLiteral("off by %1 frames at confidence %2").arg(worst / frame_s).arg(r.confidence)));
    }

    // Pictures that carry 0.4 of the one before (a coder dropping a faint edge's change as it
    // drops the noise) show a slow sine 0.67 frames late. Told how the video was coded, the sync
    // takes that lag off the offset; not told, it is that much off.
    void picturesCarriedOverShowTheMotionLate()
    {
        // Pictures that show the tip a steady trail behind it, whichever way and however fast it
        // moves (core/picture_lag.h): the trail the model gives a faint edge of this memory.
        const double offset_s = 1.317, frame_s = 1.0 / 29.97, memory = 0.6;
        const double trail_px = 0.04 + 0.53 * memory;
        auto positionAt = [](double t) { return t < 0.5 ? 0.0 : 3.0 * std::sin(2.0 * M_PI * 0.2 * (t - 0.5)); };
        const nb::TimeSignal position = recordedAt500Hz(positionAt, 11000);
        const nb::TimelineMapping truth{offset_s, 0.0};
        nb::TimeSignal picture;
        std::mt19937 rng(31);
        std::normal_distribution<double> noise(0.0, 0.1);
        for (int k = 0; k < 700; ++k) {
            const double tv = k * frame_s, t = truth.toRecording(tv);
            const double way = positionAt(t + 0.001) - positionAt(t - 0.001);
            const double shown = 200.0 + 3.4 * positionAt(t) - (way > 0 ? trail_px : way < 0 ? -trail_px : 0.0);
            picture.time_s.push_back(tv);
            picture.value.push_back(shown + noise(rng));
        }
        auto worstFrames = [&](const nb::SyncResult& r) {
            double worst = 0.0;
            for (double t = 0.0; t <= 21.0; t += 0.01)
                worst = std::max(worst, std::abs(r.mapping().toVideo(t) - truth.toVideo(t)));
            return worst / frame_s;
        };
        nb::SyncOptions told;
        told.coding = {memory, 6.0, 0.5, nb::MotionCoding::HalfPixel};  // an edge faint beside the noise
        const nb::SyncResult knowing = nb::synchroniseDisplacement(picture, position, frame_s, told);
        const nb::SyncResult unaware = nb::synchroniseDisplacement(picture, position, frame_s);
        qInfo("told: %.2f frames off, lag %.2f frames; not told: %.2f frames off", worstFrames(knowing),
              knowing.pictureLag_s / frame_s, worstFrames(unaware));
        QVERIFY2(worstFrames(knowing) < 0.25, qPrintable(QString::number(worstFrames(knowing))));
        QVERIFY2(worstFrames(unaware) > 0.6, qPrintable(QString::number(worstFrames(unaware))));
        QCOMPARE(unaware.pictureLag_s, 0.0);
        // The same pictures, their codec named H.264 (quarter pixels): they might have been coded
        // by halves first (a console's MPEG-4 made H.264), and the offset is known no better than
        // the range between the two trails; the truth lies within it.
        nb::SyncOptions quarter = told;
        quarter.coding.edgeSlope_grey_per_px = 8.0;
        quarter.coding.motion = nb::MotionCoding::QuarterPixel;
        const nb::SyncResult eitherCoder = nb::synchroniseDisplacement(picture, position, frame_s, quarter);
        qInfo("named H.264, edge 8 grey/px: lag %.2f ± %.2f frames, %.2f frames off", eitherCoder.pictureLag_s / frame_s,
              eitherCoder.pictureLagUncertainty_s / frame_s, worstFrames(eitherCoder));
        QVERIFY(eitherCoder.pictureLagUncertainty_s > 0.1 * frame_s && eitherCoder.uncertainty_s >= eitherCoder.pictureLagUncertainty_s);
        QVERIFY2(worstFrames(eitherCoder) < eitherCoder.uncertainty_s / frame_s + 0.25,
                 qPrintable(QStringLiteral("%1 frames off, uncertainty %2").arg(worstFrames(eitherCoder)).arg(eitherCoder.uncertainty_s / frame_s)));
        // Where the pictures' noise shows the most memory the meter reads, the coder dropped the
        // noise the faint trail is read from: it may be far longer, and the offset is not offered
        // for acceptance. A bold edge is shown nearly on time by any coder: its precision stays
        // what the picture gives (fastNeedleInCleanH264 in test_accuracy).
        nb::SyncOptions faintAtTheTop, boldAtTheTop;
        faintAtTheTop.coding = {nb::kMostMeasurableMemory, 1.0, 3.0};
        boldAtTheTop.coding = {nb::kMostMeasurableMemory, 0.5, 200.0};
        const nb::SyncResult faint = nb::synchroniseDisplacement(picture, position, frame_s, faintAtTheTop);
        const nb::SyncResult bold = nb::synchroniseDisplacement(picture, position, frame_s, boldAtTheTop);
        qInfo("memory at the meter's most: a faint edge's lag %.2f frames, uncertainty %.2f frames, confidence %.2f; "
              "a bold edge's lag %.2f frames, uncertainty %.2f frames (not told: %.2f)",
              faint.pictureLag_s / frame_s, faint.uncertainty_s / frame_s, faint.confidence, bold.pictureLag_s / frame_s,
              bold.uncertainty_s / frame_s, unaware.uncertainty_s / frame_s);
        QVERIFY2(faint.uncertainty_s >= frame_s, qPrintable(QString::number(faint.uncertainty_s / frame_s)));
        QVERIFY2(!faint.acceptable(), qPrintable(QString::number(faint.confidence)));
        // Which track is the needle, the picture alone says: the coder's lag does not lower that.
        QVERIFY2(faint.trackConfidence > faint.confidence && faint.trackConfidence >= unaware.trackConfidence - 0.05,
                 qPrintable(QStringLiteral("%1 against %2 (not told: %3)").arg(faint.trackConfidence).arg(faint.confidence).arg(unaware.trackConfidence)));
        QVERIFY2(bold.pictureLag_s < 0.05 * frame_s, qPrintable(QString::number(bold.pictureLag_s / frame_s)));
        QVERIFY2(bold.uncertainty_s < 1.1 * unaware.uncertainty_s + 0.05 * frame_s,
                 qPrintable(QStringLiteral("%1 against %2 frames").arg(bold.uncertainty_s / frame_s).arg(unaware.uncertainty_s / frame_s)));
    }

    void renderedSimulatedRun()
    {
        int code = -1;
        QFile tf(truth_);
        QVERIFY(tf.open(QIODevice::ReadOnly));
        const double offset = QJsonDocument::fromJson(tf.readAll()).object()["video_offset_s"].toDouble();

        // The operator draws the region around the needle tip in the middle pane.
        const QJsonObject r = runJson({"sync", run_, video_, "--roi", "240,300,240,180", "--json"}, &code);
        QCOMPARE(code, 0);
        QVERIFY2(std::abs(r["offset_s"].toDouble() - offset) < 1.0 / 29.97,
                 qPrintable(QStringLiteral("found %1 s, truth %2 s").arg(r["offset_s"].toDouble()).arg(offset)));
        QVERIFY(r["confidence"].toDouble() > 0.7);

        runJson({"sync", run_, video_, "--roi", "1,2,3"}, &code);
        QCOMPARE(code, 2);
        runJson({"sync", run_, dir_.filePath("none.avi")}, &code);
        QCOMPARE(code, 1);
    }

    // A picture in which nothing moves (a grey screen): no uncertainty is claimed for the offset
    // it cannot measure (it said "0.00 frames"), and a low answer names the offsets tried.
    void aStillPictureMeasuresNothing()
    {
        const QString grey = dir_.filePath("grey.mp4");
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-f", "lavfi", "-i", "color=c=gray:size=320x240:rate=29.97:duration=6",
                                               "-c:v", "libx264", "-pix_fmt", "yuv420p", grey});
        QVERIFY2(ffmpeg.waitForStarted(10000), "the ffmpeg tool is missing (scripts/install-deps.sh installs it)");
        QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        int code = -1;
        const QJsonObject r = runJson({"sync", run_, grey, "--json", "--max-offset", "3"}, &code);
        QCOMPARE(code, 0);
        QVERIFY(!r["acceptable"].toBool());
        QVERIFY2(r["uncertainty_frames"].isNull() && r["uncertainty_s"].isNull(), qPrintable(QJsonDocument(r).toJson()));
        // Nor an offset: it gave the search's edge, -3 s here.
        QVERIFY2(r["offset_s"].isNull(), qPrintable(QJsonDocument(r).toJson()));
        QCOMPARE(r["max_offset_s"].toDouble(), 3.0);
        const nbtest::CliResult text = nbtest::runCli({"sync", run_, grey, "--max-offset", "3"}, 240000);
        QVERIFY2(text.out.contains(QStringLiteral("uncertainty: unknown")) && text.out.contains(QStringLiteral("--max-offset"))
                     && text.out.contains(QStringLiteral("offset:      none")),
                 qPrintable(text.out));

        // Noise that changes every frame: whatever the fit takes from it, the uncertainty is a
        // figure or unknown, never the search's placeholder (it printed 15000000000 frames).
        const QString noise = dir_.filePath("noise.mp4");
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-f", "lavfi", "-i", "color=c=gray:size=320x240:rate=29.97:duration=6",
                                               "-vf", "noise=alls=40:allf=t", "-c:v", "libx264", "-pix_fmt", "yuv420p", noise});
        QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        const QJsonObject n = runJson({"sync", run_, noise, "--json", "--max-offset", "3"}, &code);
        QCOMPARE(code, 0);
        QVERIFY(!n["acceptable"].toBool());
        QVERIFY2(n["uncertainty_frames"].isNull() || n["uncertainty_frames"].toDouble() < 1e4, qPrintable(QJsonDocument(n).toJson()));

        // A picture too small to show a needle is refused, naming it: it answered -max_offset, exit 0.
        const QString tiny = dir_.filePath("tiny.avi");
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-f", "lavfi", "-i", "color=c=gray:size=16x16:rate=25:duration=2",
                                               "-c:v", "mjpeg", tiny});
        QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        const nbtest::CliResult small = nbtest::runCli({"sync", run_, tiny, "--json"}, 240000);
        QCOMPARE(small.code, 1);
        QVERIFY2(small.err.contains(tiny) && small.err.contains(QStringLiteral("too small")), qPrintable(small.err));
    }

    // A long video of which a run can lie only in a short stretch (the offsets tried, ±20 s by
    // default): that stretch is tracked, not the whole video, which took five minutes for a
    // half-hour video and a minute's run (video probe). The offset is found all the same, and
    // the answer says what was tracked.
    void aLongVideoIsTrackedWhereTheRunCanLie()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        const nb::needle_video::NeedleVideo v = plainNeedle(2400, strokeThenAnotherLater);  // 80 s
        const QString video = dir_.filePath("long.avi"), run = dir_.filePath("stroke.csv"), trace = dir_.filePath("long-trace.csv");
        const QString problem = nb::needle_video::writeNeedleVideo(video, v);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        // The video shows the stroke from 10 s: the offset is 9.5 s.
        QVERIFY(writeStrokeRun(run));
        int code = -1;
        const QJsonObject r = runJson({"sync", run, video, "--json", "--trace", trace}, &code);
        QCOMPARE(code, 0);
        QVERIFY2(std::abs(r["offset_s"].toDouble() - 9.5) < 1.0 / 30.0, qPrintable(QJsonDocument(r).toJson()));
        QCOMPARE(r["frames"].toInt(), 2400);
        // From the video's start (9.5 - 20 s is before it) to 4 + 20 s and a few seconds more.
        QVERIFY2(r["frames_tracked"].toInt() > 700 && r["frames_tracked"].toInt() < 900, qPrintable(QJsonDocument(r).toJson()));
        QFile t(trace);
        QVERIFY(t.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = t.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), r["frames_tracked"].toInt() + 1);
        QVERIFY2(lines.last().split(',').first().toDouble() < 28.0, lines.last().constData());
        const nbtest::CliResult text = nbtest::runCli({"sync", run, video}, 240000);
        QVERIFY2(text.out.contains(QStringLiteral("tracked:")) && text.out.contains(QStringLiteral("of 80.00 s")), qPrintable(text.out));
    }

    // A needle that moves in the picture against the recorded position still times the offset;
    // the answer gives it and says the motion is reversed. It said "offset: none (nothing in the
    // picture moved with the recording)" for a correlation of -0.96 (probe).
    void aPictureMovingAgainstTheRecording()
    {
        const nb::needle_video::NeedleVideo v = plainNeedle(480, strokeBackwards);  // 16 s
        const QString video = dir_.filePath("backwards.avi"), run = dir_.filePath("forwards.csv");
        const QString problem = nb::needle_video::writeNeedleVideo(video, v);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        // The offset is 9.5 s.
        QVERIFY(writeStrokeRun(run));
        int code = -1;
        const QJsonObject r = runJson({"sync", run, video, "--json"}, &code);
        QCOMPARE(code, 0);
        QVERIFY2(r["correlation"].toDouble() < -0.5, qPrintable(QJsonDocument(r).toJson()));
        QVERIFY2(!r["offset_s"].isNull() && std::abs(r["offset_s"].toDouble() - 9.5) < 1.0 / 30.0, qPrintable(QJsonDocument(r).toJson()));
        QVERIFY2(r["reversed"].toBool(), qPrintable(QJsonDocument(r).toJson()));
        const nbtest::CliResult text = nbtest::runCli({"sync", run, video}, 240000);
        QVERIFY2(!text.out.contains(QStringLiteral("offset:      none")) && text.out.contains(QStringLiteral("against the recorded position")),
                 qPrintable(text.out));
    }

    // Timestamps that go back (two MPEG-TS files joined): no span can be read off them, the
    // whole video is tracked, and the answer says so (it gave half the frames, and a "tracked:"
    // line for the whole file).
    void aVideoWhoseTimeGoesBackIsTrackedWhole()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        int code = -1;
        const QString ts = dir_.filePath("once.ts"), twice = dir_.filePath("twice.ts"), twiceTrace = dir_.filePath("twice-trace.csv");
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-i", video_, "-c:v", "libx264", "-preset", "ultrafast", "-pix_fmt",
                                               "yuv420p", "-f", "mpegts", ts});
        QVERIFY2(ffmpeg.waitForStarted(10000), "the ffmpeg tool is missing (scripts/install-deps.sh installs it)");
        QVERIFY(ffmpeg.waitForFinished(120000) && ffmpeg.exitCode() == 0);
        QFile a(ts), joined(twice);
        QVERIFY(a.open(QIODevice::ReadOnly) && joined.open(QIODevice::WriteOnly));
        const QByteArray bytes = a.readAll();
        joined.write(bytes);
        joined.write(bytes);
        joined.close();
        const QJsonObject j = runJson({"sync", run_, twice, "--json", "--trace", twiceTrace}, &code);
        QCOMPARE(code, 0);
        QCOMPARE(j["frames_tracked"].toInt(), j["frames"].toInt());
        QFile tt(twiceTrace);
        QVERIFY(tt.open(QIODevice::ReadOnly));
        QCOMPARE(int(tt.readAll().trimmed().split('\n').size()) - 1, j["frames"].toInt());
        QVERIFY(!nbtest::runCli({"sync", run_, twice}, 240000).out.contains(QStringLiteral("tracked:")));
    }

    // The operator may draw the needle's line from the tip to the shaft as well as the other
    // way: it is turned to point from the shaft to the tip (what the tracker assumes), shown so
    // in the answer, and the offset is the same either way.
    void needleDrawnEitherWay()
    {
        QFile tf(truth_);
        QVERIFY(tf.open(QIODevice::ReadOnly));
        const double offset = QJsonDocument::fromJson(tf.readAll()).object()["video_offset_s"].toDouble();
        int code = -1;
        const QJsonObject found = runJson({"sync", run_, video_, "--json"}, &code);
        QCOMPARE(code, 0);
        QVERIFY(found["needle_found"].toBool());
        const QJsonArray a = found["needle"].toArray();
        QCOMPARE(a.size(), 4);
        auto coordinates = [](const QJsonArray& p) { return QStringLiteral("%1,%2,%3,%4").arg(p[0].toDouble()).arg(p[1].toDouble()).arg(p[2].toDouble()).arg(p[3].toDouble()); };
        const QJsonArray backwards{a[2], a[3], a[0], a[1]};
        for (const QJsonArray& drawn : {a, backwards}) {
            const QJsonObject r = runJson({"sync", run_, video_, "--needle", coordinates(drawn), "--json"}, &code);
            QCOMPARE(code, 0);
            QVERIFY(!r["needle_found"].toBool());
            const QJsonArray used = r["needle"].toArray();
            QCOMPARE(used.size(), 4);
            // The same direction as the line found: from the shaft to the tip.
            const double along = (used[2].toDouble() - used[0].toDouble()) * (a[2].toDouble() - a[0].toDouble()) +
                                 (used[3].toDouble() - used[1].toDouble()) * (a[3].toDouble() - a[1].toDouble());
            QVERIFY2(along > 0, qPrintable(QStringLiteral("drawn %1, used %2, found %3").arg(coordinates(drawn), coordinates(used), coordinates(a))));
            QVERIFY2(std::abs(r["offset_s"].toDouble() - offset) < 1.0 / 29.97,
                     qPrintable(QStringLiteral("drawn %1: found %2 s, truth %3 s").arg(coordinates(drawn)).arg(r["offset_s"].toDouble()).arg(offset)));
        }
        // A line off the picture (drawn for another video, numbers mistyped) is refused, named;
        // it tracked nothing and answered "confidence 0.00". One that runs off an edge is taken.
        const nbtest::CliResult off = nbtest::runCli({"sync", run_, video_, "--needle", "900,900,1000,1000"}, 240000);
        QCOMPARE(off.code, 2);
        QVERIFY2(off.err.contains(QStringLiteral("--needle 900,900,1000,1000 lies outside the")), qPrintable(off.err));
        const QJsonArray past{a[0], a[1], a[2].toDouble() + 3.0 * (a[2].toDouble() - a[0].toDouble()), a[3].toDouble() + 3.0 * (a[3].toDouble() - a[1].toDouble())};
        runJson({"sync", run_, video_, "--needle", coordinates(past), "--json"}, &code);
        QCOMPARE(code, 0);
        // The tip is read in the region alone: a drawn line that misses the region is refused,
        // named, not tracked as nothing. The region: 16 px in the picture's corner furthest from
        // the line.
        const QLineF line(a[0].toDouble(), a[1].toDouble(), a[2].toDouble(), a[3].toDouble());
        const QPointF along = (line.p2() - line.p1()) / line.length();
        auto distance = [&](QPointF p) { return std::abs((p.x() - line.x1()) * along.y() - (p.y() - line.y1()) * along.x()); };
        const nb::video::FrameIndex index = nb::video::buildFrameIndex(video_);
        const int w = index.width, h = index.height;
        QPoint corner(0, 0);
        for (const QPoint c : {QPoint(w - 16, 0), QPoint(0, h - 16), QPoint(w - 16, h - 16)})
            if (distance(c + QPointF(8, 8)) > distance(corner + QPointF(8, 8)))
                corner = c;
        QVERIFY(distance(corner + QPointF(8, 8)) > 16.0);
        const QString roi = QStringLiteral("%1,%2,16,16").arg(corner.x()).arg(corner.y());
        const nbtest::CliResult apart = nbtest::runCli({"sync", run_, video_, "--needle", coordinates(a), "--roi", roi}, 240000);
        QCOMPARE(apart.code, 1);
        QVERIFY2(apart.err.contains(QStringLiteral("does not cross the region %1,%2 16x16").arg(corner.x()).arg(corner.y())), qPrintable(apart.err));
    }

    // A short fast stroke (8 mm at 10 mm/s) in an H.264 video begun 14 s before it: the needle
    // moved in 2 of the 40 frames spread over the video to find it, and the stretch that moves
    // went unseen in the picture's mean change (a thin needle is a few hundred of its pixels).
    // No needle was found; the weaker motion comparison said 14.016 s at confidence 0.45.
    void shortStrokeLongAfterTheVideoStarts()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        const QString run = dir_.filePath("late.csv"), video = dir_.filePath("late.mp4"), truth = dir_.filePath("late.json");
        int code = -1;
        runJson({"simulate", "--protocol", "stiffness", "--tissue", "liver2", "--velocity-mm-s", "10", "--depth-mm", "8", "--seed", "95",
                 "--out", run, "--truth", truth, "--video", video, "--video-offset-s", "14"},
                &code);
        QCOMPARE(code, 0);
        const QJsonObject r = runJson({"sync", run, video, "--json"}, &code);
        QCOMPARE(code, 0);
        QVERIFY2(r["method"].toString().startsWith("needle displacement"), qPrintable(r["method"].toString()));
        QVERIFY2(std::abs(r["offset_s"].toDouble() - 14.0) < 1.0 / 29.97,
                 qPrintable(QStringLiteral("found %1 s, truth 14 s").arg(r["offset_s"].toDouble())));
        QVERIFY(r["acceptable"].toBool());
    }

    // A video started after the recording (the imaging console switched on late): the simulator
    // renders it (--video-offset-s negative; it refused one), and sync finds the negative offset.
    void aVideoStartedAfterTheRecording()
    {
        const QString run = dir_.filePath("after.csv"), video = dir_.filePath("after.avi"), truth = dir_.filePath("after.json");
        int code = -1;
        runJson({"simulate", "--protocol", "friction", "--tissue", "liver5", "--cycles", "3", "--seed", "31", "--out", run, "--truth", truth,
                 "--video", video, "--video-offset-s", "-2.7"},
                &code);
        QCOMPARE(code, 0);
        QFile tf(truth);
        QVERIFY(tf.open(QIODevice::ReadOnly));
        QCOMPARE(QJsonDocument::fromJson(tf.readAll()).object()["video_offset_s"].toDouble(), -2.7);
        const QJsonObject r = runJson({"sync", run, video, "--json"}, &code);
        QCOMPARE(code, 0);
        QVERIFY2(std::abs(r["offset_s"].toDouble() + 2.7) < 1.0 / 29.97, qPrintable(QStringLiteral("found %1 s, truth -2.7 s").arg(r["offset_s"].toDouble())));
        QVERIFY(r["acceptable"].toBool());
        // Strokes before the video's first frame are said to be outside it, not "too little
        // motion per frame" (a helper's probe, seed 507056 case 3).
        runJson({"labels", "suggest", run, "--video", video, "--overwrite"}, &code);
        QCOMPARE(code, 0);
        const nb::Labels labels = nb::readLabelsFile(nb::labelsPathFor(run));
        QVERIFY(!labels.empty());
        QVERIFY2(labels.front().comment.contains(QStringLiteral("after.avi does not cover this stroke")), qPrintable(labels.front().comment));
        QVERIFY(std::any_of(labels.begin(), labels.end(), [](const nb::Label& l) { return l.comment.contains(QStringLiteral("tissue's motion in after.avi")); }));
        // One that would start after the run ended is refused, by name; the run file stays whole.
        runJson({"simulate", "--protocol", "friction", "--cycles", "1", "--out", dir_.filePath("never.csv"), "--video", dir_.filePath("never.avi"),
                 "--video-offset-s", "-100", "--overwrite"},
                &code);
        QCOMPARE(code, 1);
        QVERIFY(!QFile::exists(dir_.filePath("never.avi")));
        QVERIFY(nb::readRunFile(dir_.filePath("never.csv")).run.size() > 100);
    }

    // The simulator's imaging view made faint and re-coded as H.264 at -crf 30 (26 KB for 318
    // frames): the coder holds the still parts of the picture from frame to frame, so along a line
    // beside the needle nothing but the tip's edge changed, its noise measured as nothing, and a
    // line 5° off the needle outranked every other (sync 22 frames off at confidence 0.04, the
    // needle's own line never tried). A check outside the probe's matrix, drawn at random.
    void simulatorsViewCodedAlmostStill()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        const QString run = dir_.filePath("held.csv"), rendered = dir_.filePath("held.avi"), coded = dir_.filePath("held.mp4");
        int code = -1;
        runJson({"simulate", "--protocol", "friction", "--tissue", "liver7", "--seed", "822", "--cycles", "4", "--frequency-hz",
                 "0.5", "--out", run, "--video", rendered, "--video-offset-s", "1.617"},
                &code);
        QCOMPARE(code, 0);
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-y", "-loglevel", "error", "-i", rendered, "-vf", "eq=contrast=0.35,noise=alls=3:allf=t",
                                               "-c:v", "libx264", "-bf", "2", "-crf", "30", "-pix_fmt", "yuv420p", coded});
        if (!ffmpeg.waitForStarted(10000))
            QSKIP("the ffmpeg tool is not installed");
        QVERIFY(ffmpeg.waitForFinished(120000));
        QCOMPARE(ffmpeg.exitCode(), 0);
        const QJsonObject r = runJson({"sync", run, coded, "--json"}, &code);
        QCOMPARE(code, 0);
        const double error_frames = (r["offset_s"].toDouble() - 1.617) * 29.97;
        qInfo("coded almost still: %.2f frames off, confidence %.2f, picture memory %.2f", error_frames, r["confidence"].toDouble(),
              r["picture_memory"].toDouble());
        QVERIFY2(std::abs(error_frames) < 1.0, qPrintable(QString::number(error_frames)));
        QVERIFY(r["acceptable"].toBool());
        // The trail the lag was read from, as a range: least, then most.
        const QJsonArray trail = r["picture_trail_px"].toArray();
        QCOMPARE(trail.size(), 2);
        QVERIFY(trail[0].toDouble() >= 0.0 && trail[0].toDouble() <= trail[1].toDouble());
        QVERIFY(!r["coded_once"].toBool());
        // Said to be coded once (it was: rendered, then coded by x264 alone), its trail is its own
        // coder's: no range, and the lag known at least as closely.
        const QJsonObject once = runJson({"sync", run, coded, "--json", "--coded-once"}, &code);
        QCOMPARE(code, 0);
        const QJsonArray onceTrail = once["picture_trail_px"].toArray();
        qInfo("said to be coded once: %.2f frames off, confidence %.2f, trail %.3f px (not said: %.3f to %.3f)",
              (once["offset_s"].toDouble() - 1.617) * 29.97, once["confidence"].toDouble(), onceTrail[0].toDouble(),
              trail[0].toDouble(), trail[1].toDouble());
        QVERIFY(once["coded_once"].toBool());
        QCOMPARE(onceTrail[0].toDouble(), onceTrail[1].toDouble());
        QVERIFY(once["picture_lag_uncertainty_s"].toDouble() <= r["picture_lag_uncertainty_s"].toDouble());
        QVERIFY2(std::abs((once["offset_s"].toDouble() - 1.617) * 29.97) < 1.0, qPrintable(QString::number(once["offset_s"].toDouble())));
        // What the window does when the box is ticked after a sync: the sync's track fitted again,
        // not tracked again, gives what a sync told from the start gives.
        const nb::Run held = nb::readRunFile(run).run;
        const nb::video::FrameIndex index = nb::video::buildFrameIndex(coded);
        nb::video::VideoSyncOptions told;
        told.codedOnce = true;
        const nb::video::VideoSync fromTheStart = nb::video::syncVideoToRun(index, held, told);
        const nb::video::VideoSync refitted = nb::video::refitVideoSync(nb::video::syncVideoToRun(index, held), index, held, told);
        QCOMPARE(refitted.result.offset_s, fromTheStart.result.offset_s);
        QCOMPARE(refitted.result.confidence, fromTheStart.result.confidence);
        QCOMPARE(refitted.result.pictureLagUncertainty_s, fromTheStart.result.pictureLagUncertainty_s);
        QCOMPARE(refitted.track.axis, fromTheStart.track.axis);
    }

    // Suggested phases against the simulator's truth: the suggested c (dynamic friction)
    // intervals lie mostly inside true c.
    void suggestionsAgainstTruth()
    {
        int code = -1;
        const QString out = dir_.filePath("fr.labels.csv");
        runJson({"labels", "suggest", run_, "--out", out}, &code);
        QCOMPARE(code, 0);
        const nb::Labels labels = nb::readLabelsFile(out);
        QFile tf(truth_);
        QVERIFY(tf.open(QIODevice::ReadOnly));
        const QJsonArray phases = QJsonDocument::fromJson(tf.readAll()).object()["phases"].toArray();
        double inside = 0, total = 0;
        int cCount = 0;
        for (const nb::Label& l : labels) {
            if (l.label != "c")
                continue;
            ++cCount;
            total += l.end_s - l.start_s;
            for (const auto& p : phases) {
                const QJsonObject o = p.toObject();
                if (o["label"].toString() != "c")
                    continue;
                inside += std::max(0.0, std::min(l.end_s, o["end_s"].toDouble()) - std::max(l.start_s, o["start_s"].toDouble()));
            }
        }
        QVERIFY(cCount >= 5);  // 3 cycles: 6 half-cycles
        QVERIFY2(inside / total > 0.6, qPrintable(QString::number(inside / total)));
        for (const nb::Label& l : labels)
            QVERIFY(l.track == "insertion" || l.track == "withdrawal");
    }
};

QTEST_GUILESS_MAIN(TestSync)
#include "test_sync.moc"
