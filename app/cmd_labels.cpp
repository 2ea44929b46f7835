// `needlebench labels suggest RUN.csv --out LABELS.csv [--video VIDEO]`: labels suggested from
// the data, in the labels file format `track,label,start_s,end_s,comment`. With a video (the
// given one, else the one linked to the run, else the one named like the run beside it) the friction phases also use the tissue's motion
// in the picture, and on insertion runs the relaxation comes from the organ surface's
// spring-back in it (without a video none is suggested); the video's clock comes from --video-offset-s, else the run's stored link,
// else the automatic sync.
#include "cli_support.h"
#include "core/tr.h"

#include "core/label_suggest.h"
#include "core/run_file.h"
#include "core/run_video_link.h"
#include "core/tissue_trace.h"
#include "video/frame_index_store.h"
#include "video/frame_reader.h"
#include "video/labels_from_video.h"
#include "video/video_error.h"
#include "video/video_sync.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <optional>

namespace nb::cli {

int cmdLabels(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Labels of a run. Actions: suggest (phases or events from the data)."));
    parser.addPositionalArgument(QStringLiteral("ACTION"), nb::TrCli::tr("suggest"));
    parser.addPositionalArgument(QStringLiteral("RUN.csv"), nb::TrCli::tr("the run file"));
    const QCommandLineOption out(QStringLiteral("out"), nb::TrCli::tr("labels file to write (default RUN.labels.csv)"),
                                 QStringLiteral("LABELS.csv"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print the labels as JSON"));
    const QCommandLineOption video(QStringLiteral("video"),
                                   nb::TrCli::tr("the run's imaging video: friction phases also from the tissue's motion in it, "
                                                 "the relaxation of insertion runs from the surface's spring-back "
                                                 "(default: the video linked to the run, else RUN.mp4, RUN.avi… beside it)"),
                                   QStringLiteral("VIDEO"));
    const QCommandLineOption videoOffset(QStringLiteral("video-offset-s"),
                                         nb::TrCli::tr("video time at the recording's start (default: the run's stored sync, else found automatically)"),
                                         QStringLiteral("S"));
    const QCommandLineOption videoDrift(QStringLiteral("video-drift"), nb::TrCli::tr("the video clock's rate error, e.g. 0.001 (default 0)"),
                                        QStringLiteral("D"));
    const QCommandLineOption tissueTrace(QStringLiteral("tissue-trace"),
                                         nb::TrCli::tr("write the tissue's velocity read off the video as CSV (time_s,tissue_velocity_mm_s)"),
                                         QStringLiteral("FILE.csv"));
    const QCommandLineOption overwrite(QStringLiteral("overwrite"),
                                       nb::TrCli::tr("replace an existing labels file (it may hold labels made by hand), and let --tissue-trace replace a file that is not a trace"));
    parser.addOptions({out, json, video, videoOffset, videoDrift, tissueTrace, overwrite});
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("labels"), args, io, 2, 2, &code))
        return code;
    if (parser.positionalArguments()[0] != QLatin1String("suggest")) {
        io.err << nb::TrCli::tr("needlebench labels: unknown action '%1' (suggest)\n\n").arg(parser.positionalArguments()[0])
               << commandHelp(parser, QStringLiteral("labels"));
        return Usage;
    }
    const QString runPath = parser.positionalArguments()[1];
    QString outPath = parser.value(out);
    if (outPath.isEmpty())
        outPath = labelsPathFor(runPath);
    {
        const QStringList inputs{runPath, parser.value(video)};
        QString clash = overwritesInput(QStringLiteral("--out"), outPath, inputs);
        if (clash.isEmpty() && parser.isSet(tissueTrace))
            clash = overwritesInput(QStringLiteral("--tissue-trace"), parser.value(tissueTrace), inputs + QStringList{outPath});
        if (clash.isEmpty() && parser.isSet(tissueTrace))
            clash = replacesOtherThanTrace(QStringLiteral("--tissue-trace"), parser.value(tissueTrace), kTissueTraceHeader,
                                           parser.isSet(overwrite));
        if (clash.isEmpty())
            clash = existingOutput(parser.isSet(out) ? QStringLiteral("--out") : nb::TrCli::tr("the labels file"), outPath, parser.isSet(overwrite));
        if (!clash.isEmpty()) {
            io.err << "needlebench labels: " << clash << '\n';
            return Usage;
        }
        // Before the video is read, not after.
        QString unwritable = unwritableOutput(parser.isSet(out) ? QStringLiteral("--out") : nb::TrCli::tr("the labels file"), outPath);
        if (unwritable.isEmpty() && parser.isSet(tissueTrace))
            unwritable = unwritableOutput(QStringLiteral("--tissue-trace"), parser.value(tissueTrace));
        if (!unwritable.isEmpty()) {
            io.err << "needlebench labels: " << unwritable << '\n';
            return Failure;
        }
    }
    // A video asked for by name that is not there is a mistake in the command, not a run
    // without a video: labels from force and position alone would pass for what was asked.
    if (parser.isSet(video) && !QFileInfo(parser.value(video)).isFile()) {
        io.err << "needlebench labels: "
               << (QFileInfo(parser.value(video)).isDir() ? nb::TrCli::tr("%1: a folder, not a video").arg(parser.value(video))
                                                          : nb::TrCli::tr("%1: no such video").arg(parser.value(video)))
               << '\n';
        return Failure;
    }
    std::optional<TimelineMapping> given;
    if (parser.isSet(videoOffset) || parser.isSet(videoDrift)) {
        bool okOffset = true, okDrift = true;
        TimelineMapping m;
        if (parser.isSet(videoOffset))
            m.offset_s = parser.value(videoOffset).toDouble(&okOffset);
        if (parser.isSet(videoDrift))
            m.drift = parser.value(videoDrift).toDouble(&okDrift);
        if (!okOffset || !okDrift || !std::isfinite(m.offset_s) || !(std::abs(m.drift) < 0.1)) {
            io.err << nb::TrCli::tr("needlebench labels: --video-offset-s wants seconds and --video-drift a rate error below 0.1\n");
            return Usage;
        }
        given = m;
    }
    try {
        RunReadResult read = readRunFile(runPath, {.dropTruncatedLastRow = true});
        for (const QString& w : read.warnings)
            io.err << nb::TrCli::tr("warning: %1\n").arg(w);
        const Run run = std::move(read.run);
        // Too short to suggest anything: said, not an empty labels file and exit 0 (events and
        // fit refuse the same run).
        constexpr std::size_t kFewestSamples = 10;
        if (run.size() < kFewestSamples) {
            io.err << "needlebench labels: " << nb::TrCli::tr("%1: too few samples (%2) to suggest labels").arg(runPath).arg(run.size()) << '\n';
            return Failure;
        }
        Labels labels = suggestLabels(run);
        QJsonObject videoReport;
        std::optional<TissueMotion> tissue;
        {
            QString videoPath = parser.value(video);
            QString linkProblem;
            const std::optional<RunVideoLink> link = readRunVideoLink(runPath, &linkProblem);
            std::optional<TimelineMapping> mapping = given;
            QString mappingSource = given ? QStringLiteral("given") : QString();
            if (videoPath.isEmpty() && link && !link->video.isEmpty()) {
                if (QFileInfo::exists(link->video))
                    videoPath = link->video;
                else
                    io.err << nb::TrCli::tr("needlebench labels: the run's video %1 is missing; looking beside the run\n").arg(link->video);
            }
            if (videoPath.isEmpty())
                videoPath = videoBesideRun(runPath);
            // A video clock given for no video: said, not silently dropped.
            if (videoPath.isEmpty() && given)
                io.err << nb::TrCli::tr("needlebench labels: no video for %1 (none linked, none beside it): "
                                        "--video-offset-s and --video-drift are not used\n")
                              .arg(QFileInfo(runPath).fileName());
            if (!mapping && link && !videoPath.isEmpty() && link->method != SyncMethod::None &&
                QFileInfo(link->video).canonicalFilePath() == QFileInfo(videoPath).canonicalFilePath()) {
                mapping = link->mapping;
                mappingSource = QStringLiteral("stored");
            }
            if (!videoPath.isEmpty()) {
                videoReport[QStringLiteral("file")] = videoPath;
                video::VideoLabels found;
                found.phases = video::suggestsPhases(run, labels);
                try {
                    const video::FrameIndex index = video::loadOrBuildFrameIndex(videoPath);
                    if (!mapping) {
                        const video::VideoSync vs = video::syncVideoToRun(index, run);
                        mapping = vs.result.mapping();
                        mappingSource = QStringLiteral("automatic");
                        videoReport[QStringLiteral("sync_confidence")] = vs.result.confidence;
                    }
                    found = video::suggestLabelsWithVideo(run, index, *mapping, QFileInfo(videoPath).fileName());
                    labels = found.labels;
                    tissue = found.tissue;
                } catch (const video::VideoError& e) {
                    // A video named on the command line that cannot be read fails the command,
                    // as one that is not there does; one found beside the run is passed over.
                    if (parser.isSet(video)) {
                        io.err << "needlebench labels: " << e.message() << '\n';
                        return Failure;
                    }
                    found.problem = e.message();
                } catch (const std::exception& e) {
                    found.problem = QString::fromUtf8(e.what());
                }
                if (mapping) {
                    videoReport[QStringLiteral("offset_s")] = mapping->offset_s;
                    videoReport[QStringLiteral("drift")] = mapping->drift;
                    videoReport[QStringLiteral("sync")] = mappingSource;
                }
                videoReport[QStringLiteral("used")] = found.videoUsed;
                if (!found.videoUsed) {
                    videoReport[QStringLiteral("problem")] = found.problem;
                    io.err << (found.phases ? nb::TrCli::tr("needlebench labels: %1: the tissue's motion could not be read (%2); phases from force and position only\n")
                                            : nb::TrCli::tr("needlebench labels: %1: the surface's motion could not be read (%2); no relaxation suggested\n"))
                                  .arg(videoPath, found.problem);
                }
                if (found.relaxationProblem) {
                    videoReport[QStringLiteral("relaxation")] = found.relaxationProblem->isEmpty() ? QStringLiteral("suggested") : *found.relaxationProblem;
                    if (!found.relaxationProblem->isEmpty())
                        io.err << nb::TrCli::tr("needlebench labels: %1: no relaxation suggested: %2\n").arg(videoPath, *found.relaxationProblem);
                }
            }
        }
        if (tissue && parser.isSet(tissueTrace)) {
            const QByteArray csv = traceCsv(kTissueTraceHeader, tissue->time_s, tissue->velocity_mm_s, 4);
            if (const QString e = writeOutput(QStringLiteral("--tissue-trace"), parser.value(tissueTrace), csv); !e.isEmpty()) {
                io.err << "needlebench labels: " << e << '\n';
                return Failure;
            }
        }
        writeLabelsFile(outPath, labels);
        if (parser.isSet(json)) {
            QJsonArray a;
            for (const Label& l : labels)
                a.append(QJsonObject{{QStringLiteral("track"), l.track},
                                     {QStringLiteral("label"), l.label},
                                     {QStringLiteral("start_s"), l.start_s},
                                     {QStringLiteral("end_s"), l.end_s},
                                     {QStringLiteral("comment"), l.comment}});
            QJsonObject o{{QStringLiteral("labels"), a}, {QStringLiteral("out"), outPath}};
            if (!videoReport.isEmpty())
                o[QStringLiteral("video")] = videoReport;
            printJson(io, o);
        } else {
            io.out << nb::TrCli::tr("%1 labels suggested, written to %2\n").arg(labels.size()).arg(outPath);
        }
        return Ok;
    } catch (const RunFileError& e) {
        io.err << "needlebench labels: " << e.message() << '\n';
        return Failure;
    }
}

}  // namespace nb::cli
