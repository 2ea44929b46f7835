#include "interrupt_watcher.h"

#include <QTextStream>
#include "core/tr.h"

#include <QSocketNotifier>
#include <array>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <unistd.h>

namespace nb {

namespace {

int g_pipe[2] = {-1, -1};
constexpr std::array<int, 3> kSignals{SIGTERM, SIGINT, SIGHUP};
struct sigaction g_previous[kSignals.size()];

extern "C" void onSignal(int signo)
{
    const int saved = errno;
    const unsigned char byte = static_cast<unsigned char>(signo);
    [[maybe_unused]] const ssize_t n = ::write(g_pipe[1], &byte, 1);
    errno = saved;
}

}  // namespace

bool InterruptWatcher::catchEarly()
{
    if (g_pipe[0] >= 0)
        return true;
    if (::pipe2(g_pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
        g_pipe[0] = g_pipe[1] = -1;
        return false;  // without a pipe the default handlers stay: the process still ends
    }
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        struct sigaction sa {};
        sa.sa_handler = onSignal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART;
        ::sigaction(kSignals[i], &sa, &g_previous[i]);
    }
    return true;
}

InterruptWatcher::InterruptWatcher(QObject* parent) : QObject(parent)
{
    if (!catchEarly())
        return;
    notifier_ = new QSocketNotifier(g_pipe[0], QSocketNotifier::Read, this);
    connect(notifier_, &QSocketNotifier::activated, this, &InterruptWatcher::readPipe);
    // A signal caught before the watcher existed is waiting in the pipe.
    QMetaObject::invokeMethod(this, &InterruptWatcher::readPipe, Qt::QueuedConnection);
}

InterruptWatcher::~InterruptWatcher()
{
    if (g_pipe[0] < 0)
        return;
    for (std::size_t i = 0; i < kSignals.size(); ++i)
        ::sigaction(kSignals[i], &g_previous[i], nullptr);
    delete notifier_;
    ::close(g_pipe[0]);
    ::close(g_pipe[1]);
    g_pipe[0] = g_pipe[1] = -1;
}

QString InterruptWatcher::signalName(int signo)
{
    switch (signo) {
    case SIGTERM: return QStringLiteral("SIGTERM");
    case SIGINT: return QStringLiteral("SIGINT");
    case SIGHUP: return QStringLiteral("SIGHUP");
    default: return QStringLiteral("signal %1").arg(signo);
    }
}

void InterruptWatcher::readPipe()
{
    unsigned char bytes[16];
    for (;;) {
        const ssize_t n = ::read(g_pipe[0], bytes, sizeof bytes);
        if (n <= 0)
            break;
        for (ssize_t i = 0; i < n; ++i) {
            if (!first_)
                first_ = bytes[i];
            ++count_;
            emit interrupted(bytes[i]);
        }
    }
}

devices::RunOnceOptions::Interruption InterruptWatcher::interruption()
{
    if (g_pipe[0] >= 0)
        readPipe();
    devices::RunOnceOptions::Interruption i;
    i.count = count_;
    if (count_)
        i.footer.set(QStringLiteral("signal"), signalName(first_));
    return i;
}

void InterruptWatcher::announceOn(QTextStream& err, const QString& command)
{
    connect(this, &InterruptWatcher::interrupted, this, [&err, command](int signo) {
        err << "needlebench " << command << ": "
            << nb::TrCli::tr("%1 received: stopping the stage and closing the run").arg(signalName(signo)) << '\n';
        err.flush();
    });
}

}  // namespace nb
