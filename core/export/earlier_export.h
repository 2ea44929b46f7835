#pragma once
// What an export is about to write over, told apart: an earlier export's own files (a CSV with
// the needlebench-run-export sidecar beside it, that sidecar, its interval table and ELAN
// document, an HDF5 file) are the export's to replace; anything else there (a recorded run, a
// table made by hand) is somebody's data. An export into another session's folder replaced its
// run files, the calibration header and the raw columns gone, without a word.

#include <QString>
#include <QStringList>

namespace nb {

struct FilesInTheWay {
    QStringList earlierExport;  // an earlier export's files: replaced, after saying so
    QStringList other;          // not an export's: kept unless the operator says otherwise
    bool empty() const { return earlierExport.isEmpty() && other.isEmpty(); }
};

// The files a per-run export of `runNames` into `folder` writes: NAME.csv, NAME.json, and
// NAME.eaf (`eaf`) or NAME.intervals.csv.
QStringList runExportPaths(const QString& folder, const QStringList& runNames, bool eaf);

// Those of `paths` that exist, sorted into an earlier export's and others.
FilesInTheWay filesInTheWay(const QStringList& paths);

// Whether `path` begins as an HDF5 file does (its signature).
bool isHdf5File(const QString& path);

// The names a session folder's runs are exported under (the run files' base names), read from
// the folder alone: what the export dialog asks about before it loads the runs.
QStringList runNamesIn(const QString& sessionDir);

}  // namespace nb
