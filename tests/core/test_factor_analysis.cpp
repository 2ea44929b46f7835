// Analysis by factor (core/export/factor_analysis.h) on synthetic runs with known models:
// friction at three frequencies and three sites (damping differs by frequency, as the
// thesis found), stiffness with two tips named only by plain metadata.
#include "core/export/factor_analysis.h"
#include "core/statistics.h"
#include "synthetic.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace nb;

namespace {

constexpr double kThickness_mm = 30.0;
const double kFreqs[] = {0.2, 0.5, 0.8};

KarnoppModel modelAt(double f)
{
    KarnoppModel m{0.20, 0.22, 4.0, 3.5, 0.30, -0.32, 0.005};
    m.bp_Ns_per_m = 4.0 + 4.0 * f;  // N s/m: viscous damping that grows with frequency
    m.bn_Ns_per_m = 3.5 + 2.0 * f;
    return m;
}

std::uint32_t frictionSeed(int site, int k) { return std::uint32_t(1000 + 10 * site + k); }

Dataset makeDataset()
{
    Dataset d;
    d.name = QStringLiteral("synthetic");
    for (int site = 1; site <= 3; ++site)
        for (int k = 0; k < 3; ++k) {
            synthetic::Friction p;
            p.model = modelAt(kFreqs[k]);
            p.frequency_hz = kFreqs[k];
            p.cycles = 5;
            p.seed = frictionSeed(site, k);
            DatasetRun r;
            r.name = QStringLiteral("friction_s%1_f%2").arg(site).arg(k);
            r.run = synthetic::makeFriction(p);
            r.run.metadata.set(QStringLiteral("protocol"), QStringLiteral("friction"));
            r.run.metadata.set(QStringLiteral("thickness_mm"), kThickness_mm);
            r.run.metadata.set(QStringLiteral("factor_site"), QString::number(site));
            r.run.metadata.set(QStringLiteral("factor_frequency_hz"), QString::number(kFreqs[k]));
            r.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));  // as a whole recording has
            d.runs.push_back(std::move(r));
        }
    for (int i = 0; i < 6; ++i) {
        synthetic::Insertion p;
        const bool diamond = i >= 3;
        p.a1_N_per_mm = diamond ? 0.0204 : 0.0480;
        p.a2_N_per_mm2 = diamond ? 0.0008 : 0.0052;
        p.punctureDepth_mm = diamond ? 10.4 : 16.57;
        p.seed = std::uint32_t(2000 + i);
        DatasetRun r;
        r.name = QStringLiteral("stiffness_%1").arg(i);
        r.run = synthetic::makeInsertion(p);
        r.run.metadata.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
        r.run.metadata.set(QStringLiteral("tissue"), QStringLiteral("liver1"));
        r.run.metadata.set(QStringLiteral("tip"), diamond ? QStringLiteral("diamond") : QStringLiteral("beveled"));
        r.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
        d.runs.push_back(std::move(r));
    }
    return d;
}

const FactorCell* cellWith(const std::vector<FactorCell>& cells, const QStringList& levels)
{
    for (const FactorCell& c : cells)
        if (c.levels == levels)
            return &c;
    return nullptr;
}

}  // namespace

class TestFactorAnalysis : public QObject {
    Q_OBJECT
    Dataset dataset_;
    SessionAnalysis analysis_;

private slots:
    void initTestCase()
    {
        qInfo("friction seeds 1000 + 10*site + frequency index (sites 1-3), insertion seeds 2000-2005");
        dataset_ = makeDataset();
        analysis_ = analyseDataset(dataset_);
        QVERIFY2(analysis_.warnings.isEmpty(), qPrintable(analysis_.warnings.join(QLatin1Char('\n'))));
    }

    void frictionByFrequencyRecoversEachFrequencysModel()
    {
        const QStringList by{QStringLiteral("frequency_hz")};
        const auto values = runFactorValues(dataset_, analysis_, by);
        QCOMPARE(values.size(), std::size_t(15));
        const auto cells = groupByFactors(values, by);
        // Numeric order, the insertions (no frequency) last.
        QCOMPARE(cells.size(), std::size_t(4));
        QCOMPARE(cells[0].levels, QStringList{QStringLiteral("0.2")});
        QCOMPARE(cells[2].levels, QStringList{QStringLiteral("0.8")});
        QCOMPARE(cells[3].levels, QStringList{QString()});
        const double L = kThickness_mm / 1000.0;
        for (int k = 0; k < 3; ++k) {
            const FactorCell& c = cells[std::size_t(k)];
            QCOMPARE(c.runs, std::size_t(3));
            const KarnoppModel m = modelAt(kFreqs[k]);
            const auto& cp = c.stats.at(QStringLiteral("Cp_N_per_m"));
            const auto& bp = c.stats.at(QStringLiteral("bp_Ns_per_m2"));
            const auto& bn = c.stats.at(QStringLiteral("bn_Ns_per_m2"));
            QCOMPARE(cp.n, std::size_t(3));
            qInfo("%.1f Hz: Cp %.3f (true %.3f) bp %.2f (true %.2f) bn %.2f (true %.2f) N/m, N s/m^2", kFreqs[k], cp.mean, m.Cp_N / L, bp.mean,
                  m.bp_Ns_per_m / L, bn.mean, m.bn_Ns_per_m / L);
            QVERIFY(std::abs(cp.mean - m.Cp_N / L) < 0.10 * m.Cp_N / L);
            QVERIFY(std::abs(bp.mean - m.bp_Ns_per_m / L) < 0.15 * m.bp_Ns_per_m / L);
            QVERIFY(std::abs(bn.mean - m.bn_Ns_per_m / L) < 0.15 * m.bn_Ns_per_m / L);
            // The statistics are those of the per-run fits of the same runs.
            std::vector<double> per;
            for (const FrictionRunResult& f : analysis_.friction)
                if (f.run.endsWith(QStringLiteral("_f%1").arg(k)))
                    per.push_back(f.fit.perLength.Cp_N_per_m);
            QCOMPARE(per.size(), std::size_t(3));
            QCOMPARE(cp.mean, mean(per));
            QCOMPARE(cp.stdDev, sampleStdDev(per));
            QVERIFY(cp.stdDev > 0.0);
        }
        // Damping grows with frequency, as in the model.
        QVERIFY(cells[2].stats.at(QStringLiteral("bp_Ns_per_m2")).mean > cells[0].stats.at(QStringLiteral("bp_Ns_per_m2")).mean);
    }

    // A session's analysis (the Analysis tab, plan report, the demo's tables) fits each run as
    // `fit friction` does, the zero-velocity band found in its data: it kept a fixed ±2.5 mm/s,
    // and the same runs had another Cp and b there than from the command (probe).
    void theAnalysisFitsAsTheCommandDoes()
    {
        int compared = 0;
        for (const FrictionRunResult& f : analysis_.friction) {
            const auto r = std::find_if(dataset_.runs.begin(), dataset_.runs.end(), [&](const DatasetRun& d) { return d.name == f.run; });
            QVERIFY(r != dataset_.runs.end());
            FrictionOptions o;  // as the command sets them without --band-m-s
            o.thickness_mm = kThickness_mm;
            o.estimateBand = true;
            const FrictionFit alone = fitFriction(r->run, o);
            QVERIFY(f.fit.bandEstimated);
            QCOMPARE(f.fit.band_m_s, alone.band_m_s);
            QCOMPARE(f.fit.model.Cp_N, alone.model.Cp_N);
            QCOMPARE(f.fit.model.bn_Ns_per_m, alone.model.bn_Ns_per_m);
            ++compared;
        }
        QCOMPARE(compared, 9);
    }

    void twoFactorsMakeOneCellPerCombination()
    {
        const QStringList by{QStringLiteral("site"), QStringLiteral("frequency_hz")};
        const auto cells = groupByFactors(runFactorValues(dataset_, analysis_, by), by);
        QCOMPARE(cells.size(), std::size_t(9 + 1));
        const FactorCell* c = cellWith(cells, {QStringLiteral("2"), QStringLiteral("0.5")});
        QVERIFY(c);
        QCOMPARE(c->runs, std::size_t(1));
        QCOMPARE(c->stats.at(QStringLiteral("Dp_N_per_m")).n, std::size_t(1));
        QVERIFY(std::isnan(c->stats.at(QStringLiteral("Dp_N_per_m")).stdDev));  // one run: no spread to tell, not 0
        const FitTable t = factorTable(cells, by);
        QStringList keys;
        for (const TableColumn& col : t.columns)
            keys << col.key;
        QCOMPARE(keys, (QStringList{"site", "frequency_hz", "quantity", "unit", "mean", "std", "n"}));
        // 9 friction cells x 6 Karnopp values + the insertions' 4 stiffness values.
        QCOMPARE(t.rows.size(), std::size_t(9 * 6 + 4));
    }

    void stiffnessByTipFromPlainMetadata()
    {
        const QStringList by{QStringLiteral("tip")};
        const auto cells = groupByFactors(runFactorValues(dataset_, analysis_, by), by);
        const FactorCell* beveled = cellWith(cells, {QStringLiteral("beveled")});
        const FactorCell* diamond = cellWith(cells, {QStringLiteral("diamond")});
        QVERIFY(beveled && diamond);
        QCOMPARE(beveled->stats.at(QStringLiteral("a1_N_per_mm")).n, std::size_t(3));
        const double a1b = beveled->stats.at(QStringLiteral("a1_N_per_mm")).mean, a1d = diamond->stats.at(QStringLiteral("a1_N_per_mm")).mean;
        const double fd = diamond->stats.at(QStringLiteral("puncture_force_N")).mean;
        qInfo("a1 beveled %.4f (true 0.0480), diamond %.4f (true 0.0204) N/mm; diamond puncture force %.3f N", a1b, a1d, fd);
        QVERIFY(std::abs(a1b - 0.0480) < 0.1 * 0.0480);
        QVERIFY(std::abs(a1d - 0.0204) < 0.15 * 0.0204);
        synthetic::Insertion truth;
        truth.a1_N_per_mm = 0.0204;
        truth.a2_N_per_mm2 = 0.0008;
        truth.punctureDepth_mm = 10.4;
        QVERIFY(std::abs(fd - truth.force(truth.puncture_mm())) < 0.1 * truth.force(truth.puncture_mm()));
        QVERIFY(!beveled->stats.count(QStringLiteral("Cp_N_per_m")));
    }

    void table5Layout()
    {
        const QStringList by{QStringLiteral("frequency_hz")};
        const FitTable plain = frictionFrequencyTable(runFactorValues(dataset_, analysis_, by));
        QStringList keys;
        for (const TableColumn& c : plain.columns)
            keys << c.key;
        QCOMPARE(keys, (QStringList{"group", "statistic", "freq_Hz", "n", "m_est_kg", "Cp_N_per_m", "bp_Ns_per_m2", "Cn_N_per_m", "bn_Ns_per_m2",
                                    "Dp_N_per_m", "Dn_N_per_m"}));
        QCOMPARE(plain.rows.size(), std::size_t(8));
        const QStringList groups{"0.2Hz", "0.2Hz", "0.5Hz", "0.5Hz", "0.8Hz", "0.8Hz", "all", "all"};
        for (std::size_t i = 0; i < 8; ++i) {
            QCOMPARE(std::get<QString>(plain.rows[i][0]), groups[qsizetype(i)]);
            QCOMPARE(std::get<QString>(plain.rows[i][1]), i % 2 ? QStringLiteral("std") : QStringLiteral("mean"));
            QCOMPARE(std::get<double>(plain.rows[i][3]), i < 6 ? 3.0 : 9.0);
            QVERIFY(std::isnan(std::get<double>(plain.rows[i][4])));  // mass removed, not estimated
        }
        QCOMPARE(std::get<double>(plain.rows[2][2]), 0.5);
        QVERIFY(std::isnan(std::get<double>(plain.rows[6][2])));

        FactorAnalysisOptions o;
        o.estimateMass = true;
        QStringList warnings;
        const FitTable est = frictionFrequencyTable(runFactorValues(dataset_, analysis_, by, o, &warnings));
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join(QLatin1Char('\n'))));
        const double m = std::get<double>(est.rows[6][4]);
        qInfo("m_est over all runs %.4f kg (true %.4f)", m, kNeedleHolderMass_kg);
        QVERIFY(std::abs(m - kNeedleHolderMass_kg) < 0.2 * kNeedleHolderMass_kg);

        const QString text = fitTableText(plain);
        const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 9);
        QVERIFY(lines[0].startsWith(QStringLiteral("group  statistic")));
        QVERIFY(lines[7].startsWith(QStringLiteral("all    mean")));
        // Right-aligned figures: every data row ends at the same column.
        for (int i = 2; i < lines.size(); ++i)
            QCOMPARE(lines[i].size(), lines[1].size());
    }

    // A coefficient the run's fit flags as not physical is no result: left out of the run's
    // values (and so of its group's mean), and the report says which run and why. `plan
    // report` printed bp = 187 N s/m^2 where `fit friction` on the same run said "not phys.".
    void valuesTheFitFlagsAreLeftOut()
    {
        SessionAnalysis flagged = analysis_;
        FrictionRunResult& f = flagged.friction.front();
        QVERIFY(f.ok());
        f.fit.notPhysical = QStringList{QStringLiteral("bp < 0: damping cannot feed energy in")};
        f.fit.notPhysicalValues = QStringList{QStringLiteral("bp")};
        QStringList warnings;
        const auto values = runFactorValues(dataset_, flagged, QStringList{QStringLiteral("frequency_hz")}, {}, &warnings);
        const auto run = std::find_if(values.begin(), values.end(), [&](const RunFactorValues& v) { return v.run == f.run; });
        QVERIFY(run != values.end());
        QVERIFY(!run->values.count(QStringLiteral("bp_Ns_per_m2")));
        QVERIFY(run->values.count(QStringLiteral("bn_Ns_per_m2")) && run->values.count(QStringLiteral("Cp_N_per_m")));
        QCOMPARE(warnings.size(), 1);
        QVERIFY2(warnings[0].contains(f.run) && warnings[0].contains(QStringLiteral("bp < 0")), qPrintable(warnings[0]));
    }
};

QTEST_GUILESS_MAIN(TestFactorAnalysis)
#include "test_factor_analysis.moc"
