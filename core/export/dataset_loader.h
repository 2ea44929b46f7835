#pragma once
// Reads a session folder into a Dataset for export and analysis: a lab session (core/session.h)
// or any folder of run files (*.csv with time_s,position_mm,force_N), each with its labels in
// RUN.labels.csv beside it when there are any.

#include "dataset.h"

#include <QStringList>

namespace nb {

struct LoadedDataset {
    Dataset dataset;
    QStringList warnings;  // one line per skipped file or ignored problem, naming the file
    QStringList runsLeftOut;  // runs the session lists that are not in the dataset (unreadable, still recording)
};


// Runs in file-name order. A file that is not a run (or cannot be read) is skipped with a
// warning; an unreadable labels file too (the run is kept, without labels). Throws
// ExportError when `dir` is not a folder.
LoadedDataset loadDataset(const QString& dir);

}  // namespace nb
