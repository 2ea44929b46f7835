// `needlebench labels suggest RUN.csv --out LABELS.csv`: labels suggested from the data, in
// the labels file format `track,label,start_s,end_s,comment`.
#include "cli_support.h"
#include "core/tr.h"

#include "core/label_suggest.h"
#include "core/run_file.h"

#include <QCoreApplication>
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
    parser.addOptions({out, json});
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
        const Labels labels = suggestLabels(run);
        writeLabelsFile(outPath, labels);
        if (parser.isSet(json)) {
            QJsonArray a;
            for (const Label& l : labels)
                a.append(QJsonObject{{QStringLiteral("track"), l.track},
                                     {QStringLiteral("label"), l.label},
                                     {QStringLiteral("start_s"), l.start_s},
                                     {QStringLiteral("end_s"), l.end_s},
                                     {QStringLiteral("comment"), l.comment}});
            printJson(io, QJsonObject{{QStringLiteral("labels"), a}, {QStringLiteral("out"), outPath}});
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
