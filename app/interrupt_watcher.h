#pragma once
// SIGTERM, SIGINT and SIGHUP as a Qt signal, so that a recording interrupted by Ctrl+C, a
// closed terminal or `kill` stops the stage and closes its run file with a footer. The
// handler only writes the signal number to a pipe (async-signal-safe); a QSocketNotifier
// turns that into interrupted() on the thread that owns the watcher.

#include "devices/run_once.h"

#include <QObject>
#include <QString>

class QSocketNotifier;
class QTextStream;

namespace nb {

class InterruptWatcher : public QObject {
    Q_OBJECT
public:
    // Installs the handlers; the previous ones come back when the watcher is destroyed.
    // One watcher at a time per process.
    explicit InterruptWatcher(QObject* parent = nullptr);
    ~InterruptWatcher() override;

    // Catches the signals from now on (the handlers only), to be handled once a watcher
    // exists: for start-up, before the application object. False when no pipe could be made.
    static bool catchEarly();

    // The first signal received (0 if none), and how many have come.
    int signalNumber() const { return first_; }
    int count() const { return count_; }
    // Hands the signals to a headless run (devices/run_once.h): the first ends the run as
    // `interrupted` with `signal: NAME` in its footer, a second does not wait. Each one is
    // told on `err` as `needlebench COMMAND: SIGTERM received: ...`.
    // Reads what the signals left first, so that a loop without an event loop (the rendering
    // of a video) hears them too.
    devices::RunOnceOptions::Interruption interruption();
    void announceOn(QTextStream& err, const QString& command);
    // "SIGTERM", "SIGINT", "SIGHUP", else "signal N".
    static QString signalName(int signo);

signals:
    void interrupted(int signo);

private:
    void readPipe();
    QSocketNotifier* notifier_ = nullptr;
    int first_ = 0;
    int count_ = 0;
};

}  // namespace nb
