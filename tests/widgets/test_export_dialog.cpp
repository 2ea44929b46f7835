// Session ▸ Export session…: the dialog writes what `needlebench export` writes (the same
// core/export functions), reports progress, and a cancelled export leaves no file half written.
#include "core/session.h"
#include "widgets/analysis/analysis_workspace.h"
#include "widgets/export_dialog.h"

#include <QDir>
#include <QDirIterator>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
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

        // Again, the analysis's tables alone: the question counts them and names them (it
        // counted the data files alone and replaced these unsaid).
        dialog.setChoice({.csv = false, .hdf5 = false, .eaf = false, .figures = false, .tables = true});
        dialog.start();
        QMessageBox* question = nullptr;
        for (QMessageBox* q : dialog.findChildren<QMessageBox*>(QStringLiteral("replaceExport")))
            if (q->isVisible())
                question = q;
        QVERIFY(question);
        const qsizetype tables = analysis.allTablesPaths(QDir(out).filePath(QStringLiteral("analysis"))).size();
        QVERIFY(tables >= 10);
        QVERIFY2(question->text().contains(QStringLiteral(": %1 file(s) will be replaced").arg(tables)), qPrintable(question->text()));
        QVERIFY2(question->detailedText().contains(QDir::toNativeSeparators(QStringLiteral("analysis/stiffness_runs.csv"))),
                 qPrintable(question->detailedText()));
        question->button(QMessageBox::Cancel)->click();
        QVERIFY(!dialog.isRunning());

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

    // An export over an earlier one that fails half-way (the second run cannot be written) leaves
    // the earlier one as it was: it left the first run new and the second old (probe, a full disk).
    void aFailedExportLeavesTheEarlierOne()
    {
        const QString out = tmp_.filePath(QStringLiteral("earlier"));
        nb::ExportDialog dialog(session_, nullptr);
        dialog.setTargetDir(out);
        dialog.setChoice({.csv = true, .hdf5 = false, .eaf = false, .figures = false, .tables = false});
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        QVERIFY(done.wait(240000));
        QCOMPARE(done.first().first().toBool(), true);
        const QDir csv(QDir(out).filePath(QStringLiteral("csv")));
        {
            QFile f(csv.filePath(QStringLiteral("run_001_linear.csv")));
            QVERIFY(f.open(QIODevice::Append));
            f.write("# the earlier export's\n");
        }
        auto contents = [&csv] {
            QStringList all;
            for (const QString& name : csv.entryList(QDir::Files | QDir::Hidden | QDir::Dirs | QDir::NoDotAndDotDot)) {
                QFile f(csv.filePath(name));
                all << name + QLatin1Char(' ') + (f.open(QIODevice::ReadOnly) ? QString::number(qHash(f.readAll())) : QStringLiteral("-"));
            }
            return all;
        };
        // The second run's interval table cannot be written: a folder stands in its place.
        QVERIFY(QFile::remove(csv.filePath(QStringLiteral("run_002_linear.intervals.csv"))));
        QVERIFY(csv.mkdir(QStringLiteral("run_002_linear.intervals.csv")));
        const QStringList before = contents();
        QCOMPARE(before.size(), 6);
        done.clear();
        dialog.start();
        QMessageBox* q = nullptr;
        for (QMessageBox* m : dialog.findChildren<QMessageBox*>(QStringLiteral("replaceExport")))
            if (m->isVisible())
                q = m;
        QVERIFY(q);
        for (QAbstractButton* b : q->buttons())
            if (b->text().remove(QLatin1Char('&')) == QStringLiteral("Replace"))
                b->click();
        QVERIFY(done.wait(240000));
        QCOMPARE(done.first().first().toBool(), false);
        QVERIFY2(dialog.resultText().contains(QStringLiteral("is as it was")), qPrintable(dialog.resultText()));
        QCOMPARE(contents(), before);
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

    // The result is shown whole, the runs left out below it: the dialog kept its height and
    // cut the message after two lines, the warning unseen.
    void theWholeResultIsShown()
    {
        const QString cut = tmp_.filePath(QStringLiteral("cut_session"));
        nb::Session::create(cut, {});
        QFile whole(QDir(session_).filePath(QStringLiteral("run_001_linear.csv")));
        QVERIFY(whole.open(QIODevice::ReadOnly));
        QFile part(QDir(cut).filePath(QStringLiteral("run_001_linear.csv")));
        QVERIFY(part.open(QIODevice::WriteOnly));
        part.write(whole.read(whole.size() / 2));  // still recording, or cut off: left out
        part.close();
        nb::ExportDialog dialog(cut, nullptr);
        dialog.setTargetDir(tmp_.filePath(QStringLiteral("cut_export/with/a/long/enough/path/to/wrap/over/several/lines")));
        dialog.setChoice({.csv = true, .hdf5 = false, .eaf = false, .figures = false, .tables = false});
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        QVERIFY(done.wait(60000));
        QVERIFY2(dialog.resultText().contains(QStringLiteral("run_001_linear.csv")), qPrintable(dialog.resultText()));
        QLabel* status = nullptr;
        for (QLabel* l : dialog.findChildren<QLabel*>())
            if (l->text() == dialog.resultText())
                status = l;
        QVERIFY(status);
        QTRY_VERIFY2(status->height() >= status->heightForWidth(status->width()),
                     qPrintable(QStringLiteral("%1 px shown of %2").arg(status->height()).arg(status->heightForWidth(status->width()))));
    }

    // An export into a folder that holds one asks first (it replaced the files without a word):
    // an earlier export is replaced when the operator says so, Replace offered; a recorded run
    // of the same name (another session's folder) is named as such, Cancel offered, and kept.
    void replacingAsksFirst()
    {
        const QString small = tmp_.filePath(QStringLiteral("small"));
        nb::Session::create(small, {});
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                                QStringLiteral("--cycles"), QStringLiteral("1"), QStringLiteral("--frequency-hz"),
                                                QStringLiteral("1"), QStringLiteral("--out"), QDir(small).filePath(QStringLiteral("run_001_sine.csv"))});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 0);
        const auto bytes = [](const QString& path) {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const auto question = [](QWidget* dialog) -> QMessageBox* {
            for (QMessageBox* q : dialog->findChildren<QMessageBox*>(QStringLiteral("replaceExport")))
                if (q->isVisible())
                    return q;
            return nullptr;
        };
        const auto click = [](QMessageBox* q, const QString& text) {
            for (QAbstractButton* b : q->buttons())
                if (b->text().remove(QLatin1Char('&')) == text)
                    b->click();
        };

        nb::ExportDialog dialog(small, nullptr);
        const QString out = tmp_.filePath(QStringLiteral("replace"));
        dialog.setTargetDir(out);
        dialog.setChoice({.csv = true, .hdf5 = false, .eaf = false, .figures = false, .tables = false});
        QSignalSpy done(&dialog, &nb::ExportDialog::exportFinished);
        dialog.start();
        QVERIFY(!question(&dialog));  // nothing there: no question
        QVERIFY(done.wait(60000));
        QCOMPARE(done.first().first().toBool(), true);
        const QString csv = QDir(out).filePath(QStringLiteral("csv/run_001_sine.csv"));
        {
            QFile f(csv);
            QVERIFY(f.open(QIODevice::Append));
            f.write("edited after the export\n");
        }

        done.clear();
        dialog.start();
        QMessageBox* q = question(&dialog);
        QVERIFY(q);
        QVERIFY2(q->text().contains(QStringLiteral("earlier export")), qPrintable(q->text()));
        QCOMPARE(q->defaultButton()->text().remove(QLatin1Char('&')), QStringLiteral("Replace"));
        QVERIFY(!q->isModal());  // the window's emergency stop stays in reach
        q->button(QMessageBox::Cancel)->click();
        QVERIFY(!dialog.isRunning());
        QCOMPARE(done.count(), 0);
        QVERIFY(bytes(csv).contains("edited after the export"));
        QVERIFY(dialog.resultText().contains(QStringLiteral("kept")));

        dialog.start();
        q = question(&dialog);
        QVERIFY(q);
        click(q, QStringLiteral("Replace"));
        QVERIFY(done.wait(60000));
        QCOMPARE(done.first().first().toBool(), true);
        QVERIFY(!bytes(csv).contains("edited after the export"));

        // Not an export's: its sidecar gone, the CSV is a file of somebody's.
        QVERIFY(QFile::remove(QDir(out).filePath(QStringLiteral("csv/run_001_sine.json"))));
        const QByteArray theirs = bytes(csv);
        done.clear();
        dialog.start();
        q = question(&dialog);
        QVERIFY(q);
        QVERIFY2(q->text().contains(QStringLiteral("not an earlier export")), qPrintable(q->text()));
        QCOMPARE(q->defaultButton(), q->button(QMessageBox::Cancel));
        QVERIFY(q->detailedText().contains(QStringLiteral("run_001_sine.csv")));
        QTest::keyClick(q, Qt::Key_Return);  // the default: nothing replaced
        QCOMPARE(done.count(), 0);
        QCOMPARE(bytes(csv), theirs);
    }
};

QTEST_MAIN(TestExportDialog)
#include "test_export_dialog.moc"
