// The command-line contract: the real executable, run as a user's script would.
#include <QProcess>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include "support/needlebench_cli.h"
#include "core/session.h"

#include <QtTest>

#include <cstdio>
#include <unistd.h>

class TestCli : public QObject {
    Q_OBJECT

    static nbtest::CliResult run(const QStringList& args) { return nbtest::runCli(args); }

    QTemporaryDir settings_;  // no language chosen in the settings: the C locale's English

    // The executable as a user on an SSH session meets it: no display at all.
    QProcessEnvironment withoutDisplay() const
    {
        auto env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), settings_.path());
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C.UTF-8"));
        return env;
    }

private slots:
    void unknownCommandPrintsUsageAndFails()
    {
        const auto r = run({QStringLiteral("frobnicate")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QStringLiteral("unknown command 'frobnicate'")));
        QVERIFY(r.err.contains(QStringLiteral("Usage:")));
    }
    void helpListsCommands()
    {
        const auto r = run({QStringLiteral("help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains(QStringLiteral("version")));
        QVERIFY(r.out.contains(QStringLiteral("Exit status: 0 done; 1 failed")));  // what scripts test for
    }
    // An unknown option before any command opened the window (and with it the last session).
    void unknownOptionWithoutACommandFails()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        env.insert(QStringLiteral("HOME"), QDir::tempPath() + QStringLiteral("/nb-test-cli-home"));
        for (const QString& option : {QStringLiteral("--bogus"), QStringLiteral("--json"), QStringLiteral("-x")}) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(QStringLiteral(NB_EXECUTABLE), {option});
            QVERIFY2(p.waitForFinished(30000), qPrintable(option + QStringLiteral(": still running (the window opened?)")));
            if (p.state() != QProcess::NotRunning) {
                p.kill();
                p.waitForFinished();
            }
            QCOMPARE(p.exitCode(), 2);
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QVERIFY2(err.contains(QStringLiteral("unknown option '%1'").arg(option)), qPrintable(err));
        }
    }
    void badOptionFails()
    {
        const auto r = run({QStringLiteral("version"), QStringLiteral("--bogus")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QStringLiteral("bogus")));
    }
    void versionRunsHeadless_data()
    {
        QTest::addColumn<QString>("asked");
        QTest::newRow("version") << QStringLiteral("version");
        QTest::newRow("--version") << QStringLiteral("--version");
        QTest::newRow("-v") << QStringLiteral("-v");
    }
    void versionRunsHeadless()
    {
        // The command must not need a display, nor the option a user types by habit (it used
        // to start the window, which without a display aborted).
        QFETCH(QString, asked);
        QProcess p;
        p.setProcessEnvironment(withoutDisplay());
        p.start(QStringLiteral(NB_EXECUTABLE), {asked});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(p.readAllStandardOutput().startsWith("needlebench "));
    }
    // What a script reads from the standard output is the result: one that cannot be written
    // (a full disk behind `> out.json`) fails the command, saying so; it exited 0.
    void anOutputThatCannotBeWrittenFails()
    {
        if (!QFileInfo::exists(QStringLiteral("/dev/full")))
            QSKIP("no /dev/full here");
        QTemporaryDir dir;
        const QString run = dir.filePath(QStringLiteral("run.csv"));
        QCOMPARE(TestCli::run({"simulate", "--protocol", "stiffness", "--out", run}).code, 0);
        QProcess p;
        p.setProcessEnvironment(withoutDisplay());
        p.setStandardOutputFile(QStringLiteral("/dev/full"));
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("events"), run, QStringLiteral("--json")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 1);
        const QString said = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(said.contains(QStringLiteral("could not be written")), qPrintable(said));
    }

    // An output named like one of the command's inputs, an existing recording or labels file,
    // an output that cannot be written: refused before anything is read or recorded, and the
    // files stay as they were (each of these once replaced a run file or hand-made labels).
    void outputsKeepWhatIsThere()
    {
        QTemporaryDir dir;
        const QString run = dir.filePath(QStringLiteral("run_001_sine.csv"));
        QCOMPARE(TestCli::run({"simulate", "--protocol", "friction", "--cycles", "1", "--frequency-hz", "1", "--out", run}).code, 0);
        auto bytes = [](const QString& path) {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QByteArray recorded = bytes(run);
        QVERIFY(recorded.contains("time_s"));
        auto refused = [&](const QStringList& args, const QString& says) {
            const nbtest::CliResult r = TestCli::run(args);
            QVERIFY2(r.code == 2 && r.err.contains(says), qPrintable(args.join(QLatin1Char(' ')) + QStringLiteral(": exit %1: ").arg(r.code) + r.err));
            QCOMPARE(bytes(run), recorded);
        };
        const QString video = dir.filePath(QStringLiteral("run_001_sine.avi"));
        refused({"sync", run, video, "--trace", run}, QStringLiteral("--trace"));
        refused({"labels", "suggest", run, "--out", run}, QStringLiteral("--out"));
        refused({"labels", "suggest", run, "--tissue-trace", run}, QStringLiteral("--tissue-trace"));
        refused({"export", dir.path(), "--format", "csv", "--out", dir.path()}, QStringLiteral("session folder"));
        refused({"export", dir.path(), "--format", "hdf5", "--out", run}, QStringLiteral("not an HDF5 file"));
        refused({"simulate", "--protocol", "stiffness", "--out", run}, QStringLiteral("--overwrite"));
        // --truth and --video are outputs as --out is: a recorded run named there was replaced.
        const QString unrecorded = dir.filePath(QStringLiteral("unrecorded.csv"));
        refused({"simulate", "--protocol", "stiffness", "--out", unrecorded, "--truth", run}, QStringLiteral("--truth %1 already exists").arg(run));
        refused({"simulate", "--protocol", "stiffness", "--out", unrecorded, "--video", run}, QStringLiteral("--video %1 already exists").arg(run));
        QVERIFY(!QFileInfo::exists(unrecorded));
        refused({"acquire", "--daq", "sim", "--stage", "sim", "--protocol", "stiffness", "--out", run}, QStringLiteral("--overwrite"));
        // An export into a folder of recorded runs (another session's) replaced them, the
        // calibration header and raw columns gone, with exit 0. An earlier export's own files are
        // replaced, saying so; anything else only with --overwrite.
        {
            QTemporaryDir otherSession;
            const QString theirs = QDir(otherSession.path()).filePath(QStringLiteral("run_001_sine.csv"));
            QVERIFY(QFile::copy(run, theirs));
            refused({"export", dir.path(), "--format", "csv", "--out", otherSession.path()}, QStringLiteral("not an earlier export"));
            QCOMPARE(bytes(theirs), recorded);
            const QString out = dir.filePath(QStringLiteral("exported"));
            QCOMPARE(TestCli::run({"export", dir.path(), "--format", "csv", "--out", out}).code, 0);
            const nbtest::CliResult again = TestCli::run({"export", dir.path(), "--format", "csv", "--out", out});
            QVERIFY2(again.code == 0 && again.err.contains(QStringLiteral("earlier export")), qPrintable(again.err));
            // A recorded run copied over an earlier export's CSV, its sidecar still beside it, is
            // a recorded run: kept (it was replaced as the export's own).
            const QString exportedCsv = QDir(out).filePath(QStringLiteral("run_001_sine.csv"));
            QVERIFY(QFile::remove(exportedCsv) && QFile::copy(run, exportedCsv));
            refused({"export", dir.path(), "--format", "csv", "--out", out}, QStringLiteral("not an earlier export"));
            QCOMPARE(bytes(exportedCsv), recorded);
            QCOMPARE(TestCli::run({"export", dir.path(), "--format", "csv", "--out", otherSession.path(), "--overwrite"}).code, 0);
            QVERIFY(!bytes(theirs).startsWith(recorded.left(200)));
            QVERIFY(QDir(out).removeRecursively());
            // HDF5 into folders not there yet: made, as for CSV (it blamed the folder's permissions).
            QTemporaryDir elsewhere;
            const QString deeper = QDir(elsewhere.path()).filePath(QStringLiteral("nope/deeper/s.h5"));
            const nbtest::CliResult h5 = TestCli::run({"export", dir.path(), "--format", "hdf5", "--out", deeper});
            QVERIFY2(h5.code == 0 && QFileInfo(deeper).size() > 0, qPrintable(h5.err));
        }
        // A trace replaces an earlier trace only, not a run of another name, nor the run read
        // through a hard link (`export --copy-video` makes them); each replaced it, exit 0.
        const QString other = dir.filePath(QStringLiteral("run_002_sine.csv")), hard = dir.filePath(QStringLiteral("linked.csv"));
        QVERIFY(QFile::copy(run, other));
        QCOMPARE(::link(QFile::encodeName(run).constData(), QFile::encodeName(hard).constData()), 0);
        refused({"sync", run, video, "--trace", other}, QStringLiteral("not a trace"));
        refused({"labels", "suggest", run, "--tissue-trace", other, "--out", dir.filePath(QStringLiteral("x.labels.csv"))},
                QStringLiteral("not a trace"));
        refused({"sync", hard, video, "--trace", run, "--overwrite"}, QStringLiteral("a file this command reads"));
        refused({"labels", "suggest", hard, "--out", run, "--overwrite"}, QStringLiteral("a file this command reads"));
        QCOMPARE(bytes(other), recorded);
        {
            const QString earlier = dir.filePath(QStringLiteral("trace.csv"));
            QFile f(earlier);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("time_s,displacement_px\n0.000000,1.000\n");
            f.close();
            const nbtest::CliResult r = TestCli::run({"sync", run, video, "--trace", earlier});
            QVERIFY2(!r.err.contains(QStringLiteral("--trace")), qPrintable(r.err));  // fails on the missing video, not on the trace
        }

        // Labels made by hand are kept unless --overwrite says otherwise.
        const QString labels = dir.filePath(QStringLiteral("run_001_sine.labels.csv"));
        QCOMPARE(TestCli::run({"labels", "suggest", run}).code, 0);
        {
            QFile f(labels);
            QVERIFY(f.open(QIODevice::Append));
            f.write("manual,my note,1.0,2.0,made by hand\n");
        }
        const QByteArray handMade = bytes(labels);
        const nbtest::CliResult again = TestCli::run({"labels", "suggest", run});
        QCOMPARE(again.code, 2);
        QVERIFY2(again.err.contains(labels) && again.err.contains(QStringLiteral("--overwrite")), qPrintable(again.err));
        QCOMPARE(bytes(labels), handMade);
        QCOMPARE(TestCli::run({"labels", "suggest", run, "--overwrite"}).code, 0);
        QVERIFY(!bytes(labels).contains("made by hand"));

        // A video asked for that is not there fails the command, naming it, and writes nothing.
        const QByteArray suggested = bytes(labels);
        for (const QString& missing : {dir.filePath(QStringLiteral("no_such_video.mp4")), dir.path()}) {
            const nbtest::CliResult r = TestCli::run({"labels", "suggest", run, "--overwrite", "--video", missing});
            QVERIFY2(r.code == 1 && r.err.contains(missing), qPrintable(QStringLiteral("exit %1: ").arg(r.code) + r.err));
            QCOMPARE(bytes(labels), suggested);
        }

        // Outputs checked before the run is recorded: nothing recorded when one cannot be made.
        const QString fresh = dir.filePath(QStringLiteral("fresh.csv"));
        for (const QStringList& bad : {QStringList{"--video", dir.filePath(QStringLiteral("fresh.mov"))},
                                       QStringList{"--truth", dir.filePath(QStringLiteral("no/such/folder/t.json"))},
                                       QStringList{"--truth", fresh}}) {
            const nbtest::CliResult r = TestCli::run(QStringList{"simulate", "--protocol", "stiffness", "--out", fresh} + bad);
            QVERIFY2(r.code == 2, qPrintable(bad.join(QLatin1Char(' ')) + QStringLiteral(": exit %1: ").arg(r.code) + r.err));
            QVERIFY2(!QFileInfo::exists(fresh), qPrintable(bad.join(QLatin1Char(' '))));
        }
        // Runs that would never end (10^6 s) are refused, by the command and by a plan.
        QCOMPARE(TestCli::run({"simulate", "--protocol", "friction", "--frequency-hz", "1e-6", "--out", fresh}).code, 2);
        QCOMPARE(TestCli::run({"simulate", "--protocol", "friction", "--cycles", "100000", "--out", fresh}).code, 2);
        // So are a rig that could not be (a limit no load cell reaches, a slab or bone beyond the stage's travel).
        for (const QStringList& bad : {QStringList{"--max-force-n", "1e300"}, QStringList{"--max-force-n", "0.001"}, QStringList{"--thickness-mm", "1e300"},
                                       QStringList{"--bone-depth-mm", "-1"}, QStringList{"--bone-depth-mm", "1e9"}}) {
            const nbtest::CliResult r = TestCli::run(QStringList{"simulate", "--protocol", "friction", "--out", fresh} + bad);
            QVERIFY2(r.code == 2 && r.err.contains(bad.front()), qPrintable(bad.join(QLatin1Char(' ')) + QStringLiteral(": exit %1: ").arg(r.code) + r.err));
        }
        const nbtest::CliResult plan = TestCli::run({"plan", "new", "--template", "friction", "--out", dir.filePath(QStringLiteral("p.json")),
                                                     "--levels", "frequency_hz=1e-6"});
        QVERIFY2(plan.code == 2 && plan.err.contains(QStringLiteral("0.01")), qPrintable(plan.err));
        QVERIFY(!QFileInfo::exists(fresh));
    }
    // Inputs a command was not made for are named as such, before anything is read.
    // A run cut off mid-row (the recorder's process died) is read up to its last whole row by
    // every command, saying so: events, fit, labels and sync refused it whole, and only the
    // window could recover it.
    // A run whose video is gone is exported saying so (with --copy-video the export's JSON kept
    // the video's name and carried no video, without a word).
    void anExportSaysWhenARunsVideoIsMissing()
    {
        {
            // A run the session lists that the export leaves out (still recording, or cut off)
            // fails the command, after the others are written: a script went on on exit status 0.
            QTemporaryDir dir;
            const QString sessionDir = dir.filePath(QStringLiteral("s")), out = dir.filePath(QStringLiteral("out"));
            nb::Session::create(sessionDir, {});
            for (const QString& name : {QStringLiteral("run_001_linear.csv"), QStringLiteral("run_002_linear.csv")}) {
                QFile f(QDir(sessionDir).filePath(name));
                QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
                f.write("# format: needlebench-run 1\n# motion: linear\ntime_s,position_mm,force_N\n");
                for (int i = 0; i < 50; ++i)
                    f.write(QStringLiteral("%1,%2,%3\n").arg(i * 0.001).arg(i * 0.01).arg(i * 0.002).toUtf8());
                if (name.startsWith(QLatin1String("run_001")))
                    f.write("# end_reason: completed\n");
            }
            const nbtest::CliResult r = TestCli::run({"export", sessionDir, "--format", "csv", "--out", out});
            QVERIFY2(r.code == 1 && r.err.contains(QStringLiteral("1 run of the session left out")) && r.err.contains(QStringLiteral("run_002_linear.csv")),
                     qPrintable(QStringLiteral("exit %1: ").arg(r.code) + r.err));
            QVERIFY(QFileInfo::exists(QDir(out).filePath(QStringLiteral("run_001_linear.csv"))));
        }

        QTemporaryDir dir;
        const QString run = dir.filePath(QStringLiteral("run_001_sine.csv"));
        nbtest::CliResult r = TestCli::run({"simulate", "--protocol", "friction", "--cycles", "1", "--frequency-hz", "1", "--out", run});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        // Named in its header, as the window and plan run record it; not there.
        QFile f(run);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray text = f.readAll();
        f.close();
        text.prepend("# video_file: run_001_sine.avi\n");
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
        f.close();
        r = TestCli::run({"export", dir.path(), "--format", "csv", "--out", dir.filePath(QStringLiteral("out")), "--copy-video"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("run_001_sine.avi is missing")), qPrintable(r.err));
    }
    void aRunCutOffMidRowIsReadToItsLastRow()
    {
        QTemporaryDir dir;
        const QString run = dir.filePath(QStringLiteral("run_001_linear.csv"));
        QCOMPARE(TestCli::run({"simulate", "--protocol", "stiffness", "--out", run}).code, 0);
        QFile f(run);
        QVERIFY(f.open(QIODevice::ReadWrite));
        const QByteArray whole = f.readAll();
        // Cut inside a row well after the puncture, as a crash leaves it.
        const qsizetype cut = whole.indexOf('\n', whole.size() * 9 / 10) + 12;
        QVERIFY(f.resize(cut));
        f.close();
        const nbtest::CliResult events = TestCli::run({"events", run, "--json"});
        QVERIFY2(events.code == 0 && events.err.contains(QStringLiteral("partial last row")), qPrintable(events.err));
        QVERIFY(events.out.contains("puncture"));
        const nbtest::CliResult fit = TestCli::run({"fit", "stiffness", run});
        QVERIFY2(fit.code == 0 && fit.err.contains(QStringLiteral("partial last row")), qPrintable(fit.err));
        const nbtest::CliResult labels = TestCli::run({"labels", "suggest", run});
        QVERIFY2(labels.code == 0 && labels.err.contains(QStringLiteral("partial last row")), qPrintable(labels.err));
    }

    // Exported frame numbers come from the video's own index: a label past the end of a video
    // cut short names no frame (it named frame 53 of a 30-frame video).
    void exportedFramesEndWithTheVideo()
    {
        QTemporaryDir dir;
        const QString full = dir.filePath(QStringLiteral("full.csv")), fullVideo = dir.filePath(QStringLiteral("full.avi"));
        QCOMPARE(TestCli::run({"simulate", "--protocol", "friction", "--cycles", "2", "--frequency-hz", "1", "--out", full, "--video", fullVideo}).code, 0);
        const QString session = dir.filePath(QStringLiteral("cut"));
        QVERIFY(QDir().mkpath(session));
        QVERIFY(QFile::copy(full, QDir(session).filePath(QStringLiteral("run.csv"))));
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {QStringLiteral("-loglevel"), QStringLiteral("error"), QStringLiteral("-i"), fullVideo,
                                                QStringLiteral("-frames:v"), QStringLiteral("30"), QStringLiteral("-c"), QStringLiteral("copy"),
                                                QDir(session).filePath(QStringLiteral("run.avi"))});
        QVERIFY2(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0, "ffmpeg (Debian: ffmpeg) cuts the video");
        {
            QFile labels(QDir(session).filePath(QStringLiteral("run.labels.csv")));
            QVERIFY(labels.open(QIODevice::WriteOnly));
            labels.write("track,label,start_s,end_s,comment\nphases,a,0.2,0.5,\nphases,b1,0.9,1.8,\n");
        }
        const QString out = dir.filePath(QStringLiteral("out"));
        const nbtest::CliResult r = TestCli::run({"export", session, "--format", "csv", "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile intervals(QDir(out).filePath(QStringLiteral("run.intervals.csv")));
        QVERIFY(intervals.open(QIODevice::ReadOnly));
        const QList<QByteArray> rows = intervals.readAll().trimmed().split('\n');
        QCOMPARE(rows.size(), 3);
        const QList<QByteArray> a = rows[1].split(','), b1 = rows[2].split(',');
        QCOMPARE(a[5].toInt(), 5);    // 0.2 s at 29.97 frames/s
        QCOMPARE(a[6].toInt(), 14);   // 0.5 s
        QCOMPARE(b1[5].toInt(), 26);  // 0.9 s
        QVERIFY2(b1[6].isEmpty(), rows[2].constData());  // 1.8 s: after the 30th frame (1.0 s)
    }

    void misdirectedInputsAreNamed()
    {
        QTemporaryDir dir;
        const QString sine = dir.filePath(QStringLiteral("sine.csv"));
        QCOMPARE(TestCli::run({"simulate", "--protocol", "friction", "--cycles", "1", "--frequency-hz", "1", "--out", sine}).code, 0);
        for (const QStringList& insertionOnly : {QStringList{"events", sine}, QStringList{"fit", "stiffness", sine}}) {
            const nbtest::CliResult r = TestCli::run(insertionOnly);
            QVERIFY2(r.err.contains(QStringLiteral("is a friction run")), qPrintable(insertionOnly.join(QLatin1Char(' ')) + QStringLiteral(": ") + r.err));
        }
        const nbtest::CliResult image = TestCli::run({"frame", dir.filePath(QStringLiteral("v.avi")), "--index", "0", "--out", dir.filePath(QStringLiteral("f.txt"))});
        QVERIFY2(image.code == 2 && image.err.contains(QStringLiteral("f.txt")) && !image.err.contains(QStringLiteral("OpenCV")), qPrintable(image.err));
        // Labels without friction phases set the run's own phase column aside no more.
        const QString noPhases = dir.filePath(QStringLiteral("events.labels.csv"));
        {
            QFile f(noPhases);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("track,label,start_s,end_s,comment\nevent,contact,0.5,0.5,\n");
        }
        const nbtest::CliResult withPhases = TestCli::run({"fit", "friction", sine, "--thickness-mm", "30", "--json"});
        const nbtest::CliResult aside = TestCli::run({"fit", "friction", sine, "--thickness-mm", "30", "--labels", noPhases, "--json"});
        QCOMPARE(aside.code, withPhases.code);
        QVERIFY2(aside.err.contains(noPhases) && aside.err.contains(QStringLiteral("no friction phase")), qPrintable(aside.err));
        QCOMPARE(aside.out, withPhases.out);
        const nbtest::CliResult typo = TestCli::run({"plan", "new", "--template", "friction", "--out", dir.filePath(QStringLiteral("p.json")), "--levels", "location=1"});
        QCOMPARE(typo.code, 0);
        QVERIFY2(typo.err.contains(QStringLiteral("'location'")), qPrintable(typo.err));
    }
    // A file named in Latin-1 (an old instrument PC's) was "cannot open: no such file" of a name
    // with a '?': the name is said as it is and what to do about it.
    void aNameThatIsNotUtf8IsSaid()
    {
        QTemporaryDir dir;
        const QByteArray latin1 = QFile::encodeName(dir.path()) + "/caf\xe9.csv";
        {
            FILE* f = std::fopen(latin1.constData(), "w");
            QVERIFY(f);
            std::fputs("time_s,position_mm,force_N\n0,0,0\n", f);
            std::fclose(f);
        }
        QProcess p;
        p.setProcessEnvironment(withoutDisplay());
        // QProcess passes its arguments as UTF-8; the shell passes the name's own bytes.
        p.start(QStringLiteral("/bin/sh"), {QStringLiteral("-c"), QStringLiteral("exec \"$0\" events \"$1/$(printf 'caf\\351.csv')\""),
                                             QStringLiteral(NB_EXECUTABLE), dir.path()});
        QVERIFY(p.waitForFinished(60000));
        const QString said = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 2);
        QVERIFY2(said.contains(QStringLiteral("café.csv' is not UTF-8")) && said.contains(QStringLiteral("rename")), qPrintable(said));
    }
    // Qt aborts without a display it can reach and advises reinstalling; the operator is told
    // instead what is missing and what runs without it.
    void windowWithoutADisplaySaysWhatToDo_data()
    {
        QTest::addColumn<QString>("display");
        QTest::addColumn<QString>("named");
        QTest::newRow("no display (an SSH session)") << QString() << QStringLiteral("DISPLAY");
        QTest::newRow("a display that does not answer (forwarding gone)") << QStringLiteral(":9731") << QStringLiteral("':9731'");
    }
    void windowWithoutADisplaySaysWhatToDo()
    {
        QFETCH(QString, display);
        QFETCH(QString, named);
        QProcessEnvironment env = withoutDisplay();
        if (!display.isEmpty())
            env.insert(QStringLiteral("DISPLAY"), display);
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(NB_EXECUTABLE), QStringList());
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(named) && err.contains(QStringLiteral("needlebench demo")), qPrintable(err));
        QVERIFY2(!err.contains(QStringLiteral("einstall")), qPrintable(err));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
