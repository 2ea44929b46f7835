// `needlebench labels suggest RUN.csv [--video VIDEO] --out LABELS.csv`: labels suggested from
// the data (friction phases from the video's tissue motion when there is a video), in the
// labels file format `track,label,start_s,end_s,comment`; the comment says the source.
#include "cli_support.h"
#include "core/tr.h"

#include "core/label_suggest.h"
#include "core/run_file.h"
#include "video/frame_index_store.h"
#include "video/video_error.h"
#include "video/video_phases.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>

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
                                   nb::TrCli::tr("read the friction phases off this video of the run (default: the run's own video, "
                                                 "metadata video_file, when it has one)"),
                                   QStringLiteral("VIDEO"));
    const QCommandLineOption noVideo(QStringLiteral("no-video"), nb::TrCli::tr("suggest from force and position only"));
    parser.addOptions({out, json, video, noVideo});
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("labels"), args, io, 2, 2, &code))
        return code;
    if (parser.positionalArguments()[0] != QLatin1String("suggest")) {
        io.err << nb::TrCli::tr("needlebench labels: unknown action '%1' (suggest)\n\n").arg(parser.positionalArguments()[0])
               << parser.helpText();
        return Usage;
    }
    const QString runPath = parser.positionalArguments()[1];
    QString outPath = parser.value(out);
    if (outPath.isEmpty()) {
        outPath = runPath;
        if (outPath.endsWith(QLatin1String(".csv")))
            outPath.chop(4);
        outPath += QStringLiteral(".labels.csv");
    }
    try {
        const Run run = readRunFile(runPath).run;
        QString videoPath = parser.value(video);
        if (videoPath.isEmpty() && !parser.isSet(noVideo)) {
            const QString own = run.metadata.value(QStringLiteral("video_file"), QString());
            if (!own.isEmpty() && QFileInfo(QFileInfo(runPath).dir().filePath(own)).isFile())
                videoPath = QFileInfo(runPath).dir().filePath(own);
        }
        const bool friction = run.metadata.value(QStringLiteral("protocol"), QString()) == QLatin1String("friction");
        Labels labels;
        QString note;
        bool fromVideo = false;
        if (!videoPath.isEmpty() && friction && !parser.isSet(noVideo)) {
            try {
                const video::VideoPhases vp = video::suggestPhasesFromVideo(video::loadOrBuildFrameIndex(videoPath), run);
                labels = vp.labels;
                fromVideo = vp.fromVideo;
                note = vp.note;
            } catch (const video::VideoError& e) {
                io.err << "needlebench labels: " << e.message() << '\n';
                return Failure;
            }
        } else {
            labels = suggestLabels(run);
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
            QJsonObject o{{QStringLiteral("labels"), a}, {QStringLiteral("out"), outPath}, {QStringLiteral("from_video"), fromVideo}};
            if (!videoPath.isEmpty())
                o.insert(QStringLiteral("video"), videoPath);
            if (!note.isEmpty())
                o.insert(QStringLiteral("note"), note);
            printJson(io, o);
        } else {
            io.out << nb::TrCli::tr("%1 labels suggested, written to %2\n").arg(labels.size()).arg(outPath);
            if (fromVideo)
                io.out << nb::TrCli::tr("phases read off the video %1 (tissue motion beside the needle)\n").arg(videoPath);
            else if (!note.isEmpty())
                io.out << nb::TrCli::tr("the video was not used: %1; phases from force and position\n").arg(note);
        }
        return Ok;
    } catch (const RunFileError& e) {
        io.err << "needlebench labels: " << e.message() << '\n';
        return Failure;
    }
}

}  // namespace nb::cli
