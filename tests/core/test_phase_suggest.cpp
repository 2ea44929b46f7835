// Suggested friction phases against the simulator's truth (models.md 5): runs of the
// simulated friction platform made by `needlebench simulate`, their phase and tissue columns
// hidden from the suggestion, the suggestion compared sample by sample. With a tissue motion
// (as the imaging video gives it, here from the simulator's tissue column at 30 frames/s) the
// video's reading decides where it disagrees with the force.
#include "core/label_suggest.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "support/needlebench_cli.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

struct Simulated {
    nb::Run blind;                  // what a lab has
    std::vector<QString> truth;     // the simulator's phase per sample
    std::vector<double> tissue_mm;  // the simulator's tissue position per sample
};

Simulated simulate(const QString& dir, const QStringList& args)
{
    Simulated s;
    const QString path = QDir(dir).filePath(QStringLiteral("run%1.csv").arg(qHash(args.join(QLatin1Char(' ')))));
    // The same arguments make the same run again (--overwrite: the file is named by them).
    const nbtest::CliResult r = nbtest::runCli(QStringList{QStringLiteral("simulate"), QStringLiteral("--overwrite"), QStringLiteral("--protocol"),
                                                           QStringLiteral("friction"), QStringLiteral("--out"), path} + args);
    if (r.code != 0)
        qFatal("simulate failed: %s", qPrintable(r.err));
    s.blind = nb::readRunFile(path).run;
    s.truth = *s.blind.textColumn(QStringLiteral("phase"));
    s.tissue_mm = *s.blind.numericColumn(QStringLiteral("tissue_position_mm"));
    auto& text = s.blind.text;
    text.erase(std::remove_if(text.begin(), text.end(), [](const auto& c) { return c.first == QLatin1String("phase"); }), text.end());
    auto& numeric = s.blind.numeric;
    numeric.erase(std::remove_if(numeric.begin(), numeric.end(), [](const auto& c) { return c.first == QLatin1String("tissue_position_mm"); }),
                  numeric.end());
    return s;
}

double agreement(const Simulated& s, const nb::Labels& labels)
{
    const QStringList suggested = nb::phasePerSample(labels, s.blind.time_s);
    int agree = 0, counted = 0;
    for (std::size_t i = 0; i < s.truth.size(); ++i) {
        if (s.truth[i].isEmpty())
            continue;
        ++counted;
        agree += suggested.value(qsizetype(i)) == s.truth[i];
    }
    return counted ? double(agree) / counted : 0.0;
}

// Each true start of c after the first half second (the needle jumping to speed from rest),
// against the suggested start of c nearest it: suggested minus true, in seconds.
std::vector<double> cStartErrors_s(const Simulated& s, const nb::Labels& labels)
{
    std::vector<double> errors;
    for (std::size_t i = 1; i < s.truth.size(); ++i) {
        if (s.truth[i] != QLatin1String("c") || s.truth[i - 1] == QLatin1String("c") || s.truth[i - 1].isEmpty() || s.blind.time_s[i] < 0.5)
            continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (const nb::Label& l : labels)
            if (l.label == QLatin1String("c") && std::abs(l.start_s - s.blind.time_s[i]) < std::abs(nearest))
                nearest = l.start_s - s.blind.time_s[i];
        errors.push_back(nearest);
    }
    return errors;
}

// The tissue's velocity as a 30 frames/s picture would give it: one value per pair of frames.
nb::TissueMotion fromFrames(const Simulated& s, const QString& name)
{
    nb::TissueMotion m;
    m.source = name;
    m.px_per_mm = 6.0;
    const double dt = 1.0 / 30.0;
    auto at = [&](double t) {
        const auto& ts = s.blind.time_s;
        const std::size_t i = std::min(ts.size() - 1, std::size_t(std::lower_bound(ts.begin(), ts.end(), t) - ts.begin()));
        return s.tissue_mm[i];
    };
    for (double t = s.blind.time_s.front(); t + dt <= s.blind.time_s.back(); t += dt) {
        m.time_s.push_back(t + dt / 2);
        m.velocity_mm_s.push_back((at(t + dt) - at(t)) / dt);
    }
    return m;
}

}  // namespace

class TestPhaseSuggest : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    // Three runs of different tissues, speeds, bands and plate gaps (chosen to span the
    // platform, not for the result): force and position alone agree on 80 % of samples
    // (issue 13's target without video).
    void fromForceAndPosition_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<bool>("everyPhase");  // b2 may be too short to be told from b1 by the force
        QTest::newRow("liver7 0.5 Hz") << QStringList{"--tissue", "liver7", "--frequency-hz", "0.5", "--cycles", "3"} << true;
        QTest::newRow("liver3 0.3 Hz wide band") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.3", "--cycles", "2", "--stick-band-mm-s", "4.5",
                                                                "--amplitude-mm", "7"} << true;
        QTest::newRow("liver1 0.8 Hz small gap, noisy") << QStringList{"--tissue", "liver1", "--frequency-hz", "0.8", "--cycles", "3", "--plate-gap-mm",
                                                                       "0.7", "--force-noise-n", "0.008"} << true;
        // Wide stick bands and large plate gaps with short strokes: the needle is barely faster
        // than the band, the last stroke stops mid-way with the tissue still carried (both
        // below 80 % before the sliding line left out the break-away peaks).
        QTest::newRow("liver5 0.8 Hz wide band, large gap") << QStringList{"--tissue", "liver5", "--frequency-hz", "0.82", "--cycles", "3",
                                                                           "--amplitude-mm", "5", "--stick-band-mm-s", "4.2", "--plate-gap-mm", "2.45"}
                                                            << false;
        QTest::newRow("liver1 0.8 Hz band 5.6, large gap") << QStringList{"--tissue", "liver1", "--frequency-hz", "0.78", "--cycles", "3",
                                                                          "--amplitude-mm", "4.4", "--stick-band-mm-s", "5.6", "--plate-gap-mm", "2.56"}
                                                           << false;
        // A plate gap nearly as wide as the stroke: the tissue is carried across it at speed
        // (its force near zero) and slides only near the turning points; the sliding line was
        // drawn through the carried samples and the carrying read as c (46 % in
        // bench_accuracy --seed 77819, phase case 11).
        QTest::newRow("liver3 0.42 Hz gap 2.95 of 4.2 mm") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.4162", "--cycles", "4",
                                                                          "--amplitude-mm", "4.206", "--stick-band-mm-s", "4.0", "--plate-gap-mm",
                                                                          "2.95", "--force-noise-n", "0.001", "--seed", "751"}
                                                           << false;
    }
    void fromForceAndPosition()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, everyPhase);
        const Simulated s = simulate(dir_.path(), args);
        const nb::Labels labels = nb::suggestLabels(s.blind);
        const double a = agreement(s, labels);
        QVERIFY2(a >= 0.8, qPrintable(QStringLiteral("agreement %1").arg(a)));
        // Every phase of the four appears, and each label says what it came from.
        for (const char* p : {"a", "b1", "b2", "c"})
            if (everyPhase || QLatin1String(p) != QLatin1String("b2"))
                QVERIFY2(std::any_of(labels.begin(), labels.end(), [&](const nb::Label& l) { return l.label == QLatin1String(p); }), p);
        for (const nb::Label& l : labels) {
            QVERIFY(l.track == QLatin1String("insertion") || l.track == QLatin1String("withdrawal"));
            QCOMPARE(l.comment, QStringLiteral("suggested from force and position"));
        }
        // The phases tile the run to its end (the rest after the last stroke included).
        QCOMPARE(labels.back().end_s, s.blind.time_s.back());
    }

    // Runs whose force misled the suggestion once, each as it was found; without a video.
    void hardRunsFromForceAlone_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<double>("wanted");
        // Fast strokes: the tissue meets the plate at speed, and the force jumps from its low
        // level in a to static friction, holds there while the tissue slips over the plate's soft
        // part (b1), drops back and closes on the sliding line (c). The drop was taken for the end
        // of a, so every b1 read as a.
        // A small plate gap (89.7 % in bench_accuracy --seed 660251, phase case 21; 89.9 % and
        // 90.0 % in two more cases of that kind; this run 89.8 % before the hold was read).
        QTest::newRow("liver1 0.75 Hz gap 1.08") << QStringList{"--tissue", "liver1", "--frequency-hz", "0.749", "--cycles", "4", "--amplitude-mm", "5.017",
                                                                "--stick-band-mm-s", "2.8", "--plate-gap-mm", "1.08", "--force-noise-n", "0.0007",
                                                                "--seed", "150"}
                                                 << 0.93;
        // Faster still (25 mm/s): static friction lies below the sliding line at that speed,
        // and a hold at it was only read above the line (89.6 % in bench_accuracy --seed
        // 191679, phase case 4, where the blurred picture is too unclear to judge; this run
        // 89.6 % before).
        QTest::newRow("liver3 0.93 Hz gap 2.81") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.9331", "--cycles", "4", "--amplitude-mm", "4.392",
                                                                "--stick-band-mm-s", "2.65", "--plate-gap-mm", "2.81", "--force-noise-n", "0.0009",
                                                                "--seed", "572"}
                                                 << 0.92;
        // A wide stick band (5.5 mm/s) and a needle at most twice as fast: the force breaks away
        // at full speed, slides, and is held at static friction again once the needle slows into
        // the band, long before the turning point. The sliding line was drawn as an upper
        // envelope, which those peaks and that hold pulled up: c then showed only near the turning
        // point (83.4 % and 91.4 % on the old code; bench_accuracy --seed 634001 phase cases 4
        // and 21 are of this kind, 83.4 % and 82.3 %).
        QTest::newRow("liver1 0.35 Hz band 5.58, small gap")
            << QStringList{"--tissue", "liver1", "--frequency-hz", "0.3516", "--amplitude-mm", "4.642", "--stick-band-mm-s", "5.58",
                           "--plate-gap-mm", "1.17", "--force-noise-n", "0.0016", "--cycles", "4", "--seed", "814"} << 0.93;
        QTest::newRow("liver3 0.34 Hz band 5.55, large gap, noisy")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.3385", "--amplitude-mm", "4.882", "--stick-band-mm-s", "5.55",
                           "--plate-gap-mm", "2.89", "--force-noise-n", "0.0067", "--cycles", "4", "--seed", "569"} << 0.93;
        // A needle that never leaves the stick band (top speed 5.3 and 5.4 mm/s, band ±5.8 and
        // ±5.65): once the tissue meets the plate the force is held at static friction, flat, and
        // dips for a moment each time the tissue sticks again against the plate. The search for a
        // sliding line found the rise to the plate (C < 0) and labelled whole strokes c (63.8 %),
        // or read each dip as the end of c (71.4 %). Both from random draws over the command line
        // (simulate, labels suggest), the second with a tissue bench_accuracy's matrix leaves out.
        QTest::newRow("liver1 0.155 Hz band 5.79")
            << QStringList{"--tissue", "liver1", "--frequency-hz", "0.155", "--amplitude-mm", "5.44", "--stick-band-mm-s", "5.79",
                           "--plate-gap-mm", "1.66", "--cycles", "3", "--seed", "913749"} << 0.9;
        QTest::newRow("prostate 0.166 Hz band 5.65")
            << QStringList{"--tissue", "prostate", "--frequency-hz", "0.166", "--amplitude-mm", "5.15", "--stick-band-mm-s", "5.65",
                           "--plate-gap-mm", "0.8", "--cycles", "3", "--seed", "228564"} << 0.9;
        // Held so, the force also dips for 50 ms to 38 % of its level every 0.2-0.4 s, the tissue
        // sticking again for a moment; the deepest dip ended c there, 1.9 s late in each
        // withdrawal (80.1 %; liver3 at 0.08 Hz, random draw at the matrix's edge, seed 9306
        // case 16).
        QTest::newRow("liver3 0.081 Hz band 5.34, dips while held")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.0814", "--amplitude-mm", "8.1776", "--plate-gap-mm", "0.3808",
                           "--stick-band-mm-s", "5.3373", "--force-noise-n", "0.0056", "--thickness-mm", "34.2039", "--cycles", "2",
                           "--seed", "406378"} << 0.9;
        // A thin slab of a heavy lobe (19 and 12 mm, 0.69 kg): its sliding force is small beside
        // the plate's losses, so as the tissue leaves the plate behind at a turning point the
        // force dips almost to the sliding line of the new direction, then stays low while the
        // tissue is carried. The dip was read as a hold at static friction where the tissue meets
        // the plate ahead (the force before it, the other direction's push, counted as the low
        // level that must come first), and a ended at the dip: 74.1 % and 73.1 %. bench_accuracy's
        // matrix keeps the slab at 30 mm; these come from random draws of thickness on the command
        // line.
        QTest::newRow("liver2 19.2 mm") << QStringList{"--tissue", "liver2", "--frequency-hz", "0.447", "--amplitude-mm", "8.88", "--thickness-mm", "19.2",
                                                       "--stick-band-mm-s", "2.55", "--seed", "174949"} << 0.9;
        QTest::newRow("liver7 12.3 mm") << QStringList{"--tissue", "liver7", "--frequency-hz", "0.436", "--amplitude-mm", "9.89", "--thickness-mm", "12.3",
                                                       "--stick-band-mm-s", "5.14", "--plate-gap-mm", "2.0", "--cycles", "4", "--seed", "856189"} << 0.9;
        // A thin slab (10.4 mm) at 0.95 Hz: in c the force lies a little above the sliding line
        // as the needle slows to its turning point, and falls with it; that fall was read as the
        // break-away after a peak, and c started a quarter of a second late in two strokes of
        // four (78.1 %; bench_accuracy --seed 730265 --phase-thickness-mm 10:30, phase case 13,
        // whose blurred picture is too unclear to judge; 89.5 % since).
        QTest::newRow("liver3 10.4 mm 0.95 Hz") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.9532", "--amplitude-mm", "7.408", "--thickness-mm", "10.41",
                                                               "--stick-band-mm-s", "2.1", "--plate-gap-mm", "0.57", "--force-noise-n", "0.0013", "--cycles", "4",
                                                               "--seed", "248"} << 0.85;
        // Thin slabs that creep into the plate's soft part for a tenth of a second and more
        // after the force is back near the sliding line (b1 there, then c): c was read from the
        // force's return and the creep as b2. 79.4 % and 82.7 %; bench_accuracy --seed 225405
        // and 543574 --phase-thickness-mm 10:30, phase cases 19 and 8, pictures too unclear to
        // judge. 90.3 % and 93.3 % with the creep read as one settling.
        QTest::newRow("liver5 13.9 mm 0.55 Hz") << QStringList{"--tissue", "liver5", "--frequency-hz", "0.5451", "--amplitude-mm", "4.951", "--thickness-mm", "13.88",
                                                               "--stick-band-mm-s", "3.0", "--plate-gap-mm", "0.78", "--force-noise-n", "0.0024", "--cycles", "4",
                                                               "--seed", "978"} << 0.87;
        QTest::newRow("liver7 12.1 mm 0.49 Hz") << QStringList{"--tissue", "liver7", "--frequency-hz", "0.4893", "--amplitude-mm", "4.109", "--thickness-mm", "12.11",
                                                               "--stick-band-mm-s", "1.0", "--plate-gap-mm", "1.33", "--force-noise-n", "0.0076", "--cycles", "4",
                                                               "--seed", "692"} << 0.88;
        // The same creep, on a fast short stroke whose tissue sticks to the needle again before the
        // turning point (the force jumps back above the line): the settling fitted up to the
        // turning point bent its level to that jump, found no creep, and c started where the
        // force first came back to the line, 0.1 s early in every stroke (78.8 %; random draw at
        // short reach, seed 9502 case 29). The creep is fitted up to the jump.
        QTest::newRow("liver2 12.4 mm 0.80 Hz, stuck again before the turn")
            << QStringList{"--tissue", "liver2", "--frequency-hz", "0.7962", "--amplitude-mm", "3.8632", "--plate-gap-mm", "1.7650",
                           "--stick-band-mm-s", "4.4722", "--force-noise-n", "0.0013", "--thickness-mm", "12.4029", "--cycles", "4",
                           "--seed", "890860"} << 0.85;
        // A stroke that reaches little past the plate's soft part: the tissue, still stuck, is
        // carried across it, the soft part's spring pushing back through it, and breaks away only
        // on the stiff part, with a jump to static friction (a, then b2 and c at once). The force
        // rising across the sliding line on the soft part was read as c, and a ended where the
        // tissue touched the plate, 120 ms early each withdrawal (84.7 %; bench_accuracy --seed
        // 31337 phase case 4, 85.3 % with a picture too noisy to judge).
        QTest::newRow("liver1 0.49 Hz reach 1.3 mm past the gap")
            << QStringList{"--tissue", "liver1", "--frequency-hz", "0.4939", "--amplitude-mm", "4.088", "--stick-band-mm-s", "5.2",
                           "--plate-gap-mm", "2.77", "--force-noise-n", "0.0007", "--cycles", "4", "--seed", "16"} << 0.93;
        // The same where the needle stays inside the stick band once the tissue has broken away:
        // the sliding line found is static friction itself, flat, and the jump to it does not
        // stand above it. The rise over the soft part was read as b1 (89.4 %; a random draw over
        // the command line, seed 9191, case 6).
        QTest::newRow("liver1 0.22 Hz reach 1.4 mm past the gap, band 3.8")
            << QStringList{"--tissue", "liver1", "--frequency-hz", "0.2233", "--amplitude-mm", "4.042", "--stick-band-mm-s", "3.77",
                           "--plate-gap-mm", "2.657", "--force-noise-n", "0.0011", "--cycles", "3", "--seed", "567933"} << 0.915;
        // Not where the tissue slid over the soft part at the needle's top speed (36 mm/s), its
        // sliding force above static friction and rising to the stiff part's jump: that was b1
        // (94.9 %, 93.5 % when read as carried; bench_accuracy --seed 9001 phase case 22).
        QTest::newRow("liver3 0.83 Hz b1 at top speed")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.8252", "--amplitude-mm", "7.046", "--stick-band-mm-s", "3.4",
                           "--plate-gap-mm", "2.84", "--force-noise-n", "0.0008", "--cycles", "4", "--seed", "778"} << 0.945;
        // Nor where liver 3's sliding force, above static friction at speed, rose over the soft
        // part onto the sliding line and the stiff part's jump landed on the line (94.6 %, 91.3 %
        // when read as carried; bench_accuracy --seed 777 phase case 2).
        QTest::newRow("liver3 0.95 Hz b1 onto the line")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.9466", "--amplitude-mm", "4.545", "--stick-band-mm-s", "3.5",
                           "--plate-gap-mm", "2.12", "--force-noise-n", "0.0026", "--cycles", "4", "--seed", "852"} << 0.94;
        // The run's first stroke, from the centre, reaches only the plate's soft part: the tissue
        // is never released, and the force never comes near static friction, which the whole
        // strokes reach. The soft part's push, near the sliding line, was read as c for most of
        // the stroke (88.7 % and 82.9 %; random draws over the command line, seeds 9191 and
        // 5353, cases 34 and 9).
        QTest::newRow("liver2 0.59 Hz first stroke carried")
            << QStringList{"--tissue", "liver2", "--frequency-hz", "0.5911", "--amplitude-mm", "4.061", "--stick-band-mm-s", "2.16",
                           "--plate-gap-mm", "2.944", "--force-noise-n", "0.0027", "--cycles", "3", "--seed", "835237"} << 0.93;
        QTest::newRow("liver5 0.62 Hz first stroke carried, noisy")
            << QStringList{"--tissue", "liver5", "--frequency-hz", "0.6183", "--amplitude-mm", "4.218", "--stick-band-mm-s", "1.12",
                           "--plate-gap-mm", "2.998", "--force-noise-n", "0.0071", "--cycles", "3", "--seed", "408029"} << 0.88;
        // A thin slab at a fast start slides for 90 ms before friction has brought it up to the
        // needle's speed, longer than the start's first 50 ms: the first stroke, carried after
        // that (its force the slab's inertia), was read as c for most of it (77.6 % and 79.1 %;
        // random draws at short reach, seeds 4717 case 39 and 4716 case 37).
        QTest::newRow("prostate 13 mm 0.82 Hz, long start")
            << QStringList{"--tissue", "prostate", "--frequency-hz", "0.8165", "--amplitude-mm", "5.077", "--plate-gap-mm", "3.829",
                           "--stick-band-mm-s", "3.94", "--force-noise-n", "0.0027", "--thickness-mm", "13.0", "--cycles", "3",
                           "--seed", "999369"} << 0.83;
        QTest::newRow("liver5 11 mm 0.55 Hz, long start")
            << QStringList{"--tissue", "liver5", "--frequency-hz", "0.5462", "--amplitude-mm", "4.738", "--plate-gap-mm", "3.821",
                           "--stick-band-mm-s", "1.67", "--force-noise-n", "0.0008", "--thickness-mm", "11.4", "--cycles", "3",
                           "--seed", "979228"} << 0.85;
        // A plate gap nearly as wide as the stroke (reach 0.9 mm past it): the slab is carried
        // across it, meets the plate near the turning point and is taken back before it breaks
        // away, or slides for a moment. The force follows no sliding line; the fit's, with C
        // below zero, read most of each stroke as c (17.7 % and 66.2 %; random draws over the
        // command line at short reach, seed 4711, cases 30 and 8).
        QTest::newRow("liver5 0.33 Hz gap 8.6 mm of 9.6")
            << QStringList{"--tissue", "liver5", "--frequency-hz", "0.3281", "--amplitude-mm", "9.556", "--plate-gap-mm", "8.636",
                           "--stick-band-mm-s", "3.00", "--force-noise-n", "0.0020", "--thickness-mm", "39.6", "--cycles", "3",
                           "--seed", "871733"} << 0.95;
        QTest::newRow("liver3 0.81 Hz gap 3.9 mm of 4.8")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.8111", "--amplitude-mm", "4.769", "--plate-gap-mm", "3.910",
                           "--stick-band-mm-s", "4.35", "--force-noise-n", "0.0046", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "616232"} << 0.97;
        // One direction never slid, and the other's "line" is a level: the force held at static
        // friction against the plate near the turning point, read as c (65.8 % and 50.2 %; random
        // draws at short reach and at the matrix's edge, seeds 4713 case 1 and 6060 case 32).
        QTest::newRow("prostate 0.40 Hz gap 5.1 mm of 6.1, a level one way")
            << QStringList{"--tissue", "prostate", "--frequency-hz", "0.3997", "--amplitude-mm", "6.147", "--plate-gap-mm", "5.051",
                           "--stick-band-mm-s", "3.54", "--force-noise-n", "0.0011", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "604811"} << 0.92;
        QTest::newRow("liver3 0.18 Hz gap 2.8 mm of 4.1, a level one way")
            << QStringList{"--tissue", "liver3", "--frequency-hz", "0.1821", "--amplitude-mm", "4.127", "--plate-gap-mm", "2.822",
                           "--stick-band-mm-s", "2.09", "--force-noise-n", "0.0006", "--thickness-mm", "34.8", "--cycles", "3",
                           "--seed", "181063"} << 0.82;
        // The slab pressed on the plate's soft part and taken back without ever sliding (a plate
        // gap 0.9 mm short of the stroke): the plate's push and its losses, a spring and a
        // damper, drew a "line" through the force, read as c from where the push began (76.5 %
        // and 76.7 %; random draws at short reach, seeds 4712 case 19 and 4716 case 18). The
        // push ends coming out at the depth where it began going in: no slide in between.
        QTest::newRow("liver5 0.28 Hz gap 2.4 mm of 3.4, never slid")
            << QStringList{"--tissue", "liver5", "--frequency-hz", "0.2811", "--amplitude-mm", "3.356", "--plate-gap-mm", "2.425",
                           "--stick-band-mm-s", "3.31", "--force-noise-n", "0.0034", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "626711"} << 0.90;
        QTest::newRow("liver2 0.64 Hz gap 2.3 mm of 3.2, never slid")
            << QStringList{"--tissue", "liver2", "--frequency-hz", "0.6350", "--amplitude-mm", "3.172", "--plate-gap-mm", "2.263",
                           "--stick-band-mm-s", "4.12", "--force-noise-n", "0.0014", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "530634"} << 0.90;
        // One direction carried all the way to the plate and taken back before it slides (a
        // gap 5.7 mm of a 7.1 mm stroke, a thin heavy slab): the slab's inertia, pulling ahead as
        // the needle speeds up and holding back as it slows, drew a line rising with speed from
        // below zero (C −0.17 ± 0.03 N, b above two standard errors), read as sliding: c from
        // mid-stroke on (62.4 %; random draw at short reach, seed 9503 case 15). A C clearly
        // below zero is no sliding, whatever b does.
        QTest::newRow("liver5 0.68 Hz gap 5.7 mm of 7.1, carried one way")
            << QStringList{"--tissue", "liver5", "--frequency-hz", "0.6765", "--amplitude-mm", "7.0525", "--plate-gap-mm", "5.7194",
                           "--stick-band-mm-s", "4.8859", "--force-noise-n", "0.0036", "--thickness-mm", "10.3534", "--cycles", "4",
                           "--seed", "138564"} << 0.85;
        // Not where the slab, thrown back off the plate at a fast reversal, slipped back about as
        // far as it had slid in: the push ends 0.1 mm (4.6 % of its reach) from where it began
        // (liver2 at 0.95 Hz, 55 mm/s; seed 4713 case 28: 90.9 %, 89.3 % read as never slid).
        QTest::newRow("liver2 0.95 Hz slid in and slipped back")
            << QStringList{"--tissue", "liver2", "--frequency-hz", "0.9529", "--amplitude-mm", "9.584", "--plate-gap-mm", "7.838",
                           "--stick-band-mm-s", "1.60", "--force-noise-n", "0.0027", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "874728"} << 0.90;
        // Not where the force does follow a line, however briefly the tissue slides and however
        // undetermined the fit's C and b (prostate at 0.11 Hz, reach 2 mm past the gap: 95.6 %,
        // 81.9 % when the withdrawals were read as carried; seed 9191 at the matrix's edge, case 29).
        QTest::newRow("prostate 0.11 Hz brief sliding")
            << QStringList{"--tissue", "prostate", "--frequency-hz", "0.1097", "--amplitude-mm", "4.907", "--plate-gap-mm", "2.937",
                           "--stick-band-mm-s", "2.46", "--force-noise-n", "0.0024", "--thickness-mm", "30.0", "--cycles", "3",
                           "--seed", "951344"} << 0.94;
        // Strokes shorter than the plate's gap: the slab is carried all along (a), and the force
        // is its inertia and noise, the same going in and out at each depth. Lines drawn
        // through that noise labelled a third to a half of the run c (53.0 % and 56.7 %; a
        // helper's random draw, seed 507056, cases 3 and 4, outside bench_accuracy's strokes).
        QTest::newRow("prostate 1.9 mm stroke, gap 3.6")
            << QStringList{"--tissue", "prostate", "--tip", "blunt", "--frequency-hz", "0.584", "--amplitude-mm", "1.91", "--cycles", "2",
                           "--thickness-mm", "34.9", "--stick-band-mm-s", "0.83", "--plate-gap-mm", "3.61", "--force-noise-n", "0.0031",
                           "--rate-hz", "2000", "--seed", "683962"} << 0.95;
        QTest::newRow("liver5 1.5 mm stroke, gap 3.2, noisy")
            << QStringList{"--tissue", "liver5", "--tip", "diamond", "--frequency-hz", "0.834", "--amplitude-mm", "1.54", "--cycles", "3",
                           "--thickness-mm", "16.3", "--stick-band-mm-s", "1.6", "--plate-gap-mm", "3.21", "--force-noise-n", "0.0157",
                           "--rate-hz", "500", "--seed", "751299"} << 0.95;
    }
    void hardRunsFromForceAlone()
    {
        QFETCH(QStringList, args);
        QFETCH(double, wanted);
        const Simulated s = simulate(dir_.path(), args);
        const double a = agreement(s, nb::suggestLabels(s.blind));
        QVERIFY2(a >= wanted, qPrintable(QStringLiteral("agreement %1").arg(a)));
    }

    // A stroke slower than the thesis's ±2.5 mm/s band (±1 mm at 0.39 Hz tops at 2.4 mm/s)
    // still turns: one label per stroke, each on the track of its direction. It was one
    // insertion label over all six cycles.
    void slowStrokesStillTurn()
    {
        const Simulated s = simulate(dir_.path(), {"--tissue", "liver1", "--tip", "blunt", "--frequency-hz", "0.386", "--amplitude-mm", "1.0", "--cycles", "6",
                                                   "--thickness-mm", "11.2", "--plate-gap-mm", "2.61", "--stick-band-mm-s", "1.81",
                                                   "--force-noise-n", "0.0034", "--seed", "21980"});
        const nb::Labels labels = nb::suggestLabels(s.blind);
        int in = 0, out = 0;
        for (const nb::Label& l : labels) {
            QCOMPARE(l.label, QStringLiteral("a"));
            in += l.track == QLatin1String("insertion");
            out += l.track == QLatin1String("withdrawal");
        }
        QVERIFY2(in >= 6 && out >= 6, qPrintable(QStringLiteral("%1 insertion and %2 withdrawal labels").arg(in).arg(out)));
        QVERIFY(agreement(s, labels) > 0.99);
    }

    // With the tissue's motion, the labels say so, and agree at least as well.
    void withTissueMotion()
    {
        const Simulated s = simulate(dir_.path(), {"--tissue", "liver5", "--frequency-hz", "0.6", "--cycles", "3", "--plate-gap-mm", "2"});
        const nb::TissueMotion m = fromFrames(s, QStringLiteral("scan.avi"));
        const nb::Labels labels = nb::suggestPhaseLabels(s.blind, &m);
        const double with = agreement(s, labels), without = agreement(s, nb::suggestLabels(s.blind));
        QVERIFY2(with >= 0.9, qPrintable(QStringLiteral("with %1, without %2").arg(with).arg(without)));
        int fromVideo = 0;
        for (const nb::Label& l : labels)
            fromVideo += l.comment.contains(QStringLiteral("scan.avi"));
        QVERIFY(fromVideo >= 4);
    }

    // The force places c too early where the tissue is carried across a gap nearly as wide as
    // the stroke, so a clear picture disagrees with it on one reading in eight. It is trusted
    // all the same, since every clear reading is one the tissue can give (carried or at rest),
    // and moves those boundaries (81 % -> 86 %: the picture cannot follow the needle's slow
    // end of each stroke, where the tissue meets the plate and comes to rest); a garbled picture (the same readings with the sign of
    // every other one turned) is not trusted and leaves the force's phases as they are.
    void clearPictureCorrectsForce()
    {
        const Simulated s = simulate(dir_.path(), {"--tissue", "liver3", "--frequency-hz", "0.4162", "--cycles", "4", "--amplitude-mm", "4.206",
                                                   "--stick-band-mm-s", "4.0", "--plate-gap-mm", "2.95", "--force-noise-n", "0.001", "--seed", "751"});
        const nb::TissueMotion m = fromFrames(s, QStringLiteral("wide.avi"));
        const nb::Labels labels = nb::suggestPhaseLabels(s.blind, &m);
        const double with = agreement(s, labels), without = agreement(s, nb::suggestLabels(s.blind));
        QVERIFY2(with > without + 0.05, qPrintable(QStringLiteral("with %1, without %2").arg(with).arg(without)));
        QVERIFY(std::any_of(labels.begin(), labels.end(), [](const nb::Label& l) { return l.comment.startsWith(QStringLiteral("suggested from the tissue's motion in wide.avi")); }));
        nb::TissueMotion garbled = m;
        for (std::size_t k = 0; k < garbled.velocity_mm_s.size(); k += 2)
            garbled.velocity_mm_s[k] = -garbled.velocity_mm_s[k];
        const nb::Labels fromGarbled = nb::suggestPhaseLabels(s.blind, &garbled);
        QCOMPARE(nb::phasePerSample(fromGarbled, s.blind.time_s), nb::phasePerSample(nb::suggestLabels(s.blind), s.blind.time_s));
        QVERIFY2(fromGarbled.front().comment.contains(QStringLiteral("to judge")), qPrintable(fromGarbled.front().comment));
        // Nor is a picture blind to the motion: the tissue read at rest throughout is never one
        // it cannot give, and agrees with the force's every c, but with none of its a (a blurred
        // picture with little texture read so, and cut every a short: bench_accuracy --seed 424242,
        // phase case 20).
        nb::TissueMotion blind = m;
        std::fill(blind.velocity_mm_s.begin(), blind.velocity_mm_s.end(), 0.0);
        const nb::Labels fromBlind = nb::suggestPhaseLabels(s.blind, &blind);
        QCOMPARE(nb::phasePerSample(fromBlind, s.blind.time_s), nb::phasePerSample(nb::suggestLabels(s.blind), s.blind.time_s));
        QVERIFY2(fromBlind.front().comment.contains(QStringLiteral("to judge")), qPrintable(fromBlind.front().comment));
    }

    // A thin slab creeps into the plate's soft part after it meets it, at a tenth to a third of
    // the needle's speed for several frames, while the force is already back near the sliding
    // line: short of it only by b times the creep's speed. Read sample by sample, the force
    // and the picture both started c more than a frame early (the force 1.2 to 3.2 frames in
    // these rows until it read the creep as one settling too). Read as one settling, each places
    // c where the slab is at rest (slower than a twentieth of the needle): the picture within a
    // frame and a half on average, the force alone within a frame; and the creep is b1, the slab
    // pressing the plate's soft part. Rows: thin slabs in that regime.
    void thinSlabSettlingOnThePlate_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("liver1 12 mm 0.5 Hz") << QStringList{"--tissue", "liver1", "--thickness-mm", "12", "--frequency-hz", "0.5", "--amplitude-mm", "6",
                                                            "--stick-band-mm-s", "2", "--plate-gap-mm", "1.5", "--cycles", "4", "--seed", "31"};
        QTest::newRow("liver7 10 mm 0.45 Hz") << QStringList{"--tissue", "liver7", "--thickness-mm", "10", "--frequency-hz", "0.45", "--amplitude-mm", "5",
                                                             "--stick-band-mm-s", "1.5", "--plate-gap-mm", "1.2", "--cycles", "4", "--seed", "33"};
        QTest::newRow("liver2 20 mm 0.3 Hz") << QStringList{"--tissue", "liver2", "--thickness-mm", "20", "--frequency-hz", "0.3", "--amplitude-mm", "7",
                                                            "--stick-band-mm-s", "4", "--plate-gap-mm", "2", "--cycles", "3", "--seed", "34"};
    }
    void thinSlabSettlingOnThePlate()
    {
        QFETCH(QStringList, args);
        const Simulated s = simulate(dir_.path(), args);
        nb::TissueMotion m = fromFrames(s, QStringLiteral("thin.avi"));
        m.px_per_mm = 10.0;  // the imaging view's scale (the rendered view has 8 to 10 px/mm)
        const nb::Labels labels = nb::suggestPhaseLabels(s.blind, &m), fromForce = nb::suggestLabels(s.blind);
        auto cStarts = [](const nb::Labels& ls) {
            std::vector<double> starts;
            for (const nb::Label& l : ls)
                if (l.label == QLatin1String("c"))
                    starts.push_back(l.start_s);
            return starts;
        };
        const std::vector<double> suggestedC = cStarts(labels), forceC = cStarts(fromForce);
        auto nearest = [](const std::vector<double>& starts, double t) {
            double best = std::numeric_limits<double>::infinity();
            for (double x : starts)
                best = std::abs(x - t) < std::abs(best - t) ? x : best;
            return best;
        };
        // Strokes from one turning point to the next: the first starts with the needle jumping to
        // speed from rest, the slab still catching up with it when it meets the plate, and the
        // run ends half-way through the last.
        auto arg = [&](const char* name) { return args.value(args.indexOf(QLatin1String(name)) + 1).toDouble(); };
        const double period_s = 1.0 / arg("--frequency-hz"), firstTurn_s = period_s / 4, lastTurn_s = arg("--cycles") * period_s - period_s / 4;
        int strokes = 0;
        double pictureOff_s = 0.0, forceOff_s = 0.0;
        for (std::size_t i = 1; i < s.truth.size(); ++i) {
            if (s.truth[i] != QLatin1String("c") || s.truth[i - 1] == QLatin1String("c") || s.truth[i - 1].isEmpty() ||
                s.blind.time_s[i] < firstTurn_s || s.blind.time_s[i] > lastTurn_s)
                continue;
            const double t = s.blind.time_s[i];
            ++strokes;
            forceOff_s += std::abs(nearest(forceC, t) - t);
            pictureOff_s += std::abs(nearest(suggestedC, t) - t);
        }
        QVERIFY(strokes >= 4);
        const QString figures = QStringLiteral("c off by %1 s on average, from the force alone %2 s; agreement %3, without the picture %4")
                                    .arg(pictureOff_s / strokes).arg(forceOff_s / strokes).arg(agreement(s, labels)).arg(agreement(s, fromForce));
        QVERIFY2(forceOff_s / strokes <= 1.0 / 30.0, qPrintable(figures));
        QVERIFY2(pictureOff_s / strokes <= 1.5 / 30.0, qPrintable(figures));
        QVERIFY2(agreement(s, labels) >= 0.9 && agreement(s, fromForce) >= 0.9, qPrintable(figures));
        qInfo("%s", qPrintable(figures));
    }

    // A slab that stops within a frame when it meets the plate (a thick one, fast strokes): the
    // tissue carried at the needle's speed up to the stop is fitted by a settling curve of a
    // frame or two that creeps on after it, and the force, a little short of its line there,
    // read a creep of 0.1 mm. Both put c 60 to 80 ms after the stop in most strokes (bench_accuracy
    // --seed 518445 phase case 11: 88.1 % with the video). The frames after the stop show no
    // creep, and c starts where they show the tissue at rest (within half a frame on average,
    // 92.7 %; 41 ms and 88.3 % before). Rows: that case's platform, and a thinner slab of
    // another tissue that was read right and must stay so.
    void stopWithinAFrameIsNoCreep_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("liver3 30 mm 0.81 Hz") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.8052", "--amplitude-mm", "4.189",
                                                             "--stick-band-mm-s", "4.5", "--plate-gap-mm", "1.99", "--force-noise-n", "0.0039",
                                                             "--thickness-mm", "30", "--cycles", "4", "--seed", "1000"};
        QTest::newRow("liver1 25 mm 0.7 Hz") << QStringList{"--tissue", "liver1", "--frequency-hz", "0.7", "--amplitude-mm", "5",
                                                            "--stick-band-mm-s", "3.5", "--plate-gap-mm", "1.8", "--force-noise-n", "0.002",
                                                            "--thickness-mm", "25", "--cycles", "4", "--seed", "77"};
    }
    void stopWithinAFrameIsNoCreep()
    {
        QFETCH(QStringList, args);
        const Simulated s = simulate(dir_.path(), args);
        nb::TissueMotion m = fromFrames(s, QStringLiteral("stop.avi"));
        m.px_per_mm = 7.3;  // the rendered view's scale in that case
        const nb::Labels labels = nb::suggestPhaseLabels(s.blind, &m);
        const std::vector<double> errors = cStartErrors_s(s, labels);
        const int strokes = int(errors.size());
        double off_s = 0.0;
        for (double e : errors)
            off_s += std::abs(e);
        QVERIFY(strokes >= 5);
        const QString figures = QStringLiteral("c off by %1 s on average over %2 strokes; agreement %3").arg(off_s / strokes).arg(strokes).arg(agreement(s, labels));
        qInfo("%s", qPrintable(figures));
        QVERIFY2(off_s / strokes <= 1.0 / 30.0, qPrintable(figures));
        QVERIFY2(agreement(s, labels) >= 0.92, qPrintable(figures));
    }

    // The picture overrules the force where they disagree: in a stroke where the video shows
    // the tissue not moving at all, the needle slides through resting tissue (c) almost
    // from the turning point, whatever the force says.
    void videoOverrulesForce()
    {
        const Simulated s = simulate(dir_.path(), {"--tissue", "liver7", "--frequency-hz", "0.5", "--cycles", "2"});
        nb::TissueMotion m = fromFrames(s, QStringLiteral("still.avi"));
        // The second stroke (turning points every second from 0.5 s): the picture stands still.
        for (std::size_t k = 0; k < m.time_s.size(); ++k)
            if (m.time_s[k] > 1.5 && m.time_s[k] < 2.5)
                m.velocity_mm_s[k] = 0.0;
        const nb::Labels labels = nb::suggestPhaseLabels(s.blind, &m);
        double resting = 0.0;
        for (const nb::Label& l : labels)
            if (l.label == QLatin1String("c"))
                resting += std::max(0.0, std::min(l.end_s, 2.5) - std::max(l.start_s, 1.5));
        QVERIFY2(resting > 0.8, qPrintable(QString::number(resting)));
        const double truth = agreement(s, nb::suggestLabels(s.blind));
        QVERIFY(truth > 0.8);  // the force alone says otherwise there: it follows the true run
        // And a picture that says nothing (too few values) leaves the force's answer.
        nb::TissueMotion empty;
        empty.source = QStringLiteral("blank.avi");
        QCOMPARE(nb::phasePerSample(nb::suggestPhaseLabels(s.blind, &empty), s.blind.time_s),
                 nb::phasePerSample(nb::suggestLabels(s.blind), s.blind.time_s));
    }
};

QTEST_GUILESS_MAIN(TestPhaseSuggest)
#include "test_phase_suggest.moc"
