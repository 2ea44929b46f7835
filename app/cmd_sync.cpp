// `needlebench sync RUN.csv VIDEO [--roi x,y,w,h] [--json]`: finds the offset between the
// video and the force record by correlating video motion with the needle's speed.
#include "cli_support.h"
#include "core/tr.h"

#include "core/run_file.h"
#include "core/sync.h"
#include "video/frame_index_store.h"
#include "video/frame_reader.h"
#include "video/motion_signal.h"
#include "video/video_error.h"

#include <QCoreApplication>
#include <QRect>

namespace nb::cli {

int cmdSync(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Find the video's offset to the force record (video time = recording time + offset)."));
    parser.addPositionalArgument(QStringLiteral("RUN.csv"), nb::TrCli::tr("the run file"));
    parser.addPositionalArgument(QStringLiteral("VIDEO"), nb::TrCli::tr("the video of the run"));
    const QCommandLineOption roi(QStringLiteral("roi"), nb::TrCli::tr("region of the picture that moves with the needle, in pixels"),
                                 QStringLiteral("x,y,w,h"));
    const QCommandLineOption maxOffset(QStringLiteral("max-offset"), nb::TrCli::tr("largest offset to consider, seconds (default 20)"),
                                       QStringLiteral("S"), QStringLiteral("20"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOptions({roi, maxOffset, json});
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("sync"), args, io, 2, 2, &code))
        return code;
    QRect region;
    if (parser.isSet(roi)) {
        const QStringList p = parser.value(roi).split(QLatin1Char(','));
        bool ok = p.size() == 4;
        int v[4] = {0, 0, 0, 0};
        for (int i = 0; ok && i < 4; ++i)
            v[i] = p[i].trimmed().toInt(&ok);
        if (!ok || v[2] <= 0 || v[3] <= 0) {
            io.err << nb::TrCli::tr("needlebench sync: --roi wants x,y,w,h in whole pixels, w and h > 0\n\n") << parser.helpText();
            return Usage;
        }
        region = QRect(v[0], v[1], v[2], v[3]);
    }
    bool ok = false;
    SyncOptions options;
    options.maxOffset_s = parser.value(maxOffset).toDouble(&ok);
    if (!ok || options.maxOffset_s <= 0) {
        io.err << nb::TrCli::tr("needlebench sync: --max-offset wants a positive number of seconds\n");
        return Usage;
    }
    const QString runPath = parser.positionalArguments()[0], videoPath = parser.positionalArguments()[1];
    try {
        const Run run = readRunFile(runPath).run;
        video::FrameReader reader(video::loadOrBuildFrameIndex(videoPath), 8);
        if (!region.isEmpty() && !QRect(0, 0, reader.index().width, reader.index().height).contains(region)) {
            io.err << nb::TrCli::tr("needlebench sync: --roi %1,%2,%3,%4 lies outside the %5x%6 picture\n")
                          .arg(region.x()).arg(region.y()).arg(region.width()).arg(region.height())
                          .arg(reader.index().width).arg(reader.index().height);
            return Usage;
        }
        const video::MotionSignal motion = video::computeMotionSignal(reader, region);
        const SyncResult r = synchronise({motion.time_s, motion.value}, needleSpeed(run), options);
        if (parser.isSet(json)) {
            QJsonObject o;
            o[QStringLiteral("offset_s")] = r.offset_s;
            o[QStringLiteral("confidence")] = r.confidence;
            o[QStringLiteral("correlation")] = r.correlation;
            if (r.onsetOffset_s)
                o[QStringLiteral("onset_offset_s")] = *r.onsetOffset_s;
            o[QStringLiteral("frames")] = reader.index().size();
            printJson(io, o);
        } else {
            io.out << nb::TrCli::tr("offset:      %1 s (video time minus recording time)\n").arg(r.offset_s, 0, 'f', 4)
                   << nb::TrCli::tr("confidence:  %1\n").arg(r.confidence, 0, 'f', 2)
                   << nb::TrCli::tr("correlation: %1\n").arg(r.correlation, 0, 'f', 3);
            if (r.onsetOffset_s)
                io.out << nb::TrCli::tr("onsets say:  %1 s\n").arg(*r.onsetOffset_s, 0, 'f', 4);
        }
        return Ok;
    } catch (const RunFileError& e) {
        io.err << "needlebench sync: " << e.message() << '\n';
    } catch (const video::VideoError& e) {
        io.err << "needlebench sync: " << e.message() << '\n';
    } catch (const std::invalid_argument& e) {
        io.err << "needlebench sync: " << nb::TrCli::tr("cannot synchronise: %1").arg(QString::fromUtf8(e.what())) << '\n';
    }
    return Failure;
}

}  // namespace nb::cli
