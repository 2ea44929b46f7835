// The Analysis tab's "By factor" view (issue 16) on synthetic plan runs with known models:
// insertions at three velocities (a1 differs by velocity) and friction runs at three
// frequencies × two sites, tagged factor_* as a plan's runs are. The view offers the factors
// the runs carry, shows the chosen quantity per level with mean ± std and n (the numbers of
// core's factor analysis, as `plan report` prints them), follows the run list, and saves its
// tables with the others.
#include "core/synthetic.h"
#include "core/export/factor_analysis.h"
#include "core/export/fit_table.h"
#include "core/statistics.h"
#include "widgets/analysis/analysis_workspace.h"

#include <QComboBox>
#include <QListWidget>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <qcustomplot.h>

using namespace nb;

namespace {

const double kVelocities[] = {2.0, 4.0, 8.0};
const double kA1[] = {0.030, 0.048, 0.066};  // N/mm, per velocity level
const double kFreqs[] = {0.2, 0.5, 0.8};
constexpr std::uint32_t kSeed = 4100;

Dataset makeDataset()
{
    Dataset d;
    d.name = QStringLiteral("plan");
    std::uint32_t seed = kSeed;
    for (int level = 0; level < 3; ++level)
        for (int repeat = 0; repeat < 3; ++repeat) {
            synthetic::Insertion p;
            p.a1_N_per_mm = kA1[level];
            p.speed_mm_s = kVelocities[level];
            p.seed = seed++;
            DatasetRun r;
            r.name = QStringLiteral("run_v%1_r%2").arg(level).arg(repeat);
            r.run = synthetic::makeInsertion(p);
            r.run.metadata.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
            r.run.metadata.set(QStringLiteral("tissue"), QStringLiteral("liver1"));
            r.run.metadata.set(QStringLiteral("factor_velocity_mm_s"), QString::number(kVelocities[level]));
            r.run.metadata.set(QStringLiteral("factor_repeat"), QString::number(repeat + 1));
            r.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
            d.runs.push_back(std::move(r));
        }
    for (int site = 1; site <= 2; ++site)
        for (int k = 0; k < 3; ++k) {
            synthetic::Friction p;
            p.frequency_hz = kFreqs[k];
            p.cycles = 5;
            p.seed = seed++;
            DatasetRun r;
            r.name = QStringLiteral("run_s%1_f%2").arg(site).arg(k);
            r.run = synthetic::makeFriction(p);
            r.run.metadata.set(QStringLiteral("protocol"), QStringLiteral("friction"));
            r.run.metadata.set(QStringLiteral("thickness_mm"), 30.0);
            r.run.metadata.set(QStringLiteral("factor_site"), QString::number(site));
            r.run.metadata.set(QStringLiteral("factor_frequency_hz"), QString::number(kFreqs[k]));
            r.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
            d.runs.push_back(std::move(r));
        }
    return d;
}

QStringList items(const QComboBox* box)
{
    QStringList out;
    for (int i = 0; i < box->count(); ++i)
        out << box->itemText(i);
    return out;
}

// The factors' keys (the items' data); the text is the factor's name in the operator's language.
QStringList keys(const QComboBox* box)
{
    QStringList out;
    for (int i = 0; i < box->count(); ++i)
        out << box->itemData(i).toString();
    return out;
}

void choose(QComboBox* box, const QString& key)
{
    box->setCurrentIndex(box->findData(key));
}

int column(const QStandardItemModel* m, const QString& header)
{
    for (int c = 0; c < m->columnCount(); ++c)
        if (m->horizontalHeaderItem(c)->text() == header)
            return c;
    return -1;
}

}  // namespace

class TestAnalysisByFactor : public QObject {
    Q_OBJECT
private slots:
    void quantityPerLevelOfAnyFactor()
    {
        qInfo("synthetic runs with seeds %u to %u", kSeed, kSeed + 14);
        AnalysisWorkspace w;
        w.resize(1200, 800);
        w.setDataset(makeDataset());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.tabs()->tabText(3), QStringLiteral("By factor"));
        w.tabs()->setCurrentIndex(3);

        // The factors the runs carry, in the order met; the quantities fitted.
        QCOMPARE(keys(w.factorChooser()), (QStringList{"velocity_mm_s", "repeat", "site", "frequency_hz"}));
        QCOMPARE(items(w.factorChooser()), (QStringList{"velocity [mm/s]", "repeat", "site", "frequency [Hz]"}));
        const QStringList quantities = items(w.quantityChooser());
        for (const char* q : {"a1 [N/mm]", "a2 [N/mm^2]", "puncture force [N]", "puncture depth [mm]", "Cp [N/m]", "Cn [N/m]", "bp [N s/m^2]",
                              "bn [N s/m^2]", "Dp [N/m]", "Dn [N/m]"})
            QVERIFY2(quantities.contains(QLatin1String(q)), qPrintable(quantities.join(QLatin1Char('|'))));

        // a1 against velocity: three levels, n = 3 each, the numbers of core's factor analysis.
        choose(w.factorChooser(), QStringLiteral("velocity_mm_s"));
        w.quantityChooser()->setCurrentIndex(w.quantityChooser()->findData(QStringLiteral("a1_N_per_mm")));
        QStandardItemModel* m = w.factorModel();
        QCOMPARE(m->rowCount(), 3);
        const int level = column(m, QStringLiteral("velocity_mm_s")), meanCol = column(m, QStringLiteral("mean")),
                  stdCol = column(m, QStringLiteral("std")), nCol = column(m, QStringLiteral("n"));
        QVERIFY(level >= 0 && meanCol >= 0 && stdCol >= 0 && nCol >= 0);
        const auto cells = groupByFactors(runFactorValues(w.dataset(), w.analysis(), {QStringLiteral("velocity_mm_s")}),
                                          {QStringLiteral("velocity_mm_s")});
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(m->item(i, level)->text(), QString::number(kVelocities[i]));
            QCOMPARE(m->item(i, nCol)->data(Qt::UserRole).toDouble(), 3.0);
            const double shown = m->item(i, meanCol)->data(Qt::UserRole).toDouble();
            const auto& core = cells[std::size_t(i)].stats.at(QStringLiteral("a1_N_per_mm"));
            QCOMPARE(shown, core.mean);
            QCOMPARE(m->item(i, stdCol)->data(Qt::UserRole).toDouble(), core.stdDev);
            QVERIFY(core.stdDev > 0.0);
            qInfo("a1 at %.0f mm/s: %.4f ± %.4f N/mm (true %.4f)", kVelocities[i], shown, core.stdDev, kA1[i]);
            QVERIFY(std::abs(shown - kA1[i]) < 0.15 * kA1[i]);
        }

        // The plot: each run, and a mean with its error bar per level, n under each level.
        QCustomPlot* plot = w.factorPlot();
        QCPGraph* means = nullptr;
        for (int g = 0; g < plot->graphCount(); ++g)
            if (plot->graph(g)->name().contains(QStringLiteral("mean")))
                means = plot->graph(g);
        QVERIFY(means);
        QCOMPARE(means->data()->size(), 3);
        QCOMPARE(means->data()->at(1)->value, m->item(1, meanCol)->data(Qt::UserRole).toDouble());
        QCPErrorBars* bars = nullptr;
        for (int i = 0; i < plot->plottableCount(); ++i)
            if (auto* b = qobject_cast<QCPErrorBars*>(plot->plottable(i)))
                bars = b;
        QVERIFY(bars);
        QCOMPARE(bars->data()->at(2).errorPlus, m->item(2, stdCol)->data(Qt::UserRole).toDouble());
        auto ticker = plot->xAxis->ticker().dynamicCast<QCPAxisTickerText>();
        QVERIFY(ticker);
        QVERIFY(ticker->ticks().value(0.0).contains(QStringLiteral("n = 3")));

        // Friction per frequency: Cp at three levels of two runs each.
        choose(w.factorChooser(), QStringLiteral("frequency_hz"));
        w.quantityChooser()->setCurrentIndex(w.quantityChooser()->findData(QStringLiteral("Cp_N_per_m")));
        QCOMPARE(m->rowCount(), 3);
        for (int i = 0; i < 3; ++i)
            QCOMPARE(m->item(i, nCol)->data(Qt::UserRole).toDouble(), 2.0);

        // A run left out of the analysis leaves its level's n.
        QListWidget* runs = w.findChild<QListWidget*>();
        QVERIFY(runs);
        const QList<QListWidgetItem*> found = runs->findItems(QStringLiteral("run_s1_f1"), Qt::MatchExactly);
        QCOMPARE(found.size(), 1);
        found.first()->setCheckState(Qt::Unchecked);
        QCOMPARE(w.factorChooser()->currentData().toString(), QStringLiteral("frequency_hz"));
        QCOMPARE(w.quantityChooser()->currentData().toString(), QStringLiteral("Cp_N_per_m"));
        QCOMPARE(m->item(1, nCol)->data(Qt::UserRole).toDouble(), 1.0);
        QVERIFY(std::isnan(m->item(1, stdCol)->data(Qt::UserRole).toDouble()));  // one run: no spread to tell, not 0

        // Saved with the other tables: each factor's table.
        QTemporaryDir out;
        const QStringList written = w.saveAllTables(out.path());
        QVERIFY(written.contains(out.filePath(QStringLiteral("by_factor_velocity_mm_s.csv"))));
        QVERIFY(written.contains(out.filePath(QStringLiteral("by_factor_frequency_hz.tex"))));
        QFile csv(out.filePath(QStringLiteral("by_factor_velocity_mm_s.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll(), fitTableCsv(w.factorTableFor(QStringLiteral("velocity_mm_s"))));
    }

    void runsWithoutAPlanOfferNoFactorOfTheirOwn()
    {
        Dataset d = makeDataset();
        for (DatasetRun& r : d.runs) {
            Metadata kept;
            for (const auto& [k, v] : r.run.metadata.entries())
                if (!k.startsWith(QLatin1String("factor_")))
                    kept.set(k, v);
            r.run.metadata = kept;
        }
        AnalysisWorkspace w;
        w.setDataset(d);
        // No factor of a plan: only the settings the runs differ in (here the friction runs'
        // frequencies, from their headers) are offered, and no by-factor table is saved.
        for (int i = 0; i < w.factorChooser()->count(); ++i)
            QVERIFY2(datasetSettingFactors(d).contains(w.factorChooser()->itemData(i).toString()), qPrintable(w.factorChooser()->itemText(i)));
        QVERIFY(datasetFactors(d).isEmpty());
        QTemporaryDir out;
        for (const QString& f : w.saveAllTables(out.path()))
            QVERIFY(!QFileInfo(f).fileName().startsWith(QLatin1String("by_factor")));
    }

    // Runs made without a plan that differ in a setting (here their velocity, recorded as the
    // setting it is, not as a factor): By factor offers that setting, where it showed an empty
    // plot titled "a1 by no factor". A setting all runs share is no factor.
    void runsWithoutAPlanOfferTheSettingsTheyDifferIn()
    {
        Dataset d = makeDataset();
        for (DatasetRun& r : d.runs) {
            Metadata kept;
            for (const auto& [k, v] : r.run.metadata.entries())
                if (k == QLatin1String("factor_velocity_mm_s"))
                    kept.set(QStringLiteral("velocity_mm_s"), v);
                else if (!k.startsWith(QLatin1String("factor_")))
                    kept.set(k, v);
            r.run.metadata = kept;
        }
        AnalysisWorkspace w;
        w.setDataset(d);
        QStringList offered;
        for (int i = 0; i < w.factorChooser()->count(); ++i)
            offered << w.factorChooser()->itemData(i).toString();
        QVERIFY2(offered.contains(QStringLiteral("velocity_mm_s")), qPrintable(offered.join(QStringLiteral(", "))));
        QVERIFY(!offered.contains(QStringLiteral("tissue")));  // liver1 in every run
        choose(w.factorChooser(), QStringLiteral("velocity_mm_s"));
        QVERIFY(w.factorModel()->rowCount() > 0);
    }
};

QTEST_MAIN(TestAnalysisByFactor)
#include "test_analysis_by_factor.moc"
