// Signals and races on the run file: SIGTERM, SIGINT and SIGHUP during a recording stop the
// stage and close the run with end_reason "interrupted" and the signal; a second process
// writing the same file is refused by name; hostile inputs give clean errors, never an
// exception out of main, and messages quote only a short, escaped excerpt.

#include "support/needlebench_cli.h"

#include "core/plan.h"
#include "core/run_file.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <csignal>
#include <sys/file.h>

using nbtest::runCli;

namespace {

// Starts a real-time recording and returns once it writes rows.
bool startRecording(QProcess& p, const QString& out)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                            QStringLiteral("--realtime"), QStringLiteral("--out"), out});
    QElapsedTimer t;
    t.start();
    QByteArray seen;
    while (t.elapsed() < 20000 && p.state() != QProcess::NotRunning) {
        p.waitForReadyRead(100);
        seen += p.readAllStandardOutput();
        if (seen.contains("progress"))
            return true;
    }
    return false;
}

// Starts the executable headless with settings of its own, and returns once `file` has grown
// to `bytes` (a recording under way); false if it did not within 20 s.
bool startUntilWritten(QProcess& p, const QStringList& args, const QString& configDir, const QString& file, qint64 bytes)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), configDir);
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(NB_EXECUTABLE), args);
    if (!p.waitForStarted())
        return false;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 20000 && QFileInfo(file).size() < bytes)
        QTest::qWait(50);
    return QFileInfo(file).size() >= bytes;
}

void checkClean(const nbtest::CliResult& r)
{
    QVERIFY2(r.code == 0 || r.code == 1 || r.code == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.code).arg(r.err.left(500))));
    QVERIFY2(!r.err.contains(QLatin1String("terminate called")) && !r.err.contains(QLatin1String("internal error")),
             qPrintable(r.err.left(500)));
}

void writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

}  // namespace

class TestInterrupts : public QObject {
    Q_OBJECT

private slots:
    void signalClosesTheRun_data()
    {
        QTest::addColumn<int>("signo");
        QTest::addColumn<QString>("name");
        QTest::newRow("SIGTERM") << int(SIGTERM) << QStringLiteral("SIGTERM");
        QTest::newRow("SIGINT") << int(SIGINT) << QStringLiteral("SIGINT");
        QTest::newRow("SIGHUP") << int(SIGHUP) << QStringLiteral("SIGHUP");
    }

    void signalClosesTheRun()
    {
        QFETCH(int, signo);
        QFETCH(QString, name);
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("run.csv"));
        QProcess p;
        QVERIFY(startRecording(p, out));
        QTest::qWait(300);
        ::kill(pid_t(p.processId()), signo);
        QVERIFY(p.waitForFinished(10000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);  // handled, not killed by it
        QCOMPARE(p.exitCode(), 128 + signo);
        QVERIFY2(err.contains(name), qPrintable(err));
        const nb::RunReadResult read = nb::readRunFile(out);  // strict: every row whole
        QCOMPARE(read.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("interrupted"));
        QCOMPARE(read.run.footer.value(QStringLiteral("signal"), QString()), name);
        QVERIFY(read.run.size() > 100);
    }

    // The same for `acquire` (simulated devices on the wall clock).
    void acquireClosesTheRunOnSigint()
    {
        QTemporaryDir dir, config;
        const QString out = dir.filePath(QStringLiteral("acq.csv"));
        QProcess p;
        QVERIFY2(startUntilWritten(p, {QStringLiteral("acquire"), QStringLiteral("--daq"), QStringLiteral("sim"), QStringLiteral("--stage"),
                                       QStringLiteral("sim"), QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--out"), out},
                                   config.path(), out, 2000),
                 "acquire did not start recording");
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        const nb::Run run = nb::readRunFile(out).run;
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("interrupted"));
        QCOMPARE(run.footer.value(QStringLiteral("signal"), QString()), QStringLiteral("SIGINT"));
    }

    // Ctrl+C while the imaging video is rendered, after the run: it went unheard, the video was
    // finished and the command ended 0. Now it stops: no video, no truth, the run file whole.
    void simulateStopsRenderingOnSigint()
    {
        QTemporaryDir dir, config;
        const QString out = dir.filePath(QStringLiteral("fr.csv")), video = dir.filePath(QStringLiteral("fr.avi")),
                      truth = dir.filePath(QStringLiteral("fr.json"));
        QProcess p;
        QVERIFY2(startUntilWritten(p, {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                       QStringLiteral("--cycles"), QStringLiteral("20"), QStringLiteral("--out"), out,
                                       QStringLiteral("--video"), video, QStringLiteral("--truth"), truth},
                                   config.path(), video, 200000),
                 "simulate did not start rendering the video");
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(20000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        const QString said = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(said.contains(QStringLiteral("not written")) && said.contains(video), qPrintable(said));
        QVERIFY(!QFileInfo::exists(video));
        QVERIFY(!QFileInfo::exists(truth));
        const nb::Run run = nb::readRunFile(out).run;
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("completed"));
    }

    // `kill` (SIGTERM) during an export cancels it between rows and says so, as Ctrl+C does: it
    // ended silently, half the export looking complete.
    void exportSaysItWasCancelledOnSigterm()
    {
        QTemporaryDir dir, config;
        const QString session = dir.filePath(QStringLiteral("session")), out = dir.filePath(QStringLiteral("out"));
        QVERIFY(QDir().mkpath(session));
        for (const char* name : {"run_001_linear.csv", "run_002_linear.csv"})
            QCOMPARE(runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--rate-hz"),
                             QStringLiteral("10000"), QStringLiteral("--velocity-mm-s"), QStringLiteral("1"), QStringLiteral("--out"),
                             QDir(session).filePath(QLatin1String(name))})
                         .code,
                     0);
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), config.path());
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("export"), session, QStringLiteral("--format"), QStringLiteral("csv"),
                                                QStringLiteral("--out"), out});
        QByteArray seen;
        QElapsedTimer t;
        t.start();
        while (!seen.contains("[1/2]") && t.elapsed() < 60000 && p.state() != QProcess::NotRunning) {
            p.waitForReadyRead(50);
            seen += p.readAllStandardOutput();
        }
        QVERIFY2(seen.contains("[1/2]"), seen.constData());
        ::kill(pid_t(p.processId()), SIGTERM);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 1);
        const QString said = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(said.contains(QStringLiteral("cancelled")), qPrintable(said));
    }

    // `plan run` on the simulated rig: the run being recorded is closed as interrupted, the
    // plan keeps it as an interrupted attempt and stops (it used to die with the signal, the
    // run file without its footer and the plan's run left "running").
    void planRunStopsOnSigint()
    {
        QTemporaryDir dir, config;
        const QString planPath = dir.filePath(QStringLiteral("plan.json")), session = dir.filePath(QStringLiteral("session"));
        QCOMPARE(runCli({"plan", "new", "--template", "friction", "--out", planPath, "--set", "cycles=1000"}).code, 0);
        const QString runFile = QDir(session).filePath(QStringLiteral("run_001_sine.csv"));
        QProcess p;
        QVERIFY2(startUntilWritten(p, {QStringLiteral("plan"), QStringLiteral("run"), planPath, QStringLiteral("--session"), session, QStringLiteral("--yes")},
                                   config.path(), runFile, 20000),
                 "plan run did not start recording");
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(20000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        QVERIFY2(err.contains(QStringLiteral("SIGINT")) && err.contains(QStringLiteral("resume")), qPrintable(err));
        const nb::Run run = nb::readRunFile(runFile).run;
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("interrupted"));
        QCOMPARE(run.footer.value(QStringLiteral("signal"), QString()), QStringLiteral("SIGINT"));
        QVERIFY(!QFileInfo::exists(QDir(session).filePath(QStringLiteral("run_002_sine.csv"))));  // stopped there
        QFile kept(QDir(session).filePath(QStringLiteral("plan.json")));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        const QByteArray planText = kept.readAll();
        QVERIFY2(planText.contains("\"result\": \"interrupted\"") && !planText.contains("\"status\": \"running\""), planText.left(1500).constData());
    }

    // Ctrl+C while a run's imaging video is rendered: the run file is whole but its video is
    // not written, so the plan does not count the run as done (it did, and a resume went past
    // it for good); resumed, the run is recorded again with its video.
    void planRunInterruptedWhileTheVideoIsRendered()
    {
        QTemporaryDir dir, config;
        const QString planPath = dir.filePath(QStringLiteral("plan.json")), session = dir.filePath(QStringLiteral("session"));
        QCOMPARE(runCli({"plan", "new", "--template", "friction-imaging", "--out", planPath, "--levels", "frequency_hz=0.5", "--set",
                         "cycles=4"}).code, 0);
        const QString video = QDir(session).filePath(QStringLiteral("run_001_sine.avi"));
        QProcess p;
        QVERIFY2(startUntilWritten(p, {QStringLiteral("plan"), QStringLiteral("run"), planPath, QStringLiteral("--session"), session, QStringLiteral("--yes")},
                                   config.path(), video, 1),
                 "plan run did not start rendering the video");
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(out.contains(QStringLiteral("interrupted run_001_sine.csv")), qPrintable(out));
        QVERIFY(!QFileInfo::exists(video));
        const nb::Plan kept = nb::readPlanFile(QDir(session).filePath(QStringLiteral("plan.json")));
        QCOMPARE(kept.runs[0].status, nb::PlanRunStatus::Pending);
        QCOMPARE(kept.runs[0].attempts.back().result, QStringLiteral("interrupted"));
    }

    // A .part left by a killed export goes with the next export; one still being written
    // (locked) stops a second export of the same file with a message.
    void leftoverPartFilesAreCleaned()
    {
        QTemporaryDir session, out;
        QCOMPARE(runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--out"),
                         QDir(session.path()).filePath(QStringLiteral("run1.csv"))}).code, 0);
        const QString h5 = QDir(out.path()).filePath(QStringLiteral("s.h5"));
        writeFile(h5 + QStringLiteral(".part"), QByteArray(30000, 'x'));
        writeFile(QDir(out.path()).filePath(QStringLiteral("old.h5.part")), QByteArray(1000, 'x'));
        const auto r = runCli({QStringLiteral("export"), session.path(), QStringLiteral("--format"), QStringLiteral("hdf5"),
                               QStringLiteral("--out"), h5});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.err.contains(QLatin1String("old.h5.part")), qPrintable(r.err));
        QCOMPARE(QDir(out.path()).entryList({QStringLiteral("*.part")}, QDir::Files | QDir::Hidden), QStringList());
        QVERIFY(QFileInfo(h5).size() > 1000);
        // A .part held by a live writer is left alone and the second export refused.
        QFile held(h5 + QStringLiteral(".part"));
        QVERIFY(held.open(QIODevice::WriteOnly));
        QCOMPARE(::flock(held.handle(), LOCK_EX | LOCK_NB), 0);
        const auto second = runCli({QStringLiteral("export"), session.path(), QStringLiteral("--format"), QStringLiteral("hdf5"),
                                    QStringLiteral("--out"), h5});
        checkClean(second);
        QCOMPARE(second.code, 1);
        QVERIFY2(second.err.contains(QLatin1String("another export")), qPrintable(second.err));
        QVERIFY(QFileInfo::exists(h5 + QStringLiteral(".part")));
    }

    void secondWriterIsRefused()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("shared.csv"));
        QProcess first;
        QVERIFY(startRecording(first, out));
        // Even told to replace it, a second process does not write into a recording under way.
        const auto second = runCli({QStringLiteral("simulate"), QStringLiteral("--overwrite"), QStringLiteral("--protocol"),
                                    QStringLiteral("stiffness"), QStringLiteral("--out"), out});
        checkClean(second);
        QCOMPARE(second.code, 1);
        QVERIFY2(second.err.contains(out) && second.err.contains(QLatin1String("another process")), qPrintable(second.err));
        ::kill(pid_t(first.processId()), SIGTERM);
        QVERIFY(first.waitForFinished(10000));
        // The first recording is whole: one header, one footer, no foreign rows.
        const nb::RunReadResult read = nb::readRunFile(out);
        QCOMPARE(read.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("interrupted"));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll().count("# end_reason:"), 1);
    }

    void windowEndsOnSigterm()
    {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        QTemporaryDir home;
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.path());
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(NB_EXECUTABLE), {});
        QVERIFY(p.waitForStarted());
        QTest::qWait(2500);
        QCOMPARE(p.state(), QProcess::Running);
        ::kill(pid_t(p.processId()), SIGTERM);
        QVERIFY(p.waitForFinished(15000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGTERM);  // as every command ended by a signal says
    }

    // Hostile inputs through the real command line: every one a clean error or a result, none
    // an exception out of main; messages stay short and carry no raw control characters.
    void hostileInputsGiveCleanErrors()
    {
        QTemporaryDir dir;
        const QDir d(dir.path());
        const QByteArray header = "time_s,position_mm,force_N\n";
        QByteArray huge = header + "0.0,0.0,";
        huge += QByteArray(10 * 1024 * 1024, 'x');
        huge += "\n";
        writeFile(d.filePath(QStringLiteral("huge.csv")), huge);
        writeFile(d.filePath(QStringLiteral("control.csv")), header + "0.0,0.0,\x1b[31mred\x07\n");
        QByteArray big = "# protocol: stiffness\n" + header;
        QByteArray tiny = "# protocol: stiffness\n" + header;
        for (int i = 0; i < 2000; ++i) {
            const double t = i / 500.0;
            big += QByteArray::number(t, 'f', 4) + ',' + QByteArray::number(4 * t, 'f', 4) + ',' +
                   QByteArray::number(1e160 * (1 + (i % 7)), 'g', 6) + '\n';
            tiny += QByteArray::number(t, 'f', 4) + ',' + QByteArray::number(1e-300 * i, 'g', 6) + ',' +
                    QByteArray::number(0.01 * i, 'f', 4) + '\n';
        }
        writeFile(d.filePath(QStringLiteral("big.csv")), big);
        writeFile(d.filePath(QStringLiteral("tiny.csv")), tiny);
        // A real run with a puncture, its forces scaled to 1e160 N: gets as far as the fit.
        const QString real = d.filePath(QStringLiteral("real.csv"));
        QCOMPARE(runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--out"), real}).code, 0);
        nb::Run scaled = nb::readRunFile(real).run;
        for (double& f : scaled.force_N)
            f *= 1e159;
        nb::writeRunFile(d.filePath(QStringLiteral("scaled.csv")), scaled);
        QFile::remove(real);
        {
            const auto r = runCli({QStringLiteral("fit"), QStringLiteral("stiffness"), d.filePath(QStringLiteral("scaled.csv")), QStringLiteral("--json")});
            checkClean(r);
            QCOMPARE(r.code, 1);
            // Refused at the first such sample, before a fit it would make alone.
            QVERIFY2(r.err.contains(QLatin1String("scaled.csv: stiffness sample 1 is 5.058e+157 N: a corrupt sample")), qPrintable(r.err));
            QVERIFY(!r.out.contains(QLatin1String("null")));
        }

        for (const char* name : {"huge.csv", "control.csv"}) {
            const auto r = runCli({QStringLiteral("fit"), QStringLiteral("stiffness"), d.filePath(QLatin1String(name))});
            checkClean(r);
            QCOMPARE(r.code, 1);
            QVERIFY2(r.err.size() < 2000, qPrintable(r.err.left(300)));
            QVERIFY2(!r.err.contains(QChar(0x1b)) && !r.err.contains(QChar(0x07)), qPrintable(r.err));
        }
        for (const char* name : {"big.csv", "tiny.csv"}) {
            const auto r = runCli({QStringLiteral("fit"), QStringLiteral("stiffness"), d.filePath(QLatin1String(name))});
            checkClean(r);
            // A fit that is not finite is a failure, said plainly, never "nan" or "inf" as a result.
            QVERIFY2(r.code != 0 || (!r.out.contains(QLatin1String("nan"), Qt::CaseInsensitive) &&
                                     !r.out.contains(QLatin1String("inf"), Qt::CaseInsensitive) && !r.out.contains(QLatin1String("null"))),
                     qPrintable(r.out.left(500) + r.err.left(500)));
        }
        // Exports of the same folder: clean too.
        for (const char* format : {"csv", "hdf5", "eaf"}) {
            const auto r = runCli({QStringLiteral("export"), dir.path(), QStringLiteral("--format"), QLatin1String(format),
                                   QStringLiteral("--out"), d.filePath(QStringLiteral("out_") + QLatin1String(format))});
            checkClean(r);
            QVERIFY2(!r.err.contains(QChar(0x1b)), qPrintable(r.err.left(300)));
            QVERIFY2(r.err.size() < 4000, qPrintable(r.err.left(300)));
        }
    }
};

QTEST_GUILESS_MAIN(TestInterrupts)
#include "test_interrupts.moc"
