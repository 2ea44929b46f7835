// Every exporter writes real files that are read back with independent readers: Qt's CSV
// splitting and JSON parser, the HDF5 C library (and h5dump), Qt's XML reader.
#include "core/export/dataset_loader.h"
#include "core/export/eaf_export.h"
#include "core/session.h"
#include "core/export/fit_table.h"
#include "core/export/label_intervals.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_hdf5.h"
#include "support/hdf5_attributes.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>
#include <cmath>
#include <hdf5.h>

using namespace nb;

namespace {

// 2 s at 500 Hz: 4 mm/s insertion with a force ramp and a drop at 1.5 s.
DatasetRun makeRun(const QString& name, double forceScale = 1.0)
{
    DatasetRun r;
    r.name = name;
    r.sourcePath = QStringLiteral("/data/") + name + QStringLiteral(".csv");
    r.run.metadata.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
    r.run.metadata.set(QStringLiteral("rate_hz"), 500.0);
    r.run.metadata.set(QStringLiteral("sync_offset_s"), 0.5);
    r.run.metadata.set(QStringLiteral("calibration_slope_V_per_g"), 0.0012);
    r.run.metadata.set(QStringLiteral("device_force"), QStringLiteral("LabJack U6 #320012345"));
    r.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
    r.run.footer.set(QStringLiteral("dropped_samples"), 3.0);
    for (int i = 0; i < 1000; ++i) {
        const double t = i / 500.0;
        r.run.time_s.push_back(t);
        r.run.position_mm.push_back(4.0 * t);
        r.run.force_N.push_back(forceScale * (t < 1.5 ? t : 0.2 * t));
    }
    r.labels = {
        {QStringLiteral("insertion"), QStringLiteral("a"), 0.2, 0.6, QString()},
        {QStringLiteral("insertion"), QStringLiteral("c"), 1.0, 1.5, QStringLiteral("steady, then \"drop\"")},
        {QStringLiteral("events"), QStringLiteral("puncture"), 1.498, 1.498, QString()},
    };
    return r;
}

QStringList splitCsvLine(const QString& line)
{
    QStringList out;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == u'"' && i + 1 < line.size() && line[i + 1] == u'"') {
                field += c;
                ++i;
            } else if (c == u'"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == u'"') {
            quoted = true;
        } else if (c == u',') {
            out << field;
            field.clear();
        } else {
            field += c;
        }
    }
    out << field;
    return out;
}

QList<QStringList> readCsv(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QList<QStringList> rows;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (!line.isEmpty())
            rows << splitCsvLine(QString::fromUtf8(line));
    return rows;
}

std::vector<double> readDoubles(hid_t file, const char* path)
{
    const hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
    if (d < 0)
        return {};
    const hid_t s = H5Dget_space(d);
    hsize_t n = 0;
    H5Sget_simple_extent_dims(s, &n, nullptr);
    std::vector<double> v(n);
    if (n)
        H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Sclose(s);
    H5Dclose(d);
    return v;
}

// Strings as the file stores them: fixed-length (what the export writes, so that Octave and
// MATLAB read them), NUL-padded.
QStringList readStrings(hid_t file, const char* path)
{
    const hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
    if (d < 0)
        return {};
    const hid_t s = H5Dget_space(d);
    hsize_t n = 0;
    H5Sget_simple_extent_dims(s, &n, nullptr);
    const hid_t t = H5Dget_type(d);
    QStringList out;
    if (H5Tis_variable_str(t) == 0) {
        const std::size_t width = H5Tget_size(t);
        std::vector<char> buf(n * width + 1, '\0');
        if (n && H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) >= 0)
            for (hsize_t i = 0; i < n; ++i)
                out << QString::fromUtf8(QByteArray(buf.data() + i * width, qsizetype(width)).split('\0').first());
    } else {
        out << QStringLiteral("<variable-length>");
    }
    H5Tclose(t);
    H5Sclose(s);
    H5Dclose(d);
    return out;
}

// Fixed-length strings only (Octave and MATLAB need them): a variable-length one reads as such.
QString readStringAttr(hid_t obj, const char* name)
{
    const nbtest::StringAttribute a = nbtest::readStringAttribute(obj, name);
    return a.variableLength ? QStringLiteral("<variable-length>") : a.text;
}

double readDoubleAttr(hid_t obj, const char* name) { return nbtest::readDoubleAttribute(obj, name); }

QStringList filesIn(const QString& dir) { return QDir(dir).entryList(QDir::Files | QDir::Hidden); }

}  // namespace

class TestExportRoundTrip : public QObject {
    Q_OBJECT

private slots:
    void runCsvAndSidecarRoundTrip()
    {
        QTemporaryDir dir;
        const DatasetRun r = makeRun(QStringLiteral("liver5_run01"));
        const QString csv = dir.filePath(QStringLiteral("liver5_run01.csv"));
        QVERIFY(writeRunCsv(csv, r));

        const auto rows = readCsv(csv);
        QCOMPARE(rows.size(), 1001);
        QCOMPARE(rows[0], (QStringList{"time_s", "position_mm", "velocity_mm_s", "acceleration_mm_s2", "force_N",
                                       "label_insertion", "label_events"}));
        for (int i : {0, 1, 250, 749, 999}) {
            const QStringList& row = rows[i + 1];
            QCOMPARE(row.size(), 7);
            QCOMPARE(row[0].toDouble(), r.run.time_s[i]);
            QVERIFY(std::abs(row[1].toDouble() - r.run.position_mm[i]) < 1e-6);
            QVERIFY(std::abs(row[2].toDouble() - 4.0) < 1e-6);   // derived velocity of a 4 mm/s ramp
            QVERIFY(std::abs(row[3].toDouble()) < 1e-6);
            QVERIFY(std::abs(row[4].toDouble() - r.run.force_N[i]) < 1e-6);
        }
        // Sample 250 is t = 0.5 s, inside "a"; 749 (1.498 s) is in "c" and carries the puncture.
        QCOMPARE(rows[251][5], QStringLiteral("a"));
        QCOMPARE(rows[300 + 1][5], QString());  // 0.6 s: the interval is half open
        QCOMPARE(rows[750][5], QStringLiteral("c"));
        QCOMPARE(rows[750][6], QStringLiteral("puncture"));
        QCOMPARE(rows[751][6], QString());

        QFile jf(sidecarPath(csv));
        QVERIFY(jf.open(QIODevice::ReadOnly));
        QJsonParseError err;
        const QJsonObject j = QJsonDocument::fromJson(jf.readAll(), &err).object();
        QCOMPARE(err.error, QJsonParseError::NoError);
        QCOMPARE(j.value("csv").toString(), QStringLiteral("liver5_run01.csv"));
        QCOMPARE(j.value("samples").toInt(), 1000);
        const QJsonObject rate = j.value("metadata").toObject().value("rate_hz").toObject();
        QCOMPARE(rate.value("value").toDouble(), 500.0);
        QCOMPARE(rate.value("unit").toString(), QStringLiteral("Hz"));
        QCOMPARE(j.value("metadata").toObject().value("calibration_slope_V_per_g").toObject().value("unit").toString(),
                 QStringLiteral("V/g"));
        QCOMPARE(j.value("calibration").toObject().value("calibration_slope_V_per_g").toDouble(), 0.0012);
        QCOMPARE(j.value("device").toObject().value("device_force").toString(), QStringLiteral("LabJack U6 #320012345"));
        QCOMPARE(j.value("drops").toObject().value("dropped_samples").toDouble(), 3.0);
        QCOMPARE(j.value("footer").toObject().value("end_reason").toObject().value("value").toString(),
                 QStringLiteral("completed"));
        QCOMPARE(j.value("sync").toObject().value("offset_s").toDouble(), 0.5);
        {
            // A run with neither a video nor an offset says no offset; a 0 read as "synced at 0".
            DatasetRun plain = makeRun(QStringLiteral("plain"));
            plain.run.metadata.remove(QStringLiteral("sync_offset_s"));
            const QString plainCsv = dir.filePath(QStringLiteral("plain.csv"));
            QVERIFY(writeRunCsv(plainCsv, plain));
            QFile pj(sidecarPath(plainCsv));
            QVERIFY(pj.open(QIODevice::ReadOnly));
            const QJsonValue offset = QJsonDocument::fromJson(pj.readAll()).object().value("sync").toObject().value("offset_s");
            QVERIFY2(offset.isNull(), qPrintable(QString::number(offset.toDouble())));
        }
        const QJsonArray labels = j.value("labels").toArray();
        QCOMPARE(labels.size(), 3);
        QCOMPARE(labels[1].toObject().value("comment").toString(), QStringLiteral("steady, then \"drop\""));
        const QJsonArray cols = j.value("columns").toArray();
        QCOMPARE(cols.size(), 7);
        QCOMPARE(cols[2].toObject().value("unit").toString(), QStringLiteral("mm/s"));
        QCOMPARE(cols[4].toObject().value("unit").toString(), QStringLiteral("N"));
    }

    void recordedVelocityIsKept()
    {
        QTemporaryDir dir;
        DatasetRun r = makeRun(QStringLiteral("v"));
        auto& v = r.run.addNumericColumn(QStringLiteral("velocity_mm_s"));
        v.assign(r.run.size(), 7.5);
        auto& volts = r.run.addNumericColumn(QStringLiteral("voltage_V"));
        volts.assign(r.run.size(), 0.25);
        const QString csv = dir.filePath(QStringLiteral("v.csv"));
        QVERIFY(writeRunCsv(csv, r));
        const auto rows = readCsv(csv);
        QCOMPARE(rows[0].mid(0, 6), (QStringList{"time_s", "position_mm", "velocity_mm_s", "acceleration_mm_s2", "force_N", "voltage_V"}));
        QCOMPARE(rows[10][2].toDouble(), 7.5);
        QCOMPARE(rows[10][5].toDouble(), 0.25);
    }

    // The simulated rig's true phase (a text column) goes into both exports, as recorded: it
    // was left out, and the truth a suggestion is measured against with it.
    void recordedTextColumnsAreKept()
    {
        QTemporaryDir dir;
        Dataset d;
        d.runs.push_back(makeRun(QStringLiteral("p")));
        DatasetRun& r = d.runs.back();
        auto& phase = r.run.addTextColumn(QStringLiteral("phase"));
        for (std::size_t i = 0; i < r.run.size(); ++i)
            phase.push_back(i < 300 ? QStringLiteral("a") : i < 600 ? QStringLiteral("b1") : QStringLiteral("c"));
        const QString csv = dir.filePath(QStringLiteral("p.csv"));
        QVERIFY(writeRunCsv(csv, r));
        const auto rows = readCsv(csv);
        QCOMPARE(rows[0].last(), QStringLiteral("phase"));
        QCOMPARE(rows[1].last(), QStringLiteral("a"));
        QCOMPARE(rows[451].last(), QStringLiteral("b1"));
        QCOMPARE(rows[1000].last(), QStringLiteral("c"));
        QFile jf(sidecarPath(csv));
        QVERIFY(jf.open(QIODevice::ReadOnly));
        const QJsonArray cols = QJsonDocument::fromJson(jf.readAll()).object().value("columns").toArray();
        QCOMPARE(cols.last().toObject().value("name").toString(), QStringLiteral("phase"));
        QCOMPARE(cols.size(), rows[0].size());

        const QString h5 = dir.filePath(QStringLiteral("s.h5"));
        QVERIFY(writeSessionHdf5(h5, d));
        const hid_t f = H5Fopen(QFile::encodeName(h5).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
        QVERIFY(f >= 0);
        const QStringList back = readStrings(f, "/runs/p/phase");
        H5Fclose(f);
        QCOMPARE(back.size(), qsizetype(1000));
        QCOMPARE(back[0], QStringLiteral("a"));
        QCOMPARE(back[450], QStringLiteral("b1"));
        QCOMPARE(back[999], QStringLiteral("c"));
    }

    void cancelledCsvLeavesNothing()
    {
        QTemporaryDir dir;
        DatasetRun r = makeRun(QStringLiteral("big"));
        // Enough rows for several progress calls.
        for (int i = 1000; i < 200000; ++i) {
            r.run.time_s.push_back(i / 500.0);
            r.run.position_mm.push_back(i / 125.0);
            r.run.force_N.push_back(1.0);
        }
        int calls = 0;
        const bool finished = writeRunCsv(dir.filePath(QStringLiteral("big.csv")), r, [&](qint64, qint64) { return ++calls < 2; });
        QVERIFY(!finished);
        QCOMPARE(calls, 2);
        QCOMPARE(filesIn(dir.path()), QStringList());
    }

    void unwritableFolderNamesTheFile()
    {
        const QString path = QStringLiteral("/nonexistent-folder-nb/run.csv");
        try {
            writeRunCsv(path, makeRun(QStringLiteral("x")));
            QFAIL("no error");
        } catch (const ExportError& e) {
            QCOMPARE(e.file(), path);
            QVERIFY(e.message().contains(path));
        }
        try {
            Dataset d;
            d.runs.push_back(makeRun(QStringLiteral("x")));
            writeSessionHdf5(QStringLiteral("/nonexistent-folder-nb/s.h5"), d);
            QFAIL("no error");
        } catch (const ExportError& e) {
            QVERIFY(e.message().contains(QStringLiteral("/nonexistent-folder-nb/s.h5")));
        }
    }

    void labelIntervalTable()
    {
        const DatasetRun r = makeRun(QStringLiteral("x"));
        const auto rows = labelIntervals(r.run, r.labels, frameClockFor(r.run));
        QCOMPARE(rows.size(), std::size_t(3));
        QCOMPARE(rows[0].label, QStringLiteral("a"));
        QCOMPARE(rows[0].duration_s, 0.6 - 0.2);
        // video time = run time + 0.5 s at 29.97 fps
        QCOMPARE(rows[0].start_frame, (long long)std::floor((0.2 + 0.5) * 29.97));
        QCOMPARE(rows[0].end_frame, (long long)std::floor((0.6 + 0.5) * 29.97));
        // force = t on [0.2, 0.6): samples 100..299, peak 299/500, mean of t
        QVERIFY(std::abs(rows[0].peak_force_N - 299 / 500.0) < 1e-12);
        QVERIFY(std::abs(rows[0].mean_force_N - (100 + 299) / 2.0 / 500.0) < 1e-12);
        QCOMPARE(rows[1].label, QStringLiteral("c"));
        QCOMPARE(rows[2].label, QStringLiteral("puncture"));
        QCOMPARE(rows[2].duration_s, 0.0);
        QVERIFY(std::abs(rows[2].peak_force_N - 1.498) < 1e-9);

        // A video index wins over the frame rate, and the video ends with it: a frame number
        // past a truncated video's last frame named a frame it does not have.
        FrameClock indexed;
        indexed.frameTimes_s = {0.0, 0.1, 0.25, 0.5, 0.7};
        QCOMPARE(indexed.frameAt(0.2), 1LL);
        QCOMPARE(indexed.frameAt(0.25), 2LL);
        QCOMPARE(indexed.frameAt(0.8), 4LL);   // the last is shown for a median frame's time (0.175 s)
        QCOMPARE(indexed.frameAt(9.0), -1LL);
        QCOMPARE(indexed.frameAt(-0.1), -1LL);
        // With the sync's offset and drift (video = 1.001 · t + 0.5): t = 0.2 is video 0.7002.
        indexed.offset_s = 0.5;
        indexed.drift = 1e-3;
        QCOMPARE(indexed.frameAt(0.2), 4LL);
        QCOMPARE(indexed.frameAt(-0.45), 0LL);
        FrameClock drifting;
        drifting.drift = 1e-3;
        QCOMPARE(drifting.frameAt(100.0), (long long)std::floor(100.1 * 29.97));

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("labels.csv"));
        writeLabelIntervalsCsv(path, rows);
        const auto csv = readCsv(path);
        QCOMPARE(csv[0], (QStringList{"label", "track", "start_s", "end_s", "duration_s", "start_frame", "end_frame",
                                      "peak_force_N", "mean_force_N", "comment"}));
        QCOMPARE(csv.size(), 4);
        QCOMPARE(csv[2][9], QStringLiteral("steady, then \"drop\""));
        QCOMPARE(csv[1][5].toLongLong(), rows[0].start_frame);
    }

    // Issue 15: the peak is the extreme in the direction of motion; frames only with a video.
    void peakFollowsMotionAndFramesNeedAVideo()
    {
        nb::Run run;
        for (int i = 0; i < 200; ++i) {
            const double t = i * 0.01;
            run.time_s.push_back(t);
            // In 1 s, out 1 s: force positive going in, negative coming out.
            run.position_mm.push_back(t < 1.0 ? 10.0 * t : 10.0 * (2.0 - t));
            run.force_N.push_back(t < 1.0 ? 0.5 + t : -0.2 - (t - 1.0));
        }
        const nb::Labels labels{{QStringLiteral("phases"), QStringLiteral("insertion"), 0.0, 1.0, QString()},
                                {QStringLiteral("phases"), QStringLiteral("withdrawal"), 1.0, 2.0, QString()}};
        nb::FrameClock noVideo = frameClockFor(run);
        QVERIFY(!noVideo.hasVideo);
        const auto rows = labelIntervals(run, labels, noVideo);
        QCOMPARE(rows.size(), std::size_t(2));
        QVERIFY(std::abs(rows[0].peak_force_N - 1.49) < 1e-9);
        QVERIFY(std::abs(rows[1].peak_force_N - (-1.19)) < 1e-9);  // the most negative, not the least
        QCOMPARE(rows[0].start_frame, -1LL);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("t.csv"));
        writeLabelIntervalsCsv(path, rows);
        const auto csv = readCsv(path);
        QVERIFY(csv[1][5].isEmpty() && csv[1][6].isEmpty());
        run.metadata.set(QStringLiteral("video_file"), QStringLiteral("v.avi"));
        QVERIFY(frameClockFor(run).hasVideo);
        QCOMPARE(labelIntervals(run, labels, frameClockFor(run))[1].start_frame, (long long)std::floor(1.0 * 29.97));
        // A label far beyond any video has no frame (not a wrapped-around integer).
        QCOMPARE(frameClockFor(run).frameAt(1e300), -1LL);
    }

    // A session's run without a footer is being recorded (or was cut off by a crash): the
    // export leaves it out and says so, where it exported the first seconds as a whole run.
    void unfinishedRunIsLeftOut()
    {
        QTemporaryDir dir;
        const QString sessionDir = dir.filePath(QStringLiteral("s"));
        nb::Session session = nb::Session::create(sessionDir, {});
        auto write = [&](const QString& name, bool closed) {
            QFile f(QDir(sessionDir).filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            f.write("# format: needlebench-run 1\n# motion: linear\ntime_s,position_mm,force_N\n");
            for (int i = 0; i < 50; ++i)
                f.write(QStringLiteral("%1,%2,%3\n").arg(i * 0.001).arg(i * 0.01).arg(i * 0.002).toUtf8());
            if (closed)
                f.write("# end_reason: completed\n");
        };
        write(QStringLiteral("run_001_linear.csv"), true);
        write(QStringLiteral("run_002_linear.csv"), false);
        const nb::LoadedDataset loaded = nb::loadDataset(sessionDir);
        QCOMPARE(int(loaded.dataset.runs.size()), 1);
        QVERIFY(loaded.dataset.runs[0].sourcePath.endsWith(QStringLiteral("run_001_linear.csv")));
        const QString warnings = loaded.warnings.join(QLatin1Char('\n'));
        QVERIFY2(warnings.contains(QStringLiteral("run_002_linear.csv: left out, the run is still recording")), qPrintable(warnings));
        // A picture saved under a run's name has no footer either; it is named for what it is,
        // not as a run to wait for.
        {
            QFile f(QDir(sessionDir).filePath(QStringLiteral("run_003_linear.csv")));
            QVERIFY(f.open(QIODevice::WriteOnly));
            static constexpr char pngHead[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x02\x80";
            f.write(pngHead, sizeof pngHead - 1);
        }
        const nb::LoadedDataset withPicture = nb::loadDataset(sessionDir);
        const QString said = withPicture.warnings.join(QLatin1Char('\n'));
        QVERIFY2(said.contains(QStringLiteral("run_003_linear.csv: skipped, binary data, not a text run file")), qPrintable(said));
        QVERIFY2(!said.contains(QStringLiteral("run_003_linear.csv: left out, the run is still recording")), qPrintable(said));
        QVERIFY(withPicture.runsLeftOut.filter(QStringLiteral("run_003_linear.csv")).size() == 1);
        // A folder that is not a session keeps every run file it holds.
        QDir(sessionDir).rename(QStringLiteral("session.json"), QStringLiteral("session.json.away"));
        QCOMPARE(int(nb::loadDataset(sessionDir).dataset.runs.size()), 2);
    }

    // A hand-edited labels file: a typo costs its row, not the run's other labels; a phase drawn
    // from before the first sample keeps its part in the run; overlapping phases are said.
    void handEditedLabelsKeepWhatTheyCan()
    {
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("run.csv")));
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
        f.write("# format: needlebench-run 1\n# motion: linear\ntime_s,position_mm,force_N\n");
        for (int i = 0; i <= 1000; ++i)
            f.write(QStringLiteral("%1,%2,%3\n").arg(i * 0.01).arg(i * 0.01).arg(i * 0.002).toUtf8());
        f.write("# end_reason: completed\n");
        f.close();
        QFile l(dir.filePath(QStringLiteral("run.labels.csv")));
        QVERIFY(l.open(QIODevice::WriteOnly | QIODevice::Text));
        l.write("track,label,start_s,end_s,comment\n"
                "insertion,a,-2.5,1.5,drawn from before the start\n"
                "insertion,b1,3,2,typed backwards\n"
                "insertion,b2,4,6,\n"
                "insertion,c,5.5,7,overlaps b2\n"
                "events,puncture,8,8,\n");
        l.close();
        const nb::LoadedDataset loaded = nb::loadDataset(dir.path());
        QCOMPARE(int(loaded.dataset.runs.size()), 1);
        const nb::Labels& got = loaded.dataset.runs[0].labels;
        const QString warnings = loaded.warnings.join(QLatin1Char('\n'));
        QCOMPARE(int(got.size()), 4);
        QCOMPARE(got[0].label, QStringLiteral("a"));
        QCOMPARE(got[0].start_s, 0.0);
        QCOMPARE(got[0].end_s, 1.5);
        QCOMPARE(got[1].label, QStringLiteral("b2"));
        QCOMPARE(got[3].label, QStringLiteral("puncture"));
        QVERIFY2(warnings.contains(QStringLiteral("run.labels.csv:3")) && warnings.contains(QStringLiteral("end_s 2 is before start_s 3")),
                 qPrintable(warnings));
        QVERIFY2(warnings.contains(QStringLiteral("its part from 0.000 s to 1.500 s is used")), qPrintable(warnings));
        QVERIFY2(warnings.contains(QStringLiteral("'b2' (4.000 s to 6.000 s) and 'c' (5.500 s to 7.000 s) overlap on track 'insertion'; 'b2' is taken")),
                 qPrintable(warnings));
        // Where they overlap the exported column says what the fit reads: the earlier label.
        const std::vector<double> t{5.75, 6.5};
        QCOMPARE(labelsPerSample(got, t, QStringLiteral("insertion")), (QStringList{"b2", "c"}));
        QCOMPARE(phasePerSample(got, t), (QStringList{"b2", "c"}));
    }

    void sessionHdf5RoundTrip()
    {
        QTemporaryDir dir;
        Dataset d;
        d.name = QStringLiteral("liver5 imaging");
        d.metadata.set(QStringLiteral("tissue"), QStringLiteral("bovine liver 5"));
        d.metadata.set(QStringLiteral("needle_holder_mass_kg"), 0.087);
        d.runs.push_back(makeRun(QStringLiteral("run01")));
        d.runs.push_back(makeRun(QStringLiteral("run/02"), 2.0));
        d.runs.back().labels.clear();  // a run without labels still gets (empty) label columns
        d.runs.back().run.metadata.remove(QStringLiteral("sync_offset_s"));  // nor a video nor an offset
        const QString path = dir.filePath(QStringLiteral("session.h5"));
        std::vector<qint64> steps;
        QVERIFY(writeSessionHdf5(path, d, [&](qint64 done, qint64 total) {
            steps.push_back(done);
            return total == 2;
        }));
        QCOMPARE(steps, (std::vector<qint64>{0, 1, 2}));
        QCOMPARE(filesIn(dir.path()), QStringList{QStringLiteral("session.h5")});

        const hid_t f = H5Fopen(QFile::encodeName(path).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
        QVERIFY(f >= 0);
        QCOMPARE(readStringAttr(f, "format"), QStringLiteral("needlebench-session"));
        QCOMPARE(readStringAttr(f, "tissue"), QStringLiteral("bovine liver 5"));
        QCOMPARE(readDoubleAttr(f, "needle_holder_mass_kg"), 0.087);
        QCOMPARE(readStringAttr(f, "needle_holder_mass_kg_units"), QStringLiteral("kg"));

        const auto t = readDoubles(f, "/runs/run01/time_s");
        QCOMPARE(t, d.runs[0].run.time_s);
        QCOMPARE(readDoubles(f, "/runs/run01/force_N"), d.runs[0].run.force_N);
        QCOMPARE(readDoubles(f, "/runs/run_02/force_N"), d.runs[1].run.force_N);
        const auto v = readDoubles(f, "/runs/run01/velocity_mm_s");
        QCOMPARE(v.size(), std::size_t(1000));
        QVERIFY(std::abs(v[500] - 4.0) < 1e-9);
        const hid_t ds = H5Dopen2(f, "/runs/run01/force_N", H5P_DEFAULT);
        QCOMPARE(readStringAttr(ds, "units"), QStringLiteral("N"));
        H5Dclose(ds);

        const hid_t g = H5Gopen2(f, "/runs/run01", H5P_DEFAULT);
        QVERIFY(g >= 0);
        QCOMPARE(readDoubleAttr(g, "rate_hz"), 500.0);
        QCOMPARE(readStringAttr(g, "rate_hz_units"), QStringLiteral("Hz"));
        QCOMPARE(readStringAttr(g, "protocol"), QStringLiteral("stiffness"));
        QCOMPARE(readStringAttr(g, "end_reason"), QStringLiteral("completed"));
        QCOMPARE(readDoubleAttr(g, "dropped_samples"), 3.0);
        QCOMPARE(readDoubleAttr(g, "sync_offset_s"), 0.5);
        // Links are relative to the exported file; the absolute path is kept beside.
        QCOMPARE(readStringAttr(g, "source_absolute"), QStringLiteral("/data/run01.csv"));
        QCOMPARE(QDir::cleanPath(QDir(dir.path()).absoluteFilePath(readStringAttr(g, "source"))), QStringLiteral("/data/run01.csv"));
        H5Gclose(g);
        const hid_t g2 = H5Gopen2(f, "/runs/run_02", H5P_DEFAULT);
        QCOMPARE(readStringAttr(g2, "name"), QStringLiteral("run/02"));
        // No offset where the run has neither a video nor one: a 0 there read as "synced at 0".
        QCOMPARE(H5Aexists(g2, "sync_offset_s"), 0);
        H5Gclose(g2);

        QCOMPARE(readStrings(f, "/runs/run01/labels/label"), (QStringList{"a", "c", "puncture"}));
        QCOMPARE(readStrings(f, "/runs/run01/labels/track"), (QStringList{"insertion", "insertion", "events"}));
        QCOMPARE(readStrings(f, "/runs/run01/labels/comment")[1], QStringLiteral("steady, then \"drop\""));
        const auto intervals = labelIntervals(d.runs[0].run, d.runs[0].labels, frameClockFor(d.runs[0].run));
        const auto peak = readDoubles(f, "/runs/run01/labels/peak_force_N");
        QCOMPARE(peak.size(), std::size_t(3));
        QCOMPARE(peak[0], intervals[0].peak_force_N);
        QCOMPARE(readDoubles(f, "/runs/run01/labels/start_s"), (std::vector<double>{0.2, 1.0, 1.498}));
        QVERIFY(readStrings(f, "/runs/run_02/labels/label").isEmpty());
        QCOMPARE(readDoubles(f, "/runs/run_02/labels/start_s").size(), std::size_t(0));
        H5Fclose(f);

        // h5dump, a reader that knows nothing of NeedleBench, reads it all.
        const QString h5dump = QStandardPaths::findExecutable(QStringLiteral("h5dump"));
        if (!h5dump.isEmpty()) {
            QProcess p;
            p.start(h5dump, {QStringLiteral("-A"), path});
            QVERIFY(p.waitForFinished(30000));
            QCOMPARE(p.exitCode(), 0);
            const QByteArray out = p.readAllStandardOutput();
            QVERIFY(out.contains("GROUP \"run01\""));
            QVERIFY(out.contains("DATASET \"force_N\""));
            QVERIFY(out.contains("\"needlebench-session\""));
        }
    }

    void cancelledHdf5LeavesNothing()
    {
        QTemporaryDir dir;
        Dataset d;
        for (int i = 0; i < 3; ++i)
            d.runs.push_back(makeRun(QStringLiteral("r%1").arg(i)));
        const QString path = dir.filePath(QStringLiteral("s.h5"));
        QVERIFY(!writeSessionHdf5(path, d, [](qint64 done, qint64) { return done < 1; }));
        QCOMPARE(filesIn(dir.path()), QStringList());
    }

    void eafIsElanXml()
    {
        QTemporaryDir dir;
        DatasetRun r = makeRun(QStringLiteral("run01"));
        r.run.metadata.set(QStringLiteral("factor_frequency_hz"), 0.5);
        r.run.metadata.set(QStringLiteral("factor_site"), QStringLiteral("3"));
        r.run.metadata.set(QStringLiteral("plan_run"), QStringLiteral("7"));
        const QString path = dir.filePath(QStringLiteral("run01.eaf"));
        writeEaf(path, r, {dir.filePath(QStringLiteral("run01.csv")), dir.filePath(QStringLiteral("run01.mp4")), QString()});
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QXmlStreamReader x(&f);
        QMap<QString, qint64> timeSlots;
        QMap<QString, QString> tierOf;  // annotation value -> tier
        QString tier, media, linked, origin, commentParent;
        QStringList values;
        QStringList refs;
        QMap<QString, QString> properties;
        while (!x.atEnd()) {
            x.readNext();
            if (!x.isStartElement())
                continue;
            const auto a = x.attributes();
            if (x.name() == u"TIME_SLOT")
                timeSlots[a.value("TIME_SLOT_ID").toString()] = a.value("TIME_VALUE").toLongLong();
            else if (x.name() == u"TIER") {
                tier = a.value("TIER_ID").toString();
                if (a.hasAttribute("PARENT_REF"))
                    commentParent = a.value("PARENT_REF").toString();
            } else if (x.name() == u"ALIGNABLE_ANNOTATION")
                refs << a.value("TIME_SLOT_REF1").toString() + u'-' + a.value("TIME_SLOT_REF2").toString();
            else if (x.name() == u"ANNOTATION_VALUE") {
                const QString v = x.readElementText();
                values << v;
                tierOf[v] = tier;
            } else if (x.name() == u"MEDIA_DESCRIPTOR") {
                media = a.value("RELATIVE_MEDIA_URL").toString();
                origin = a.value("TIME_ORIGIN").toString();
            } else if (x.name() == u"LINKED_FILE_DESCRIPTOR")
                linked = a.value("RELATIVE_LINK_URL").toString();
            else if (x.name() == u"PROPERTY") {
                const QString name = a.value("NAME").toString();
                properties[name] = x.readElementText();
            }
        }
        // The plan's factor levels travel with the document; other metadata stays in the CSV.
        QCOMPARE(properties.value(QStringLiteral("factor_frequency_hz")), QStringLiteral("0.5"));
        QCOMPARE(properties.value(QStringLiteral("factor_site")), QStringLiteral("3"));
        QCOMPARE(properties.value(QStringLiteral("plan_run")), QStringLiteral("7"));
        QVERIFY(!properties.contains(QStringLiteral("protocol")));
        QVERIFY2(!x.hasError(), qPrintable(x.errorString()));
        QCOMPARE(values, (QStringList{"a", "c", "puncture", "steady, then \"drop\""}));
        QCOMPARE(tierOf["a"], QStringLiteral("insertion"));
        QCOMPARE(tierOf["puncture"], QStringLiteral("events"));
        QCOMPARE(tierOf["steady, then \"drop\""], QStringLiteral("insertion comment"));
        QCOMPARE(commentParent, QStringLiteral("insertion"));
        QCOMPARE(media, QStringLiteral("./run01.mp4"));
        QCOMPARE(origin, QStringLiteral("500"));
        QCOMPARE(linked, QStringLiteral("./run01.csv"));
        QCOMPARE(refs.size(), 3);
        const QStringList first = refs[0].split(u'-');
        QCOMPARE(timeSlots[first[0]], 200);
        QCOMPARE(timeSlots[first[1]], 600);
        const QStringList point = refs[2].split(u'-');
        QCOMPARE(timeSlots[point[0]], 1498);
        QCOMPARE(timeSlots[point[1]], 1499);  // a point becomes a 1 ms annotation
    }

    void fitTableCsvAndLatex()
    {
        FitTable t;
        t.caption = QStringLiteral("Pooled fits (4 mm/s)");
        t.label = QStringLiteral("tab:stiffness");
        t.columns = {{QStringLiteral("liver"), QStringLiteral("liver"), {}, -1, {}},
                     {QStringLiteral("a1_N_per_mm"), QStringLiteral("a1"), QStringLiteral("N/mm"), 4, QStringLiteral("$a_1$")},
                     {QStringLiteral("r2"), QStringLiteral("r^2 & more"), {}, 3, {}}};
        t.rows = {{QStringLiteral("liver_1"), 0.048, 0.99512}, {QStringLiteral("pooled"), 0.05, std::nan("")}};
        const QByteArray csv = fitTableCsv(t);
        QCOMPARE(csv, QByteArray("liver,a1_N_per_mm,r2\nliver_1,0.0480,0.995\npooled,0.0500,\n"));
        const QString tex = QString::fromUtf8(fitTableLatex(t));
        QVERIFY(tex.contains(QStringLiteral("\\begin{tabular}{lrr}")));
        QVERIFY(tex.contains(QStringLiteral("liver & $a_1$ & r\\textasciicircum{}2 \\& more \\\\")));
        QVERIFY(tex.contains(QStringLiteral(" & [$\\mathrm{N}/\\mathrm{mm}$] &  \\\\")));
        // Units typeset, not escaped: powers raised, products with a thin space.
        QCOMPARE(latexUnit(QStringLiteral("N/mm^2")), QStringLiteral("$\\mathrm{N}/\\mathrm{mm}^{2}$"));
        QCOMPARE(latexUnit(QStringLiteral("N s/m^2")), QStringLiteral("$\\mathrm{N}\\,\\mathrm{s}/\\mathrm{m}^{2}$"));
        QCOMPARE(latexUnit(QStringLiteral("N·s/m²")), QStringLiteral("$\\mathrm{N}\\,\\mathrm{s}/\\mathrm{m}^{2}$"));
        QVERIFY(tex.contains(QStringLiteral("liver\\_1 & 0.0480 & 0.995 \\\\")));
        QVERIFY(tex.contains(QStringLiteral("pooled & 0.0500 & -- \\\\")));
        QVERIFY(tex.contains(QStringLiteral("\\caption{Pooled fits (4 mm/s)}")));
        QTemporaryDir dir;
        writeFitTableLatex(dir.filePath(QStringLiteral("t.tex")), t);
        QFile f(dir.filePath(QStringLiteral("t.tex")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), tex.toUtf8());
    }
};

QTEST_GUILESS_MAIN(TestExportRoundTrip)
#include "test_export_roundtrip.moc"
