// The operator's choices in Analysis, met in the real window on the simulated rig: a run taken
// out of the fits stays out when the next run is recorded (the session is read again then), and
// after a restart the page, the switch for runs cut short, By factor's factor and quantity and
// the runs taken out come back. All of them were lost: the list was ticked afresh with every
// recording and every start.
#include "main_window.h"
#include "support/needlebench_cli.h"
#include "support/simulated_window.h"
#include "support/truth_columns.h"

#include "core/run_file.h"
#include "core/session.h"
#include "devices/acquisition_engine.h"
#include "widgets/analysis/analysis_workspace.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

namespace {

QListWidgetItem* runItem(nb::AnalysisWorkspace* a, const QString& name)
{
    const auto found = a->findChild<QListWidget*>()->findItems(name, Qt::MatchExactly);
    return found.isEmpty() ? nullptr : found.first();
}

nb::WorkbenchOptions persisted(const QString& sessionDir, std::shared_ptr<nb::devices::sim::SimulatedRig>* rig)
{
    nb::WorkbenchOptions o = nbtest::simulatedWindow(sessionDir, true, rig);
    o.persistSettings = true;
    return o;
}

}  // namespace

class TestAnalysisChoices : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);  // the test's settings, not the user's
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_analysis_choices"));
        QSettings().clear();
    }

    void choicesOutliveARecordingAndARestart()
    {
        QTemporaryDir tmp;
        const QString sessionDir = tmp.filePath(QStringLiteral("session"));
        nb::Session::create(sessionDir, {});
        // Three friction runs at two frequencies: the frequency is a setting they differ in,
        // which By factor offers as a factor.
        const QStringList names{QStringLiteral("run_001_slow"), QStringLiteral("run_002_slow"), QStringLiteral("run_003_fast")};
        const QStringList hz{QStringLiteral("0.3"), QStringLiteral("0.3"), QStringLiteral("0.6")};
        for (int i = 0; i < names.size(); ++i) {
            const nbtest::CliResult sim = nbtest::runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                                          QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--frequency-hz"), hz[i],
                                                          QStringLiteral("--seed"), QString::number(11 + i), QStringLiteral("--out"),
                                                          QDir(sessionDir).filePath(names[i] + QStringLiteral(".csv"))});
            QVERIFY2(sim.code == 0, qPrintable(sim.err));
        }

        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        QString factor, quantity;
        {
            nb::MainWindow w(persisted(sessionDir, &rig));
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            nb::AnalysisWorkspace* a = w.analysisWorkspace();
            w.workspaces()->setCurrentWidget(a);
            QVERIFY2(runItem(a, QStringLiteral("run_002_slow")), qPrintable(a->statusText()));
            runItem(a, QStringLiteral("run_002_slow"))->setCheckState(Qt::Unchecked);
            QVERIFY(!a->selectedRuns().contains(QStringLiteral("run_002_slow")));
            a->setIncludeJudgedOut(true);
            a->tabs()->setCurrentIndex(a->tabs()->count() - 1);  // By factor
            QVERIFY2(a->factorChooser()->count() >= 1, "no factor offered for runs at two frequencies");
            QVERIFY(a->quantityChooser()->count() >= 2);
            a->quantityChooser()->setCurrentIndex(1);
            factor = a->factorChooser()->currentData().toString();
            quantity = a->quantityChooser()->currentData().toString();

            // A new run is recorded while Analysis shows: the session is read again at its end.
            nbtest::prepareToRecord(w);
            w.controlPanel()->button(nb::Control::StartInsertion)->click();
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().moving && w.engine()->status().recording, 20000);
            const int before = a->findChild<QListWidget*>()->count();
            nbtest::endRun(w);
            QTRY_COMPARE_WITH_TIMEOUT(a->findChild<QListWidget*>()->count(), before + 1, 20000);
            QVERIFY2(!a->selectedRuns().contains(QStringLiteral("run_002_slow")), qPrintable(a->selectedRuns().join(QLatin1Char(','))));
            QCOMPARE(a->selectedRuns().size(), before);  // the new run counts, the one taken out does not
            // Read again, the session is analysed once, with the run already out: every run is
            // fitted again, and twice was a second's wait on a day's session.
            QSignalSpy analysed(a, &nb::AnalysisWorkspace::analysisUpdated);
            QVERIFY(a->openSession(sessionDir));
            QCOMPARE(analysed.count(), 1);
            QVERIFY(!a->selectedRuns().contains(QStringLiteral("run_002_slow")));
            QVERIFY(a->includeJudgedOut());
            QCOMPARE(a->quantityChooser()->currentData().toString(), quantity);
            // Stopped a few millimetres in, the needle may be in the tissue: if the window asks,
            // the operator confirms the quit.
            nbtest::quitConfirming(w);
        }  // a restart follows

        {
            nb::MainWindow w(persisted(QString(), &rig));  // the last session, as a plain start opens it
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.session());
            nb::AnalysisWorkspace* a = w.analysisWorkspace();
            QVERIFY(runItem(a, QStringLiteral("run_002_slow")));
            QCOMPARE(runItem(a, QStringLiteral("run_002_slow"))->checkState(), Qt::Unchecked);
            QCOMPARE(runItem(a, QStringLiteral("run_001_slow"))->checkState(), Qt::Checked);
            QCOMPARE(runItem(a, QStringLiteral("run_003_fast"))->checkState(), Qt::Checked);
            QVERIFY(a->includeJudgedOut());
            QCOMPARE(a->tabs()->currentIndex(), a->tabs()->count() - 1);
            QCOMPARE(a->factorChooser()->currentData().toString(), factor);
            QCOMPARE(a->quantityChooser()->currentData().toString(), quantity);
            QVERIFY(w.close());
        }

        // Another session does not take this one's runs out, and opening this one again does.
        const QString other = tmp.filePath(QStringLiteral("other"));
        nb::Session::create(other, {});
        const nbtest::CliResult sim = nbtest::runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                                      QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--out"),
                                                      QDir(other).filePath(QStringLiteral("run_002_slow.csv"))});
        QVERIFY2(sim.code == 0, qPrintable(sim.err));
        nb::MainWindow o(persisted(other, &rig));
        o.show();
        QVERIFY(QTest::qWaitForWindowExposed(&o));
        QVERIFY(runItem(o.analysisWorkspace(), QStringLiteral("run_002_slow")));
        QCOMPARE(runItem(o.analysisWorkspace(), QStringLiteral("run_002_slow"))->checkState(), Qt::Checked);
        // Back to the first session in the same window: its run is out again.
        QVERIFY(o.openSession(sessionDir));
        QCOMPARE(runItem(o.analysisWorkspace(), QStringLiteral("run_002_slow"))->checkState(), Qt::Unchecked);
        QCOMPARE(runItem(o.analysisWorkspace(), QStringLiteral("run_001_slow"))->checkState(), Qt::Checked);
        QVERIFY(o.close());
        QSettings().clear();
    }

    // One noisy liver 3 slab at three frequencies (after bench_accuracy --seed 88, rig set 2),
    // force and position only, read in the real window's Analysis while the stage moves and
    // records the next insertion. The 0.51 Hz run's own Cp is 5.6 % high, 6.0 % from the line
    // through the runs' peak speeds (the draw test_rig_friction's
    // runsOffTheLineAreToldWhateverTheirOwnError takes). Before, the set had no such line and no
    // run was named; now the summary carries the line and the status names the run that departs
    // from it.
    void runOffThePeakSpeedLineIsNamed()
    {
        QTemporaryDir tmp;
        const QString sessionDir = tmp.filePath(QStringLiteral("liver3"));
        nb::Session::create(sessionDir, {});
        const QStringList hz{QStringLiteral("0.2899"), QStringLiteral("0.5070"), QStringLiteral("0.6809")};
        for (int k = 0; k < 3; ++k) {
            const QString full = tmp.filePath(QStringLiteral("full_%1.csv").arg(k));
            const nbtest::CliResult sim = nbtest::runCli(
                {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"), QStringLiteral("--tissue"), QStringLiteral("liver3"),
                 QStringLiteral("--frequency-hz"), hz[k], QStringLiteral("--amplitude-mm"), QStringLiteral("7.009"), QStringLiteral("--stick-band-mm-s"),
                 QStringLiteral("3.465"), QStringLiteral("--plate-gap-mm"), QStringLiteral("1.431"), QStringLiteral("--force-noise-n"),
                 QStringLiteral("0.00930"), QStringLiteral("--cycles"), QStringLiteral("7"), QStringLiteral("--seed"), QString::number(83923 + k),
                 QStringLiteral("--out"), full});
            QVERIFY2(sim.code == 0, qPrintable(sim.err));
            nb::writeRunFile(QDir(sessionDir).filePath(QStringLiteral("run_00%1_sine.csv").arg(k + 1)),
                             nbtest::withoutTruthColumns(nb::readRunFile(full).run));
        }
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(persisted(sessionDir, &rig));
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        nbtest::prepareToRecord(w);
        w.controlPanel()->button(nb::Control::StartInsertion)->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().moving && w.engine()->status().recording, 20000);
        nb::AnalysisWorkspace* a = w.analysisWorkspace();
        w.workspaces()->setCurrentWidget(a);
        const QString status = a->statusText();
        QVERIFY2(status.contains(QStringLiteral("run_002_sine: C departs from the peak-speed line")), qPrintable(status));
        QVERIFY2(!status.contains(QStringLiteral("run_003_sine: C departs")), qPrintable(status));
        bool lineRow = false;
        for (int r = 0; r < a->frictionSummaryModel()->rowCount(); ++r)
            lineRow |= a->frictionSummaryModel()->item(r, 0)->text().startsWith(QStringLiteral("peak speeds"));
        QVERIFY2(lineRow, "the friction summary carries the line through the peak speeds");
        nbtest::endRun(w);
        nbtest::quitConfirming(w);
        QSettings().clear();
    }
};

QTEST_MAIN(TestAnalysisChoices)
#include "test_analysis_choices.moc"
