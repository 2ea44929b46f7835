// The session HDF5 as other people's programs read it: Octave's `load` (octave-cli) and h5py
// (with pandas for the CSV), run for real on a file exported from a simulated session. And
// the links: after the export folder is moved, the EAF, the JSON sidecars and the HDF5 still
// find their video and CSV (relative paths, video placed beside with --copy-video).

#include "support/needlebench_cli.h"

#include "core/labels.h"
#include "core/session.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using nbtest::runCli;

namespace {

struct Run {
    int code = -1;
    QString out;
};

Run runTool(const QString& program, const QStringList& args, int timeout_ms = 180000)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(program, args);
    if (!p.waitForFinished(timeout_ms)) {
        p.kill();
        p.waitForFinished();
        return {-1, QStringLiteral("timed out")};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAll())};
}

// A system python with h5py (a pyenv shim on PATH may lack it).
QString pythonWithH5py()
{
    for (const QString& dir : {QStringLiteral("/usr/bin"), QString()}) {
        const QString py = dir.isEmpty() ? QStandardPaths::findExecutable(QStringLiteral("python3"))
                                         : QStandardPaths::findExecutable(QStringLiteral("python3"), {dir});
        if (!py.isEmpty() && runTool(py, {QStringLiteral("-c"), QStringLiteral("import h5py, pandas")}).code == 0)
            return py;
    }
    return {};
}

}  // namespace

class TestReaders : public QObject {
    Q_OBJECT
    QTemporaryDir root;
    QString session, moved;

private slots:
    void initTestCase()
    {
        QVERIFY(root.isValid());
        session = QDir(root.path()).filePath(QStringLiteral("session"));
        nb::SessionInfo info;
        info.organ = QStringLiteral("nan");  // a text field that reads like a number
        info.specimen = QStringLiteral("0012");
        info.tip = QStringLiteral("diamond");
        info.thickness_mm = 30;
        info.operatorName = QStringLiteral("Zoë");
        info.protocol = QStringLiteral("stiffness");
        nb::Session::create(session, info);
        const QDir s(session);
        const auto sim = runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                 QStringLiteral("--out"), s.filePath(QStringLiteral("run_001.csv")), QStringLiteral("--video"),
                                 s.filePath(QStringLiteral("run_001.avi"))});
        QVERIFY2(sim.code == 0, qPrintable(sim.err));
        nb::Labels labels{{QStringLiteral("insertion"), QStringLiteral("a"), 0.5, 2.0, QString()},
                          {QStringLiteral("insertion"), QStringLiteral("b1"), 2.0, 4.0, QStringLiteral("Zoë's note")},
                          {QStringLiteral("events"), QStringLiteral("far away"), 1e300, 1e300, QString()}};
        nb::writeLabelsFile(s.filePath(QStringLiteral("run_001.labels.csv")), labels);

        const QString a = QDir(root.path()).filePath(QStringLiteral("exportA"));
        for (const char* fmt : {"hdf5", "csv", "eaf"}) {
            const QString out = fmt == QByteArray("hdf5") ? QDir(a).filePath(QStringLiteral("session.h5")) : QDir(a).filePath(QLatin1String(fmt));
            const auto r = runCli({QStringLiteral("export"), session, QStringLiteral("--format"), QLatin1String(fmt),
                                   QStringLiteral("--out"), out, QStringLiteral("--copy-video")});
            QVERIFY2(r.code == 0, qPrintable(r.err));
            // The label at 1e300 s is refused, by name, not turned into a frame number.
            QVERIFY2(r.err.contains(QLatin1String("far away")) && r.err.contains(QLatin1String("outside the run")), qPrintable(r.err));
        }
        // The export folder travels: every link must still resolve from its new place.
        moved = QDir(root.path()).filePath(QStringLiteral("moved/elsewhere"));
        QVERIFY(QDir().mkpath(QFileInfo(moved).absolutePath()));
        QVERIFY(QDir().rename(a, moved));
    }

    void h5pyAndPandasRead()
    {
        const QString py = pythonWithH5py();
        if (py.isEmpty())
            QSKIP("python3 with h5py and pandas is not installed (scripts/install-deps.sh installs it)");
        const QString script = QStringLiteral(NB_SOURCE_DIR "/tests/export/read_session_h5.py");
        const auto r = runTool(py, {script, QDir(moved).filePath(QStringLiteral("session.h5")),
                                    QDir(moved).filePath(QStringLiteral("csv/run_001.csv"))});
        QVERIFY2(r.code == 0 && r.out.contains(QLatin1String("h5py-ok")), qPrintable(r.out));
    }

    void octaveLoads()
    {
        const QString octave = QStandardPaths::findExecutable(QStringLiteral("octave-cli"));
        if (octave.isEmpty())
            QSKIP("octave-cli is not installed (scripts/install-deps.sh installs it)");
        const QString code = QStringLiteral(
            "s = load('%1'); r = s.runs.run_001; "
            "assert(strcmp(class(r.seq), 'int64')); assert(numel(r.force_N) == numel(r.time_s)); "
            "assert(numel(r.force_N) > 1000); assert(size(r.labels.label, 1) == 2); "
            "assert(strcmp(strtrim(r.labels.label(2, :)), 'b1')); "
            "printf('octave-ok %d\\n', numel(r.force_N)); exit(0);")
                                 .arg(QDir(moved).filePath(QStringLiteral("session.h5")));
        const auto r = runTool(octave, {QStringLiteral("--no-gui"), QStringLiteral("--norc"), QStringLiteral("--eval"), code});
        QVERIFY2(r.out.contains(QLatin1String("octave-ok")), qPrintable(r.out.right(3000)));
        QVERIFY2(!r.out.contains(QLatin1String("error while reading")), qPrintable(r.out.right(3000)));
    }

    void eafLinksResolveAfterTheMove()
    {
        const QString eaf = QDir(moved).filePath(QStringLiteral("eaf/run_001.eaf"));
        QFile f(eaf);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader x(&f);
        QString media, link;
        QStringList elements;
        while (!x.atEnd()) {
            if (x.readNext() != QXmlStreamReader::StartElement)
                continue;
            elements << x.name().toString();
            if (x.name() == QLatin1String("MEDIA_DESCRIPTOR"))
                media = x.attributes().value(QLatin1String("RELATIVE_MEDIA_URL")).toString();
            if (x.name() == QLatin1String("LINKED_FILE_DESCRIPTOR"))
                link = x.attributes().value(QLatin1String("RELATIVE_LINK_URL")).toString();
        }
        QVERIFY2(!x.hasError(), qPrintable(x.errorString()));
        // Structure ELAN's schema asks for, in order: HEADER, TIME_ORDER, TIER(s), LINGUISTIC_TYPE.
        QCOMPARE(elements.first(), QStringLiteral("ANNOTATION_DOCUMENT"));
        QVERIFY(elements.indexOf(QStringLiteral("HEADER")) < elements.indexOf(QStringLiteral("TIME_ORDER")));
        QVERIFY(elements.indexOf(QStringLiteral("TIME_ORDER")) < elements.indexOf(QStringLiteral("TIER")));
        QVERIFY(elements.indexOf(QStringLiteral("TIER")) < elements.indexOf(QStringLiteral("LINGUISTIC_TYPE")));
        const QDir here = QFileInfo(eaf).dir();
        QVERIFY2(QFileInfo(here.filePath(media)).isFile(), qPrintable(media));
        QVERIFY2(QFileInfo(here.filePath(link)).isFile(), qPrintable(link));
        QVERIFY(!QDir::isAbsolutePath(media) && !QDir::isAbsolutePath(link));
        const QString xmllint = QStandardPaths::findExecutable(QStringLiteral("xmllint"));
        if (!xmllint.isEmpty())
            QCOMPARE(runTool(xmllint, {QStringLiteral("--noout"), eaf}).code, 0);
    }

    void sidecarLinksResolveAfterTheMove()
    {
        const QString json = QDir(moved).filePath(QStringLiteral("csv/run_001.json"));
        const QJsonObject j = nbtest::readJsonFile(json);
        const QDir here = QFileInfo(json).dir();
        QVERIFY(QFileInfo(here.filePath(j.value(QStringLiteral("csv")).toString())).isFile());
        QVERIFY2(QFileInfo(here.filePath(j.value(QStringLiteral("video")).toString())).isFile(), qPrintable(j.value("video").toString()));
        QVERIFY(!QDir::isAbsolutePath(j.value(QStringLiteral("video")).toString()));
        // The source run stayed where it was: the relative link still leads to it.
        QCOMPARE(QFileInfo(here.filePath(j.value(QStringLiteral("source")).toString())).canonicalFilePath(),
                 QFileInfo(QDir(session).filePath(QStringLiteral("run_001.csv"))).canonicalFilePath());
    }

    void intervalsHaveFramesOnlyWithAVideo()
    {
        QFile f(QDir(moved).filePath(QStringLiteral("csv/run_001.intervals.csv")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().split('\n');
        QVERIFY(lines.size() >= 3);
        QVERIFY(!lines[1].split(',')[5].isEmpty());  // this run has a video: frames given
    }
};

QTEST_GUILESS_MAIN(TestReaders)
#include "test_readers.moc"
