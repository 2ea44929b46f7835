// `needlebench labels suggest RUN.csv --video VIDEO` on an insertion run: the relaxation from
// the organ surface's spring-back in the imaging video (a real rendered and MJPEG-encoded
// video from `simulate --video`, the real decoder, real processes), within two frames of the
// simulator's truth; without the video none is suggested (the force cannot show it). The run
// the command sees has no truth columns, as a lab's has none.
#include "core/run_file.h"
#include "support/needlebench_cli.h"
#include "support/truth_columns.h"

#include <QJsonArray>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

class TestRelaxVideo : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString blind_, video_;
    double truth_s_ = 0.0, fps_ = 0.0;

    static QJsonArray relaxations(const QJsonObject& o)
    {
        QJsonArray out;
        for (const QJsonValue& v : o.value(QStringLiteral("labels")).toArray())
            if (v.toObject().value(QStringLiteral("label")).toString() == QLatin1String("relaxation"))
                out.append(v);
        return out;
    }

private slots:
    void initTestCase()
    {
        const QString full = dir_.filePath(QStringLiteral("run.csv")), truth = dir_.filePath(QStringLiteral("truth.json"));
        video_ = dir_.filePath(QStringLiteral("scan.avi"));
        const nbtest::CliResult r = nbtest::runCli({"simulate", "--protocol", "stiffness", "--tissue", "liver1", "--velocity-mm-s", "7",
                                                    "--depth-mm", "30", "--seed", "4", "--out", full, "--truth", truth, "--video", video_,
                                                    "--video-offset-s", "0.6"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject t = nbtest::readJsonFile(truth);
        truth_s_ = t.value(QStringLiteral("relaxed_s")).toDouble(-1.0);  // on the run's clock
        fps_ = t.value(QStringLiteral("video")).toObject().value(QStringLiteral("fps")).toDouble();
        QVERIFY2(truth_s_ > 0.0 && fps_ > 0.0, "the simulator's truth has no relaxation or no video");
        blind_ = dir_.filePath(QStringLiteral("blind.csv"));
        nb::writeRunFile(blind_, nbtest::withoutTruthColumns(nb::readRunFile(full).run));
    }

    void relaxationFromTheVideo()
    {
        const nbtest::CliResult r = nbtest::runCli({"labels", "suggest", blind_, "--video", video_, "--video-offset-s", "0.6", "--json",
                                                    "--out", dir_.filePath(QStringLiteral("with.csv"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = r.json();
        const QJsonArray relax = relaxations(o);
        QVERIFY2(relax.size() == 1, qPrintable(r.out + r.err));
        const double t = relax[0].toObject().value(QStringLiteral("start_s")).toDouble();
        qInfo("relaxation suggested at %.4f s, true %.4f s (%.2f frames); %s", t, truth_s_, (t - truth_s_) * fps_,
              qPrintable(relax[0].toObject().value(QStringLiteral("comment")).toString()));
        // Two frames: the spring-back is fitted over all frames, its onset is the force's
        // puncture (bench_accuracy --relax-cases measures the spread over looks and codecs).
        QVERIFY2(std::abs(t - truth_s_) <= 2.0 / fps_, qPrintable(QStringLiteral("suggested %1 s, true %2 s").arg(t).arg(truth_s_)));
        QVERIFY(relax[0].toObject().value(QStringLiteral("comment")).toString().contains(QLatin1String("scan.avi")));
        QCOMPARE(o.value(QStringLiteral("video")).toObject().value(QStringLiteral("relaxation")).toString(), QStringLiteral("suggested"));
    }

    void noneWithoutTheVideo()
    {
        const nbtest::CliResult r = nbtest::runCli({"labels", "suggest", blind_, "--json", "--out", dir_.filePath(QStringLiteral("without.csv"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject o = r.json();
        QVERIFY(relaxations(o).isEmpty());
        // The force's events are still there.
        bool puncture = false;
        for (const QJsonValue& v : o.value(QStringLiteral("labels")).toArray())
            puncture |= v.toObject().value(QStringLiteral("label")).toString() == QLatin1String("puncture");
        QVERIFY(puncture);
    }

    // A picture in which nothing moves (the video's first frame held, made with the ffmpeg
    // tool): no relaxation, and the command says why.
    void noneWhenTheVideoDoesNotShowIt()
    {
        if (QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
            QSKIP("the ffmpeg tool is needed to make the still video");
        const QString still = dir_.filePath(QStringLiteral("still.avi"));
        QProcess p;
        p.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-i", video_, "-vf", "select=eq(n\\,0),loop=loop=200:size=1:start=0,setpts=N/(30000/1001)/TB",
                                           "-r", "30000/1001", "-c:v", "mjpeg", "-q:v", "3", still});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const nbtest::CliResult r = nbtest::runCli({"labels", "suggest", blind_, "--video", still, "--video-offset-s", "0.6", "--json",
                                                    "--out", dir_.filePath(QStringLiteral("still.labels.csv"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(relaxations(r.json()).isEmpty(), qPrintable(r.out));
        QVERIFY2(r.err.contains(QLatin1String("no relaxation suggested")), qPrintable(r.err));
        qInfo("%s", qPrintable(r.err.trimmed()));
    }
};

QTEST_GUILESS_MAIN(TestRelaxVideo)
#include "test_relax_video.moc"
