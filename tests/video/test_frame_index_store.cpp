// The stored frame index: a real H.264 video indexed once is read back from the store, equal
// in every frame; a changed video, a damaged or foreign store file and a cancelled build are
// never taken for a valid index; the store keeps a bounded number of indexes.
#include "video/frame_index_store.h"
#include "video/frame_reader.h"
#include "video_fixtures.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using namespace nb::video;
using namespace nb::test;

namespace {
void compareIndexes(const FrameIndex& a, const FrameIndex& b)
{
    QCOMPARE(a.size(), b.size());
    QCOMPARE(a.codec, b.codec);
    QCOMPARE(a.width, b.width);
    QCOMPARE(a.height, b.height);
    QCOMPARE(a.fpsNominal, b.fpsNominal);
    QCOMPARE(a.keyframesKnown, b.keyframesKnown);
    QCOMPARE(a.timeOrigin_s, b.timeOrigin_s);
    QCOMPARE(a.warnings, b.warnings);
    QCOMPARE(a.frameDuration(), b.frameDuration());
    for (int i = 0; i < a.size(); ++i) {
        QCOMPARE(a.frames[std::size_t(i)].time_s, b.frames[std::size_t(i)].time_s);
        QCOMPARE(a.frames[std::size_t(i)].keyframe, b.frames[std::size_t(i)].keyframe);
        QCOMPARE(a.frames[std::size_t(i)].duplicate, b.frames[std::size_t(i)].duplicate);
    }
}

QString storeFileIn(const QString& dir)
{
    const QStringList files = QDir(dir).entryList({QStringLiteral("*.nbindex")}, QDir::Files);
    return files.size() == 1 ? QDir(dir).filePath(files.first()) : QString();
}
}  // namespace

class TestFrameIndexStore : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString video_, store_;

private slots:
    void initTestCase()
    {
        if (!haveFfmpeg())
            QSKIP("the ffmpeg tool is needed to make the test videos");
        video_ = dir_.filePath(QStringLiteral("run.mp4"));
        VideoSpec spec;
        spec.rate = QStringLiteral("30000/1001");
        spec.codes = sequence(60);
        spec.encodeArgs = QStringList{"-c:v", "libx264", "-preset", "veryfast", "-g", "30", "-bf", "2", "-pix_fmt", "yuv420p"};
        const QString err = writeVideo(video_, spec);
        QVERIFY2(err.isEmpty(), qPrintable(err));
        store_ = dir_.filePath(QStringLiteral("store"));
    }

    void secondOpenComesFromTheStore()
    {
        bool fromStore = true;
        const FrameIndex built = loadOrBuildFrameIndex(video_, {}, nullptr, &fromStore, store_);
        QVERIFY(!fromStore);
        QCOMPARE(built.size(), 60);
        QVERIFY(!storeFileIn(store_).isEmpty());
        int progressCalls = 0;
        const FrameIndex again =
            loadOrBuildFrameIndex(video_, [&](int done, int expected) { progressCalls += done == expected; }, nullptr, &fromStore, store_);
        QVERIFY(fromStore);
        QCOMPARE(progressCalls, 1);  // a view waiting on progress hears that it is done
        compareIndexes(again, built);
        // And the stored index reads frames as exactly as the built one.
        FrameReader reader(again, 8);
        for (int n : {59, 0, 31, 30, 29})
            QCOMPARE(readCode(reader.read(n).image), n);
    }

    // A stored index speaks the language of the program reading it, not of the one that made
    // it (a video indexed by the command line in English showed its warnings in English in the
    // German window); and a file that starts at 5 s is not taken for a cut one.
    void warningsInTheReadersLanguage()
    {
        const QString plain = dir_.filePath(QStringLiteral("plain.mp4")), rotated = dir_.filePath(QStringLiteral("rotated.mp4")),
                      late = dir_.filePath(QStringLiteral("late.mkv"));
        const QStringList lavfi{"-f", "lavfi", "-i", "testsrc2=size=320x240:rate=30", "-t", "4", "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p"};
        // The rotation tag as a phone writes it, put on by a copy (ffmpeg 5.1 drops it on encoding).
        for (const QStringList& args : {lavfi + QStringList{plain}, QStringList{"-i", plain, "-c", "copy", "-metadata:s:v:0", "rotate=90", rotated},
                                        lavfi + QStringList{"-output_ts_offset", "5", late}}) {
            QProcess ffmpeg;
            ffmpeg.start(QStringLiteral("ffmpeg"), QStringList{"-v", "error", "-y"} + args);
            QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        }
        const QString store = dir_.filePath(QStringLiteral("store-language"));
        bool fromStore = true;
        const FrameIndex english = loadOrBuildFrameIndex(rotated, {}, nullptr, &fromStore, store);
        QVERIFY(!fromStore);
        QCOMPARE(english.warnings.size(), 1);
        QVERIFY2(english.warnings.first().contains(QStringLiteral("turned by 90")), qPrintable(english.warnings.join('\n')));
        QTranslator german;
        QVERIFY(german.load(QStringLiteral(NB_BINARY_DIR "/app/needlebench_de.qm")));
        QCoreApplication::installTranslator(&german);
        const FrameIndex stored = loadOrBuildFrameIndex(rotated, {}, nullptr, &fromStore, store);
        QCoreApplication::removeTranslator(&german);
        QVERIFY(fromStore);
        QCOMPARE(stored.warnings.size(), 1);
        QVERIFY2(stored.warnings.first().contains(QStringLiteral("gedreht")), qPrintable(stored.warnings.join('\n')));
        QCOMPARE(stored.width, english.width);

        const FrameIndex later = loadOrBuildFrameIndex(late, {}, nullptr, &fromStore, store);
        QCOMPARE(later.size(), 120);
        QVERIFY2(later.warnings.isEmpty(), qPrintable(later.warnings.join('\n')));
    }

    // A file with a second video stream says that only the first is read (a capture's small
    // preview stream first and the imaging second was read as the video without a word); a
    // cover picture is no stream of pictures.
    void aSecondVideoStreamIsSaid()
    {
        const QString two = dir_.filePath(QStringLiteral("two.mp4")), cover = dir_.filePath(QStringLiteral("cover.mp4")),
                      png = dir_.filePath(QStringLiteral("cover.png")), ts = dir_.filePath(QStringLiteral("one.ts"));
        const QStringList small{"-f", "lavfi", "-t", "2", "-i", "testsrc2=size=160x120:rate=25"};
        const QStringList large{"-f", "lavfi", "-t", "2", "-i", "testsrc2=size=320x240:rate=25"};
        for (const QStringList& args : {small + large + QStringList{"-map", "0", "-map", "1", "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p", two},
                                        QStringList{"-f", "lavfi", "-i", "color=c=red:size=64x64", "-frames:v", "1", png},
                                        large + QStringList{"-i", png, "-map", "0", "-map", "1", "-c:v:0", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p",
                                                            "-c:v:1", "png", "-disposition:v:1", "attached_pic", cover},
                                        large + QStringList{"-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p", "-f", "mpegts", ts}}) {
            QProcess ffmpeg;
            ffmpeg.start(QStringLiteral("ffmpeg"), QStringList{"-v", "error", "-y"} + args);
            QVERIFY(ffmpeg.waitForFinished(60000));
            QVERIFY2(ffmpeg.exitCode() == 0, qPrintable(QString::fromUtf8(ffmpeg.readAllStandardError())));
        }
        const QString store = dir_.filePath(QStringLiteral("store-streams"));
        bool fromStore = true;
        const FrameIndex built = loadOrBuildFrameIndex(two, {}, nullptr, &fromStore, store);
        QCOMPARE(built.width, 160);
        QCOMPARE(built.warnings.size(), 1);
        QVERIFY2(built.warnings.first().contains(QStringLiteral("2 video streams")), qPrintable(built.warnings.join('\n')));
        QVERIFY(built.keyframesKnown);
        const FrameIndex stored = loadOrBuildFrameIndex(two, {}, nullptr, &fromStore, store);
        QVERIFY(fromStore);
        QCOMPARE(stored.warnings, built.warnings);
        const FrameIndex withCover = loadOrBuildFrameIndex(cover, {}, nullptr, &fromStore, store);
        QCOMPARE(withCover.width, 320);
        QVERIFY2(withCover.warnings.isEmpty(), qPrintable(withCover.warnings.join('\n')));
        // ffprobe lists an MPEG-TS file's stream twice, in its program and on its own: one stream
        // (every TS file was said to hold two).
        const FrameIndex transport = loadOrBuildFrameIndex(ts, {}, nullptr, &fromStore, store);
        QCOMPARE(transport.videoStreams, 1);
        QVERIFY2(transport.warnings.isEmpty(), qPrintable(transport.warnings.join('\n')));
    }

    void aChangedVideoIsIndexedAgain()
    {
        loadOrBuildFrameIndex(video_, {}, nullptr, nullptr, store_);  // stored, if no function before did
        QVERIFY(loadStoredFrameIndex(video_, store_));
        const QString other = dir_.filePath(QStringLiteral("other.mp4"));
        VideoSpec spec;
        spec.codes = sequence(45);
        spec.encodeArgs = QStringList{"-c:v", "libx264", "-preset", "veryfast", "-g", "15", "-pix_fmt", "yuv420p"};
        QVERIFY(writeVideo(other, spec).isEmpty());
        QFile::remove(video_ + QStringLiteral(".bak"));
        QVERIFY(QFile::rename(video_, video_ + QStringLiteral(".bak")));
        QVERIFY(QFile::copy(other, video_));  // same name, other content
        QVERIFY(!loadStoredFrameIndex(video_, store_));
        bool fromStore = true;
        QCOMPARE(loadOrBuildFrameIndex(video_, {}, nullptr, &fromStore, store_).size(), 45);
        QVERIFY(!fromStore);
        QVERIFY(loadStoredFrameIndex(video_, store_));
        QVERIFY(QFile::remove(video_));
        QVERIFY(QFile::rename(video_ + QStringLiteral(".bak"), video_));
        QVERIFY(!loadStoredFrameIndex(video_, store_));  // the restored file differs from what was stored last
        QCOMPARE(loadOrBuildFrameIndex(video_, {}, nullptr, nullptr, store_).size(), 60);
    }

    void aDamagedStoreIsIgnored_data()
    {
        QTest::addColumn<int>("cut");
        QTest::addColumn<QByteArray>("junk");
        QTest::newRow("truncated") << 40 << QByteArray();
        QTest::newRow("trailing bytes") << 0 << QByteArray("xyz");
        QTest::newRow("not an index") << -1 << QByteArray("time_s,position_mm,force_N\n0,0,0\n");
    }
    void aDamagedStoreIsIgnored()
    {
        QFETCH(int, cut);
        QFETCH(QByteArray, junk);
        QVERIFY(loadOrBuildFrameIndex(video_, {}, nullptr, nullptr, store_).size() == 60);
        const QString file = storeFileIn(store_);
        QVERIFY(!file.isEmpty());
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray bytes = f.readAll();
        f.close();
        if (cut > 0)
            bytes.chop(cut);
        else if (cut < 0)
            bytes.clear();
        bytes += junk;
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(bytes);
        f.close();
        QVERIFY(!loadStoredFrameIndex(video_, store_));
        bool fromStore = true;
        QCOMPARE(loadOrBuildFrameIndex(video_, {}, nullptr, &fromStore, store_).size(), 60);
        QVERIFY(!fromStore);
        QVERIFY(loadStoredFrameIndex(video_, store_));  // and stored afresh
    }

    void aCancelledBuildIsNotStored()
    {
        const QString store = dir_.filePath(QStringLiteral("cancelled"));
        std::atomic_bool cancel{false};
        const FrameIndex partial =
            loadOrBuildFrameIndex(video_, [&](int done, int) { cancel = cancel || done >= 10; }, &cancel, nullptr, store);
        QVERIFY2(partial.size() >= 10 && partial.size() < 60, qPrintable(QString::number(partial.size())));
        QVERIFY(!loadStoredFrameIndex(video_, store));
    }

    void anUnwritableStoreOnlyCostsTheShortcut()
    {
        const QString blocker = dir_.filePath(QStringLiteral("a-file"));
        QFile f(blocker);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.close();
        bool fromStore = true;
        // The store "directory" is a file: nothing can be stored, the index is still built.
        QCOMPARE(loadOrBuildFrameIndex(video_, {}, nullptr, &fromStore, blocker + QStringLiteral("/store")).size(), 60);
        QVERIFY(!fromStore);
    }
};

QTEST_GUILESS_MAIN(TestFrameIndexStore)
#include "test_frame_index_store.moc"
