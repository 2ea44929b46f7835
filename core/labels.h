#pragma once
// Labels on a run's timeline: phase intervals (a, b1, b2, c per direction) and point events
// (contact, puncture, relaxation, internal puncture), in recording time.
//
// File format (a contract): CSV `track,label,start_s,end_s,comment`, one label per row; a
// point event has start_s == end_s. Comments may be quoted ("...") to hold commas.

#include "core/run_file.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace nb {

struct Label {
    QString track;   // e.g. "insertion", "withdrawal", "events"
    QString label;   // e.g. "a", "b1", "b2", "c", "contact", "puncture"
    double start_s = 0.0;
    double end_s = 0.0;
    QString comment;

    bool isPoint() const { return start_s == end_s; }
    bool contains(double t) const { return t >= start_s && t < end_s; }
    friend bool operator==(const Label&, const Label&) = default;
};

using Labels = std::vector<Label>;

// Whether `labels` mark the event `name` (a point label, any case: "Puncture" as "puncture").
bool marksEvent(const Labels& labels, const QString& name);

// A labels file as read: the labels of its good rows, and each row that could not be taken
// (file, line, why). One typo in a hand-edited file costs its row, not the file's labels.
struct LabelsRead {
    Labels labels;
    std::vector<RunFileError> skipped;
    QStringList problems() const;  // one message a skipped row
};
// Throws RunFileError only for a file that cannot be read or has no header.
LabelsRead readLabels(const QString& path);
// The strict reading: throws RunFileError (core/run_file.h) at the first bad row too.
Labels readLabelsFile(const QString& path);
void writeLabelsFile(const QString& path, const Labels& labels);
// Where a run's labels live: beside the run file, `x/run_001.csv` -> `x/run_001.labels.csv`
// (any extension: `run.txt` -> `run.labels.csv`). The window, the command line and the
// exporters all ask here.
QString labelsPathFor(const QString& runPath);

// Interval labels on one track that overlap, one message a pair: phasePerSample takes the one
// earlier in the list where they do, and a reader should know that.
QStringList overlappingLabels(const Labels& labels);

// Per-sample phase names for `time_s` (empty where no interval of `track` covers the
// sample; any track when `track` is empty).
QStringList phasePerSample(const Labels& labels, const std::vector<double>& time_s, const QString& track = {});

}  // namespace nb
