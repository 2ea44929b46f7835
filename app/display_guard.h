#pragma once
// The window needs a display; without one Qt aborts with advice to reinstall, which sends an
// operator on an SSH session or a stale DISPLAY the wrong way. These say what is missing.

#include <QString>

namespace nb {

// Whether the window has somewhere to go as far as the environment tells (a display, a
// Wayland socket, or a platform chosen with QT_QPA_PLATFORM or -platform).
bool haveDisplay(int argc, char** argv);

// While the window's application is being made: a fatal error from Qt (it could not reach the
// display it was given) prints `explanation` and ends the process with exit code 2.
void explainFatalStartup(const QString& explanation);
// Qt's own handling again, once the application is made.
void endStartupExplanation();

}  // namespace nb
