#include "earlier_export.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>

namespace nb {

namespace {

// NAME for NAME.csv, NAME.json, NAME.intervals.csv and NAME.eaf.
QString runNameOf(const QString& fileName)
{
    for (const QLatin1String suffix : {QLatin1String(".intervals.csv"), QLatin1String(".csv"), QLatin1String(".json"),
                                       QLatin1String(".eaf")})
        if (fileName.endsWith(suffix))
            return fileName.chopped(suffix.size());
    return {};
}

// The sidecar an export writes beside NAME.csv, naming that CSV.
bool isExportSidecar(const QString& path, const QString& runName)
{
    QFile f(path);
    if (f.size() > 64 * 1024 * 1024 || !f.open(QIODevice::ReadOnly))
        return false;
    const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
    return o.value(QStringLiteral("format")).toString() == QLatin1String("needlebench-run-export")
        && o.value(QStringLiteral("csv")).toString() == runName + QStringLiteral(".csv");
}

// A file that begins as a recorded run does ("# protocol: …"): an export's CSV is its columns'
// names and rows alone, for pandas and MATLAB.
bool looksRecorded(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && f.read(1) == "#";
}

}  // namespace

bool isHdf5File(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && f.read(8).startsWith("\x89HDF\r\n\x1a\n");
}

QStringList runExportPaths(const QString& folder, const QStringList& runNames, bool eaf)
{
    const QDir dir(folder);
    QStringList paths;
    for (const QString& name : runNames)
        paths << dir.filePath(name + QStringLiteral(".csv")) << dir.filePath(name + QStringLiteral(".json"))
              << dir.filePath(name + (eaf ? QStringLiteral(".eaf") : QStringLiteral(".intervals.csv")));
    return paths;
}

FilesInTheWay filesInTheWay(const QStringList& paths)
{
    FilesInTheWay way;
    QHash<QString, bool> sidecars;  // a run's sidecar, read once for its CSV, itself and its table
    for (const QString& path : paths) {
        const QFileInfo info(path);
        if (!info.exists())
            continue;
        const QString name = runNameOf(info.fileName());
        const QString sidecar = info.dir().filePath(name + QStringLiteral(".json"));
        const auto knownSidecar = [&] {
            if (!sidecars.contains(sidecar))
                sidecars.insert(sidecar, isExportSidecar(sidecar, name));
            return sidecars.value(sidecar);
        };
        // By its sidecar, and for the run's CSV by itself too: a recorded run copied over an
        // earlier export's CSV, the sidecar still beside it, was replaced as the export's own.
        const bool exported = info.isFile()
                              && (info.suffix() == QLatin1String("h5") ? isHdf5File(path) : !name.isEmpty() && knownSidecar())
                              && !(info.fileName() == name + QStringLiteral(".csv") && looksRecorded(path));
        (exported ? way.earlierExport : way.other) << path;
    }
    return way;
}

QStringList runNamesIn(const QString& sessionDir)
{
    QStringList names;
    for (const QString& file : QDir(sessionDir).entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name))
        if (!file.endsWith(QLatin1String(".labels.csv")))
            names << QFileInfo(file).completeBaseName();
    return names;
}

}  // namespace nb
