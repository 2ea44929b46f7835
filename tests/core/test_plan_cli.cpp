// `needlebench plan`: the real executable. The "done when": the friction-under-imaging
// template runs headless on the simulated rig, 15 runs with video, each tagged with its site
// and frequency, and the report prints the per-frequency and overall table in Table 5's
// layout. And a plan killed mid-run resumes at the run it was killed in.
#include "core/plan.h"
#include "core/run_file.h"
#include "core/session.h"
#include "support/needlebench_cli.h"

#include <QDir>
#include <QJsonArray>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>
#include <cmath>

namespace {
nbtest::CliResult plan(const QStringList& args, int timeout_ms = 120000)
{
    return nbtest::runCli(QStringList{QStringLiteral("plan")} + args, timeout_ms);
}
}  // namespace

class TestPlanCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString path(const QString& n) const { return dir_.filePath(n); }

private slots:
    void templatesAreListed()
    {
        const nbtest::CliResult r = plan({"templates"});
        QCOMPARE(r.code, 0);
        for (const char* name : {"overall-stiffness", "internal-stiffness", "friction", "stiffness-imaging", "friction-imaging", "prostate"})
            QVERIFY2(r.out.contains(QLatin1String(name)), qPrintable(r.out));
        const nbtest::CliResult j = plan({"templates", "--json"});
        QCOMPARE(j.code, 0);
        const QJsonArray t = j.json().value(QStringLiteral("templates")).toArray();
        QCOMPARE(t.size(), 6);
        for (const QJsonValue& v : t)
            if (v.toObject().value(QStringLiteral("name")).toString() == QLatin1String("friction-imaging"))
                QCOMPARE(v.toObject().value(QStringLiteral("runs")).toInt(), 15);
    }

    void badInputIsNamed_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("message");
        const QString out = path(QStringLiteral("bad.json"));
        QTest::newRow("no template") << QStringList{"new", "--out", out} << 2 << "--template";
        QTest::newRow("unknown template") << QStringList{"new", "--template", "juggling", "--out", out} << 2 << "juggling";
        QTest::newRow("bad order") << QStringList{"new", "--template", "friction", "--order", "sorted", "--out", out} << 2 << "sorted";
        QTest::newRow("bad set") << QStringList{"new", "--template", "friction", "--set", "cycles=0", "--out", out} << 2 << "cycles";
        QTest::newRow("set a factor") << QStringList{"new", "--template", "friction", "--set", "site=3", "--out", out} << 2 << "--levels site=";
        QTest::newRow("unknown sub") << QStringList{"dance"} << 2 << "dance";
        QTest::newRow("report without factors") << QStringList{"report", dir_.path()} << 2 << "--by";
        QTest::newRow("run without session") << QStringList{"run", out} << 2 << "--session";
        QTest::newRow("missing plan") << QStringList{"run", path(QStringLiteral("absent.json")), "--session", path(QStringLiteral("s0"))} << 1
                                      << "absent.json";
    }
    void badInputIsNamed()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, message);
        const nbtest::CliResult r = plan(args);
        QCOMPARE(r.code, code);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(path(QStringLiteral("bad.json"))));
    }

    void aBrokenPlanFileNamesTheField()
    {
        const QString p = path(QStringLiteral("broken.json"));
        QCOMPARE(plan({"new", "--template", "prostate", "--out", p}).code, 0);
        QFile f(p);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QByteArray text = f.readAll();
        text.replace("\"velocity_mm_s\": 4", "\"velocity_mm_s\": \"fast\"");
        f.resize(0);
        f.write(text);
        f.close();
        const nbtest::CliResult r = plan({"run", p, "--session", path(QStringLiteral("s-broken"))});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(p + QStringLiteral(": defaults.velocity_mm_s: ")), qPrintable(r.err));
    }

    // A session another NeedleBench holds (a window recording into it) is not run into: the
    // plan "recovered" the window's run in progress. Free again once the holder lets go.
    void aSessionInUseIsNotRunInto()
    {
        const QString planFile = path(QStringLiteral("held.json")), session = path(QStringLiteral("held"));
        QCOMPARE(plan({"new", "--template", "prostate", "--out", planFile}).code, 0);
        nb::Session::create(session, {});
        {
            const nb::SessionLock held = nb::lockSession(session);
            QVERIFY(held.file && !held.refused());
            const nbtest::CliResult r = plan({"run", planFile, "--session", session});
            QCOMPARE(r.code, 1);
            QVERIFY2(r.err.contains(QStringLiteral("open in another NeedleBench (process %1").arg(QCoreApplication::applicationPid())), qPrintable(r.err));
            QVERIFY(!QFileInfo::exists(QDir(session).filePath(QStringLiteral("plan.json"))));
        }
        QVERIFY(!nb::lockSession(session).refused());
        // A lock file that names no process (left empty by a crash or a full disk) is taken
        // over once it is not being written any more; a fresh one says what to delete.
        const QString lockPath = QDir(session).filePath(QStringLiteral(".needlebench.lock"));
        for (const QByteArray& content : {QByteArray(), QByteArray("garbage\n")}) {
            QFile lockFile(lockPath);
            QVERIFY(lockFile.open(QIODevice::WriteOnly | QIODevice::Truncate));
            lockFile.write(content);
            lockFile.close();
            const nb::SessionLock young = nb::lockSession(session);
            QVERIFY(young.refused());
            QVERIFY2(young.heldBy.contains(QStringLiteral("names no process")) && young.heldBy.contains(lockPath), qPrintable(young.heldBy));
            QVERIFY(lockFile.open(QIODevice::ReadWrite));
            QVERIFY(lockFile.setFileTime(QDateTime::currentDateTime().addSecs(-60), QFileDevice::FileModificationTime));
            lockFile.close();
            const nb::SessionLock taken = nb::lockSession(session);
            QVERIFY2(taken.file && !taken.refused(), qPrintable(taken.heldBy));
        }
        // plan new keeps a file that is not a plan unless told to replace it.
        const QString notAPlan = path(QStringLiteral("recorded.csv"));
        {
            QFile f(notAPlan);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("# protocol: stiffness\ntime_s,position_mm,force_N\n0,0,0\n");
        }
        nbtest::CliResult kept = plan({"new", "--template", "prostate", "--out", notAPlan});
        QCOMPARE(kept.code, 1);
        QVERIFY2(kept.err.contains(QStringLiteral("already exists; it is kept")), qPrintable(kept.err));
        QFile again(notAPlan);
        QVERIFY(again.open(QIODevice::ReadOnly));
        QVERIFY(again.readAll().startsWith("# protocol: stiffness"));
        QCOMPARE(plan({"new", "--template", "prostate", "--out", notAPlan, "--overwrite"}).code, 0);
    }

    void frictionUnderImagingEndToEnd()
    {
        const QString planFile = path(QStringLiteral("friction-imaging.json")), session = path(QStringLiteral("liver7"));
        // Short sine runs (2 cycles) keep this test quick; everything else is the template.
        nbtest::CliResult r = plan({"new", "--template", "friction-imaging", "--set", "cycles=2", "--out", planFile});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = plan({"run", planFile, "--session", session});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));

        // A progress line per run, in order.
        static const QRegularExpression line(QStringLiteral("^run (\\d+) of 15: friction site (\\d) (0\\.\\d) Hz \\.\\.\\. done (run_\\d+_sine\\.csv)$"),
                                             QRegularExpression::MultilineOption);
        int n = 0;
        for (auto it = line.globalMatch(r.out); it.hasNext();) {
            const auto m = it.next();
            ++n;
            QCOMPARE(m.captured(1).toInt(), n);
        }
        QCOMPARE(n, 15);
        QVERIFY(r.out.contains(QStringLiteral("operator: Mount Liver 7.")));
        QVERIFY(r.out.contains(QStringLiteral("operator: Move the slab to site 5.")));
        const QJsonObject summary = r.json();
        QCOMPARE(summary.value(QStringLiteral("done")).toInt(), 15);
        QCOMPARE(summary.value(QStringLiteral("pending")).toInt(), 0);

        // Each run: its factor levels in its metadata, its video beside it.
        const nb::Plan stored = nb::readPlanFile(QDir(session).filePath(QStringLiteral("plan.json")));
        QCOMPARE(stored.countWith(nb::PlanRunStatus::Done), 15);
        QJsonObject truth;
        for (const nb::PlannedRun& pr : stored.runs) {
            const nb::PlanAttempt* a = pr.currentAttempt();
            QVERIFY(a);
            const nb::Run run = nb::readRunFile(QDir(session).filePath(a->runFile)).run;
            QCOMPARE(run.meta(QStringLiteral("factor_site")).value_or(QString()), nb::levelText(pr.factors.value(QStringLiteral("site"))));
            QCOMPARE(run.meta(QStringLiteral("factor_frequency_hz")).value_or(QString()),
                     nb::levelText(pr.factors.value(QStringLiteral("frequency_hz"))));
            QCOMPARE(run.meta(QStringLiteral("frequency_hz")).value_or(QString()), nb::levelText(pr.factors.value(QStringLiteral("frequency_hz"))));
            QCOMPARE(run.meta(QStringLiteral("plan_run")).value_or(QString()), QString::number(pr.number));
            QCOMPARE(run.meta(QStringLiteral("end_reason")).value_or(QString()), QStringLiteral("completed"));
            QCOMPARE(run.meta(QStringLiteral("video_file")).value_or(QString()), a->videoFile);
            QVERIFY(QFileInfo(QDir(session).filePath(a->videoFile)).size() > 0);
            truth = nbtest::readJsonFile(QDir(session).filePath(QFileInfo(a->runFile).completeBaseName() + QStringLiteral(".truth.json")));
        }
        // The last run's video decodes to the frames the renderer wrote.
        const nb::PlanAttempt* last = stored.runs.back().currentAttempt();
        const nbtest::CliResult info = nbtest::runCli({"video-info", QDir(session).filePath(last->videoFile), "--json"});
        QVERIFY2(info.code == 0, qPrintable(info.err));
        QCOMPARE(info.json().value(QStringLiteral("frames")).toInt(), truth.value(QStringLiteral("video")).toObject().value(QStringLiteral("frames")).toInt());

        // The report: Table 5's layout, per frequency and overall.
        r = plan({"report", session, "--by", "frequency,site"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        qInfo().noquote() << r.out.mid(r.out.indexOf(QStringLiteral("Karnopp")));
        static const QRegularExpression head(
            QStringLiteral("\ngroup +statistic +freq_Hz +n +m_est_kg +Cp_N_per_m +bp_Ns_per_m2 +Cn_N_per_m +bn_Ns_per_m2 +Dp_N_per_m +Dn_N_per_m\n"));
        const qsizetype t5 = r.out.indexOf(head);
        QVERIFY2(t5 >= 0, qPrintable(r.out));
        const QStringList rows = r.out.mid(t5 + 1).split(QLatin1Char('\n'), Qt::SkipEmptyParts).mid(1);
        QCOMPARE(rows.size(), 8);
        const QStringList starts{"0.2Hz mean", "0.2Hz std", "0.5Hz mean", "0.5Hz std", "0.8Hz mean", "0.8Hz std", "all mean", "all std"};
        for (int i = 0; i < 8; ++i) {
            QVERIFY2(rows[i].simplified().startsWith(starts[i]), qPrintable(rows[i]));
            QCOMPARE(rows[i].split(QLatin1Char(' '), Qt::SkipEmptyParts).at(i < 6 ? 3 : 2), i < 6 ? QStringLiteral("5") : QStringLiteral("15"));
        }

        // The same as JSON, against the simulated tissue's true friction.
        r = plan({"report", session, "--by", "frequency_hz,site", "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject rep = r.json();
        QCOMPARE(rep.value(QStringLiteral("fitted_runs")).toInt(), 15);
        const QJsonArray table = rep.value(QStringLiteral("friction_by_frequency")).toArray();
        QCOMPARE(table.size(), 8);
        const QJsonObject overall = table[6].toObject();
        QCOMPARE(overall.value(QStringLiteral("group")).toString(), QStringLiteral("all"));
        QCOMPARE(overall.value(QStringLiteral("n")).toInt(), 15);
        const QJsonObject trueFriction = truth.value(QStringLiteral("model")).toObject().value(QStringLiteral("friction_per_length")).toObject();
        for (const char* k : {"Cp_N_per_m", "bp_Ns_per_m2", "Cn_N_per_m", "bn_Ns_per_m2"}) {
            const double got = overall.value(QLatin1String(k)).toDouble(), want = trueFriction.value(QLatin1String(k)).toDouble();
            qInfo("%s: overall mean %.3f, simulated tissue %.3f", k, got, want);
            QVERIFY2(std::abs(got - want) < 0.1 * std::abs(want), k);
        }
        QCOMPARE(rep.value(QStringLiteral("run_list")).toArray().size(), 15);
        r = plan({"report", session, "--by", "frequency", "--out-dir", path(QStringLiteral("tables"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile csv(path(QStringLiteral("tables/friction_by_frequency.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readLine().trimmed(), QByteArray("group,statistic,freq_Hz,n,m_est_kg,Cp_N_per_m,bp_Ns_per_m2,Cn_N_per_m,bn_Ns_per_m2,Dp_N_per_m,Dn_N_per_m"));
        QVERIFY(QFileInfo(path(QStringLiteral("tables/friction_by_frequency.tex"))).size() > 0);
        QVERIFY(QFileInfo(path(QStringLiteral("tables/runs_by_factor.csv"))).size() > 0);

        // Site x frequency: 15 cells of one run each.
        int cellsWithCp = 0;
        for (const QJsonValue& v : rep.value(QStringLiteral("by_factor")).toArray())
            if (v.toObject().value(QStringLiteral("quantity")).toString() == QLatin1String("Cp_N_per_m")) {
                ++cellsWithCp;
                QCOMPARE(v.toObject().value(QStringLiteral("n")).toInt(), 1);
            }
        QCOMPARE(cellsWithCp, 15);

        // Run again: nothing left to do.
        r = plan({"run", planFile, "--session", session});
        QCOMPARE(r.code, 0);
        QVERIFY(!r.out.contains(QStringLiteral("run 1 of 15")));
        QCOMPARE(r.json().value(QStringLiteral("done")).toInt(), 15);
    }

    void aKilledPlanResumesAtTheRunItWasKilledIn()
    {
        const QString planFile = path(QStringLiteral("stiffness.json")), session = path(QStringLiteral("liver1"));
        nbtest::CliResult r = plan({"new", "--template", "overall-stiffness", "--levels", "site=1,2,3,4", "--set", "velocity_mm_s=2", "--out", planFile});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE), {"plan", "run", planFile, "--session", session});
        QVERIFY(p.waitForStarted());
        // Kill it (SIGKILL: no clean-up) while run 2 records.
        const QString stored = QDir(session).filePath(QStringLiteral("plan.json"));
        bool killed = false;
        for (int i = 0; i < 6000 && !killed && p.state() == QProcess::Running; ++i) {
            QThread::msleep(5);
            try {
                const nb::Plan s = nb::readPlanFile(stored);
                // Recording: its file exists and has no footer yet.
                QFile rf(QDir(session).filePath(s.runs[1].attempts.empty() ? QString() : s.runs[1].attempts.back().runFile));
                if (s.runs[1].status == nb::PlanRunStatus::Running && rf.open(QIODevice::ReadOnly) && rf.size() > 0 &&
                    !rf.readAll().contains("# end_reason")) {
                    p.kill();
                    killed = true;
                }
            } catch (const nb::PlanError&) {
                // Not written yet.
            }
        }
        p.waitForFinished();
        QVERIFY2(killed, "run 2 was never seen recording");

        r = plan({"run", planFile, "--session", session});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        QVERIFY2(r.out.contains(QStringLiteral("run 2 was interrupted; it runs again")), qPrintable(r.out));
        QVERIFY(!r.out.contains(QStringLiteral("run 1 of 4")));
        const qsizetype first = r.out.indexOf(QStringLiteral("run 2 of 4: stiffness site 2 ... done"));
        QVERIFY2(first >= 0, qPrintable(r.out));
        QVERIFY(r.out.indexOf(QStringLiteral("run 3 of 4")) > first);
        const nb::Plan s = nb::readPlanFile(stored);
        QCOMPARE(s.firstIncomplete(), -1);
        QCOMPARE(s.runs[1].status, nb::PlanRunStatus::Redone);
        QCOMPARE(s.runs[1].attempts.size(), std::size_t(2));
        QCOMPARE(s.runs[1].attempts[0].result, QStringLiteral("interrupted"));
        QVERIFY(s.runs[1].attempts[0].runFile != s.runs[1].attempts[1].runFile);

        // The report counts the four runs the plan counts, not the interrupted recording.
        r = plan({"report", session, "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value(QStringLiteral("runs")).toInt(), 4);
        // ... and says it left the interrupted one out, by name (a table of fewer runs than the
        // folder holds passed for all of them).
        const QString interrupted = QFileInfo(s.runs[1].attempts[0].runFile).fileName();
        const QJsonArray warnings = r.json().value(QStringLiteral("warnings")).toArray();
        QVERIFY2(std::any_of(warnings.begin(), warnings.end(),
                             [&](const QJsonValue& w) {
                                 return w.toString().contains(QStringLiteral("left out: ") + interrupted) && w.toString().contains(QStringLiteral("--all-runs"));
                             }),
                 qPrintable(QJsonDocument(warnings).toJson()));
        QCOMPARE(plan({"report", session, "--json", "--all-runs"}).json().value(QStringLiteral("runs")).toInt(), 5);

        // Killed after run 4 had ended and been tagged but before plan.json said so: kept.
        {
            nb::Plan k = nb::readPlanFile(stored);
            k.runs[3].status = nb::PlanRunStatus::Running;
            k.runs[3].attempts.back().result.clear();
            nb::writePlanFile(stored, k);
            r = plan({"run", planFile, "--session", session});
            QVERIFY2(r.code == 0, qPrintable(r.err));
            QVERIFY2(r.out.contains(QStringLiteral("run 4 had ended before the interruption")), qPrintable(r.out));
            QVERIFY(!r.out.contains(QStringLiteral("run 4 of 4")));
            QCOMPARE(nb::readPlanFile(stored).runs[3].status, nb::PlanRunStatus::Done);
        }

        // plan new does not overwrite a plan with recorded runs.
        r = plan({"new", "--template", "prostate", "--out", stored});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("not overwritten")), qPrintable(r.err));

        // Another plan may not take over this session.
        const QString other = path(QStringLiteral("other.json"));
        QCOMPARE(plan({"new", "--template", "prostate", "--out", other}).code, 0);
        r = plan({"run", other, "--session", session});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("different plan")), qPrintable(r.err));

        // Redo and skip from the command line.
        QCOMPARE(plan({"redo", stored, "--run", "3", "--reason", "bias forgotten"}).code, 0);
        QCOMPARE(plan({"skip", stored, "--run", "4"}).code, 2);
        r = plan({"show", stored, "--json"});
        QCOMPARE(r.json().value(QStringLiteral("next")).toInt(), 3);
    }
};

QTEST_GUILESS_MAIN(TestPlanCli)
#include "test_plan_cli.moc"
