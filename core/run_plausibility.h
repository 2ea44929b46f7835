#pragma once
// What a run file's numbers say about how they were written, before anything is fitted to them:
// a force no load cell reads, a force flat at its top while the needle moves (the sensor or its
// amplifier saturated), positions that only make sense in metres. Each is kept as written and
// said, naming the file, so that a fit of such a run is not taken for a result.

#include "core/run.h"

#include <QString>
#include <QStringList>

namespace nb {

// A corrupt sample or a unit slip: `events` took 1e308 N for the puncture.
inline constexpr double kNoLoadCellReads_N = 1e4;

QStringList implausibleRun(const Run& run, const QString& name);

}  // namespace nb
