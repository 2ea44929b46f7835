// Friction fits on the simulated rig's own runs through the command line, as a lab scripts
// them: `simulate --protocol friction` writes the runs, the simulator's phase and tissue
// columns are removed (a real rig has neither), `fit friction --json` fits them.
#include "support/accuracy_seed.h"
#include "support/needlebench_cli.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

struct Truth {
    double Cp = 0, Cn = 0, bp = 0, bn = 0;  // per length
};

double relErr(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

// The peak-speed line's errors per length against the truth; all 1 (100 %) when there is none.
struct LineErrors {
    double Cp = 1, Cn = 1, bp = 1, bn = 1;
    double C() const { return std::max(Cp, Cn); }
    double b() const { return std::max(bp, bn); }
};
LineErrors lineErrors(const QJsonObject& doc, const Truth& truth)
{
    if (!doc.contains(QStringLiteral("peak_speed_line")))
        return {};
    const QJsonObject pl = doc.value(QStringLiteral("peak_speed_line")).toObject().value(QStringLiteral("per_length")).toObject();
    return {relErr(pl.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp), relErr(pl.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn),
            relErr(pl.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), truth.bp),
            relErr(pl.value(QStringLiteral("bn_Ns_per_m2")).toDouble(), truth.bn)};
}

// A run's file name and its own Cp's error.
QString runName(const QJsonObject& run) { return run.value(QStringLiteral("file")).toString().section(QLatin1Char('/'), -1); }
double ownCpError(const QJsonObject& run, const Truth& truth)
{
    return relErr(run.value(QStringLiteral("per_length")).toObject().value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp);
}

// One rig case as a benchmark draw describes it, in `simulate --protocol friction`'s terms.
struct RigCase {
    QString tissue, frequency_hz, amplitude_mm, stickBand_mm_s, plateGap_mm, forceNoise_N;
    int seed = 1;
    int cycles = 5;
    QStringList args() const
    {
        return {QStringLiteral("--tissue"), tissue, QStringLiteral("--frequency-hz"), frequency_hz, QStringLiteral("--amplitude-mm"),
                amplitude_mm, QStringLiteral("--stick-band-mm-s"), stickBand_mm_s, QStringLiteral("--plate-gap-mm"), plateGap_mm,
                QStringLiteral("--force-noise-n"), forceNoise_N, QStringLiteral("--cycles"), QString::number(cycles),
                QStringLiteral("--seed"), QString::number(seed)};
    }
};

}  // namespace

class TestRigFriction : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // Simulates one run and returns the path of its copy without the truth columns.
    QString simulate(const QString& name, const QStringList& args, Truth* truth)
    {
        const QString full = dir_.filePath(name + QStringLiteral(".full.csv"));
        const QString truthPath = dir_.filePath(name + QStringLiteral(".truth.json"));
        const auto r = nbtest::runCli(QStringList{QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                                  QStringLiteral("--cycles"), QStringLiteral("5"), QStringLiteral("--out"), full,
                                                  QStringLiteral("--truth"), truthPath}
                                      << args);
        if (r.code != 0) {
            qWarning("%s", qPrintable(r.err));
            return {};
        }
        const QJsonObject f = nbtest::readJsonFile(truthPath).value(QStringLiteral("model")).toObject().value(QStringLiteral("friction_per_length")).toObject();
        *truth = {f.value(QStringLiteral("Cp_N_per_m")).toDouble(), f.value(QStringLiteral("Cn_N_per_m")).toDouble(),
                  f.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), f.value(QStringLiteral("bn_Ns_per_m2")).toDouble()};
        QFile in(full);
        if (!in.open(QIODevice::ReadOnly | QIODevice::Text))
            return {};
        const QString blind = dir_.filePath(name + QStringLiteral(".csv"));
        QFile out(blind);
        if (!out.open(QIODevice::WriteOnly | QIODevice::Text))
            return {};
        QTextStream is(&in), os(&out);
        QList<int> keep;
        while (!is.atEnd()) {
            const QString line = is.readLine();
            if (line.startsWith(QLatin1Char('#'))) {
                os << line << '\n';
                continue;
            }
            const QStringList cells = line.split(QLatin1Char(','));
            if (keep.isEmpty()) {
                for (int i = 0; i < cells.size(); ++i)
                    if (cells[i] != QLatin1String("phase") && cells[i] != QLatin1String("tissue_position_mm"))
                        keep << i;
            }
            QStringList kept;
            for (int i : keep)
                kept << cells.value(i);
            os << kept.join(QLatin1Char(',')) << '\n';
        }
        return blind;
    }

    // One slab at three frequencies as a benchmark rig set draws it: the runs' seeds follow on.
    QStringList simulateSet(const QString& name, RigCase rig, const QStringList& frequencies, Truth* truth)
    {
        QStringList files;
        const int firstSeed = rig.seed;
        for (int k = 0; k < frequencies.size(); ++k) {
            rig.frequency_hz = frequencies[k];
            rig.seed = firstSeed + k;
            files << simulate(QStringLiteral("%1_%2").arg(name).arg(k), rig.args(), truth);
        }
        return files;
    }

    static QJsonObject fit(const QStringList& files)
    {
        const auto r = nbtest::runCli(QStringList{QStringLiteral("fit"), QStringLiteral("friction"), QStringLiteral("--thickness-mm"),
                                                  QStringLiteral("30"), QStringLiteral("--json")}
                                      << files);
        if (r.code != 0)
            qWarning("%s", qPrintable(r.err));
        return r.json();
    }

private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    // The thesis's Table 4 slab (C small against b) springs back off the plate as the needle
    // slows: a plain line through one run tilts, so the fit takes the slab's motion into the
    // relative velocity; the line through the three runs' peak speeds agrees.
    void compliantSlabAtThreeFrequencies()
    {
        Truth truth;
        QStringList files;
        for (const char* f : {"0.2", "0.5", "0.8"})
            files << simulate(QStringLiteral("liver3_%1").arg(QLatin1String(f)),
                              {QStringLiteral("--tissue"), QStringLiteral("liver3"), QStringLiteral("--frequency-hz"), QLatin1String(f),
                               QStringLiteral("--stick-band-mm-s"), QStringLiteral("3.5"), QStringLiteral("--seed"), QStringLiteral("11")},
                              &truth);
        QVERIFY(!files.contains(QString()));
        const QJsonObject doc = fit(files);
        QVERIFY2(doc.contains(QStringLiteral("peak_speed_line")), "three frequencies give a peak-speed line");
        const LineErrors line = lineErrors(doc, truth);
        const double eC = line.C(), eB = line.b();
        qInfo("peak-speed line on liver3 at 0.2/0.5/0.8 Hz: C error %.2f %%, b error %.2f %% (%lld runs)", 100 * eC, 100 * eB,
              qint64(doc.value(QStringLiteral("peak_speed_line")).toObject().value(QStringLiteral("runs")).toInteger()));
        QVERIFY2(eC < 0.05, qPrintable(QStringLiteral("line C error %1 %").arg(100 * eC)));
        QVERIFY2(eB < 0.15, qPrintable(QStringLiteral("line b error %1 %").arg(100 * eB)));
        // Each run alone: the fit takes the slab's spring-back (the tissue moving back off the
        // plate as the friction falls) into the relative velocity, so the fast runs are no longer
        // tilted (10 % and 25 % off in C before), and the give is reported where the run shows it.
        for (const QJsonValue& rv : doc.value(QStringLiteral("runs")).toArray()) {
            const QJsonObject r = rv.toObject();
            const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
            const double e = std::max(relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp),
                                      relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn));
            const double eb = std::max(relErr(p.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), truth.bp),
                                       relErr(p.value(QStringLiteral("bn_Ns_per_m2")).toDouble(), truth.bn));
            const QJsonObject give = r.value(QStringLiteral("spring_back")).toObject();
            const QString name = r.value(QStringLiteral("file")).toString().section(QLatin1Char('/'), -1);
            qInfo("  %s: own C error %.1f %%, b error %.1f %%, spring-back + %.2f ms, - %.2f ms, departs %d", qPrintable(name), 100 * e,
                  100 * eb, 1000 * give.value(QStringLiteral("positive_s")).toDouble(), 1000 * give.value(QStringLiteral("negative_s")).toDouble(),
                  int(r.value(QStringLiteral("departs_from_peak_line")).toBool()));
            QVERIFY2(e < 0.05, qPrintable(QStringLiteral("%1: C off by %2 %").arg(name).arg(100 * e)));
            QVERIFY2(eb < 0.15, qPrintable(QStringLiteral("%1: b off by %2 %").arg(name).arg(100 * eb)));
            QVERIFY2(!r.value(QStringLiteral("departs_from_peak_line")).toBool(), qPrintable(name));
            if (name.contains(QLatin1String("0.8"))) {
                // The simulated plate gives 5000 N/m once the slab is fully against it.
                const double k = give.value(QStringLiteral("slab_stiffness_positive_N_per_m")).toDouble();
                QVERIFY2(k > 2500.0 && k < 10000.0, qPrintable(QStringLiteral("slab stiffness %1 N/m").arg(k)));
            }
        }
    }

    // Short strokes with a large plate gap: the tissue is carried for much of each stroke and
    // arrives at the plate near the top speed. The band alone took those samples as sliding
    // (b < 0); the fit now keeps only the samples that follow one sliding line.
    void shortStrokeLargeGap_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("liver5 0.23 Hz ±6.6 mm gap 2.85") << QStringList{
            QStringLiteral("--tissue"), QStringLiteral("liver5"), QStringLiteral("--frequency-hz"), QStringLiteral("0.23"),
            QStringLiteral("--amplitude-mm"), QStringLiteral("6.6"), QStringLiteral("--stick-band-mm-s"), QStringLiteral("2.0"),
            QStringLiteral("--plate-gap-mm"), QStringLiteral("2.85"), QStringLiteral("--seed"), QStringLiteral("21")};
        QTest::newRow("liver2 0.69 Hz ±7.4 mm gap 2.94") << QStringList{
            QStringLiteral("--tissue"), QStringLiteral("liver2"), QStringLiteral("--frequency-hz"), QStringLiteral("0.69"),
            QStringLiteral("--amplitude-mm"), QStringLiteral("7.4"), QStringLiteral("--stick-band-mm-s"), QStringLiteral("4.7"),
            QStringLiteral("--plate-gap-mm"), QStringLiteral("2.94"), QStringLiteral("--seed"), QStringLiteral("22")};
        QTest::newRow("liver2 0.24 Hz ±5 mm band 4.1") << QStringList{
            QStringLiteral("--tissue"), QStringLiteral("liver2"), QStringLiteral("--frequency-hz"), QStringLiteral("0.24"),
            QStringLiteral("--amplitude-mm"), QStringLiteral("5.0"), QStringLiteral("--stick-band-mm-s"), QStringLiteral("4.1"),
            QStringLiteral("--plate-gap-mm"), QStringLiteral("0.82"), QStringLiteral("--seed"), QStringLiteral("23")};
    }
    void shortStrokeLargeGap()
    {
        QFETCH(QStringList, args);
        Truth truth;
        static int count = 0;
        const QString file = simulate(QStringLiteral("short_%1").arg(++count), args, &truth);
        QVERIFY(!file.isEmpty());
        const QJsonArray runs = fit({file}).value(QStringLiteral("runs")).toArray();
        QCOMPARE(runs.size(), 1);
        const QJsonObject r = runs.first().toObject();
        // D comes from the velocity band, which cannot tell a carried tissue from a sliding one;
        // C and b must be plausible.
        const QJsonArray bad = r.value(QStringLiteral("not_physical_values")).toArray();
        for (const char* name : {"Cp", "Cn", "bp", "bn"})
            QVERIFY2(!bad.contains(QLatin1String(name)), name);
        const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
        const double eC = std::max(relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp),
                                   relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn));
        const double eB = std::max(relErr(p.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), truth.bp),
                                   relErr(p.value(QStringLiteral("bn_Ns_per_m2")).toDouble(), truth.bn));
        qInfo("%s: C error %.2f %%, b error %.2f %%", QTest::currentDataTag(), 100 * eC, 100 * eB);
        QVERIFY2(eC < 0.05, qPrintable(QStringLiteral("C error %1 %").arg(100 * eC)));
        QVERIFY2(eB < 0.15, qPrintable(QStringLiteral("b error %1 %").arg(100 * eB)));
    }

    // A stroke hardly longer than the slab's free travel carries the tissue all along: the
    // simulator's own phases are a throughout, with no phase c to slide in. Fitting the run
    // as written (its phase column kept) must say that, naming the file, not blame the band.
    void strokeWithinTheFreeTravelSaysWhy()
    {
        Truth truth;
        const QString blind = simulate(QStringLiteral("carried"),
                                       {QStringLiteral("--tissue"), QStringLiteral("liver7"), QStringLiteral("--amplitude-mm"),
                                        QStringLiteral("3.2"), QStringLiteral("--frequency-hz"), QStringLiteral("0.59"),
                                        QStringLiteral("--stick-band-mm-s"), QStringLiteral("1.93"), QStringLiteral("--plate-gap-mm"),
                                        QStringLiteral("2.88"), QStringLiteral("--seed"), QStringLiteral("49509")},
                                       &truth);
        QVERIFY(!blind.isEmpty());
        const QString full = dir_.filePath(QStringLiteral("carried.full.csv"));
        const auto r = nbtest::runCli(QStringList{QStringLiteral("fit"), QStringLiteral("friction"), QStringLiteral("--thickness-mm"),
                                                  QStringLiteral("30"), full});
        QVERIFY2(r.code != 0, qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("carried.full.csv")) && r.err.contains(QStringLiteral("no phase c")), qPrintable(r.err));
    }

    // A slow, short stroke leaves the slab resting at the knee of its contact with the plate:
    // soft below about 0.2 N, stiff above, so its give changes along the stroke and no single
    // stiffness follows it (Cp 23 % high). The fit must not print that C as a result: the
    // sliding residual is several times the force's noise, and Cp and bp are flagged.
    void slabAtTheKneeOfThePlateIsFlagged()
    {
        Truth truth;
        const QString file = simulate(QStringLiteral("knee"),
                                      RigCase{QStringLiteral("liver3"), QStringLiteral("0.23"), QStringLiteral("5.6"), QStringLiteral("1.2"),
                                              QStringLiteral("2.46"), QStringLiteral("0.0006"), 5}
                                          .args(),
                                      &truth);
        QVERIFY(!file.isEmpty());
        const QJsonObject r = fit({file}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
        const double eCp = relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp);
        const double eCn = relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn);
        const QJsonArray flagged = r.value(QStringLiteral("not_physical_values")).toArray();
        const double shape = r.value(QStringLiteral("residual_to_noise")).toObject().value(QStringLiteral("positive")).toDouble();
        qInfo("knee: Cp error %.1f %%, Cn error %.1f %%, + residual %.1fx the noise", 100 * eCp, 100 * eCn, shape);
        if (eCp > 0.05) {
            QVERIFY2(flagged.contains(QStringLiteral("Cp")) && flagged.contains(QStringLiteral("bp")),
                     qPrintable(QStringLiteral("Cp %1 % off and not flagged").arg(100 * eCp)));
            QVERIFY(shape > 2.0);
        }
        // The other direction rests on the stiff part of the plate: its line is right and stands.
        QVERIFY2(eCn < 0.05, qPrintable(QStringLiteral("Cn off by %1 %").arg(100 * eCn)));
        QVERIFY(!flagged.contains(QStringLiteral("Cn")));

        // With a run that determines Cp, the group's mean is that run's Cp alone: a flagged
        // value is not averaged in; and a group of the flagged run alone has no Cp (null).
        Truth same;
        const QString good = simulate(QStringLiteral("knee_partner"),
                                      {QStringLiteral("--tissue"), QStringLiteral("liver3"), QStringLiteral("--frequency-hz"), QStringLiteral("0.5"),
                                       QStringLiteral("--stick-band-mm-s"), QStringLiteral("3.5"), QStringLiteral("--seed"), QStringLiteral("11")},
                                      &same);
        QVERIFY(!good.isEmpty());
        const QJsonObject both = fit({file, good});
        const QJsonObject partner = both.value(QStringLiteral("runs")).toArray().at(1).toObject();
        QVERIFY(!partner.value(QStringLiteral("not_physical_values")).toArray().contains(QStringLiteral("Cp")));
        const double partnerCp = partner.value(QStringLiteral("per_length")).toObject().value(QStringLiteral("Cp_N_per_m")).toDouble();
        const QJsonObject overall = both.value(QStringLiteral("overall")).toObject();
        QCOMPARE(overall.value(QStringLiteral("mean")).toObject().value(QStringLiteral("Cp_N_per_m")).toDouble(), partnerCp);
        QVERIFY(overall.value(QStringLiteral("std")).toObject().value(QStringLiteral("Cp_N_per_m")).isNull());
        bool kneeGroupSeen = false;
        for (const QJsonValue& g : both.value(QStringLiteral("by_frequency")).toArray()) {
            const QJsonObject o = g.toObject();
            if (std::fabs(o.value(QStringLiteral("frequency_hz")).toDouble() - 0.23) < 0.01) {
                kneeGroupSeen = true;
                QVERIFY(o.value(QStringLiteral("mean")).toObject().value(QStringLiteral("Cp_N_per_m")).isNull());
                QVERIFY(!o.value(QStringLiteral("mean")).toObject().value(QStringLiteral("Cn_N_per_m")).isNull());
            }
        }
        QVERIFY(kneeGroupSeen);
    }

    // A slow, short liver3 stroke (0.24 Hz, ±5.5 mm, wide band, large gap) slides only while
    // slowing down, with the slab springing back across the soft part of its plate as the
    // friction falls below what that part carries. The straight line (with its one-stiffness
    // spring-back term) leans: Cp came out ~38 % high and bp ~26 % low with small standard
    // errors and a residual of 1.4x the noise, and nothing flagged them. Letting the line bend
    // (a v² term) moves Cp by far more than 5 %, so Cp and bp are flagged as not determined and
    // say why; the other direction, on the stiff part of its plate, stays a result.
    void slowSoftSlabStrokeIsFlagged()
    {
        Truth truth;
        const QString file = simulate(QStringLiteral("slow_soft"),
                                      RigCase{QStringLiteral("liver3"), QStringLiteral("0.2438"), QStringLiteral("5.548"), QStringLiteral("4.3"),
                                              QStringLiteral("3.0"), QStringLiteral("0.0015"), 87646}
                                          .args(),
                                      &truth);
        QVERIFY(!file.isEmpty());
        const QJsonObject r = fit({file}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
        const double eCp = relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp);
        const double eBp = relErr(p.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), truth.bp);
        const double eCn = relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn);
        const QJsonArray flagged = r.value(QStringLiteral("not_physical_values")).toArray();
        qInfo("slow soft slab: Cp error %.1f %%, bp error %.1f %%, Cn error %.1f %%, Cp flagged %d", 100 * eCp, 100 * eBp, 100 * eCn,
              int(flagged.contains(QStringLiteral("Cp"))));
        QVERIFY2(eCn < 0.05, qPrintable(QStringLiteral("Cn off by %1 %").arg(100 * eCn)));
        // Cn is right, and flagged only for where it rests: 4.6-7.1 mm/s of a stroke reaching
        // 8.5 once the samples still settling onto the plate are left out (steadilySliding), 0.29
        // of the top where kMinSlidingShareOfTop asks 0.3. The bend and the shape leave it.
        const QJsonArray reasons = r.value(QStringLiteral("not_physical")).toArray();
        if (flagged.contains(QStringLiteral("Cn")))
            QVERIFY2(std::any_of(reasons.begin(), reasons.end(),
                                 [](const QJsonValue& w) {
                                     return w.toString().startsWith(QStringLiteral("bn is not determined")) && w.toString().contains(QStringLiteral("of a stroke reaching 8."));
                                 }) &&
                         std::none_of(reasons.begin(), reasons.end(), [](const QJsonValue& w) { return w.toString().startsWith(QStringLiteral("Cn and bn")); }),
                     qPrintable(QJsonDocument(reasons).toJson()));
        const bool rightOrFlagged = (eCp < 0.05 && eBp < 0.15) || (flagged.contains(QStringLiteral("Cp")) && flagged.contains(QStringLiteral("bp")));
        QVERIFY2(rightOrFlagged, qPrintable(QStringLiteral("Cp %1 % / bp %2 % off and not flagged").arg(100 * eCp).arg(100 * eBp)));
        const double shift = r.value(QStringLiteral("c_shift_if_bent")).toObject().value(QStringLiteral("positive")).toDouble();
        QVERIFY2(std::fabs(shift) > 0.05, qPrintable(QString::number(shift)));
        QVERIFY(std::fabs(r.value(QStringLiteral("c_shift_if_bent")).toObject().value(QStringLiteral("negative")).toDouble()) < 0.05);
        const QJsonArray why = r.value(QStringLiteral("not_physical")).toArray();
        QVERIFY2(std::any_of(why.begin(), why.end(), [](const QJsonValue& w) { return w.toString().contains(QStringLiteral("bend")); }),
                 qPrintable(QJsonDocument(why).toJson()));
        // The speeds Cp was carried down to zero from.
        const QJsonArray speeds = r.value(QStringLiteral("sliding_speed_m_s")).toObject().value(QStringLiteral("positive")).toArray();
        QCOMPARE(speeds.size(), 2);
        QVERIFY(speeds.at(0).toDouble() > 0.0 && speeds.at(0).toDouble() < speeds.at(1).toDouble());
    }

    // The Table 4 slab at 0.66 Hz with a wide band (±5.6 mm/s, bench_accuracy --seed 895, rig set
    // 2): the tissue reaches the plate only as the needle passes its top speed, so the force goes
    // on rising while the needle slows. Those samples, below the sliding line, bent the
    // spring-back term and Cp came out 9 % low with its residual at the noise, unflagged. They
    // are not sliding against resting tissue and are left out: Cp within 5 %.
    void slabArrivingAtTopSpeed()
    {
        Truth truth;
        const QString file = simulate(QStringLiteral("arriving"),
                                      RigCase{QStringLiteral("liver3"), QStringLiteral("0.6625"), QStringLiteral("6.908"), QStringLiteral("5.642"),
                                              QStringLiteral("2.179"), QStringLiteral("0.00287"), 98938, 7}
                                          .args(),
                                      &truth);
        QVERIFY(!file.isEmpty());
        const QJsonObject r = fit({file}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
        const double eCp = relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp);
        const double eCn = relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn);
        const double eBp = relErr(p.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), truth.bp);
        const double eBn = relErr(p.value(QStringLiteral("bn_Ns_per_m2")).toDouble(), truth.bn);
        const QJsonArray flagged = r.value(QStringLiteral("not_physical_values")).toArray();
        qInfo("slab arriving at top speed: Cp %.1f %%, bp %.1f %%, Cn %.1f %%, bn %.1f %% off; flagged %s", 100 * eCp, 100 * eBp, 100 * eCn,
              100 * eBn, qPrintable(QJsonDocument(flagged).toJson(QJsonDocument::Compact)));
        QVERIFY2(eCp < 0.05 && eBp < 0.15, qPrintable(QStringLiteral("Cp %1 %, bp %2 % off").arg(100 * eCp).arg(100 * eBp)));
        QVERIFY2(eCn < 0.05 && eBn < 0.15, qPrintable(QStringLiteral("Cn %1 %, bn %2 % off").arg(100 * eCn).arg(100 * eBn)));
        // Its static limits come from the velocity band, which here cannot see Dn apart from the
        // sliding, and says so; C and b are results.
        for (const char* name : {"Cp", "bp", "Cn", "bn"})
            QVERIFY2(!flagged.contains(QLatin1String(name)), name);
    }

    // The same slab at 0.26 / 0.50 / 0.80 Hz with a large gap (bench_accuracy --seed 70555, rig set
    // 6): at 0.80 Hz the tissue reaches the plate just as the needle passes its top speed and the
    // force there is 10 mN short of the sliding line, too little to rise as the needle slows. That
    // run's peak point sat low, the line through the three peaks came out with Cp 6.4 % high, the
    // run's own Cp 5.6 % low, and the two right runs were told they departed from the line. The
    // top bins short of the line through the next ones are left out of both.
    void peakLineThroughASlabArrivingAtTheTop()
    {
        Truth truth;
        const QStringList files = simulateSet(QStringLiteral("late"),
                                              RigCase{QStringLiteral("liver3"), {}, QStringLiteral("8.18534"), QStringLiteral("3.34675"),
                                                      QStringLiteral("2.59054"), QStringLiteral("0.0008289"), 90421, 7},
                                              {QStringLiteral("0.25591"), QStringLiteral("0.499673"), QStringLiteral("0.796597")}, &truth);
        QVERIFY(!files.contains(QString()));
        const QJsonObject doc = fit(files);
        QVERIFY2(doc.contains(QStringLiteral("peak_speed_line")), "three frequencies give a peak-speed line");
        const LineErrors e = lineErrors(doc, truth);
        qInfo("peak-speed line through a slab arriving at the top: C error %.2f %%, b error %.2f %%", 100 * e.C(), 100 * e.b());
        QVERIFY2(e.C() < 0.05 && e.b() < 0.15, qPrintable(QStringLiteral("line C %1 %, b %2 % off").arg(100 * e.C()).arg(100 * e.b())));
        const QJsonArray runs = doc.value(QStringLiteral("runs")).toArray();
        QCOMPARE(runs.size(), 3);
        for (const QJsonValue& rv : runs) {
            const QJsonObject r = rv.toObject();
            const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
            const double own = std::max(relErr(p.value(QStringLiteral("Cp_N_per_m")).toDouble(), truth.Cp),
                                        relErr(p.value(QStringLiteral("Cn_N_per_m")).toDouble(), truth.Cn));
            const QString name = runName(r);
            QVERIFY2(own < 0.05, qPrintable(QStringLiteral("%1: C off by %2 %").arg(name).arg(100 * own)));
            QVERIFY2(!r.value(QStringLiteral("departs_from_peak_line")).toBool(), qPrintable(name));
        }
        // The fast run says where the tissue was still arriving.
        const QJsonObject fast = runs.at(2).toObject().value(QStringLiteral("arriving_above_m_s")).toObject();
        QVERIFY2(fast.value(QStringLiteral("positive")).isDouble(), qPrintable(QJsonDocument(fast).toJson(QJsonDocument::Compact)));
        QVERIFY(fast.value(QStringLiteral("positive")).toDouble() < 0.0411);
    }

    // Liver 3 at 0.24 / 0.42 / 0.66 Hz with a 2.5 mm gap (bench_accuracy --seed 249338, rig set
    // 4): at 0.66 Hz the tissue reaches the plate at the top speed itself and creeps on for
    // 10-30 ms, all within the top 2 % of the speed, so no speed bin shows it. The peak point,
    // the median of that window, sat 5.7 mN low and the line's Cp came out 6 % high. In time it
    // shows: the later half of each top is read, and only when its two quarters agree. The
    // run's own Cp, 6.4 % high, then departed from the line and said so (now 2.9 % low, 5.0 %
    // from a line 2.3 % high: still told, as any run more than 5 % from the line is).
    void peakLineReadsTheTopAfterTheTissueSettles()
    {
        Truth truth;
        const QStringList files = simulateSet(QStringLiteral("settling"),
                                              RigCase{QStringLiteral("liver3"), {}, QStringLiteral("8.048"), QStringLiteral("4.889"),
                                                      QStringLiteral("2.500"), QStringLiteral("0.00321"), 59898, 7},
                                              {QStringLiteral("0.2417"), QStringLiteral("0.4250"), QStringLiteral("0.6637")}, &truth);
        QVERIFY(!files.contains(QString()));
        const QJsonObject doc = fit(files);
        QVERIFY2(doc.contains(QStringLiteral("peak_speed_line")), "three frequencies give a peak-speed line");
        const LineErrors e = lineErrors(doc, truth);
        qInfo("peak-speed line, tissue settling just after the top: Cp %.2f %%, Cn %.2f %%, b %.2f %% off", 100 * e.Cp, 100 * e.Cn, 100 * e.b());
        QVERIFY2(e.C() < 0.04 && e.b() < 0.15, qPrintable(QStringLiteral("line Cp %1 %, Cn %2 %, b %3 % off").arg(100 * e.Cp).arg(100 * e.Cn).arg(100 * e.b())));
        const QJsonArray runs = doc.value(QStringLiteral("runs")).toArray();
        QCOMPARE(runs.size(), 3);
        for (const QJsonValue& rv : runs) {
            const QJsonObject r = rv.toObject();
            const double own = ownCpError(r, truth);
            const bool departs = r.value(QStringLiteral("departs_from_peak_line")).toBool();
            const QString name = runName(r);
            qInfo("  %s: own Cp %.1f %% off, departs %d", qPrintable(name), 100 * own, int(departs));
            // Off by more than 5 %: told; and told exactly when more than 5 % from the line (the
            // line itself is 2.3 % high, so a run 2.9 % low is 5.0 % from it and told).
            if (own > 0.05)
                QVERIFY2(departs, qPrintable(QStringLiteral("%1: Cp %2 % off, not told").arg(name).arg(100 * own)));
            const double fromLine = r.value(QStringLiteral("C_from_peak_line_percent")).toObject().value(QStringLiteral("Cp")).toDouble();
            QCOMPARE(departs, std::fabs(fromLine) > 5.0);
        }
    }

    // Liver 3 at 0.29 / 0.51 / 0.68 Hz, noisy (9.3 mN; after bench_accuracy --seed 88, rig set 2):
    // each run's own Cp came out 6-8 % high with a standard error of 2 % (the slab's spring-back
    // tilts its line; the noise does not hold that), while the line through the peaks is within
    // 2 %. The run's standard error excused its departure before; now only the line's does, and
    // the slow run, whose fit flags Cp as bent, still gives its peak point to the line (the
    // point needs no line of its own, only a flat top): before, the set had no line at all.
    // Since the settling samples are left out and the spring-back kept wherever positive
    // (friction_fit.cpp), the runs of the first draw (seed 83899) are 4-6 % high and none is
    // more than 5 % from the line; a later draw of the same slab (seed 83923) still has one,
    // the 0.51 Hz run, 5.6 % high and 6.0 % from the line.
    void runsOffTheLineAreToldWhateverTheirOwnError()
    {
        Truth truth;
        const QStringList files = simulateSet(QStringLiteral("noisy"),
                                              RigCase{QStringLiteral("liver3"), {}, QStringLiteral("7.009"), QStringLiteral("3.465"),
                                                      QStringLiteral("1.431"), QStringLiteral("0.00930"), 83923, 7},
                                              {QStringLiteral("0.2899"), QStringLiteral("0.5070"), QStringLiteral("0.6809")}, &truth);
        QVERIFY(!files.contains(QString()));
        const QJsonObject doc = fit(files);
        QVERIFY2(doc.contains(QStringLiteral("peak_speed_line")), "three frequencies give a peak-speed line");
        const LineErrors e = lineErrors(doc, truth);
        qInfo("peak-speed line through noisy liver 3 runs: C %.2f %% off", 100 * e.C());
        QVERIFY2(e.C() < 0.04, qPrintable(QStringLiteral("line C %1 % off").arg(100 * e.C())));
        const QJsonArray runs = doc.value(QStringLiteral("runs")).toArray();
        QCOMPARE(runs.size(), 3);
        for (const QJsonValue& rv : runs) {
            const QJsonObject r = rv.toObject();
            const double fromLine = r.value(QStringLiteral("C_from_peak_line_percent")).toObject().value(QStringLiteral("Cp")).toDouble();
            const bool departs = r.value(QStringLiteral("departs_from_peak_line")).toBool();
            qInfo("  %s: own Cp %.1f %% off, %.1f %% from the line, departs %d", qPrintable(runName(r)), 100 * ownCpError(r, truth), fromLine,
                  int(departs));
            QCOMPARE(departs, std::fabs(fromLine) > 5.0);
        }
        QVERIFY2(runs.at(1).toObject().value(QStringLiteral("departs_from_peak_line")).toBool(), "the 0.51 Hz run, 5.6 % off, is told");
    }

    // A wide stick band (±3.9 mm/s) on a short, quick stroke (±3.7 mm at 0.57 Hz): phase c holds
    // sliding samples only between 7.1 and 7.9 mm/s, the top tenth of the stroke's speed. Their
    // line's slope was 23 % high in both directions with standard errors of 1.5 %, nothing
    // flagged it, and C rested on it. A line seen over less than a quarter of its top speed is
    // not a result: b and C are flagged, and the reason names the speeds.
    void narrowSlidingRangeIsFlagged()
    {
        Truth truth;
        const QString blind = simulate(QStringLiteral("narrow"),
                                       {QStringLiteral("--tissue"), QStringLiteral("liver2"), QStringLiteral("--amplitude-mm"), QStringLiteral("3.7"),
                                        QStringLiteral("--frequency-hz"), QStringLiteral("0.57"), QStringLiteral("--stick-band-mm-s"),
                                        QStringLiteral("3.87"), QStringLiteral("--plate-gap-mm"), QStringLiteral("2.2"), QStringLiteral("--cycles"),
                                        QStringLiteral("7"), QStringLiteral("--seed"), QStringLiteral("61397")},
                                       &truth);
        QVERIFY(!blind.isEmpty());
        // With the run's own phase column: C and b from phase c as labelled.
        const QJsonObject r = fit({dir_.filePath(QStringLiteral("narrow.full.csv"))}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const QJsonObject p = r.value(QStringLiteral("per_length")).toObject();
        const QJsonArray flagged = r.value(QStringLiteral("not_physical_values")).toArray();
        const QJsonArray why = r.value(QStringLiteral("not_physical")).toArray();
        for (const char* d : {"p", "n"}) {
            const QString b = QStringLiteral("b") + QLatin1String(d), c = QStringLiteral("C") + QLatin1String(d);
            const double eB = relErr(p.value(b + QStringLiteral("_Ns_per_m2")).toDouble(), d[0] == 'p' ? truth.bp : truth.bn);
            const double eC = relErr(p.value(c + QStringLiteral("_N_per_m")).toDouble(), d[0] == 'p' ? truth.Cp : truth.Cn);
            const QJsonArray speeds = r.value(QStringLiteral("sliding_speed_m_s")).toObject()
                                          .value(QLatin1String(d[0] == 'p' ? "positive" : "negative")).toArray();
            const double from = speeds.at(0).toDouble(), to = speeds.at(1).toDouble();
            qInfo("narrow %s: sliding %.2f-%.2f mm/s, b error %.1f %%, C error %.1f %%", d, 1000 * from, 1000 * to, 100 * eB, 100 * eC);
            QVERIFY2(to - from < 0.25 * to, qPrintable(QStringLiteral("the run now slides over %1-%2 mm/s").arg(1000 * from).arg(1000 * to)));
            QVERIFY2(flagged.contains(b) && flagged.contains(c), qPrintable(QJsonDocument(flagged).toJson()));
        }
        QVERIFY2(std::any_of(why.begin(), why.end(), [](const QJsonValue& w) { return w.toString().contains(QStringLiteral("too narrow a range")); }),
                 qPrintable(QJsonDocument(why).toJson()));
    }

    // A short stroke (±3.3 mm at 0.45 Hz, top 9.3 mm/s) with a stick band of ±2.2 mm/s on
    // liver 1, force and position only: the tissue has not come to rest at the top speeds, which
    // the fit leaves out, and the + line rests on 4.9-7.6 mm/s. That is a third of what is left
    // (kMinSlidingSpan passed it) but 0.29 of the top: bp came out 43 % high with a standard error
    // under 1 %, unflagged (friction_cli_matrix.py --seed 4242, run r64). Measured against the
    // stroke's top, it is not a result, and the reason named the top. Since the samples still
    // settling onto the plate are left out (steadilySliding) the line rests on 4.9-6.2 mm/s, and
    // the reason is that narrow range itself (slowSoftSlabStrokeIsFlagged keeps the top's). (slowSoftSlabStrokeIsFlagged
    // keeps its right Cn: 4.4-7.2 mm/s of 8.5, 0.33 of the top.)
    void slidingShortOfTheTopIsFlagged()
    {
        Truth truth;
        const QString blind = simulate(QStringLiteral("short_of_top"),
                                       {QStringLiteral("--tissue"), QStringLiteral("liver1"), QStringLiteral("--amplitude-mm"), QStringLiteral("3.3"),
                                        QStringLiteral("--frequency-hz"), QStringLiteral("0.45"), QStringLiteral("--stick-band-mm-s"),
                                        QStringLiteral("2.24"), QStringLiteral("--plate-gap-mm"), QStringLiteral("1.76"), QStringLiteral("--cycles"),
                                        QStringLiteral("7"), QStringLiteral("--seed"), QStringLiteral("69072")},
                                       &truth);
        QVERIFY(!blind.isEmpty());
        const QJsonObject r = fit({blind}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const double bp = r.value(QStringLiteral("per_length")).toObject().value(QStringLiteral("bp_Ns_per_m2")).toDouble();
        const QJsonArray speeds = r.value(QStringLiteral("sliding_speed_m_s")).toObject().value(QStringLiteral("positive")).toArray();
        qInfo("sliding %.2f-%.2f mm/s, bp %.1f %% off", 1000 * speeds.at(0).toDouble(), 1000 * speeds.at(1).toDouble(), 100 * relErr(bp, truth.bp));
        QVERIFY2(relErr(bp, truth.bp) > 0.15, "the case no longer shows the miss it was kept for");
        const QJsonArray flagged = r.value(QStringLiteral("not_physical_values")).toArray();
        QVERIFY2(flagged.contains(QStringLiteral("bp")) && flagged.contains(QStringLiteral("Cp")), qPrintable(QJsonDocument(flagged).toJson()));
        const QJsonArray why = r.value(QStringLiteral("not_physical")).toArray();
        QVERIFY2(std::any_of(why.begin(), why.end(),
                             [](const QJsonValue& w) {
                                 return w.toString().startsWith(QStringLiteral("bp is not determined")) &&
                                        (w.toString().contains(QStringLiteral("of a stroke reaching 9.")) || w.toString().contains(QStringLiteral("too narrow a range")));
                             }),
                 qPrintable(QJsonDocument(why).toJson()));
    }

    // Liver 3's Cp is small beside bp·v, so the slab's give as the needle slows (it springs
    // back off the plate by Ḟ/k, some 0.3 mm/s) moves it by 5-10 %. The force's rate for the
    // spring-back term was smoothed across each slide's ends, where the force changes its law,
    // and read b/k as nothing: Cp 5.4 % and 9.7 % high with nothing said. Read within each
    // slide, and kept wherever it comes out positive, it holds Cp or says it cannot. The third is
    // a narrow sliding range (7-15 mm/s) whose term showed at only 2.5 standard errors: Cp 5.7 %
    // high where three were asked for. Draws of bench/friction_cli_matrix.py --seed 2611 (r111,
    // r67) and bench_accuracy --seed 552402 (rig set 7, 0.74 Hz).
    void slabGivingAsTheNeedleSlows_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<bool>("flagAllowed");
        QTest::newRow("liver3 0.51 Hz band 5.37") << QStringList{"--tissue", "liver3", "--amplitude-mm", "5.2", "--frequency-hz", "0.51",
                                                                 "--stick-band-mm-s", "5.37", "--plate-gap-mm", "1.65", "--cycles", "7",
                                                                 "--seed", "35383"}
                                                  << false;
        QTest::newRow("liver3 0.745 Hz gap 2.48") << QStringList{"--tissue", "liver3", "--frequency-hz", "0.7450", "--amplitude-mm", "5.551",
                                                                 "--stick-band-mm-s", "4.801", "--plate-gap-mm", "2.484", "--force-noise-n",
                                                                 "0.00053", "--cycles", "7", "--seed", "35307"}
                                                  << true;
        QTest::newRow("liver3 0.54 Hz narrow range") << QStringList{"--tissue", "liver3", "--amplitude-mm", "4.5", "--frequency-hz", "0.54",
                                                                    "--stick-band-mm-s", "5.87", "--plate-gap-mm", "1.14", "--cycles", "7",
                                                                    "--seed", "10054"}
                                                     << false;
        // The slab still settling onto the plate as each slide begins: its climb to the line read as
        // a give (b/k 4.8 ms for 3.3, Cp 6.4 % low), or on a shorter stroke leaning the plain line
        // (Cp 5.2 % high); left out by the force-rate check (steadilySliding). Draws of
        // bench/friction_cli_matrix.py --seed 2703 (r50, r157).
        QTest::newRow("liver3 0.70 Hz settling") << QStringList{"--tissue", "liver3", "--amplitude-mm", "9.1", "--frequency-hz", "0.7",
                                                                "--stick-band-mm-s", "3.31", "--plate-gap-mm", "2.98", "--cycles", "7",
                                                                "--seed", "45464"}
                                                 << false;
        QTest::newRow("liver3 0.64 Hz settling") << QStringList{"--tissue", "liver3", "--amplitude-mm", "4.6", "--frequency-hz", "0.64",
                                                                "--stick-band-mm-s", "4.02", "--plate-gap-mm", "2.43", "--cycles", "7",
                                                                "--seed", "51707"}
                                                 << false;
    }
    void slabGivingAsTheNeedleSlows()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, flagAllowed);
        Truth truth;
        const QString file = simulate(QStringLiteral("giving_%1").arg(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('_')), args, &truth);
        QVERIFY(!file.isEmpty());
        const QJsonObject r = fit({file}).value(QStringLiteral("runs")).toArray().at(0).toObject();
        const double eCp = ownCpError(r, truth);
        const bool flagged = r.value(QStringLiteral("not_physical_values")).toArray().contains(QStringLiteral("Cp"));
        QVERIFY2(eCp < 0.05 || (flagAllowed && flagged), qPrintable(QStringLiteral("Cp %1 % off, %2").arg(100 * eCp).arg(flagged ? "flagged" : "not flagged")));
    }

    // Liver 3 moving in rests on the soft part of its plate: its friction (Cp small against bp)
    // stays under what that part carries, so the slab creeps back by about 1 mm/s all through
    // the slide as the friction falls, and a line in the needle's speed took that for C (Cp
    // 15-25 % high, its residual at the noise, nothing flagged; bench/friction_cli_matrix.py
    // --seed 2701, r27 and r176). The give is read where the needle carries the slab into the
    // plate (plate_give in the JSON) and the creep taken out: Cp within 5 % or flagged, from
    // the run's phases and from force and position alone, on slow strokes drawn at random.
    void slabRestingOnTheSoftPartOfItsPlate()
    {
        std::mt19937 rng(nb::test::accuracySeed(40263u));
        auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
        int fits = 0, right = 0, gives = 0;
        for (int k = 0; k < 6; ++k) {
            // The top speed keeps the friction at the top (0.085 N + 16.7 N·s/m · v) under the
            // soft part's 0.2 N; the stroke reaches at least 1.5 mm past the plate, and the band
            // is narrow enough to leave it a slide.
            const double amplitude = uniform(2.5, 5.0), top_mm_s = uniform(3.0, 6.0);
            const RigCase rig{QStringLiteral("liver3"), QString::number(top_mm_s / (2.0 * M_PI * amplitude), 'f', 4),
                              QString::number(amplitude, 'f', 2), QString::number(uniform(0.5, 1.5), 'f', 2),
                              QString::number(uniform(0.5, amplitude - 1.5), 'f', 2), QStringLiteral("0.0006"),
                              std::uniform_int_distribution<int>(1, 99999)(rng)};
            const QString name = QStringLiteral("soft_%1").arg(k);
            const QString drawn = QStringLiteral("%1 %2 Hz ±%3 mm band ±%4 mm/s gap %5 mm seed %6")
                                      .arg(rig.tissue, rig.frequency_hz, rig.amplitude_mm, rig.stickBand_mm_s, rig.plateGap_mm)
                                      .arg(rig.seed);
            Truth truth;
            const QString blind = simulate(name, rig.args(), &truth);
            QVERIFY(!blind.isEmpty());
            const QJsonObject plate = nbtest::readJsonFile(dir_.filePath(name + QStringLiteral(".truth.json")))
                                          .value(QStringLiteral("model")).toObject().value(QStringLiteral("plate")).toObject();
            const double soft_N_per_m = plate.value(QStringLiteral("soft_N_per_m")).toDouble();
            QVERIFY(soft_N_per_m > 0.0);
            for (const QString& file : {dir_.filePath(name + QStringLiteral(".full.csv")), blind}) {
                const auto out = nbtest::runCli(QStringList{QStringLiteral("fit"), QStringLiteral("friction"), QStringLiteral("--thickness-mm"),
                                                            QStringLiteral("30"), QStringLiteral("--json"), file});
                ++fits;
                if (out.code != 0) {
                    // A refusal names the run and why (a band as wide as the stroke's slow part
                    // leaves no sliding in one direction): no value, so nothing wrong printed.
                    qInfo("%s: refused: %s", qPrintable(drawn), qPrintable(out.err.trimmed()));
                    QVERIFY2(out.err.contains(file.section(QLatin1Char('/'), -1)), qPrintable(out.err));
                    continue;
                }
                const QJsonObject r = out.json().value(QStringLiteral("runs")).toArray().at(0).toObject();
                QVERIFY2(!r.isEmpty(), qPrintable(drawn + QStringLiteral(": ") + file));
                const double eCp = ownCpError(r, truth);
                const bool flagged = r.value(QStringLiteral("not_physical_values")).toArray().contains(QStringLiteral("Cp"));
                const QJsonValue give = r.value(QStringLiteral("plate_give")).toObject().value(QStringLiteral("positive"));
                const double k_N_per_m = give.toObject().value(QStringLiteral("stiffness_N_per_m")).toDouble();
                const QString what = QStringLiteral("%1 (%2): Cp %3 % off%4, give %5 N/m")
                                         .arg(drawn, file == blind ? QStringLiteral("force only") : QStringLiteral("phases"))
                                         .arg(100 * eCp, 0, 'f', 1)
                                         .arg(flagged ? QStringLiteral(", flagged") : QString())
                                         .arg(give.isObject() ? QString::number(k_N_per_m, 'f', 0) : QStringLiteral("none"));
                qInfo("%s", qPrintable(what));
                QVERIFY2(eCp < 0.05 || flagged, qPrintable(what));
                if (give.isObject()) {
                    ++gives;
                    QVERIFY2(relErr(k_N_per_m, soft_N_per_m) < 0.15, qPrintable(what + QStringLiteral(", true %1 N/m").arg(soft_N_per_m)));
                }
                right += eCp < 0.05 && !flagged;
            }
        }
        // Not by flagging them all: a third or more are results, and most read the give. (The
        // rest are flagged mostly because the slide left after the settling spans too few
        // speeds for its line to be sure of C, c_shift_if_bent.)
        qInfo("%d of %d fits right and not flagged, %d with the give read", right, fits, gives);
        QVERIFY2(3 * right >= fits, qPrintable(QStringLiteral("%1 of %2 right").arg(right).arg(fits)));
        QVERIFY2(2 * gives >= fits, qPrintable(QStringLiteral("%1 of %2 read the give").arg(gives).arg(fits)));
    }

    void oneFrequencyMakesNoLine()
    {
        Truth truth;
        QStringList files;
        for (const char* seed : {"31", "32"})
            files << simulate(QStringLiteral("same_%1").arg(QLatin1String(seed)),
                              {QStringLiteral("--tissue"), QStringLiteral("liver7"), QStringLiteral("--frequency-hz"), QStringLiteral("0.5"),
                               QStringLiteral("--seed"), QLatin1String(seed)},
                              &truth);
        QVERIFY(!files.contains(QString()));
        QVERIFY(!fit(files).contains(QStringLiteral("peak_speed_line")));
        const auto text = nbtest::runCli(QStringList{QStringLiteral("fit"), QStringLiteral("friction"), QStringLiteral("--thickness-mm"),
                                                     QStringLiteral("30")}
                                         << files);
        QCOMPARE(text.code, 0);
        QVERIFY2(text.out.contains(QStringLiteral("no peak-speed line")), qPrintable(text.out));
    }
};

QTEST_GUILESS_MAIN(TestRigFriction)
#include "test_rig_friction.moc"
