#include "cli_support.h"
#include "core/tr.h"

#include <QCoreApplication>

namespace nb::cli {

bool parseArgs(QCommandLineParser& parser, const QString& command, const QStringList& args, Io io,
               int minPositional, int maxPositional, int* exitCode)
{
    parser.setApplicationDescription(QString());
    const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")},
                                  nb::TrCli::tr("show this help"));
    parser.addOption(help);
    auto helpText = [&] {
        QString h = parser.helpText();
        // QCommandLineParser names the program from argv[0]; name the command instead.
        const qsizetype nl = h.indexOf(QLatin1Char('\n'));
        const QString firstLine = h.left(nl);
        const qsizetype opts = firstLine.indexOf(QLatin1String("[options]"));
        return QStringLiteral("Usage: needlebench %1 %2").arg(command, firstLine.mid(opts)) + h.mid(nl);
    };
    if (!parser.parse(QStringList{QStringLiteral("needlebench")} + args)) {
        io.err << "needlebench " << command << ": " << parser.errorText() << "\n\n" << helpText();
        *exitCode = Usage;
        return false;
    }
    if (parser.isSet(help)) {
        io.out << helpText();
        *exitCode = Ok;
        return false;
    }
    const auto n = parser.positionalArguments().size();
    if (n < minPositional || (maxPositional >= 0 && n > maxPositional)) {
        io.err << "needlebench " << command << ": "
               << (n < minPositional ? nb::TrCli::tr("missing arguments")
                                     : nb::TrCli::tr("too many arguments"))
               << "\n\n"
               << helpText();
        *exitCode = Usage;
        return false;
    }
    return true;
}

void printJson(Io io, const QJsonObject& object)
{
    io.out << QJsonDocument(object).toJson(QJsonDocument::Indented);
}

std::optional<int> parseStopAt(const QString& value)
{
    if (value == QLatin1String("puncture"))
        return 1;
    if (!value.startsWith(QLatin1String("puncture:")))
        return std::nullopt;
    bool ok = false;
    const int n = value.mid(9).toInt(&ok);
    return ok && n >= 1 ? std::optional(n) : std::nullopt;
}

}  // namespace nb::cli
