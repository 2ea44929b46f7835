#pragma once
// The case matrices (the accuracy matrices, their regression cases, the needle tracker's cases)
// cost most of the suite's time: every case encodes and reads its own videos. Run whole, they
// kept the README's test command at 21 to 27 minutes on two cores against the 15 it must keep.
// So the suite runs a share of them, set by tests/CMakeLists.txt in NB_CASE_SHARE:
// - the README's test command: one case in 4 (in 3 it took 15 min 13 s on a clean clone);
// - under AddressSanitizer and UBSan (five to ten times slower a video): one in 8;
// - NB_ALL_CASES=1 (scripts/test-all-cases.sh, which CI runs after the test command): every case.
// The first case of each matrix and of each program always runs, so every program goes through
// its code paths; a case outside the share is reported as skipped, saying why, never as passed.
// The accuracy figures quoted anywhere come from the whole matrices (test-all-cases, bench_accuracy).

#include <QtTest>

#include <cstddef>

namespace nb::test {

inline std::size_t caseShare()
{
    if (qEnvironmentVariableIsSet("NB_ALL_CASES"))
        return 1;
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("NB_CASE_SHARE", &ok);
    return ok && n > 1 ? std::size_t(n) : 1;
}

// Whether case `i` of a matrix runs here.
inline bool caseInShare(std::size_t i)
{
    return i % caseShare() == 0;
}

// Whether this regression case (a test function or one of its data rows) runs here: they are
// counted in the order they run, the first running.
inline bool regressionCaseInShare()
{
    static std::size_t seen = 0;
    return caseInShare(seen++);
}

}  // namespace nb::test

#define NB_SKIP_OUTSIDE_CASE_SHARE()                                                               \
    do {                                                                                           \
        if (!nb::test::regressionCaseInShare())                                                    \
            QSKIP("one case in NB_CASE_SHARE runs here; scripts/test-all-cases.sh runs them all"); \
    } while (false)
