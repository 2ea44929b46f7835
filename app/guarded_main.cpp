#include "guarded_main.h"

#include "core/excerpt.h"
#include "core/tr.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>

namespace nb {

int runGuarded(const QString& what, const std::function<int()>& body, QTextStream& err)
{
    QString reason;
    try {
        return body();
    } catch (const std::bad_alloc&) {
        reason = nb::TrCli::tr("out of memory");
    } catch (const std::exception& e) {
        reason = excerpt(QByteArray(e.what()), 300);
    } catch (...) {
        reason = nb::TrCli::tr("unknown exception");
    }
    err << "needlebench " << what << ": " << nb::TrCli::tr("internal error: %1").arg(reason) << '\n';
    err.flush();
    return 1;
}

namespace {

[[noreturn]] void onTerminate()
{
    const char* what = "unknown";
    if (const std::exception_ptr p = std::current_exception()) {
        try {
            std::rethrow_exception(p);
        } catch (const std::exception& e) {
            what = e.what();
        } catch (...) {
        }
    }
    std::fprintf(stderr, "needlebench: internal error (uncaught exception: %.300s)\n", what);
    std::fflush(stderr);
    std::_Exit(1);
}

}  // namespace

void installTerminateHandler()
{
    std::set_terminate(onTerminate);
}

}  // namespace nb
