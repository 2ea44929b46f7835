// Which runs the analysis takes (core/run_judgement.h) and the video kept with a run
// (core/run_video_link.h), on real run files written by `needlebench simulate` and on
// runs with a random seed that is printed.
#include "core/export/dataset_loader.h"
#include "core/export/session_analysis.h"
#include "core/run_file.h"
#include "core/run_judgement.h"
#include "core/run_keys.h"
#include "core/run_video_link.h"
#include "core/session.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

namespace {

nb::Run noiseRun(double sigma_N, double offset_N, quint32 seed, const char* endReason = "completed")
{
    nb::Run r;
    QRandomGenerator rng(seed);
    for (int i = 0; i < 2000; ++i) {
        r.time_s.push_back(i * 0.001);
        r.position_mm.push_back(std::sin(i * 0.003));
        // Box-Muller: Gaussian sensor noise.
        const double u1 = std::max(1e-12, rng.generateDouble()), u2 = rng.generateDouble();
        r.force_N.push_back(offset_N + sigma_N * std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    r.footer.set(nb::key::end_reason, QString::fromLatin1(endReason));
    return r;
}

bool simulate(const QStringList& args)
{
    QProcess p;
    p.start(QStringLiteral(NB_EXECUTABLE), QStringList{QStringLiteral("simulate")} + args);
    return p.waitForFinished(120000) && p.exitCode() == 0;
}

}  // namespace

class TestRunJudgement : public QObject {
    Q_OBJECT
private slots:
    void endReasonsAndContact()
    {
        const quint32 seed = QRandomGenerator::global()->generate();
        qInfo("seed %u", seed);
        // Noise alone, at any offset and level a load cell gives: no contact.
        QRandomGenerator rng(seed);
        for (int k = 0; k < 20; ++k) {
            const double sigma = 0.0005 + 0.004 * rng.generateDouble();
            QVERIFY2(!nb::touchedTissue(noiseRun(sigma, rng.generateDouble() - 0.5, rng.generate())),
                     qPrintable(QStringLiteral("sigma %1 N").arg(sigma)));
        }
        nb::Run contact = noiseRun(0.002, 0.0, seed);
        for (std::size_t i = 1000; i < contact.size(); ++i)
            contact.force_N[i] += 0.2 * double(i - 1000) / 1000.0;  // tissue loads the needle
        QVERIFY(nb::touchedTissue(contact));
        QVERIFY(nb::judgeRun(contact).usable);
        for (const char* reason : {"force_limit", "emergency_stop", "fault", "recovered"}) {
            nb::Run r = contact;
            r.footer.set(nb::key::end_reason, QString::fromLatin1(reason));
            const nb::RunJudgement j = nb::judgeRun(r);
            QVERIFY2(!j.usable && j.reason.startsWith(QStringLiteral("ended early (")), qPrintable(j.reason));
        }
        nb::Run cutOff = contact;
        cutOff.footer = {};
        QVERIFY(!nb::judgeRun(cutOff).usable);
        const nb::RunJudgement air = nb::judgeRun(noiseRun(0.002, 0.1, seed));
        QVERIFY(!air.usable && air.reason.contains(QStringLiteral("contact")));
    }

    void robustOutliers()
    {
        const QStringList r = nb::robustOutlierReasons({1.00, 1.02, 0.98, 1.01, 0.99, 1.60}, QStringLiteral("puncture force"), QStringLiteral("N"));
        QCOMPARE(r.size(), 6);
        for (int i = 0; i < 5; ++i)
            QVERIFY(r[i].isEmpty());
        QVERIFY(r[5].contains(QStringLiteral("puncture force 1.6 N")));
        QVERIFY(r[5].contains(QStringLiteral("median")));
        // Too few runs to say.
        for (const QString& s : nb::robustOutlierReasons({1.0, 5.0, 1.0}, QStringLiteral("x"), QStringLiteral("N")))
            QVERIFY(s.isEmpty());
    }

    // A session of four complete insertions and one stopped by the force limit: the stopped
    // one is left out by default (its stop is no puncture), taken on request.
    void analysisLeavesOutARunStoppedByTheForceLimit()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("s"));
        nb::Session::create(dir, {});
        for (int k = 1; k <= 4; ++k)
            QVERIFY(simulate({QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--seed"), QString::number(k),
                              QStringLiteral("--out"), QDir(dir).filePath(QStringLiteral("run_%1_linear.csv").arg(k, 3, 10, QLatin1Char('0')))}));
        const QString limited = QDir(dir).filePath(QStringLiteral("run_005_linear.csv"));
        QVERIFY(simulate({QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--max-force-n"), QStringLiteral("0.4"),
                          QStringLiteral("--out"), limited}));
        QCOMPARE(nb::readRunFile(limited).run.meta(nb::key::end_reason).value_or(QString()), QStringLiteral("force_limit"));

        const nb::Dataset d = nb::loadDataset(dir).dataset;
        const nb::SessionAnalysis judged = nb::analyseDataset(d);
        QCOMPARE(judged.stiffness.size(), std::size_t(4));
        QCOMPARE(judged.leftOut.size(), 1);
        QVERIFY(judged.leftOut.front().startsWith(QStringLiteral("run_005_linear: ended early (")));
        for (const nb::StiffnessRunResult& s : judged.stiffness)
            QVERIFY2(!s.outlier, qPrintable(s.run + QStringLiteral(": ") + s.outlierReason));

        const nb::SessionAnalysis all = nb::analyseDataset(d, {.includeJudgedOut = true});
        QCOMPARE(all.stiffness.size(), std::size_t(5));
        QVERIFY(all.leftOut.isEmpty());
    }

    void runsAreGroupedByTheTissueTheyName()
    {
        // Recorded in the window: the session's organ and specimen; on the command line: tissue;
        // on the simulated rig in the window without details: its preset.
        auto run = [](std::initializer_list<std::pair<QString, QString>> meta) {
            nb::DatasetRun r;
            r.name = QStringLiteral("r%1").arg(meta.size());
            r.run = noiseRun(0.001, 0.0, 7);
            r.run.metadata.set(QStringLiteral("motion"), QStringLiteral("linear"));
            for (const auto& [k, v] : meta)
                r.run.metadata.set(k, v);
            return r;
        };
        nb::Dataset d;
        d.runs.push_back(run({{nb::key::organ, QStringLiteral("liver")}, {nb::key::specimen, QStringLiteral("5")}}));
        d.runs.push_back(run({{nb::key::tissue, QStringLiteral("liver7")}, {nb::key::organ, QStringLiteral("liver")}}));
        d.runs.push_back(run({{QStringLiteral("sim_tissue"), QStringLiteral("liver3")}}));
        d.runs.push_back(run({}));
        const nb::SessionAnalysis a = nb::analyseDataset(d, {.includeJudgedOut = true});
        QStringList groups;
        for (const nb::StiffnessRunResult& s : a.stiffness)
            groups << s.group;
        QCOMPARE(groups, (QStringList{QStringLiteral("liver 5"), QStringLiteral("liver7"), QStringLiteral("liver3"), QString()}));
    }

    void videoLinkKeptWithTheRun()
    {
        QTemporaryDir tmp;
        const QString run = tmp.filePath(QStringLiteral("run_002_sine.csv"));
        QVERIFY(!nb::readRunVideoLink(run));
        nb::RunVideoLink link;
        link.video = tmp.filePath(QStringLiteral("videos/cam1.mp4"));
        link.mapping = {0.4123, 1.5e-4};
        link.method = nb::SyncMethod::EventMarks;
        nb::writeRunVideoLink(run, link);
        QFile f(nb::videoLinksPath(tmp.path()));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains("\"videos/cam1.mp4\""));  // relative inside the session
        f.close();
        const auto back = nb::readRunVideoLink(run);
        QVERIFY(back);
        QCOMPARE(back->video, QDir::cleanPath(link.video));
        QCOMPARE(back->mapping, link.mapping);
        QCOMPARE(back->method, nb::SyncMethod::EventMarks);
        QVERIFY(!back->confidence);
        QVERIFY(back->marks.region.isEmpty() && back->marks.needle.isNull());  // nothing drawn, nothing kept

        // What the operator drew on the video for its sync comes back as drawn; a hand-edited
        // mark that makes no sense (no width, a word for a number) is dropped, not drawn.
        link.marks.region = QRect(240, 300, 240, 180);
        link.marks.needle = QLineF(636.5, 20, 636, 290.25);
        nb::writeRunVideoLink(run, link);
        QCOMPARE(nb::readRunVideoLink(run)->marks.region, link.marks.region);
        QCOMPARE(nb::readRunVideoLink(run)->marks.needle, link.marks.needle);
        {
            QVERIFY(f.open(QIODevice::ReadOnly));
            QByteArray edited = f.readAll();
            f.close();
            QVERIFY(edited.contains("\"region\"") && edited.contains("\"needle\""));
            edited.replace("180", "0").replace("290.25", "\"far\"");
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(edited);
            f.close();
        }
        const auto edited = nb::readRunVideoLink(run);
        QVERIFY(edited && edited->marks.region.isEmpty() && edited->marks.needle.isNull());
        QCOMPARE(edited->mapping, link.mapping);
        link.marks = {};

        // Outside the session folder: kept absolute.
        QTemporaryDir elsewhere;
        link.video = elsewhere.filePath(QStringLiteral("cam2.avi"));
        nb::writeRunVideoLink(run, link);
        QCOMPARE(nb::readRunVideoLink(run)->video, QDir::cleanPath(link.video));

        nb::Run r;
        // Recorded with the simulator's video, synced automatically; then another video linked
        // by hand: its file, and nothing of the first video's (frame rate, confidence) left.
        r.metadata.set(nb::key::video_file, QStringLiteral("run_002_sine.avi"));
        r.metadata.set(nb::key::video_fps, 29.97002997);
        r.metadata.set(nb::key::sync_method, QStringLiteral("needle_displacement"));
        r.metadata.set(nb::key::sync_confidence, 0.9959);
        nb::applyRunVideoLink(r, run, *nb::readRunVideoLink(run));
        QCOMPARE(r.meta(nb::key::sync_offset_s).value_or(QString()), QStringLiteral("0.4123"));
        QCOMPARE(r.meta(nb::key::sync_method).value_or(QString()), QStringLiteral("event_marks"));
        QCOMPARE(r.meta(nb::key::video_file).value_or(QString()), QDir::cleanPath(link.video));
        QVERIFY(!r.meta(nb::key::video_fps));
        QVERIFY(!r.meta(nb::key::sync_confidence));
        // The same video linked again keeps its frame rate.
        nb::Run same;
        same.metadata.set(nb::key::video_file, QDir::cleanPath(link.video));
        same.metadata.set(nb::key::video_fps, 25.0);
        nb::applyRunVideoLink(same, run, *nb::readRunVideoLink(run));
        QCOMPARE(same.meta(nb::key::video_fps).value_or(QString()), QStringLiteral("25"));
        same.metadata.set(QStringLiteral("later"), 1.0);
        QCOMPARE(same.meta(QStringLiteral("later")).value_or(QString()), QStringLiteral("1"));

        nb::writeRunVideoLink(run, std::nullopt);
        QVERIFY(!nb::readRunVideoLink(run));

        // A camera's file beside the run, its suffix in capitals.
        QVERIFY(nb::videoBesideRun(run).isEmpty());
        {
            QFile cam(tmp.filePath(QStringLiteral("run_002_sine.MP4")));
            QVERIFY(cam.open(QIODevice::WriteOnly));
        }
        QCOMPARE(nb::videoBesideRun(run), QFileInfo(tmp.filePath(QStringLiteral("run_002_sine.MP4"))).absoluteFilePath());

        // A broken store is reported, not taken for "no video", and not overwritten.
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ not json");
        f.close();
        QString problem;
        QVERIFY(!nb::readRunVideoLink(run, &problem));
        QVERIFY(problem.contains(QStringLiteral("videos.json")));
        QVERIFY_THROWS_EXCEPTION(nb::SessionError, nb::writeRunVideoLink(run, link));
    }
};

QTEST_MAIN(TestRunJudgement)
#include "test_run_judgement.moc"
