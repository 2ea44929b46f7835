// Along the needle's line, the tip read where it is on a textured background (issue 13): at
// rest as well as moving, faint or clear. A texture's own edges pull the edge detector, and the
// tracker takes out what is always there; how well it learns that decides where a resting tip
// reads, and at a slow stroke's onset and stop half a pixel is one to two frames of sync.
#include "support/case_share.h"
#include "needle_video.h"
#include "video_fixtures.h"

#include "video/packet_index.h"
#include "video/video_error.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace {

using namespace nb::needle_video;

// A slow stroke (0.6 px a frame for 60 frames), then at rest for the last 30.
double strokeThenRest(int frame)
{
    return -18.0 + 0.6 * std::min(frame, 60);
}

// At rest for the first 300 frames, then a slow stroke (0.3 px a frame for 100 frames).
double longRestThenStroke(int frame)
{
    return -15.0 + 0.3 * std::clamp(frame - 300, 0, 100);
}

// At rest for the first 50 frames, then a sine of 40 px each way, a cycle in 40 frames.
double restThenSine(int frame)
{
    return frame < 50 ? 0.0 : 40.0 * std::sin(2.0 * kPi * (frame - 50) / 40.0);
}

// A needle on grain of 25 grey levels (4 px squares, from `grainSeed`), its tip where `tip`
// puts it in each of `frames` frames.
NeedleVideo onGrain(unsigned grainSeed, double (*tip)(int), double contrast, double noise, int frames = kFrames)
{
    NeedleVideo v{0.0};
    v.grainSeed = grainSeed;
    v.tip = tip;
    v.contrast = contrast;
    v.grain = 25.0;
    v.noise = noise;
    v.frames = frames;
    return v;
}

// How far the tip is read from the truth in each frame of `v` (NaN where it is not read),
// tracked along the line across the picture's middle; nothing, and `problem` says why, when the
// video cannot be made or the track has a frame too many or too few.
std::optional<std::vector<double>> tipErrors(const NeedleVideo& v, QString* problem)
{
    const std::optional<nb::video::NeedleTrack> track = trackedAcrossTheMiddle(v, problem);
    if (!track)
        return std::nullopt;
    if (int(track->displacement_px.size()) != v.frames) {
        *problem = QStringLiteral("%1 frames tracked of %2").arg(track->displacement_px.size()).arg(v.frames);
        return std::nullopt;
    }
    const double centreAt = kWidth / 2.0 - track->axis.x1();
    std::vector<double> errors;
    for (int k = 0; k < v.frames; ++k)
        errors.push_back(track->displacement_px[std::size_t(k)] - centreAt - v.tip(k));
    return errors;
}

void addGrainRows(unsigned from, unsigned to)
{
    QTest::addColumn<unsigned>("grainSeed");
    for (unsigned seed = from; seed <= to; ++seed)
        QTest::newRow(qPrintable(QStringLiteral("grain %1").arg(seed))) << seed;
}

}  // namespace

class TestNeedleTip : public QObject {
    Q_OBJECT

private slots:
    // On a textured background the edge response has the texture's edges in it, of both signs,
    // in every frame, and the strip's middle differs from its sides by the texture as much as
    // by the shaft. The texture's edges of the tip's sign were taken out as what is always
    // there; those of the other sign were left in (what is always there was held at zero), and
    // beside a tip at rest they pulled its edge onto the texture's next edge (probe seed 314159
    // case 12: at the final rest of a slow stroke the tip read 4.5 px ahead; 246810 case 15:
    // 3.7 px short, and the sync 1.5 frames off). Where the picture ahead of the tip was
    // brighter in the middle than at the sides, no shaft seemed to end at the tip and it went
    // unread (314159 case 1: through the whole final rest). Both are now learnt from the frames
    // whose tip is elsewhere. Before, on three of these nine grains the tip at rest read 2.2 and
    // 3.5 px off or went unread in most frames.
    void readsATipAtRestOnTexture_data()
    {
        QTest::addColumn<unsigned>("grainSeed");
        for (unsigned seed : {12345u, 777u, 4242u, 31337u, 2024u, 99u, 5u, 6u, 7u})
            QTest::newRow(qPrintable(QStringLiteral("grain %1").arg(seed))) << seed;
    }
    void readsATipAtRestOnTexture()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(unsigned, grainSeed);
        QString problem;
        const std::optional<std::vector<double>> errors = tipErrors(onGrain(grainSeed, strokeThenRest, 40.0, 15.0), &problem);
        QVERIFY2(errors, qPrintable(problem));
        std::vector<double> atRest, moving;
        for (int k = 0; k < kFrames; ++k)
            if (const double error = (*errors)[std::size_t(k)]; std::isfinite(error))
                (k > 62 ? atRest : moving).push_back(error);
        QVERIFY2(atRest.size() >= 20 && moving.size() >= 50, "the tip is lost in too many frames");
        const double restError = median(atRest), movingError = median(moving);
        qInfo("median error at rest %.2f px (%zu frames), moving %.2f px (%zu frames)", restError, atRest.size(), movingError,
              moving.size());
        QVERIFY2(std::abs(restError) < 1.0, qPrintable(QStringLiteral("at rest the tip reads %1 px off").arg(restError)));
        QVERIFY2(std::abs(movingError) < 1.0, qPrintable(QStringLiteral("moving, the tip reads %1 px off").arg(movingError)));
    }

    // A faint needle (its tip 3-4 σ in most frames, too faint for the shaft gate) that rests
    // through more than half the frames. Against the frames' usual edge response, the places the
    // tip visits while it moves show as edges of the other sign in the frames at rest, and its
    // place at rest as one in the frames that move: both signs stand out about as much, and
    // taking the one that stood out more was a coin toss (probe seed 271828 case 10: 187 against
    // 180 for the wrong sign, the tip read at its turning points while it rested, and the sync
    // 715 frames off). The shaft's own sign decides. Before, grain 17 had the wrong sign and no
    // frame within 2 px (one grain in 24 here, one in 16 cases on that seed).
    void takesTheShaftsSignForAFaintTip_data() { addGrainRows(12, 17); }
    void takesTheShaftsSignForAFaintTip()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(unsigned, grainSeed);
        QString problem;
        const std::optional<std::vector<double>> errors = tipErrors(onGrain(grainSeed, restThenSine, 36.0, 28.0), &problem);
        QVERIFY2(errors, qPrintable(problem));
        int read = 0, close = 0;
        for (double error : *errors) {
            read += std::isfinite(error);
            close += std::abs(error) <= 2.0;
        }
        qInfo("%d of %d frames read, %d within 2 px", read, kFrames, close);
        // So faint a tip is read more than 2 px off in 11 to 37 of the 90 frames on these grains;
        // with the wrong sign it is read off in all of them.
        QVERIFY2(read >= 0.85 * kFrames, qPrintable(QStringLiteral("%1 frames without a tip").arg(kFrames - read)));
        QVERIFY2(close >= 0.5 * kFrames, qPrintable(QStringLiteral("the tip within 2 px in %1 of %2 frames").arg(close).arg(kFrames)));
    }

    // A tip that rests through three quarters of a long video, then moves slowly. What is always
    // there was learnt from the start-up's sampled frames whose tip is elsewhere: a dozen of
    // them, and beside the resting tip their low percentile is off by a fraction of the noise,
    // the same in every frame, which pulls the tip by up to half a pixel for the whole rest.
    // Over a stroke of 0.3 px a frame that is one to two frames of sync (probe seed 187716
    // case 8: 0.46 px short at rest, the sync 1.6 frames off). Every frame now teaches it, and
    // the tips are read again against it at the end. Before, the rest read 0.46-0.92 px from
    // where the stroke put it on 4 of these 6 grains; now 0.32 px at most. (Not all of that is
    // the percentile's: on a fainter needle, 45 over noise 25, 0.5-0.75 px is left on 3 grains
    // in 6, where there was 0.4-2.0 px on all 6.)
    void readsALongRestAsTheStrokeDoes_data() { addGrainRows(21, 26); }
    void readsALongRestAsTheStrokeDoes()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(unsigned, grainSeed);
        QString problem;
        const std::optional<std::vector<double>> errors = tipErrors(onGrain(grainSeed, longRestThenStroke, 45.0, 15.0, 400), &problem);
        QVERIFY2(errors, qPrintable(problem));
        std::vector<double> atRest, moving;
        for (int k = 0; k < 400; ++k)
            if (const double error = (*errors)[std::size_t(k)]; std::isfinite(error))
                (k < 300 ? atRest : moving).push_back(error);
        QVERIFY2(atRest.size() >= 270 && moving.size() >= 90, "the tip is lost in too many frames");
        const double restError = median(atRest), movingError = median(moving);
        qInfo("median error at rest %.2f px, moving %.2f px", restError, movingError);
        QVERIFY2(std::abs(restError - movingError) < 0.4,
                 qPrintable(QStringLiteral("at rest the tip reads %1 px from where the stroke puts it").arg(restError - movingError)));
    }

    // A frame counter burnt in on the needle's line ahead of a faint tip: white digits on a black
    // box, as ffmpeg draws one, changing every frame. Its edges stand 10-25 σ out of the noise and
    // change too much to be taken out as what is always there, and a faint tip's course keeps to
    // them (probe seed 577215 case 14: on a counter's digit in every frame). When no line's track
    // explains the recording, the sync tracks a line again without the place its track kept to;
    // asked not to read a few pixels of the counter (as little as a track keeps to), the tracker
    // reads none of it (the rest of the counter changes as much) and finds the tip beyond.
    void readsPastAStretchNotRead_data() { addGrainRows(31, 36); }
    void readsPastAStretchNotRead()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(unsigned, grainSeed);
        NeedleVideo v = onGrain(grainSeed, restThenSine, 30.0, 22.0);
        v.counterAhead = true;
        QTemporaryDir dir;
        QString problem;
        const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
        QVERIFY2(index, qPrintable(problem));
        nb::video::FrameReader reader(*index);
        const nb::video::NeedleAxis drawn(QPointF(10.0, kHeight / 2.0), QPointF(kWidth - 10.0, kHeight / 2.0));
        const nb::video::NeedleTrack first = nb::video::trackNeedle(reader, drawn);
        const double centreAt = kWidth / 2.0 - first.axis.x1();
        const double counterAt = centreAt + v.travelCentre + 110.0;
        auto count = [&](const nb::video::NeedleTrack& track, int* close, int* onCounter) {
            QCOMPARE(int(track.displacement_px.size()), v.frames);
            *close = *onCounter = 0;
            for (int k = 0; k < v.frames; ++k) {
                const double error = track.displacement_px[std::size_t(k)] - centreAt - v.tip(k);
                *close += std::abs(error) <= 2.0;
                *onCounter += error > 30.0;
            }
        };
        int close = 0, onCounter = 0;
        count(first, &close, &onCounter);
        qInfo("read everywhere: %d of %d frames within 2 px, %d on the counter", close, v.frames, onCounter);
        const std::vector<nb::video::NeedleTrack> again =
            nb::video::trackNeedles(reader, {first.axis}, {}, nullptr, {nb::video::AxisStretch{counterAt - 2.0, counterAt + 2.0}});
        QCOMPARE(again.size(), std::size_t(1));
        count(again.front(), &close, &onCounter);
        qInfo("not read about the counter's middle: %d within 2 px, %d on the counter", close, onCounter);
        QVERIFY2(onCounter == 0, qPrintable(QStringLiteral("the tip read on the counter in %1 frames").arg(onCounter)));
        QVERIFY2(close >= 0.5 * v.frames, qPrintable(QStringLiteral("the tip within 2 px in %1 of %2 frames").arg(close).arg(v.frames)));
    }

    // A faint needle (27 over noise 23) whose first frame is coded worse than the rest: four
    // times the noise. What is always there is learnt from the start-up's sampled frames whose
    // tip is elsewhere, and of the few such frames near a faint tip the lowest edge counts: the
    // noisier frame's. It put what is always there far too low along the strip, and the tip's
    // course kept to a still edge. The sampled frames that scatter more than twice as much as
    // the usual one are left out. Before, on grains 45 and 46 no frame was read within 2 px.
    void shrugsOffANoisierFrame_data() { addGrainRows(41, 50); }
    void shrugsOffANoisierFrame()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(unsigned, grainSeed);
        NeedleVideo v = onGrain(grainSeed, restThenSine, 27.0, 23.0, 160);
        v.noisierFrame = 0;
        QString problem;
        const std::optional<std::vector<double>> errors = tipErrors(v, &problem);
        QVERIFY2(errors, qPrintable(problem));
        int read = 0, close = 0;
        for (double error : *errors) {
            read += std::isfinite(error);
            close += std::abs(error) <= 2.0;
        }
        qInfo("%d of %d frames read, %d within 2 px", read, v.frames, close);
        // So faint a tip is read within 2 px in 109-132 of the 160 frames on these grains.
        QVERIFY2(close >= 0.6 * v.frames, qPrintable(QStringLiteral("the tip within 2 px in %1 of %2 frames").arg(close).arg(v.frames)));
    }

    // A file damaged in its middle, indexed from its packets (as a video over ten minutes is):
    // the frames in the damaged stretch cannot be decoded, and the tracker leaves them out as
    // dropped frames and reads the others as it reads them in the whole file. The first such
    // frame ended the track (the sync of the whole video failed), after decoding the file from
    // its start again.
    void tracksPastADamagedStretch()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const NeedleVideo v = onGrain(3, restThenSine, 40.0, 6.0, 120);
        const QString whole = dir.filePath(QStringLiteral("whole.avi")), damaged = dir.filePath(QStringLiteral("damaged.avi"));
        const QString written = writeNeedleVideo(whole, v);
        QVERIFY2(written.isEmpty(), qPrintable(written));
        // Frames 60-71 (2.0 s to 2.37 s), one JPEG picture each.
        QCOMPARE(nb::test::writeScratched(whole, damaged, 1.99, 2.38), 12);
        const std::optional<nb::video::FrameIndex> fromPackets = nb::video::buildFrameIndexFromPackets(damaged);
        QVERIFY(fromPackets);
        QCOMPARE(fromPackets->size(), v.frames);

        const nb::video::NeedleAxis drawn(QPointF(10.0, kHeight / 2.0), QPointF(kWidth - 10.0, kHeight / 2.0));
        nb::video::FrameReader wholeReader(nb::video::buildFrameIndex(whole));
        const nb::video::NeedleTrack reference = nb::video::trackNeedle(wholeReader, drawn);
        nb::video::FrameReader reader(*fromPackets);
        // A damaged frame is said to be one, without decoding the file from its start again.
        QVERIFY_THROWS_EXCEPTION(nb::video::DamagedFrame, reader.read(65));
        QCOMPARE(reader.stats().sequentialResets, 0);
        QCOMPARE(readerFrameAfter(reader, 72), 72);
        // Playback's prefetch passes over the damaged frames (it stopped at the first), and a
        // frame found damaged is said so again at once.
        reader.cache().clear();
        QCOMPARE(reader.fillCache(55, 80), 26 - 12);
        const int grabbed = reader.stats().grabbed;
        QVERIFY_THROWS_EXCEPTION(nb::video::DamagedFrame, reader.read(65));
        QCOMPARE(reader.stats().grabbed, grabbed);
        const nb::video::NeedleTrack track = nb::video::trackNeedle(reader, drawn);
        QCOMPARE(int(track.time_s.size()), v.frames - 12);
        QCOMPARE(track.damaged, 12);  // and said so
        QCOMPARE(track.displacement_px.size(), track.time_s.size());
        int compared = 0, apart = 0;
        for (std::size_t k = 0; k < track.time_s.size(); ++k) {
            const int frame = int(std::lround(track.time_s[k] * 30.0));
            QVERIFY2(frame < 60 || frame > 71, qPrintable(QStringLiteral("frame %1 of the damaged stretch tracked").arg(frame)));
            const double there = reference.displacement_px[std::size_t(frame)], here = track.displacement_px[k];
            if (!std::isfinite(there) || !std::isfinite(here))
                continue;
            ++compared;
            apart += std::abs(here - there) > 0.5;
        }
        qInfo("%d frames read in both, %d of them more than 0.5 px apart", compared, apart);
        QVERIFY2(compared >= v.frames - 12 - 5 && apart <= 2, qPrintable(QStringLiteral("%1 compared, %2 apart").arg(compared).arg(apart)));
    }

private:
    static int readerFrameAfter(nb::video::FrameReader& reader, int n) { return reader.read(n).index; }
};

QTEST_GUILESS_MAIN(TestNeedleTip)
#include "test_needle_tip.moc"
