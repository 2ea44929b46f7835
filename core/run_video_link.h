#pragma once
// The video a run was filmed on and how the two timelines meet, kept per run in the session
// folder (videos.json beside session.json) so a restart, another workstation or an export
// finds them again:
//
//   { "runs": { "run_002_sine.csv": { "video": "run_002_sine.mp4", "offset_s": 0.41,
//        "drift": 1e-4, "method": "automatic", "confidence": 0.93,
//        "region": [240, 300, 240, 180], "needle": [636, 20, 636, 290] } } }
//
// `region` (x, y, width, height) and `needle` (x1, y1, x2, y2) are what the operator drew on the
// video for its sync, in its pixels; each is left out when nothing was drawn.
//
// The video is stored relative to the session folder when it lies inside it (the folder may
// move), absolute otherwise.

#include "core/run.h"
#include "core/sync.h"

#include <QLineF>
#include <QRect>
#include <QString>
#include <QStringList>
#include <optional>

namespace nb {

enum class SyncMethod { None, Manual, EventMarks, Automatic };
QString syncMethodKey(SyncMethod m);  // "", "manual", "event_marks", "automatic" (file and export values)
SyncMethod syncMethodFromKey(const QString& key);
QString syncMethodName(SyncMethod m);  // operator-facing (translated)

// What the operator drew on a video for its sync, in the video's pixels.
struct PictureMarks {
    QRect region;   // where the needle is read; empty: everywhere
    QLineF needle;  // the needle's line from its shaft to its tip; null: found in the picture
    bool operator==(const PictureMarks&) const = default;
};

struct RunVideoLink {
    QString video;  // absolute path when read; empty: no video attached
    TimelineMapping mapping;
    SyncMethod method = SyncMethod::None;
    std::optional<double> confidence;  // 0..1, from the automatic sync
    PictureMarks marks;
    // The operator says the video is as its camera or console coded it (never converted): the
    // coder's lag on a slow needle is then known more closely (PictureCoding::codedOnce).
    bool codedOnce = false;
};

QString videoLinksPath(const QString& sessionDir);
// The link stored for `runPath` (in the videos.json of the run's folder); nullopt when none.
// A missing or unreadable store reads as none (with `problem` saying why when it is unreadable).
std::optional<RunVideoLink> readRunVideoLink(const QString& runPath, QString* problem = nullptr);
// Stores (or, with nullopt, forgets) the link of `runPath`; written atomically. Throws SessionError.
void writeRunVideoLink(const QString& runPath, const std::optional<RunVideoLink>& link);
// The file suffixes taken as video: the Open video dialog's filter and the run's own video.
const QStringList& videoSuffixes();
// The run's own video: RUN.<suffix> beside the run file (mp4 first); empty when there is none.
QString videoBesideRun(const QString& runPath);

// Puts the link into the run's metadata as the exporters read it (video_file relative to the
// run file when beside or below it, sync_offset_s, sync_drift, sync_method, sync_confidence).
void applyRunVideoLink(Run& run, const QString& runPath, const RunVideoLink& link);
// The reverse: the link a run file carries itself (`needlebench demo` and exports write
// sync_offset_s and video_file into the run); nullopt when it names no offset.
std::optional<RunVideoLink> runVideoLinkFromRun(const Run& run, const QString& runPath);

}  // namespace nb
