#include "run_plausibility.h"

#include "core/tr.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace nb {

namespace {

QString beyondAnyLoadCell(const Run& run, const QString& name)
{
    std::size_t beyond = 0, first = 0;
    for (std::size_t i = 0; i < run.force_N.size(); ++i)
        if (std::abs(run.force_N[i]) > kNoLoadCellReads_N && beyond++ == 0)
            first = i;
    if (beyond == 0)
        return {};
    return nb::TrCore::tr("%1: force_N of %2 N at %3 s is beyond what any needle load cell reads (10 kN): a corrupt sample? "
                          "(%n such sample(s))",
                          nullptr, int(std::min<std::size_t>(beyond, INT_MAX)))
        .arg(name)
        .arg(run.force_N[first], 0, 'g', 4)
        .arg(run.time_s[first], 0, 'f', 3);
}

// An amplifier or converter at its rail gives one number again and again. A smooth force gives
// one at its peak for a moment too, but not while the needle travels half a millimetre on.
constexpr double kClippedTravel_mm = 0.5;
constexpr double kClippedHold_s = 0.1;

QString clipped(const Run& run, const QString& name)
{
    const std::size_t n = std::min({run.time_s.size(), run.force_N.size(), run.position_mm.size()});
    if (n < 20)
        return {};
    const auto [lo, hi] = std::minmax_element(run.force_N.begin(), run.force_N.begin() + std::ptrdiff_t(n));
    if (*hi == *lo)
        return {};
    for (const double rail : {*hi, *lo}) {
        if (!std::isfinite(rail) || rail == 0.0)
            continue;
        for (std::size_t i = 0; i < n;) {
            if (run.force_N[i] != rail) {
                ++i;
                continue;
            }
            std::size_t j = i;
            double pMin = run.position_mm[i], pMax = run.position_mm[i];
            while (j + 1 < n && run.force_N[j + 1] == rail) {
                ++j;
                pMin = std::min(pMin, run.position_mm[j]);
                pMax = std::max(pMax, run.position_mm[j]);
            }
            if (run.time_s[j] - run.time_s[i] >= kClippedHold_s && pMax - pMin >= kClippedTravel_mm)
                return nb::TrCore::tr("%1: force_N stays at %2 N from %3 s to %4 s while the needle moves %5 mm: the sensor or its "
                                      "amplifier saturated there, and the force beyond it is not in the file")
                    .arg(name)
                    .arg(rail, 0, 'g', 6)
                    .arg(run.time_s[i], 0, 'f', 3)
                    .arg(run.time_s[j], 0, 'f', 3)
                    .arg(pMax - pMin, 0, 'f', 1);
            i = j + 1;
        }
    }
    return {};
}

// Positions written in metres (0.03 for 30 mm) span a few hundredths of a "millimetre".
constexpr double kLeastTravel_mm = 0.25;

QString metres(const Run& run, const QString& name)
{
    if (run.position_mm.size() < 100)
        return {};
    const auto [lo, hi] = std::minmax_element(run.position_mm.begin(), run.position_mm.end());
    const double span = *hi - *lo;
    if (!(span >= 0.002 && span < kLeastTravel_mm))
        return {};
    return nb::TrCore::tr("%1: position_mm spans only %2 mm: if the positions were written in metres, they are 1000 times too small "
                          "(position_mm is in millimetres)")
        .arg(name)
        .arg(span, 0, 'g', 3);
}

}  // namespace

QStringList implausibleRun(const Run& run, const QString& name)
{
    QStringList said;
    for (const QString& s : {beyondAnyLoadCell(run, name), clipped(run, name), metres(run, name)})
        if (!s.isEmpty())
            said << s;
    return said;
}

}  // namespace nb
