#include "realtime.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <cerrno>
#include <cstring>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

namespace nb::devices {

namespace {

bool underSanitizer()
{
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}
}  // namespace

RealtimeResult makeCurrentThreadRealtime(int priority)
{
    RealtimeResult r;
    QStringList problems;
    sched_param param{};
    param.sched_priority = priority;
    const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (err == 0) {
        r.fifo = true;
    } else {
        problems << nb::TrDevices::tr("real-time scheduling (SCHED_FIFO) not permitted: %1; sample timing may jitter "
                       "(grant rtprio in /etc/security/limits.conf or CAP_SYS_NICE)")
                        .arg(QString::fromLocal8Bit(std::strerror(err)));
    }
    // ASan reserves terabytes of shadow memory: locking it all would exhaust RAM.
    if (underSanitizer()) {
        problems << nb::TrDevices::tr("memory not locked (sanitizer build)");
    } else if (r.fifo) {
        if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0)
            r.memoryLocked = true;
        else
            problems << nb::TrDevices::tr("memory could not be locked (mlockall: %1); page faults may delay samples")
                            .arg(QString::fromLocal8Bit(std::strerror(errno)));
    }
    r.warning = problems.join(QStringLiteral("; "));
    return r;
}

}  // namespace nb::devices
