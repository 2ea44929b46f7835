#pragma once
// The headless command line: `needlebench WORD [options]`. Each command lives in its own
// cmd_*.cpp file and is listed once in commands.cpp.

#include <QStringList>
#include <QTextStream>
#include <functional>
#include <vector>

namespace nb::cli {

// Exit codes shared by every command.
enum ExitCode : int { Ok = 0, Failure = 1, Usage = 2 };

struct Io {
    QTextStream& out;
    QTextStream& err;
};

struct Command {
    QString name;
    QString summary;                                     // one line for `needlebench help`
    std::function<int(const QStringList& args, Io io)> run;  // args start after the command word
    // Renders widgets (plots to PNG/SVG/PDF): gets a QApplication on the offscreen platform
    // instead of a QCoreApplication, so it still needs no display.
    bool rendersWidgets = false;
};

// True when `arguments` (argv[1..]) names a command that renders widgets.
bool needsWidgets(const QStringList& arguments);

const std::vector<Command>& commands();

// Runs `argv[1..]`; prints usage and returns Usage for an unknown command.
int run(const QStringList& arguments, Io io);

}  // namespace nb::cli
