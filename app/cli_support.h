#pragma once
// Small helpers shared by the cmd_*.cpp files.

#include "commands.h"

#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <optional>

namespace nb::cli {

// Parses `args` (after the command word) with `parser`, which already has its options and
// positional arguments. On a parse error or a wrong count of positionals prints the error and
// the command's help to io.err and returns false; `--help` prints help to io.out and returns
// false with *exitCode = Ok.
bool parseArgs(QCommandLineParser& parser, const QString& command, const QStringList& args, Io io,
               int minPositional, int maxPositional, int* exitCode);

void printJson(Io io, const QJsonObject& object);

// `--stop-at`: "puncture" is 1, "puncture:N" is N (N >= 1); nullopt for anything else.
std::optional<int> parseStopAt(const QString& value);

}  // namespace nb::cli
