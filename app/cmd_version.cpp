#include "cli_support.h"

namespace nb::cli {

int cmdVersion(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("version"), args, io, 0, 0, &code))
        return code;
    io.out << "needlebench " << NEEDLEBENCH_VERSION << '\n';
    return Ok;
}

}  // namespace nb::cli
