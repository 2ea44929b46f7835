#include "cli_support.h"
#include "core/export/csv_text.h"
#include "core/export/export_error.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QTemporaryFile>

#ifdef Q_OS_UNIX
#include <sys/stat.h>
#endif

namespace nb::cli {

bool parseArgs(QCommandLineParser& parser, const QString& command, const QStringList& args, Io io,
               int minPositional, int maxPositional, int* exitCode)
{
    parser.setApplicationDescription(QString());
    const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")},
                                  nb::TrCli::tr("show this help"));
    parser.addOption(help);
    auto helpText = [&] { return commandHelp(parser, command); };
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

QString commandHelp(const QCommandLineParser& parser, const QString& command)
{
    const QString h = parser.helpText();
    // QCommandLineParser names the program from argv[0]; name the command instead.
    const qsizetype nl = h.indexOf(QLatin1Char('\n'));
    const QString firstLine = h.left(nl);
    const qsizetype opts = firstLine.indexOf(QLatin1String("[options]"));
    return QStringLiteral("Usage: needlebench %1 %2").arg(command, firstLine.mid(opts)) + h.mid(nl);
}

void printJson(Io io, const QJsonObject& object)
{
    io.out << QJsonDocument(object).toJson(QJsonDocument::Indented);
}

bool samePath(const QString& a, const QString& b)
{
    const QFileInfo x(a), y(b);
    if (x.exists() && y.exists()) {
#ifdef Q_OS_UNIX
        struct stat sa {}, sb {};
        if (::stat(QFile::encodeName(a).constData(), &sa) == 0 && ::stat(QFile::encodeName(b).constData(), &sb) == 0)
            return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
#endif
        return x.canonicalFilePath() == y.canonicalFilePath();
    }
    return QDir::cleanPath(x.absoluteFilePath()) == QDir::cleanPath(y.absoluteFilePath());
}

QString overwritesInput(const QString& option, const QString& out, const QStringList& inputs)
{
    for (const QString& in : inputs)
        if (!in.isEmpty() && samePath(out, in))
            return nb::TrCli::tr("%1 %2 is a file this command reads; writing it would destroy it. Name another file.").arg(option, out);
    return {};
}

QString existingOutput(const QString& option, const QString& out, bool overwrite)
{
    if (overwrite || !QFileInfo(out).isFile())
        return {};
    return nb::TrCli::tr("%1 %2 already exists; it is kept. Name another file, or add --overwrite to replace it.").arg(option, out);
}

QString replacesOtherThanTrace(const QString& option, const QString& out, const char* header, bool overwrite)
{
    QFile existing(out);
    if (overwrite || !QFileInfo(out).isFile() || !existing.open(QIODevice::ReadOnly))
        return {};
    if (existing.readLine(256).trimmed() == QByteArray(header))
        return {};
    return nb::TrCli::tr("%1 %2 already exists and is not a trace this command wrote; it is kept. Name another file, or add "
                         "--overwrite to replace it.").arg(option, out);
}

QString unwritableOutput(const QString& option, const QString& out)
{
    const QFileInfo info(out);
    if (info.isDir())
        return nb::TrCli::tr("%1 %2 is a folder; name a file").arg(option, out);
    const QString folder = info.absolutePath();
    if (!QFileInfo(folder).isDir())
        return nb::TrCli::tr("%1 %2: the folder %3 does not exist").arg(option, out, folder);
    QTemporaryFile probe(QDir(folder).filePath(QStringLiteral(".needlebench-write-check-XXXXXX")));
    if (!probe.open())
        return nb::TrCli::tr("%1 %2: no file can be written in %3 (%4)").arg(option, out, folder, probe.errorString());
    return {};
}

QByteArray traceCsv(const char* header, const std::vector<double>& time_s, const std::vector<double>& value, int decimals)
{
    QByteArray csv = QByteArray(header) + '\n';
    for (std::size_t i = 0; i < time_s.size() && i < value.size(); ++i)
        csv += csvNumber(time_s[i], 6) + ',' + csvNumber(value[i], decimals) + '\n';
    return csv;
}

QString writeOutput(const QString& option, const QString& out, const QByteArray& bytes)
{
    try {
        writeFileAtomically(out, bytes);
        return {};
    } catch (const ExportError& e) {
        return nb::TrCli::tr("%1 %2: %3").arg(option, out, e.reason());
    }
}

QString notAnInsertionRun(const Run& run, const QString& path)
{
    const bool sine = run.meta(QStringLiteral("motion")).value_or(QString()) == QLatin1String("sine")
                      || run.meta(QStringLiteral("protocol")).value_or(QString()) == QLatin1String("friction");
    if (!sine)
        return {};
    return nb::TrCli::tr("warning: %1 is a friction run (a sine on the platform, by its header); contact, punctures and "
                         "stiffness are read for insertion runs and mean little here ('needlebench fit friction' fits it)")
        .arg(path);
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
