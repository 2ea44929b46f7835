// `needlebench simulate`: the real executable, as users' scripts run it, including a
// recording killed with SIGKILL mid-run.
#include "core/run_file.h"
#include "support/needlebench_cli.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <csignal>

namespace {
nbtest::CliResult run(const QStringList& args)
{
    return nbtest::runCli(QStringList{QStringLiteral("simulate")} + args);
}
}  // namespace

class TestSimulateCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString path(const QString& n) const { return dir_.filePath(n); }

private slots:
    void badArgumentsExitWithUsage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString out = path(QStringLiteral("x.csv"));
        QTest::newRow("no protocol") << QStringList{"--out", out} << "--protocol";
        QTest::newRow("bad protocol") << QStringList{"--protocol", "dance", "--out", out} << "dance";
        QTest::newRow("no out") << QStringList{"--protocol", "stiffness"} << "--out";
        QTest::newRow("bad tissue") << QStringList{"--protocol", "stiffness", "--tissue", "liver4", "--out", out} << "liver4";
        QTest::newRow("bad rate") << QStringList{"--protocol", "stiffness", "--rate-hz", "50", "--out", out} << "rate-hz";
        QTest::newRow("not a number") << QStringList{"--protocol", "friction", "--frequency-hz", "fast", "--out", out} << "fast";
        QTest::newRow("unknown option") << QStringList{"--protocol", "stiffness", "--colour", "red", "--out", out} << "colour";
    }
    void badArgumentsExitWithUsage()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const nbtest::CliResult r = run(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(path(QStringLiteral("x.csv"))));
    }

    void stiffnessRunWithTruth()
    {
        const QString out = path(QStringLiteral("stiff.csv")), truth = path(QStringLiteral("stiff.json"));
        const nbtest::CliResult r = run({"--protocol", "stiffness", "--tissue", "liver1", "--seed", "4", "--depth-mm", "35",
                              "--truth", truth, "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject summary = r.json();
        QCOMPARE(summary.value(QStringLiteral("end_reason")).toString(), QStringLiteral("completed"));
        QCOMPARE(summary.value(QStringLiteral("dropped")).toInt(), 0);

        const auto file = nb::readRunFile(out);
        const nb::Run& run = file.run;
        for (const char* key : {"protocol", "tissue", "tip", "rate_hz", "velocity_mm_s", "depth_mm", "thickness_mm", "seed", "device", "end_reason"})
            QVERIFY2(run.meta(QLatin1String(key)).has_value(), key);
        QCOMPARE(*run.meta(QStringLiteral("tip")), QStringLiteral("beveled"));
        QCOMPARE(*run.meta(QStringLiteral("seed")), QStringLiteral("4"));
        QCOMPARE(static_cast<int>(run.size()), summary.value(QStringLiteral("samples")).toInt());

        const QJsonObject t = nbtest::readJsonFile(truth);
        QCOMPARE(t.value(QStringLiteral("model")).toObject().value(QStringLiteral("a1_N_per_mm")).toDouble(), 0.0480);
        const double tp = t.value(QStringLiteral("puncture_s")).toDouble();
        const double fp = t.value(QStringLiteral("puncture_force_N")).toDouble();
        QVERIFY(t.value(QStringLiteral("contact_s")).toDouble() > 0 && tp > t.value(QStringLiteral("contact_s")).toDouble());
        QVERIFY(t.value(QStringLiteral("relaxed_mm")).toDouble() < t.value(QStringLiteral("puncture_mm")).toDouble());
        // Truth times are on the run file's time axis: the force peaks where the truth says.
        const auto it = std::max_element(run.force_N.begin(), run.force_N.end());
        const double tPeak = run.time_s[it - run.force_N.begin()];
        QVERIFY2(std::fabs(tPeak - tp) < 0.01, qPrintable(QStringLiteral("%1 vs %2").arg(tPeak).arg(tp)));
        QVERIFY(std::fabs(*it - fp) < 0.1);
        QVERIFY(!t.value(QStringLiteral("events")).toArray().isEmpty());
    }

    void sameSeedSameFile()
    {
        // On the simulated clock the operator's sequence lands at the same simulated times,
        // so a seed reproduces the run byte for byte; another seed does not.
        auto bytes = [&](const QString& seed, const QString& name) {
            const nbtest::CliResult r = run({"--protocol", "stiffness", "--tissue", "liver3", "--depth-mm", "20", "--seed", seed, "--out", path(name)});
            QFile f(path(name));
            return r.code == 0 && f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QByteArray a = bytes(QStringLiteral("9"), QStringLiteral("a.csv"));
        QVERIFY(!a.isEmpty());
        QCOMPARE(bytes(QStringLiteral("9"), QStringLiteral("b.csv")), a);
        QVERIFY(bytes(QStringLiteral("10"), QStringLiteral("c.csv")) != a);
    }

    void frictionRunHasPhaseTruth()
    {
        const QString out = path(QStringLiteral("fric.csv")), truth = path(QStringLiteral("fric.json"));
        const nbtest::CliResult r = run({"--protocol", "friction", "--cycles", "2", "--frequency-hz", "0.8", "--thickness-mm", "25",
                              "--truth", truth, "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const auto file = nb::readRunFile(out);
        QCOMPARE(*file.run.meta(QStringLiteral("frequency_hz")), QStringLiteral("0.8"));
        QCOMPARE(*file.run.meta(QStringLiteral("thickness_mm")), QStringLiteral("25"));
        const auto* phase = file.run.textColumn(QStringLiteral("phase"));
        QVERIFY(phase);
        const QJsonArray phases = nbtest::readJsonFile(truth).value(QStringLiteral("phases")).toArray();
        QVERIFY(phases.size() >= 12);
        for (const auto& v : phases) {
            const QJsonObject p = v.toObject();
            QCOMPARE(p.value(QStringLiteral("track")).toString(), QStringLiteral("phase"));
            const double mid = 0.5 * (p.value(QStringLiteral("start_s")).toDouble() + p.value(QStringLiteral("end_s")).toDouble());
            const auto i = std::lower_bound(file.run.time_s.begin(), file.run.time_s.end(), mid) - file.run.time_s.begin();
            if (i < static_cast<long>(phase->size()) && p.value(QStringLiteral("end_s")).toDouble() - p.value(QStringLiteral("start_s")).toDouble() > 0.01)
                QCOMPARE((*phase)[i], p.value(QStringLiteral("label")).toString());
        }
    }

    void forceLimitAtBone()
    {
        const QString out = path(QStringLiteral("bone.csv"));
        const nbtest::CliResult r = run({"--protocol", "stiffness", "--tissue", "liver2", "--bone-depth-mm", "30", "--max-force-n", "4",
                              "--depth-mm", "60", "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(r.json().value(QStringLiteral("end_reason")).toString(), QStringLiteral("force_limit"));
        const auto file = nb::readRunFile(out);
        QCOMPARE(*file.run.meta(QStringLiteral("end_reason")), QStringLiteral("force_limit"));
        QVERIFY(file.run.meta(QStringLiteral("force_limit_tripped_s")).has_value());
        QVERIFY(!file.run.meta(QStringLiteral("force_over_range")).has_value());

        // At the default 8 N limit, beyond the 7.79 N the nominal chain reads at +10 V: the
        // reading's end stops the stage (it drove 20 mm into bone and saved "completed").
        const QString over = path(QStringLiteral("bone-default-limit.csv"));
        const nbtest::CliResult o = run({"--protocol", "stiffness", "--tissue", "liver1", "--bone-depth-mm", "15", "--out", over});
        QVERIFY2(o.code == 0, qPrintable(o.err));
        QCOMPARE(o.json().value(QStringLiteral("end_reason")).toString(), QStringLiteral("force_limit"));
        const auto stopped = nb::readRunFile(over);
        QCOMPARE(stopped.run.meta(QStringLiteral("force_over_range")).value_or(QString()), QStringLiteral("true"));
        const double deepest = *std::max_element(stopped.run.position_mm.begin(), stopped.run.position_mm.end());
        QVERIFY2(deepest < 25.0, qPrintable(QString::number(deepest)));  // it went on to 40 mm
    }

    void killedRecordingKeepsAllButTheLast100ms()
    {
        const QString out = path(QStringLiteral("killed.csv"));
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                                QStringLiteral("--realtime"), QStringLiteral("--depth-mm"), QStringLiteral("60"),
                                                QStringLiteral("--out"), out});
        QVERIFY(p.waitForStarted());
        static const QRegularExpression progress(QStringLiteral("progress run_time_s=([0-9.]+)"));
        double lastProgress = -1.0;
        QSet<QString> progressLines;
        QByteArray buffer;
        while (lastProgress < 1.5) {
            QVERIFY2(p.state() == QProcess::Running || p.bytesAvailable() > 0, "simulate ended early");
            p.waitForReadyRead(1000);
            buffer += p.readAllStandardOutput();
            qsizetype nl;
            while ((nl = buffer.indexOf('\n')) >= 0) {
                const QString line = QString::fromUtf8(buffer.left(nl));
                const auto m = progress.match(line);
                if (m.hasMatch()) {
                    lastProgress = m.captured(1).toDouble();
                    // Each line once (every one came twice: a tick saw the engine's last status again).
                    QVERIFY2(!progressLines.contains(line), qPrintable(line));
                    progressLines.insert(line);
                }
                buffer.remove(0, nl + 1);
            }
        }
        ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitStatus(), QProcess::CrashExit);

        nb::RunReadOptions o;
        o.dropTruncatedLastRow = true;
        const auto file = nb::readRunFile(out, o);
        const nb::Run& run = file.run;
        QVERIFY(!run.footer.contains(QStringLiteral("end_reason")));  // it never got to write one
        QVERIFY(run.size() > 0);
        // Everything up to 100 ms before the engine's last reported time is on disk.
        QVERIFY2(run.time_s.back() >= lastProgress - 0.1,
                 qPrintable(QStringLiteral("last sample %1 s, progress %2 s").arg(run.time_s.back()).arg(lastProgress)));
        const auto* seq = run.numericColumn(QStringLiteral("seq"));
        QVERIFY(seq);
        for (std::size_t i = 1; i < seq->size(); ++i)
            QCOMPARE((*seq)[i], (*seq)[i - 1] + 1.0);
    }
};

QTEST_GUILESS_MAIN(TestSimulateCli)
#include "test_simulate_cli.moc"
