// A labels file edited by hand, met in the real window on the simulated rig: the operator opens
// the run in Review while the stage moves a new insertion, the run shows with its good rows, the
// bad row is named, the file as typed is kept beside the run when the next label saves over it,
// and after a restart the window shows the saved labels without complaint.
#include "main_window.h"
#include "support/needlebench_cli.h"
#include "support/simulated_window.h"

#include "core/labels.h"
#include "core/session.h"
#include "devices/acquisition_engine.h"
#include "widgets/label_model.h"
#include "widgets/review_workspace.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

class TestHandEditedLabels : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_hand_edited_labels"));
    }

    void aBadRowWhileTheStageMoves()
    {
        QTemporaryDir tmp;
        const QString sessionDir = tmp.filePath(QStringLiteral("session"));
        nb::Session::create(sessionDir, {});
        const QString run = QDir(sessionDir).filePath(QStringLiteral("hand.csv"));
        const nbtest::CliResult sim = nbtest::runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                                      QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--out"), run});
        QVERIFY2(sim.code == 0, qPrintable(sim.err));
        const QByteArray typed = "track,label,start_s,end_s,comment\n"
                                 "insertion,a,0.1,0.4,\n"
                                 "insertion,b1,0.9,0.6,typed backwards\n"
                                 "events,puncture,1.5,1.5,\n";
        const QString labelsPath = nb::labelsPathFor(run);
        {
            QFile f(labelsPath);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(typed);
        }

        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        {
            nb::MainWindow w(nbtest::simulatedWindow(sessionDir, true, &rig));
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            nbtest::prepareToRecord(w);
            w.controlPanel()->button(nb::Control::StartInsertion)->click();
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().moving && w.engine()->status().recording, 20000);

            nb::ReviewWorkspace* review = w.reviewWorkspace();
            w.reviewRun(run);
            QVERIFY(w.engine()->status().moving);  // the stage still moves
            QCOMPARE(review->runPath(), run);
            QCOMPARE(review->labelModel()->labels().size(), std::size_t(2));
            QVERIFY2(review->status().contains(QStringLiteral("hand.labels.csv:3")), qPrintable(review->status()));
            const QString copy = QDir(sessionDir).filePath(QStringLiteral("hand.unread.labels.csv"));
            QVERIFY2(review->status().contains(QDir::toNativeSeparators(copy)), qPrintable(review->status()));
            QVERIFY(review->labelModel()->insertLabel({QStringLiteral("events"), QStringLiteral("contact"), 0.05, 0.05, {}}));
            QCOMPARE(nb::readLabelsFile(labelsPath).size(), std::size_t(3));
            QFile kept(copy);
            QVERIFY(kept.open(QIODevice::ReadOnly));
            QCOMPARE(kept.readAll(), typed);

            nbtest::endRun(w);
        }  // the window closes: a restart follows

        nb::MainWindow w(nbtest::simulatedWindow(sessionDir, true, &rig));
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.reviewRun(run);
        QCOMPARE(w.reviewWorkspace()->labelModel()->labels().size(), std::size_t(3));
        QVERIFY2(!w.reviewWorkspace()->status().contains(QStringLiteral("skipped")), qPrintable(w.reviewWorkspace()->status()));
    }
};

QTEST_MAIN(TestHandEditedLabels)
#include "test_hand_edited_labels.moc"
