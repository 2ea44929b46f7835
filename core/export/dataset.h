#pragma once
// What the exporters take: a session's runs, each with its labels, plus the columns every
// export shows (velocity and acceleration derived when the recording has none).

#include "core/labels.h"
#include "core/run.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace nb {

struct DatasetRun {
    QString name;        // unique within the session, used for file and group names
    QString sourcePath;  // the run file it came from (empty when built in memory)
    Run run;
    Labels labels;
};

struct Dataset {
    QString name;
    Metadata metadata;  // session-wide (operator, tissue, rig...)
    std::vector<DatasetRun> runs;
};

// A column of an export: its samples, name and unit.
struct SignalColumn {
    QString name;
    QString unit;
    QString description;
    std::vector<double> values;
};

// time, position, velocity, acceleration, force, then any other numeric columns of the run.
// Velocity and acceleration come from the run when recorded, otherwise from central
// differences of position (np.gradient-like, so no sample is lost at the ends).
std::vector<SignalColumn> exportSignals(const Run& run);

// Label tracks in order of first appearance.
QStringList labelTracks(const Labels& labels);

// The label of `track` active at each sample: intervals cover [start, end); a point event
// marks the first sample at or after its time.
QStringList labelsPerSample(const Labels& labels, const std::vector<double>& time_s, const QString& track);

// The unit a metadata key or column name carries in its suffix (`rate_hz` -> Hz,
// `speed_mm_s` -> mm/s, `mass_g` -> g); empty when the name says none.
QString unitFromName(const QString& name);

// Video frame rate when the run does not say (NTSC, as the thesis's imaging console).
constexpr double kDefaultVideoFps = 29.97;

// Video time minus run time [s]: read from the run's metadata (`sync_offset_s`, or
// `video_offset_s`), 0 when absent.
double syncOffset(const Run& run);
double videoFps(const Run& run);

}  // namespace nb
