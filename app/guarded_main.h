#pragma once
// No exception leaves `main`: a command or the window that throws is reported with what it
// was doing and ends with exit code 1, instead of std::terminate's "terminate called ..." and
// a core dump (exit 134).

#include <QTextStream>
#include <functional>

namespace nb {

// Runs `body` and returns its exit code; an exception is written to `err` as
// "needlebench WHAT: internal error: ..." (a short excerpt) and returns 1.
int runGuarded(const QString& what, const std::function<int()>& body, QTextStream& err);

// For exceptions thrown where no runGuarded can catch them (other threads): prints a clear
// message before the process aborts.
void installTerminateHandler();

}  // namespace nb
