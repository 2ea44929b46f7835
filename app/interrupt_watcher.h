#pragma once
// SIGTERM, SIGINT and SIGHUP as a Qt signal, so that a recording interrupted by Ctrl+C, a
// closed terminal or `kill` stops the stage and closes its run file with a footer. The
// handler only writes the signal number to a pipe (async-signal-safe); a QSocketNotifier
// turns that into interrupted() on the thread that owns the watcher.

#include <QObject>
#include <QString>

class QSocketNotifier;

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

    // The first signal received (0 if none).
    int signalNumber() const { return first_; }
    // "SIGTERM", "SIGINT", "SIGHUP", else "signal N".
    static QString signalName(int signo);

signals:
    void interrupted(int signo);

private:
    void readPipe();
    QSocketNotifier* notifier_ = nullptr;
    int first_ = 0;
};

}  // namespace nb
