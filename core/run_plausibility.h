#pragma once
// What a run file's numbers say about how they were written, before anything is fitted to them:
// a force no load cell reads, a force flat at its top while the needle moves (the sensor or its
// amplifier saturated), positions that only make sense in metres. Each is kept as written and
// said, naming the file, so that a fit of such a run is not taken for a result.

#include "core/run.h"

#include <QString>
#include <QStringList>

namespace nb {

QStringList implausibleRun(const Run& run, const QString& name);

}  // namespace nb
