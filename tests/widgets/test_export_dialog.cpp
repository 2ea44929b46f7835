// Session ▸ Export session…: the dialog writes what `needlebench export` writes (the same
// core/export functions), reports progress, and a cancelled export leaves no file half written.
#include "core/session.h"
#include "widgets/analysis/analysis_workspace.h"
#include "widgets/export_dialog.h"

#include <QDir>
#include <QDirIterator>
#include <QProcess>
#include <QProgressBar>
#include <QTemporaryDir>
#include <QtTest>

class TestExportDialog : public QObject {
    Q_OBJECT
    QTemporaryDir tmp_;
    QString session_;

private slots:
    void initTestCase()
    {
        session_ = tmp_.filePath(QStringLiteral("liver_export"));
        nb::Session::create(session_, {});
        // Long runs (10 kHz) so that an export takes long enough to be cancelled.
        for (const char* name : {"run_001_linear.csv", "run_002_linear.csv"}) {
            QProcess p;
            p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                                    QStringLiteral("--rate-hz"), QStringLiteral("10000"), QStringLiteral("--velocity-mm-s"),
                                                    QStringLiteral("1"), QStringLiteral("--out"), QDir(session_).filePath(QLatin1String(name))});
            QVERIFY(p.waitForFinished(240000));
            QCOMPARE(p.exitCode(), 0);
        }
    }

    void exportsEverythingChosen()
    {
        nb::AnalysisWorkspace analysis;
        QVERIFY(analysis.openSession(session_));
        nb::ExportDialog dialog(session_, &analysis);
        const QString out = tmp_.filePath(QStringLiteral("all"));
        dialog.setTargetDir(out);
        dialog.setChoice({.csv = true, .hdf5 = true, .eaf = true, .figures = true, .tables = true});
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        QVERIFY(dialog.isRunning());
        QVERIFY(done.wait(240000));
        QCOMPARE(done.first().first().toBool(), true);
        for (const QString& f : {QStringLiteral("csv/run_001_linear.csv"), QStringLiteral("csv/run_001_linear.json"),
                                 QStringLiteral("csv/run_002_linear.intervals.csv"), QStringLiteral("eaf/run_002_linear.eaf"),
                                 QStringLiteral("liver_export.h5"), QStringLiteral("analysis/stiffness_runs.csv"),
                                 QStringLiteral("analysis/stiffness_runs.tex"), QStringLiteral("analysis/stiffness.png"),
                                 QStringLiteral("analysis/stiffness.pdf")})
            QVERIFY2(QFileInfo(QDir(out).filePath(f)).size() > 0, qPrintable(f));
        QVERIFY(dialog.written().contains(dialog.hdf5Path()));
        QCOMPARE(dialog.findChild<QProgressBar*>()->value(), dialog.findChild<QProgressBar*>()->maximum());
        QVERIFY(dialog.resultText().contains(QStringLiteral("Exported")));

        // The same bytes as the command line writes for the run CSV.
        const QString cli = tmp_.filePath(QStringLiteral("cli"));
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("export"), session_, QStringLiteral("--format"), QStringLiteral("csv"),
                                                QStringLiteral("--out"), cli});
        QVERIFY(p.waitForFinished(240000));
        QCOMPARE(p.exitCode(), 0);
        QFile a(QDir(out).filePath(QStringLiteral("csv/run_002_linear.csv"))), b(QDir(cli).filePath(QStringLiteral("run_002_linear.csv")));
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QVERIFY(a.readAll() == b.readAll());
    }

    void cancelLeavesNoHalfFile()
    {
        nb::ExportDialog dialog(session_, nullptr);
        const QString out = tmp_.filePath(QStringLiteral("cancelled"));
        dialog.setTargetDir(out);
        dialog.setChoice({.csv = false, .hdf5 = true, .eaf = false, .figures = false, .tables = false});
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        dialog.cancel();  // at once: the first chunk of a 10 kHz run is not written yet
        QVERIFY(done.wait(240000));
        QCOMPARE(done.first().first().toBool(), false);
        QVERIFY2(dialog.resultText().startsWith(QStringLiteral("Cancelled")), qPrintable(dialog.resultText()));
        QVERIFY(!QFileInfo::exists(dialog.hdf5Path()));
        QDirIterator it(out, QDir::Files, QDirIterator::Subdirectories);
        QStringList left;
        while (it.hasNext())
            left << it.next();
        QVERIFY2(left.isEmpty(), qPrintable(left.join(QLatin1Char(' '))));
        QVERIFY2(!QFileInfo::exists(out), "the folder made for the export, left empty");
    }

    // An export that fails takes away the folders it made and left empty (on a full disk an
    // empty csv/ folder was all there was), and keeps a folder that was there before.
    void failureLeavesNoEmptyFolder()
    {
        const QString empty = tmp_.filePath(QStringLiteral("no_runs"));
        nb::Session::create(empty, {});
        nb::ExportDialog dialog(empty, nullptr);
        const QString out = tmp_.filePath(QStringLiteral("nothing/to/export"));
        dialog.setTargetDir(out);
        dialog.setChoice({.csv = true, .hdf5 = false, .eaf = true, .figures = false, .tables = false});
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        QVERIFY(done.wait(60000));
        QCOMPARE(done.first().first().toBool(), false);
        QVERIFY2(dialog.resultText().contains(QStringLiteral("no runs")), qPrintable(dialog.resultText()));
        QVERIFY(!QFileInfo::exists(tmp_.filePath(QStringLiteral("nothing"))));

        // A folder that was there stays, even empty.
        const QString before = tmp_.filePath(QStringLiteral("was_there"));
        QVERIFY(QDir().mkpath(before));
        dialog.setTargetDir(before);
        done.clear();
        dialog.start();
        QVERIFY(done.wait(60000));
        QVERIFY(QFileInfo(before).isDir());
        QVERIFY(!QFileInfo::exists(QDir(before).filePath(QStringLiteral("csv"))));
    }
};

QTEST_MAIN(TestExportDialog)
#include "test_export_dialog.moc"
