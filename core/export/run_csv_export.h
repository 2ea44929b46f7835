#pragma once
// Per-run export: a plain CSV (one header row, no comment lines, so any spreadsheet or
// `pandas.read_csv` opens it) and a JSON sidecar with everything else.
//
// CSV columns: time_s, position_mm, velocity_mm_s, acceleration_mm_s2, force_N, the run's
// other numeric columns, then `label_<track>` per label track (the label active at the sample).
// Sidecar (`RUN.json` beside `RUN.csv`): columns with units, metadata with units, calibration,
// device, drops, sync offset, labels.

#include "dataset.h"
#include "export_error.h"

#include <QJsonObject>

namespace nb {

// The sidecar path for a CSV path (`x/run.csv` -> `x/run.json`).
QString sidecarPath(const QString& csvPath);

// `sidecarFile`: where the sidecar goes; its `source` and `video` links are relative to it
// (empty: the source path as given).
QJsonObject runSidecar(const DatasetRun& run, const QString& csvFileName, const QString& sidecarFile = {});

// Writes the CSV and its sidecar, both or neither. Returns false when cancelled through
// `progress` (nothing is left behind). Throws ExportError.
bool writeRunCsv(const QString& csvPath, const DatasetRun& run, const ExportProgress& progress = {});

}  // namespace nb
