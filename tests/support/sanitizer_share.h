#pragma once
// Under AddressSanitizer and UBSan the suite runs a second time to find memory errors and
// undefined behaviour, not to measure: the accuracy figures are the plain build's. There every
// case of a matrix costs five to ten times its plain time, and the whole matrix ran CI past its
// limit. So under the sanitizers (NB_SANITIZER_SHARE=N, set by tests/CMakeLists.txt) a matrix
// runs one case in N, the first always, and of a program's regression cases (its functions and
// data rows, in their order) one in N: every program still goes through its code paths, on
// fewer videos.

#include <QtTest>

#include <cstddef>

namespace nb::test {

inline std::size_t sanitizerShare()
{
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("NB_SANITIZER_SHARE", &ok);
    return ok && n > 1 ? std::size_t(n) : 1;
}

// Whether case `i` of a matrix runs here.
inline bool caseInShare(std::size_t i)
{
    return i % sanitizerShare() == 0;
}

// Whether this regression case (a test function or one of its data rows) runs here: they are
// counted in the order they run, the first running.
inline bool regressionCaseInShare()
{
    static std::size_t seen = 0;
    return caseInShare(seen++);
}

}  // namespace nb::test

// A case outside the share is reported as skipped, with the reason, never as passed.
#define NB_SKIP_OUTSIDE_SANITIZER_SHARE()                                                          \
    do {                                                                                           \
        if (!nb::test::regressionCaseInShare())                                                    \
            QSKIP("under the sanitizers one regression case in NB_SANITIZER_SHARE runs; the plain build runs them all"); \
    } while (false)
