// `needlebench video-info FILE [--json]` and `needlebench frame FILE --index N --out IMAGE [--json]`.
#include "cli_support.h"
#include "core/tr.h"

#include "video/frame_index.h"
#include "video/frame_index_store.h"
#include "video/frame_reader.h"
#include "video/video_error.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <opencv2/imgcodecs.hpp>

namespace nb::cli {

using nb::video::FrameIndex;

static QJsonObject infoJson(const FrameIndex& index)
{
    QJsonObject o;
    o[QStringLiteral("frames")] = index.size();
    o[QStringLiteral("fps_nominal")] = index.fpsNominal;
    o[QStringLiteral("duration_s")] = index.duration_s();
    o[QStringLiteral("codec")] = index.codec;
    o[QStringLiteral("width")] = index.width;
    o[QStringLiteral("height")] = index.height;
    o[QStringLiteral("variable_frame_rate")] = index.variableFrameRate();
    o[QStringLiteral("duplicate_frames")] = index.duplicateCount();
    o[QStringLiteral("keyframes_known")] = index.keyframesKnown;
    int keys = 0;
    for (const auto& f : index.frames)
        keys += f.keyframe ? 1 : 0;
    o[QStringLiteral("keyframes")] = keys;
    QJsonArray damaged;
    for (const nb::video::DamagedSpan& d : index.damaged)
        damaged.append(QJsonObject{{QStringLiteral("after_s"), d.after_s}, {QStringLiteral("before_s"), d.before_s}, {QStringLiteral("packets"), d.packets}});
    o[QStringLiteral("damaged")] = damaged;
    QJsonArray warnings;
    for (const QString& w : index.warnings)
        warnings.append(w);
    o[QStringLiteral("warnings")] = warnings;
    return o;
}

int cmdVideoInfo(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Index a video file frame by frame and describe it."));
    parser.addPositionalArgument(QStringLiteral("FILE"), nb::TrCli::tr("the video file"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOption(json);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("video-info"), args, io, 1, 1, &code))
        return code;
    const QString path = parser.positionalArguments().first();
    try {
        const FrameIndex index = nb::video::loadOrBuildFrameIndex(path);
        for (const QString& w : index.warnings)
            io.err << nb::TrCli::tr("warning: %1: %2").arg(path, w) << '\n';
        if (parser.isSet(json)) {
            printJson(io, infoJson(index));
        } else {
            io.out << nb::TrCli::tr("file:        %1\n").arg(path) << nb::TrCli::tr("codec:       %1\n").arg(index.codec)
                   << nb::TrCli::tr("size:        %1x%2\n").arg(index.width).arg(index.height)
                   << nb::TrCli::tr("frames:      %1\n").arg(index.size())
                   << nb::TrCli::tr("rate:        %1 frames/s nominal%2\n")
                          .arg(index.fpsNominal, 0, 'f', 3)
                          .arg(index.variableFrameRate() ? nb::TrCli::tr(", variable") : QString())
                   << nb::TrCli::tr("duration:    %1 s\n").arg(index.duration_s(), 0, 'f', 3)
                   << nb::TrCli::tr("duplicates:  %1\n").arg(index.duplicateCount());
        }
        return Ok;
    } catch (const nb::video::VideoError& e) {
        io.err << "needlebench video-info: " << e.message() << '\n';
        return Failure;
    }
}

int cmdFrame(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Write frame N (N-th in presentation order, from 0) of a video as an image."));
    parser.addPositionalArgument(QStringLiteral("FILE"), nb::TrCli::tr("the video file"));
    const QCommandLineOption indexOpt(QStringLiteral("index"), nb::TrCli::tr("frame number, from 0"), QStringLiteral("N"));
    const QCommandLineOption outOpt(QStringLiteral("out"), nb::TrCli::tr("image to write (.png)"), QStringLiteral("IMAGE"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOptions({indexOpt, outOpt, json});
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("frame"), args, io, 1, 1, &code))
        return code;
    bool ok = false;
    const qlonglong n = parser.value(indexOpt).toLongLong(&ok);
    if (!parser.isSet(indexOpt) || !ok || n < 0 || !parser.isSet(outOpt)) {
        io.err << nb::TrCli::tr("needlebench frame: --index N (a whole number >= 0) and --out IMAGE are required\n\n")
               << commandHelp(parser, QStringLiteral("frame"));
        return Usage;
    }
    const QString path = parser.positionalArguments().first();
    const QString out = parser.value(outOpt);
    // Checked before the video is read: OpenCV's own message names its source file, not ours.
    if (!cv::haveImageWriter(out.toStdString())) {
        io.err << nb::TrCli::tr("needlebench frame: --out %1: not an image type that can be written (use .png, .tif or .jpg)\n").arg(out);
        return Usage;
    }
    if (const QString e = unwritableOutput(QStringLiteral("--out"), out); !e.isEmpty()) {
        io.err << "needlebench frame: " << e << '\n';
        return Failure;
    }
    if (const QString e = overwritesInput(QStringLiteral("--out"), out, {path}); !e.isEmpty()) {
        io.err << "needlebench frame: " << e << '\n';
        return Usage;
    }
    try {
        nb::video::FrameIndex index = nb::video::loadOrBuildFrameIndex(path);
        // Checked here for a number beyond int as well (it read "--index N is required").
        if (n >= index.size()) {
            io.err << nb::TrCli::tr("needlebench frame: %1: frame %2 does not exist (the video has %3 frames)\n").arg(path).arg(n).arg(index.size());
            return Failure;
        }
        nb::video::FrameReader reader(std::move(index), 4);
        const auto frame = reader.read(int(n));
        bool written = false;
        try {
            written = cv::imwrite(out.toStdString(), frame.image);
        } catch (const cv::Exception& e) {
            io.err << nb::TrCli::tr("needlebench frame: %1: %2\n").arg(out, QString::fromStdString(e.msg));
            return Failure;
        }
        if (!written) {
            io.err << nb::TrCli::tr("needlebench frame: %1: cannot write the image\n").arg(out);
            return Failure;
        }
        if (parser.isSet(json)) {
            QJsonObject o;
            o[QStringLiteral("index")] = frame.index;
            o[QStringLiteral("time_s")] = frame.time_s;
            printJson(io, o);
        } else {
            io.out << nb::TrCli::tr("frame %1 at %2 s written to %3\n").arg(frame.index).arg(frame.time_s, 0, 'f', 6).arg(out);
        }
        return Ok;
    } catch (const nb::video::VideoError& e) {
        io.err << "needlebench frame: " << e.message() << '\n';
        return Failure;
    }
}

}  // namespace nb::cli
