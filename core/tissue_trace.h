#pragma once
// The tissue's velocity as `labels suggest --tissue-trace` writes it (time_s,tissue_velocity_mm_s;
// an empty cell where the picture gave no measurement), read back and put on a run's samples: the
// friction fit then has the relative velocity of needle and tissue that the model is written in
// (models.md 5), where a slab that creeps against its plate would otherwise pass for friction.

#include "error.h"
#include "tissue_motion.h"

#include <QString>
#include <span>
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

// The tissue's velocity through one slide of the needle, as the friction fit takes it: a
// polynomial in time of the lowest degree (0 to 6) the readings support beyond their scatter,
// or the readings as they are where they are far cleaner than any such curve. A slab's creep
// through a slide is steady or changes slowly (it grows as the needle slows), while the video
// tracker reads each frame with noise several times that creep (about 2 mm/s rms against
// 0.5 mm/s in phase c): taken frame by frame as the fit's regressor, that noise pulls b low and
// shakes the sliding line, and every fit from the real tracker's trace was flagged.
struct SlideTissue {
    std::vector<double> velocity;   // at each of the slide's samples, in the trace's unit
    int degree = 0;                 // of the polynomial; -1: the readings as they are
};
// `measurements`: how many independent readings the slide spans (its frames; the samples are
// interpolated between them), which decides whether a term is kept.
SlideTissue tissueOverSlide(std::span<const double> time_s, std::span<const double> velocity, double measurements);

}  // namespace nb
