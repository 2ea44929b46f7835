#pragma once
// What the exporters take: a session's runs, each with its labels, plus the columns every
// export shows (velocity and acceleration derived when the recording has none).

#include "core/labels.h"
#include "core/run.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <vector>

namespace nb {

struct DatasetRun {
    QString name;        // unique within the session, used for file and group names
    QString sourcePath;  // the run file it came from (empty when built in memory)
    Run run;
    Labels labels;
    // The run's video (absolute), empty when it has none: frames are given only with one.
    QString videoPath;
    // Its frames' times (video time, from its index) when it was indexed: exported frame
    // numbers follow dropped and repeated frames and end with the video. Empty: its frame rate.
    std::vector<double> videoFrameTimes_s;
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
    bool integer = false;  // counts (seq): written without decimals, as int64 in HDF5
};

// time, position, velocity, acceleration, force, then any other numeric columns of the run.
// Velocity and acceleration come from the run when recorded, otherwise from central
// differences of position (np.gradient-like, so no sample is lost at the ends).
std::vector<SignalColumn> exportSignals(const Run& run);

// The run's own text columns (the simulated rig's `phase`, its `event`), as recorded, for the
// exports; a name an export already uses (a signal, `label_*`, `labels`) is left out.
struct TextColumn {
    QString name;
    QString description;
    QStringList values;
};
std::vector<TextColumn> exportTextColumns(const Run& run, const Labels& labels);

// Label tracks in order of first appearance.
QStringList labelTracks(const Labels& labels);

// The label of `track` active at each sample: intervals cover [start, end); a point event
// marks the first sample at or after its time.
QStringList labelsPerSample(const Labels& labels, const std::vector<double>& time_s, const QString& track);

// The unit a metadata key or column name carries in its suffix (`rate_hz` -> Hz,
// `speed_mm_s` -> mm/s, `mass_g` -> g); empty when the name says none.
QString unitFromName(const QString& name);

// How an export types a metadata value. Numbers written as numbers (finite, plain decimal or
// exponent notation) are numbers, integers when written without fraction or exponent; the
// rest is text ("nan", "inf", "1e999" too). Keys that name text (organ, specimen, tip,
// operator, protocol, notes, ...) are always text, whatever they hold.
enum class MetadataValueKind { Integer, Number, Text };
MetadataValueKind metadataValueKind(const QString& key, const QString& value);

// The video of a run file: named in its metadata (`video`, `video_file`, `video_path`;
// relative to the run file) or sharing its base name (.mp4, .avi, .mkv, .mov). Absolute path,
// empty when there is none on disk.
QString findRunVideo(const QString& runPath, const Run& run);

// `target` as a path relative to the folder of `fromFile` (both made absolute first): what
// an export writes so that the folder can be moved with its files.
QString relativeLink(const QString& fromFile, const QString& target);

// The link an export stores: relative (as above) when `target` lies in the folder of
// `fromFile` or below it, so that the folder can move with it; absolute otherwise (a path
// climbing out with "../" would break as soon as the folder moved).
QString portableLink(const QString& fromFile, const QString& target);

// Video frame rate when the run does not say (NTSC, as the thesis's imaging console).
constexpr double kDefaultVideoFps = 29.97;

// Video time minus run time [s]: read from the run's metadata (`sync_offset_s`, or
// `video_offset_s`), 0 when absent.
double syncOffset(const Run& run);
// The same, nullopt when the run names none: an export writes no offset for a run without a
// video or one (a 0 there read as "synced at 0").
std::optional<double> namedSyncOffset(const Run& run);
// The video clock's rate error the sync found (sync_drift), 0 when unsaid.
double syncDrift(const Run& run);
double videoFps(const Run& run);

// Gives each run with a video its frames' times, from `frameTimesOf` (video/'s index, which
// core does not reach); a video that cannot be read keeps its frame rate, with a warning.
void addVideoFrameTimes(Dataset& d, const std::function<std::vector<double>(const QString&, QString*)>& frameTimesOf,
                        QStringList* warnings);

}  // namespace nb
