#include "run_csv_export.h"
#include "core/tr.h"
#include "core/save_file.h"

#include "csv_text.h"
#include "label_intervals.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

namespace nb {

namespace {

// Integers as JSON integers, numbers as numbers, the rest (also "nan") as the text it is.
QJsonValue valueOf(const QString& key, const QString& text)
{
    switch (metadataValueKind(key, text)) {
    case MetadataValueKind::Integer: return QJsonValue(text.trimmed().toLongLong());
    case MetadataValueKind::Number: return text.trimmed().toDouble();
    case MetadataValueKind::Text: break;
    }
    return text;
}

QJsonObject metadataObject(const Metadata& m)
{
    QJsonObject o;
    for (const auto& [key, value] : m.entries()) {
        QJsonObject field{{QStringLiteral("value"), valueOf(key, value)}};
        const QString unit = unitFromName(key);
        if (!unit.isEmpty())
            field.insert(QStringLiteral("unit"), unit);
        o.insert(key, field);
    }
    return o;
}

// The fields of both header and footer whose key matches one of `prefixes` (footer wins).
QJsonObject pick(const Run& run, std::initializer_list<const char*> fragments)
{
    QJsonObject o;
    for (const Metadata* m : {&run.metadata, &run.footer}) {
        for (const auto& [key, value] : m->entries()) {
            for (const char* f : fragments) {
                if (key.contains(QLatin1String(f), Qt::CaseInsensitive)) {
                    o.insert(key, valueOf(key, value));
                    break;
                }
            }
        }
    }
    return o;
}

}  // namespace

QString sidecarPath(const QString& csvPath)
{
    const QFileInfo fi(csvPath);
    return fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".json"));
}

QJsonObject runSidecar(const DatasetRun& r, const QString& csvFileName, const QString& sidecarFile)
{
    QJsonArray columns;
    for (const SignalColumn& c : exportSignals(r.run))
        columns.append(QJsonObject{{QStringLiteral("name"), c.name},
                                   {QStringLiteral("unit"), c.unit},
                                   {QStringLiteral("description"), c.description}});
    for (const QString& track : labelTracks(r.labels))
        columns.append(QJsonObject{{QStringLiteral("name"), QStringLiteral("label_") + track},
                                   {QStringLiteral("unit"), QString()},
                                   {QStringLiteral("description"), nb::TrCore::tr("label of track '%1' active at the sample").arg(track)}});
    for (const TextColumn& c : exportTextColumns(r.run, r.labels))
        columns.append(QJsonObject{{QStringLiteral("name"), c.name}, {QStringLiteral("unit"), QString()}, {QStringLiteral("description"), c.description}});
    QJsonArray labels;
    for (const Label& l : r.labels)
        labels.append(QJsonObject{{QStringLiteral("track"), l.track},
                                  {QStringLiteral("label"), l.label},
                                  {QStringLiteral("start_s"), l.start_s},
                                  {QStringLiteral("end_s"), l.end_s},
                                  {QStringLiteral("comment"), l.comment}});
    return QJsonObject{
        {QStringLiteral("format"), QStringLiteral("needlebench-run-export")},
        {QStringLiteral("version"), 1},
        {QStringLiteral("run"), r.name},
        // Links relative to the sidecar, so that the export folder can be moved whole.
        {QStringLiteral("source"), sidecarFile.isEmpty() ? r.sourcePath : portableLink(sidecarFile, r.sourcePath)},
        {QStringLiteral("source_absolute"), r.sourcePath.isEmpty() ? QString() : QFileInfo(r.sourcePath).absoluteFilePath()},
        {QStringLiteral("csv"), csvFileName},
        {QStringLiteral("video"), sidecarFile.isEmpty() || r.videoPath.isEmpty() ? QFileInfo(r.videoPath).fileName()
                                                                                  : portableLink(sidecarFile, r.videoPath)},
        {QStringLiteral("samples"), qint64(r.run.size())},
        {QStringLiteral("columns"), columns},
        {QStringLiteral("metadata"), metadataObject(r.run.metadata)},
        {QStringLiteral("footer"), metadataObject(r.run.footer)},
        {QStringLiteral("calibration"), pick(r.run, {"calib", "slope", "v0", "bias", "tare"})},
        {QStringLiteral("device"), pick(r.run, {"device", "sensor", "stage", "daq", "rig", "serial", "firmware"})},
        {QStringLiteral("drops"), pick(r.run, {"drop", "lost", "overrun", "gap", "late"})},
        {QStringLiteral("sync"), QJsonObject{{QStringLiteral("offset_s"), frameClockFor(r).hasVideo || namedSyncOffset(r.run)
                                                                               ? QJsonValue(syncOffset(r.run)) : QJsonValue()},
                                             {QStringLiteral("video_fps"), frameClockFor(r).hasVideo ? QJsonValue(videoFps(r.run)) : QJsonValue()},
                                             {QStringLiteral("video_file"), r.run.meta(QStringLiteral("video_file")).value_or(QString())},
                                             {QStringLiteral("meaning"), QStringLiteral("video time = recording time + offset_s")}}},
        {QStringLiteral("labels"), labels},
    };
}

bool writeRunCsv(const QString& csvPath, const DatasetRun& r, const ExportProgress& progress)
{
    const std::vector<SignalColumn> cols = exportSignals(r.run);
    const QStringList tracks = labelTracks(r.labels);
    std::vector<QStringList> trackValues;
    for (const QString& t : tracks)
        trackValues.push_back(labelsPerSample(r.labels, r.run.time_s, t));

    QSaveFile csv(csvPath);
    if (!csv.open(QIODevice::WriteOnly))
        throw ExportError(csvPath, writeFailure(csv, csvPath));
    QByteArray buf;
    for (std::size_t c = 0; c < cols.size(); ++c)
        buf += (c ? "," : "") + csvField(cols[c].name);
    for (const QString& t : tracks)
        buf += ',' + csvField(QStringLiteral("label_") + t);
    const std::vector<TextColumn> texts = exportTextColumns(r.run, r.labels);
    for (const TextColumn& c : texts)
        buf += ',' + csvField(c.name);
    buf += '\n';
    const std::size_t n = r.run.size();
    // Time and position keep micro-resolution; other signals a fixed 6 decimals too, which is
    // below the load cell's and encoder's resolution.
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < cols.size(); ++c) {
            if (c)
                buf += ',';
            buf += csvNumber(cols[c].values[i], cols[c].integer ? 0 : 6);
        }
        for (const QStringList& tv : trackValues)
            buf += ',' + csvField(tv[qsizetype(i)]);
        for (const TextColumn& c : texts)
            buf += ',' + csvField(c.values[qsizetype(i)]);
        buf += '\n';
        if (buf.size() > (1 << 20) || i + 1 == n) {
            if (csv.write(buf) != buf.size())
                throw ExportError(csvPath, writeFailure(csv, csvPath));
            buf.clear();
            if (!keepGoing(progress, qint64(i + 1), qint64(n))) {
                csv.cancelWriting();
                return false;
            }
        }
    }
    if (!buf.isEmpty() && csv.write(buf) != buf.size())
        throw ExportError(csvPath, writeFailure(csv, csvPath));

    const QString jsonPath = sidecarPath(csvPath);
    writeFileAtomically(jsonPath,
                        QJsonDocument(runSidecar(r, QFileInfo(csvPath).fileName(), jsonPath)).toJson(QJsonDocument::Indented));
    if (!commitWhole(csv)) {
        QFile::remove(jsonPath);
        throw ExportError(csvPath, writeFailure(csv, csvPath));
    }
    return true;
}

}  // namespace nb
