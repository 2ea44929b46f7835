// A full disk, for real: a small tmpfs this test mounts (we need root; without the right to
// mount the whole program is skipped with exit code 77). A recording that fills it must end
// with a footer saying why, keep every row before the failure whole, tell the operator and
// exit 1; exports onto it must fail with a clear message and leave nothing half-written.

#include "support/needlebench_cli.h"

#include "core/labels.h"
#include "core/run_file.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <cstdio>

using nbtest::runCli;

namespace {

bool mountTmpfs(const QString& dir, const QString& size)
{
    QProcess p;
    p.start(QStringLiteral("mount"), {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                                      QStringLiteral("size=") + size, QStringLiteral("tmpfs"), dir});
    return p.waitForFinished(10000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

void unmount(const QString& dir)
{
    QProcess p;
    p.start(QStringLiteral("umount"), {dir});
    p.waitForFinished(10000);
}

void emptyFolder(const QString& dir)
{
    QDir d(dir);
    for (const QString& f : d.entryList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden)) {
        QFileInfo fi(d.filePath(f));
        if (fi.isDir())
            QDir(fi.filePath()).removeRecursively();
        else
            QFile::remove(fi.filePath());
    }
}

// Nothing escaped main and nothing crashed: exit codes are the documented ones.
void checkClean(const nbtest::CliResult& r)
{
    QVERIFY2(r.code == 0 || r.code == 1 || r.code == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(!r.err.contains(QLatin1String("terminate called")) && !r.err.contains(QLatin1String("internal error")), qPrintable(r.err));
}

}  // namespace

class TestDiskFull : public QObject {
    Q_OBJECT
public:
    QString small;   // 3 MB: a recording fills it in seconds
    QString tiny;    // 64 kB: exports do not fit

private slots:
    void cleanup()
    {
        emptyFolder(small);
        emptyFolder(tiny);
    }

    void recordingOnAFullDiskEndsWithFooterAndExit1()
    {
        const QString out = QDir(small).filePath(QStringLiteral("run.csv"));
        const auto r = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                               QStringLiteral("--rate-hz"), QStringLiteral("10000"), QStringLiteral("--out"), out});
        checkClean(r);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QLatin1String("recording failed")) && r.err.contains(QLatin1String("No space left")), qPrintable(r.err));
        QCOMPARE(r.json().value(QStringLiteral("end_reason")).toString(), QStringLiteral("write_error"));
        // Read strictly: a partial row would be an error here, not a warning.
        const nb::RunReadResult read = nb::readRunFile(out);
        QVERIFY(read.warnings.isEmpty());
        const nb::Run& run = read.run;
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("write_error"));
        QVERIFY(run.footer.value(QStringLiteral("write_error"), QString()).contains(QLatin1String("No space left")));
        QVERIFY(run.size() > 1000);
        QCOMPARE(run.footer.number(QStringLiteral("rows_written")).value_or(-1), double(run.size()));
        QCOMPARE(r.json().value(QStringLiteral("samples")).toDouble(), double(run.size()));
        // Every row whole: the last one has all its columns and a sane time.
        QCOMPARE(run.numericColumn(QStringLiteral("seq"))->size(), run.size());
        QVERIFY(run.time_s.back() > 0.1);
    }

    void truthAndVideoAreNotListedWhenTheDiskIsFull()
    {
        const QDir d(small);
        const auto r = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                               QStringLiteral("--rate-hz"), QStringLiteral("10000"), QStringLiteral("--out"), d.filePath(QStringLiteral("run.csv")),
                               QStringLiteral("--truth"), d.filePath(QStringLiteral("truth.json")), QStringLiteral("--video"),
                               d.filePath(QStringLiteral("view.avi"))});
        checkClean(r);
        QCOMPARE(r.code, 1);
        QVERIFY(!r.json().contains(QStringLiteral("truth")));
        const QFileInfo truth(d.filePath(QStringLiteral("truth.json")));
        QVERIFY2(!truth.exists() || truth.size() > 0, "a 0-byte truth file was left");
        QVERIFY2(!QFileInfo::exists(d.filePath(QStringLiteral("view.avi"))), "a half video was left");

        // A run that fits and a video that does not: said in NeedleBench's words alone (the
        // read-back of the half-written video went through GStreamer, whose errors were printed).
        emptyFolder(small);
        const auto v = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--out"),
                               d.filePath(QStringLiteral("s.csv")), QStringLiteral("--video"), d.filePath(QStringLiteral("s.avi"))});
        checkClean(v);
        QCOMPARE(v.code, 1);
        QVERIFY2(v.err.contains(QStringLiteral("s.avi")), qPrintable(v.err));
        QVERIFY2(!v.err.contains(QStringLiteral("GStreamer")) && !v.err.contains(QStringLiteral("OpenCV")), qPrintable(v.err));
        QVERIFY(!QFileInfo::exists(d.filePath(QStringLiteral("s.avi"))));
    }

    void realTimeRecordingWarnsBeforeTheDiskIsFull()
    {
        const QString out = QDir(small).filePath(QStringLiteral("rt.csv"));
        const auto r = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                               QStringLiteral("--realtime"), QStringLiteral("--rate-hz"), QStringLiteral("10000"),
                               QStringLiteral("--out"), out});
        checkClean(r);
        QCOMPARE(r.code, 1);
        const qsizetype warned = r.err.indexOf(QLatin1String("will be full"));
        const qsizetype failed = r.err.indexOf(QLatin1String("recording failed"));
        QVERIFY2(warned >= 0 && failed > warned, qPrintable(r.err));
        // Progress stops with the recording: no progress line claims more than the file holds.
        const nb::Run run = nb::readRunFile(out).run;
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("write_error"));
    }

    // Free space is checked before a run starts: on a disk with less than a megabyte free the
    // run is refused, naming the file and what is free.
    void tooLittleSpaceRefusesTheRun()
    {
        const QString out = QDir(tiny).filePath(QStringLiteral("run.csv"));
        const auto r = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                               QStringLiteral("--out"), out});
        checkClean(r);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(out) && r.err.contains(QLatin1String("kB free")), qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(out));
    }

    void exportsOntoAFullDiskFailCleanly()
    {
        QTemporaryDir session;
        const auto sim = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                 QStringLiteral("--out"), QDir(session.path()).filePath(QStringLiteral("run1.csv"))});
        QCOMPARE(sim.code, 0);
        for (const char* format : {"hdf5", "csv", "eaf"}) {
            const QString out = QDir(tiny).filePath(format == QByteArray("hdf5") ? QStringLiteral("s.h5") : QStringLiteral("out"));
            const auto r = runCli({QStringLiteral("export"), session.path(), QStringLiteral("--format"), QLatin1String(format),
                                   QStringLiteral("--out"), out});
            checkClean(r);
            QCOMPARE(r.code, 1);
            QVERIFY2(r.err.contains(QLatin1String("space"), Qt::CaseInsensitive), qPrintable(r.err));
            QVERIFY2(!r.err.contains(QLatin1String("Unknown error")), qPrintable(r.err));
            QVERIFY(!QFileInfo::exists(out + QStringLiteral(".part")));
            QVERIFY(!QFileInfo::exists(QDir(tiny).filePath(QStringLiteral("s.h5"))));
            QVERIFY2(!QFileInfo::exists(QDir(tiny).filePath(QStringLiteral("out"))), "the folder made for the export, left empty");
            emptyFolder(tiny);
        }

        // Small runs first, written whole, then one the disk cannot take: the small ones' files
        // are taken away with the folder. They were left, looking like a whole export of fewer runs.
        for (int k = 0; k < 3; ++k) {
            QFile f(QDir(session.path()).filePath(QStringLiteral("run0%1.csv").arg(k)));
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            f.write("# format: needlebench-run 1\n# motion: linear\ntime_s,position_mm,force_N\n");
            for (int i = 0; i < 20; ++i)
                f.write(QStringLiteral("%1,%2,%3\n").arg(i * 0.001).arg(i * 0.01).arg(i * 0.002).toUtf8());
            f.write("# end_reason: completed\n");
        }
        const QString out = QDir(tiny).filePath(QStringLiteral("out"));
        const auto r = runCli({QStringLiteral("export"), session.path(), QStringLiteral("--format"), QStringLiteral("csv"), QStringLiteral("--out"), out});
        checkClean(r);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.out.contains(QStringLiteral("[4/4] run1")) && r.err.contains(QStringLiteral("written are removed")), qPrintable(r.out + r.err));
        QVERIFY2(!QFileInfo::exists(out), qPrintable(QDir(out).entryList(QDir::Files).join(QLatin1Char(' '))));
    }

    // An export over an earlier one that fails half-way leaves the earlier one as it was: it left
    // the first run new and the rest old, naming only the file that failed (probe).
    void anExportThatFailsLeavesTheEarlierOne()
    {
        QTemporaryDir first, second;
        auto simulate = [](const QString& dir, const QString& name, const QStringList& more) {
            return runCli(QStringList{QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                      QStringLiteral("--out"), QDir(dir).filePath(name)} + more).code;
        };
        const QStringList small{QStringLiteral("--depth-mm"), QStringLiteral("8"), QStringLiteral("--rate-hz"), QStringLiteral("100")};
        QCOMPARE(simulate(first.path(), QStringLiteral("run1.csv"), small), 0);
        const QString out = QDir(tiny).filePath(QStringLiteral("out"));
        const auto earlier = runCli({QStringLiteral("export"), first.path(), QStringLiteral("--format"), QStringLiteral("csv"),
                                     QStringLiteral("--out"), out});
        QVERIFY2(earlier.code == 0, qPrintable(earlier.err));
        auto contents = [&out] {
            QStringList all;
            for (const QString& f : QDir(out).entryList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden)) {
                QFile file(QDir(out).filePath(f));
                all << f + QLatin1Char(' ') + (file.open(QIODevice::ReadOnly) ? QString::number(qHash(file.readAll())) : QStringLiteral("dir"));
            }
            return all;
        };
        const QStringList before = contents();
        QCOMPARE(before.size(), 3);  // run1.csv, .json, .intervals.csv
        // Another session: its run1 fits, its run2 (a whole run at 1 kHz) does not.
        QCOMPARE(simulate(second.path(), QStringLiteral("run1.csv"), small + QStringList{QStringLiteral("--tissue"), QStringLiteral("liver2")}), 0);
        QCOMPARE(simulate(second.path(), QStringLiteral("run2.csv"), {}), 0);
        const auto r = runCli({QStringLiteral("export"), second.path(), QStringLiteral("--format"), QStringLiteral("csv"),
                               QStringLiteral("--out"), out});
        checkClean(r);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QLatin1String("space"), Qt::CaseInsensitive) && r.err.contains(QLatin1String("is as it was")), qPrintable(r.err));
        QCOMPARE(contents(), before);
    }

    // Review saves the labels after every change. On a full disk the save fails and the labels
    // saved before stay whole: Qt's QSaveFile replaced them with an empty file and said it had
    // written them.
    void labelsOnAFullDiskKeepTheLastSaved()
    {
        const QString path = QDir(tiny).filePath(QStringLiteral("run.labels.csv"));
        nb::Labels labels;
        for (int i = 0; i < 20; ++i)
            labels.push_back({QStringLiteral("insertion"), QStringLiteral("a"), i * 1.0, i + 0.5, QStringLiteral("by hand")});
        nb::writeLabelsFile(path, labels);
        QCOMPARE(nb::readLabelsFile(path), labels);
        QFile filler(QDir(tiny).filePath(QStringLiteral("filler")));
        QVERIFY(filler.open(QIODevice::WriteOnly));
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size() && filler.flush()) {
        }
        filler.close();
        nb::Labels more = labels;
        more.push_back({QStringLiteral("events"), QStringLiteral("puncture"), 30.0, 30.0, QString()});
        bool refused = false;
        try {
            nb::writeLabelsFile(path, more);
        } catch (const nb::Error& e) {
            refused = true;
            QVERIFY2(e.message().contains(QLatin1String("space"), Qt::CaseInsensitive), qPrintable(e.message()));
        }
        QVERIFY(refused);
        QCOMPARE(nb::readLabelsFile(path), labels);
    }

    // The traces `sync` and `labels suggest` write after minutes of tracking: a full disk gets a
    // message that says so and leaves no half-written trace (it said "cannot write the trace
    // here" and wrote no reason). Nothing but the trace is written to the full disk.
    void tracesOntoAFullDiskFailCleanly()
    {
        QTemporaryDir work;
        const QString run = QDir(work.path()).filePath(QStringLiteral("fr.csv")), video = QDir(work.path()).filePath(QStringLiteral("fr.avi"));
        const auto sim = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"), QStringLiteral("--cycles"),
                                 QStringLiteral("2"), QStringLiteral("--frequency-hz"), QStringLiteral("0.8"), QStringLiteral("--out"), run,
                                 QStringLiteral("--video"), video, QStringLiteral("--video-offset-s"), QStringLiteral("0.5")});
        QCOMPARE(sim.code, 0);
        QFile filler(QDir(tiny).filePath(QStringLiteral("filler")));
        QVERIFY(filler.open(QIODevice::WriteOnly));
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size() && filler.flush()) {
        }
        filler.close();
        const QString syncTrace = QDir(tiny).filePath(QStringLiteral("track.csv"));
        const auto s = runCli({QStringLiteral("sync"), run, video, QStringLiteral("--trace"), syncTrace});
        checkClean(s);
        QCOMPARE(s.code, 1);
        QVERIFY2(s.err.contains(QLatin1String("--trace")) && s.err.contains(QLatin1String("space"), Qt::CaseInsensitive), qPrintable(s.err));
        QVERIFY(!QFileInfo::exists(syncTrace));
        const QString tissueTrace = QDir(tiny).filePath(QStringLiteral("tissue.csv"));
        const auto l = runCli({QStringLiteral("labels"), QStringLiteral("suggest"), run, QStringLiteral("--video"), video,
                               QStringLiteral("--video-offset-s"), QStringLiteral("0.5"), QStringLiteral("--tissue-trace"), tissueTrace});
        checkClean(l);
        QCOMPARE(l.code, 1);
        QVERIFY2(l.err.contains(QLatin1String("--tissue-trace")) && l.err.contains(QLatin1String("space"), Qt::CaseInsensitive), qPrintable(l.err));
        QVERIFY(!QFileInfo::exists(tissueTrace));
        // The labels were not written either: the command failed as a whole.
        QVERIFY(!QFileInfo::exists(QDir(work.path()).filePath(QStringLiteral("fr.labels.csv"))));
    }
};

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QTemporaryDir a, b;
    if (!mountTmpfs(a.path(), QStringLiteral("3m")) || !mountTmpfs(b.path(), QStringLiteral("64k"))) {
        unmount(a.path());
        std::fprintf(stderr, "test_disk_full: cannot mount a tmpfs here (not root?); skipped\n");
        return 77;
    }
    TestDiskFull t;
    t.small = a.path();
    t.tiny = b.path();
    const int code = QTest::qExec(&t, argc, argv);
    unmount(a.path());
    unmount(b.path());
    return code;
}

#include "test_disk_full.moc"
