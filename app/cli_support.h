#pragma once
// Small helpers shared by the cmd_*.cpp files.

#include "commands.h"
#include "core/run.h"

#include <QCommandLineParser>
#include <QJsonDocument>
#include <QJsonObject>
#include <optional>
#include <vector>

namespace nb::cli {

// Parses `args` (after the command word) with `parser`, which already has its options and
// positional arguments. On a parse error or a wrong count of positionals prints the error and
// the command's help to io.err and returns false; `--help` prints help to io.out and returns
// false with *exitCode = Ok.
bool parseArgs(QCommandLineParser& parser, const QString& command, const QStringList& args, Io io,
               int minPositional, int maxPositional, int* exitCode);

void printJson(Io io, const QJsonObject& object);

// The command's help as parseArgs prints it: "Usage: needlebench COMMAND [options] ..." (Qt's
// own names the program by the path it was started from).
QString commandHelp(const QCommandLineParser& parser, const QString& command);

// Whether `a` and `b` name the same file, whether or not it exists yet (links resolved; hard
// links too: `export --copy-video` makes them).
bool samePath(const QString& a, const QString& b);

// What to tell the user when the output `out` (given with `option`) is one of the command's
// `inputs`: writing it would destroy what the command reads. Empty when it is none of them.
QString overwritesInput(const QString& option, const QString& out, const QStringList& inputs);

// What to tell the user when `out` (given with `option`) already exists and holds data a person
// would not want to lose (a recording, labels made by hand), unless `overwrite` (--overwrite)
// says so. Empty when it may be written.
QString existingOutput(const QString& option, const QString& out, bool overwrite);

// What to tell the user when a trace `out` (given with `option`, its first line `header`) would
// replace a file that is not such a trace (a run, labels, a video), unless `overwrite` says so.
// An earlier trace is replaced, as a script run again expects. Empty when it may be written.
QString replacesOtherThanTrace(const QString& option, const QString& out, const char* header, bool overwrite);

// What to tell the user when `out` (given with `option`) cannot be written: a folder, in a folder
// that does not exist, or where no file can be made. Checked before a run records, so that a
// run is not recorded (the needle inserted) only to fail on its outputs. Empty when writable.
QString unwritableOutput(const QString& option, const QString& out);

// A trace as CSV: `header`, then a row per sample, the time to the microsecond and the value to
// `decimals` places (empty where it is NaN: no reading).
QByteArray traceCsv(const char* header, const std::vector<double>& time_s, const std::vector<double>& value, int decimals);

// Writes `bytes` to `out` (given with `option`) whole or not at all (a temporary renamed once
// written). Empty when written, else what to tell the user: the file and why (a full disk by name).
QString writeOutput(const QString& option, const QString& out, const QByteArray& bytes);

// A warning for commands made for insertion runs (events, stiffness) given a friction run (a
// sine on the platform, by its header): their contact and punctures are then meaningless.
// Empty for any other run.
QString notAnInsertionRun(const Run& run, const QString& path);

// `--stop-at`: "puncture" is 1, "puncture:N" is N (N >= 1); nullopt for anything else.
std::optional<int> parseStopAt(const QString& value);

}  // namespace nb::cli
