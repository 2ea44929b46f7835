#pragma once
// The tissue's velocity as `labels suggest --tissue-trace` writes it (time_s,tissue_velocity_mm_s;
// an empty cell where the picture gave no measurement), read back and put on a run's samples: the
// friction fit then has the relative velocity of needle and tissue that the model is written in
// (models.md 5), where a slab that creeps against its plate would otherwise pass for friction.

#include "error.h"
#include "tissue_motion.h"

#include <QString>
#include <vector>

namespace nb {

// The trace file's first line: written by `labels suggest --tissue-trace`, checked on reading.
inline constexpr char kTissueTraceHeader[] = "time_s,tissue_velocity_mm_s";

class TissueTraceError : public Error {
public:
    using Error::Error;
};

// Throws TissueTraceError naming the file (and the line) when it cannot be read, is not such a
// trace, or its times do not rise.
TissueMotion readTissueTrace(const QString& path);

// The trace's velocity (mm/s) at each of `time_s`, linear between its measurements; NaN outside
// the trace and between two measurements either of which is missing.
std::vector<double> tissueVelocityAt(const TissueMotion& trace, const std::vector<double>& time_s);

}  // namespace nb
