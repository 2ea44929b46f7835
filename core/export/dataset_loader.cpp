#include "dataset_loader.h"
#include "core/tr.h"

#include "export_error.h"

#include "core/excerpt.h"
#include "core/run_file.h"
#include "core/run_video_link.h"
#include "core/session.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {

bool isLabelsFile(const QString& fileName) { return fileName.endsWith(QLatin1String(".labels.csv")); }

// A label outside the recording (a typo, 1e300 s) describes nothing in it and is set aside; one
// that reaches past either end (drawn from before the first sample) keeps the part inside.
Labels labelsWithinRun(Labels labels, const Run& run, const QString& labelsPath, QStringList& warnings)
{
    const double t0 = run.time_s.front(), t1 = run.time_s.back();
    const double slack = 1.0;  // a label may end just after the last sample
    Labels kept;
    for (Label& l : labels) {
        const bool outside = l.isPoint() ? (l.start_s < t0 - slack || l.start_s > t1 + slack) : (l.end_s <= t0 || l.start_s >= t1);
        if (outside) {
            warnings << nb::TrCore::tr("%1: label '%2' (%3 s to %4 s) lies outside the run (%5 s to %6 s); ignored")
                            .arg(labelsPath, excerpt(l.label))
                            .arg(l.start_s, 0, 'g', 6)
                            .arg(l.end_s, 0, 'g', 6)
                            .arg(t0, 0, 'f', 3)
                            .arg(t1, 0, 'f', 3);
            continue;
        }
        if (!l.isPoint() && (l.start_s < t0 - slack || l.end_s > t1 + slack)) {
            const double from = std::max(l.start_s, t0), to = std::min(l.end_s, t1);
            warnings << nb::TrCore::tr("%1: label '%2' (%3 s to %4 s) reaches beyond the run (%5 s to %6 s); its part from %7 s to %8 s is used")
                            .arg(labelsPath, excerpt(l.label))
                            .arg(l.start_s, 0, 'g', 6)
                            .arg(l.end_s, 0, 'g', 6)
                            .arg(t0, 0, 'f', 3)
                            .arg(t1, 0, 'f', 3)
                            .arg(from, 0, 'f', 3)
                            .arg(to, 0, 'f', 3);
            l.start_s = from;
            l.end_s = to;
        }
        kept.push_back(std::move(l));
    }
    return kept;
}

}  // namespace

LoadedDataset loadDataset(const QString& dirPath)
{
    const QFileInfo info(dirPath);
    if (!info.isDir())
        throw ExportError(dirPath, info.exists() ? nb::TrCore::tr("not a folder") : nb::TrCore::tr("no such folder"));
    LoadedDataset out;
    Dataset& d = out.dataset;
    d.name = info.fileName();
    const QDir dir(dirPath);

    QStringList runPaths;
    bool fromSession = false;  // the session's own list of runs, not every CSV in the folder
    if (Session::isSession(dirPath)) {
        try {
            const Session s = Session::open(dirPath);
            fromSession = true;
            const SessionInfo& si = s.info();
            const Metadata sm = sessionMetadata(si);
            for (const auto& [k, v] : sm.entries())
                d.metadata.set(k, v);
            d.metadata.set(QStringLiteral("notes"), si.notes);
            d.metadata.set(QStringLiteral("created"), si.created.toString(Qt::ISODate));
            if (const auto cal = s.activeCalibration()) {
                d.metadata.set(QStringLiteral("calibration"), cal->name);
                d.metadata.set(QStringLiteral("calibration_slope_V_per_g"), cal->fit.slope_V_per_g);
                d.metadata.set(QStringLiteral("calibration_intercept_V"), cal->fit.intercept_V);
                d.metadata.set(QStringLiteral("calibration_r2"), cal->fit.r2);
            }
            for (const RunEntry& e : s.runs()) {
                if (e.state == RunState::Unreadable) {
                    out.warnings << nb::TrCore::tr("%1: skipped, %2").arg(e.path, e.detail);
                    out.runsLeftOut << e.path;
                } else if (e.endReason.isEmpty()) {
                    // No footer: a run still recording (exported half, it looked complete) or
                    // one cut off by a crash, which opening the session in the window recovers.
                    out.warnings << nb::TrCore::tr("%1: left out, the run is still recording or was cut off before it was closed "
                                                   "(export it after it ends; a cut-off run is recovered when its session is "
                                                   "opened in the window)")
                                        .arg(e.path);
                    out.runsLeftOut << e.path;
                } else {
                    runPaths << e.path;
                }
            }
        } catch (const SessionError& e) {
            out.warnings << e.message();
        }
    }
    if (!fromSession) {
        for (const QString& name : dir.entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name))
            if (!isLabelsFile(name))
                runPaths << dir.filePath(name);
    }

    QStringList used;
    for (const QString& path : runPaths) {
        DatasetRun r;
        r.sourcePath = path;
        try {
            RunReadResult res = readRunFile(path, {.dropTruncatedLastRow = true});
            r.run = std::move(res.run);
            for (const QString& w : res.warnings)
                out.warnings << w;
        } catch (const RunFileError& e) {
            out.warnings << nb::TrCore::tr("%1: skipped, not a run file (%2)").arg(path, e.message());
            if (fromSession)
                out.runsLeftOut << path;
            continue;
        }
        // The video and sync the operator set in the window (videos.json) win over the file's.
        QString linkProblem;
        if (const auto link = readRunVideoLink(path, &linkProblem))
            applyRunVideoLink(r.run, path, *link);
        if (!linkProblem.isEmpty() && !out.warnings.contains(linkProblem))
            out.warnings << linkProblem;
        const QString labelsPath = labelsPathFor(path);
        if (QFileInfo::exists(labelsPath)) {
            try {
                LabelsRead read = readLabels(labelsPath);
                r.labels = std::move(read.labels);
                out.warnings << read.problems();
            } catch (const RunFileError& e) {
                out.warnings << nb::TrCore::tr("%1: labels ignored (%2)").arg(labelsPath, e.message());
            }
            if (!r.run.time_s.empty())
                r.labels = labelsWithinRun(std::move(r.labels), r.run, labelsPath, out.warnings);
            for (const QString& overlap : overlappingLabels(r.labels))
                out.warnings << QStringLiteral("%1: %2").arg(labelsPath, overlap);
        }
        // Names become file and group names: keep them unique.
        QString name = QFileInfo(path).completeBaseName();
        for (int k = 2; used.contains(name); ++k)
            name = QFileInfo(path).completeBaseName() + QStringLiteral("_%1").arg(k);
        used << name;
        r.name = name;
        r.videoPath = findRunVideo(path, r.run);
        // A video the run names that is not there: said, as the export then links none (with
        // --copy-video the export's JSON kept the name of a video it did not carry).
        if (const auto named = r.run.meta(QStringLiteral("video_file")); r.videoPath.isEmpty() && named && !named->trimmed().isEmpty())
            out.warnings << nb::TrCore::tr("%1: its video %2 is missing; the export links none").arg(path, named->trimmed());
        d.runs.push_back(std::move(r));
    }
    return out;
}

}  // namespace nb
