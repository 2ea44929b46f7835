// The video commands' contracts, run as real processes: video-info and frame.
#include "video_fixtures.h"
#include "support/needlebench_cli.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace nb::test;

static nbtest::CliResult run(const QStringList& args)
{
    return nbtest::runCli(args);
}

class TestVideoCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString vfr_;

private slots:
    void initTestCase()
    {
        if (!haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to make the test videos");
        vfr_ = dir_.filePath("vfr.mp4");
        VideoSpec spec;
        for (int i = 0; i < 90; ++i)
            spec.codes.push_back(i % 9 == 8 ? spec.codes.back() : i);  // every ninth frame repeats
        // A stretch of 10 frame periods missing after frame 44 makes the rate variable.
        spec.filterArgs = QStringList{"-vf", "settb=1/600,setpts=(N+floor(N/45)*10)*20", "-fps_mode", "passthrough",
                                      "-enc_time_base", "1/600"};
        spec.encodeArgs = QStringList{"-c:v", "libx264", "-preset", "veryfast", "-g", "30", "-bf", "2", "-pix_fmt", "yuv420p",
                                      "-video_track_timescale", "600"};
        const QString err = writeVideo(vfr_, spec);
        QVERIFY2(err.isEmpty(), qPrintable(err));
    }

    void videoInfoJson()
    {
        const nbtest::CliResult r = run({"video-info", vfr_, "--json"});
        QCOMPARE(r.code, 0);
        const QJsonObject o = r.json();
        for (const char* key : {"frames", "fps_nominal", "duration_s", "codec", "width", "height", "variable_frame_rate",
                                "duplicate_frames"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        QCOMPARE(o["frames"].toInt(), 90);
        QCOMPARE(o["width"].toInt(), 320);
        QCOMPARE(o["height"].toInt(), 240);
        QCOMPARE(o["variable_frame_rate"].toBool(), true);
        QCOMPARE(o["duplicate_frames"].toInt(), 10);  // frames 8, 17, ..., 89
        QCOMPARE(o["codec"].toString(), QStringLiteral("h264"));
        QVERIFY(std::abs(o["duration_s"].toDouble() - 100 / 30.0) < 0.002);

        // A video named with a leading dash (given after --) is indexed as any other: ffprobe
        // took the name for an option, and the index went without its codec.
        QVERIFY(QFile::copy(vfr_, dir_.filePath(QStringLiteral("-dash.mp4"))));
        const QString cwd = QDir::currentPath();
        QVERIFY(QDir::setCurrent(dir_.path()));
        const nbtest::CliResult dash = run({"video-info", "--json", "--", "-dash.mp4"});
        QDir::setCurrent(cwd);
        QVERIFY2(dash.code == 0, qPrintable(dash.err));
        QCOMPARE(dash.json()["codec"].toString(), QStringLiteral("h264"));
        QCOMPARE(dash.json()["frames"].toInt(), 90);
        QCOMPARE(dash.json()["variable_frame_rate"].toBool(), true);
    }

    void frameWritesTheExactFrame()
    {
        for (int n : {0, 44, 45, 46, 80, 89}) {
            const QString png = dir_.filePath(QStringLiteral("f%1.png").arg(n));
            const nbtest::CliResult r = run({"frame", vfr_, "--index", QString::number(n), "--out", png, "--json"});
            QCOMPARE(r.code, 0);
            const QJsonObject o = r.json();
            QCOMPARE(o["index"].toInt(), n);
            const double expected = (n + (n >= 45 ? 10 : 0)) / 30.0;
            QVERIFY(std::abs(o["time_s"].toDouble() - expected) < 0.001);
            const int code = readCode(QImage(png));
            QCOMPARE(code, n % 9 == 8 ? n - 1 : n);
        }
    }

    void badInput()
    {
        QCOMPARE(run({"frame", vfr_, "--out", dir_.filePath("x.png")}).code, 2);  // no --index
        QCOMPARE(run({"frame", vfr_, "--index", "-3", "--out", dir_.filePath("x.png")}).code, 2);
        QCOMPARE(run({"video-info"}).code, 2);
        const nbtest::CliResult beyond = run({"frame", vfr_, "--index", "90", "--out", dir_.filePath("x.png")});
        QCOMPARE(beyond.code, 1);
        QVERIFY(beyond.err.contains("frame 90 does not exist"));
        // Beyond an int: the same answer with the number given (it read "--index N is required").
        const nbtest::CliResult huge = run({"frame", vfr_, "--index", "99999999999", "--out", dir_.filePath("x.png")});
        QCOMPARE(huge.code, 1);
        QVERIFY2(huge.err.contains("frame 99999999999 does not exist"), qPrintable(huge.err));
        const nbtest::CliResult missing = run({"video-info", dir_.filePath("none.mp4")});
        QCOMPARE(missing.code, 1);
        QVERIFY(missing.err.contains("none.mp4"));
        const nbtest::CliResult unwritable = run({"frame", vfr_, "--index", "3", "--out", dir_.filePath("no/such/dir/x.png")});
        QCOMPARE(unwritable.code, 1);
        QVERIFY2(unwritable.err.contains(QStringLiteral("does not exist")), qPrintable(unwritable.err));
        // An MP4 recording cut off before it was closed (no index at its end): said so, by name,
        // without FFmpeg's own log line (it was "cannot open as video (not a video file…)").
        VideoSpec whole;
        whole.codes = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
        whole.encodeArgs = QStringList{"-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p"};
        const QString full = dir_.filePath("whole.mp4"), cut = dir_.filePath("cut off.mp4");
        QVERIFY(writeVideo(full, whole).isEmpty());
        {
            QFile in(full), out(cut);
            QVERIFY(in.open(QIODevice::ReadOnly) && out.open(QIODevice::WriteOnly));
            out.write(in.read(in.size() / 2));
        }
        const nbtest::CliResult cutOff = run({"video-info", cut});
        QCOMPARE(cutOff.code, 1);
        QVERIFY2(cutOff.err.contains(cut) && cutOff.err.contains(QStringLiteral("cut off")) && !cutOff.err.contains(QStringLiteral("@ 0x")),
                 qPrintable(cutOff.err));
        // A scratch in its middle: the frames after it are read, and where it lies is said.
        const QString scratched = dir_.filePath("scratched.mp4");
        QVERIFY(writeScratched(full, scratched, 0.3, 0.35) >= 1);
        const nbtest::CliResult damaged = run({"video-info", scratched, "--json"});
        QCOMPARE(damaged.code, 0);
        QVERIFY2(damaged.err.contains(scratched) && damaged.err.contains(QStringLiteral("damaged between")), qPrintable(damaged.err));
        const QJsonObject info = QJsonDocument::fromJson(damaged.out.toUtf8()).object();
        QVERIFY2(!info.value("damaged").toArray().isEmpty(), qPrintable(damaged.out));
        QVERIFY2(info.value("damaged").toArray().first().toObject().value("before_s").toDouble() > 0.3, qPrintable(damaged.out));
        QVERIFY2(info.value("duration_s").toDouble() > 0.6, qPrintable(damaged.out));
        // A video of one frame holds no motion to match: named, with what it lacks.
        VideoSpec one;
        one.codes = {0};
        one.encodeArgs = QStringList{"-c:v", "mjpeg", "-pix_fmt", "yuvj420p"};
        const QString still = dir_.filePath("one.avi");
        QVERIFY(writeVideo(still, one).isEmpty());
        const QString runFile = dir_.filePath("run.csv");
        QCOMPARE(run({"simulate", "--protocol", "friction", "--cycles", "1", "--frequency-hz", "1", "--out", runFile}).code, 0);
        const nbtest::CliResult tooShort = run({"sync", runFile, still});
        QCOMPARE(tooShort.code, 1);
        QVERIFY2(tooShort.err.contains(still) && tooShort.err.contains(QStringLiteral("1 frame")), qPrintable(tooShort.err));
    }
};

QTEST_GUILESS_MAIN(TestVideoCli)
#include "test_video_cli.moc"
