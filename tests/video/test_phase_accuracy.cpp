// Issue 13's targets for the friction phases on a small matrix drawn at random (the seed is
// printed; NB_ACCURACY_SEED repeats a draw, NB_ACCURACY_SEED=random draws afresh): simulated
// runs through `needlebench simulate`, their imaging video rendered, given a look and encoded
// with the ffmpeg tool, read back with the real decoder. bench/bench_accuracy prints the full
// table.
#include "support/accuracy_seed.h"
#include "video/phase_case_check.h"
#include "video/phase_matrix.h"
#include "video/video_fixtures.h"

#include <QTemporaryDir>
#include <QtTest>


using namespace nb::accuracy;

class TestPhaseAccuracy : public QObject {
    Q_OBJECT

private slots:
    void phasesAgreeWithTheTruth()
    {
        if (!nb::test::haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to encode the videos");
        // CI repeats one draw (its seed drawn at random once, not chosen for the result).
        const unsigned seed = nb::test::accuracySeed(603917u, "phase matrix seed");
        std::mt19937 rng(seed ^ 0x9e3779b9u);
        QTemporaryDir dir;
        const std::vector<PhaseMatrixCase> cases = drawPhaseMatrix(rng, 6, true);
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (!nb::test::caseInShare(i))
                continue;
            const PhaseMatrixOutcome o = runPhaseMatrixCase(cases[i], QStringLiteral(NB_EXECUTABLE), dir.filePath(QStringLiteral("c%1").arg(i)));
            const QString what = cases[i].describe();
            QVERIFY2(o.ok, qPrintable(what + QStringLiteral(": ") + o.problem));
            qInfo("%s: without video %.1f %%, with video %.1f %% (%s)", qPrintable(what), 100 * o.withoutVideo, 100 * o.withVideo,
                  qPrintable(o.videoSource));
            // Issue 13's targets in every case: 80 % without the video, 90 % with it (this draw's
            // closest, liver1's short fast strokes at 0.82 Hz, reads 90.1 %).
            QVERIFY2(o.withoutVideo >= 0.8, qPrintable(what + QStringLiteral(": without video %1").arg(o.withoutVideo)));
            QVERIFY2(o.withVideo >= 0.9, qPrintable(what + QStringLiteral(": with video %1, without %2").arg(o.withVideo).arg(o.withoutVideo)));
        }
    }

    // Cases drawn by bench_accuracy where the picture was misread, kept as they were drawn.
    void slowNeedleInAPoorPicture_data()
    {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<int>("index");
        // 0.2 Hz, never faster than 5 mm/s, a picture that drops and repeats frames: under
        // 1.5 px a frame, the tissue's motion was too unclear to judge frame by frame and the
        // force's phases stood (80.6 %, its a ending 0.27 s early where the force does not
        // change). Read over a few frames, the picture places the end of a.
        QTest::newRow("seed 191679 case 3: dropped and repeated frames") << 191679u << 3;
        // 0.13 Hz with a burnt-in clock and frame counter: at the start of the last stroke the
        // picture read the tissue 0.1 mm backwards while the needle had moved 0.01 mm, took
        // that for the tissue falling behind, and called the whole stroke b1 (84.3 %, the
        // force alone 90.7 %).
        QTest::newRow("seed 660251 case 10: burnt-in counter, slow strokes") << 660251u << 10;
        // 0.10 Hz, a picture that drops and repeats frames: in the last stroke the tissue floats
        // in the plate gap, carried. Two readings in a row read it falling behind, but they
        // were summed over the same repeated frame, and the stroke became b1 for 1.5 s (89.8 %).
        QTest::newRow("seed 608326 case 17: repeated frames, tissue carried to the end") << 608326u << 17;
    }

    void slowNeedleInAPoorPicture()
    {
        checkDrawnRow([](const PhaseMatrixCase& d) { return d.frequency_hz < 0.21; });
    }

    // Drawn by bench_accuracy --seed 608326 (case 21): liver5 at 0.13 Hz, a blurred picture with
    // little texture. Its noise (0.57 mm/s) is above what the slow needle moves it, so not one
    // reading is clear where the force is plain, and the picture could not be checked. It was
    // trusted all the same (fewer than ten checks counted as no objection), read the carried
    // tissue as resting and cut phase a short: 73.3 % with the video, 92.1 % without.
    void uncheckedPictureLeavesTheForce()
    {
        checkDrawnCase(608326u, 21, [](const PhaseMatrixCase& d) { return d.frequency_hz < 0.2; }, QStringLiteral("too unclear to judge"));
    }

    // Drawn by bench_accuracy --seed 424242 (case 20): liver3 at 0.99 Hz, a blurred picture with
    // little texture coded as H.264, 1.5 px/mm. The picture is blind to the tissue's motion: it
    // read it at rest in the force's every a (none of 19 readings carried), never impossible, and
    // was trusted; it cut every a short (74.3 % with the video, 94.6 % without).
    void blindPictureLeavesTheForce()
    {
        checkDrawnCase(424242u, 20, [](const PhaseMatrixCase& d) { return d.look == Look::Plain && d.frequency_hz > 0.95; },
                       QStringLiteral("too unclear to judge"));
    }

    // Drawn by bench_accuracy --seed 31337 (case 4): liver1 at 0.49 Hz, ±4.1 mm over a 2.77 mm
    // plate gap, a picture too noisy to judge, so the force decides. The tissue is carried
    // across the plate's soft part and breaks away only on the stiff part; the force's a ended
    // where it touched the plate, 120 ms early each withdrawal (85.3 %).
    void carriedAcrossTheSoftPart()
    {
        checkDrawnCase(31337u, 4, [](const PhaseMatrixCase& d) { return d.plateGap_mm > 0.65 * d.amplitude_mm && d.look == Look::NoisyLowContrast; },
                       QStringLiteral("too unclear to judge"));
    }

    // Cases drawn by bench_accuracy where the tissue slides only for the last few frames of
    // a stroke, while the needle slows into its turning point and moves the picture too
    // little to tell a tissue at rest from one carried. The picture's "kept up throughout"
    // overruled the force's c there (89.5 % and 88.8 % with video).
    void shortSlideAtTheTurn_data()
    {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<int>("index");
        // 0.96 Hz, ±4.0 mm over a 2.92 mm plate gap: c lasts 44 ms a stroke.
        QTest::newRow("seed 551053 case 18: gap 2.92 of 4.0 mm, burnt-in counter, DV") << 551053u << 18;
        // 0.42 Hz, ±4.2 mm over a 2.95 mm plate gap, the picture turned 90 degrees.
        QTest::newRow("seed 77819 case 11: gap 2.95 of 4.2 mm, turned picture, H.264") << 77819u << 11;
    }

    void shortSlideAtTheTurn()
    {
        checkDrawnRow([](const PhaseMatrixCase& d) { return d.plateGap_mm > 0.65 * d.amplitude_mm; });
    }

    // Drawn by bench_accuracy --seed 66063 (case 16): liver7 at 0.75 Hz, a picture that drops
    // and repeats frames, coded as H.264 with B-frames. A repeated picture came out of the coder
    // as a B-frame near the one before, not the same: read as a picture, it stopped the tissue
    // for a frame, and the picture cut a stroke's a to 28 ms where the force had it whole (with
    // the video 90.5 %, without 95.6 %). A picture must not place the phases worse than the
    // force alone did here.
    void repeatsCodedAgain()
    {
        checkDrawnCase(66063u, 16, [](const PhaseMatrixCase& d) { return d.look == Look::VariableRate && d.codec == Codec::H264; },
                       QStringLiteral("suggested from the tissue's motion"), {}, 0.02);
    }
};

QTEST_GUILESS_MAIN(TestPhaseAccuracy)
#include "test_phase_accuracy.moc"
