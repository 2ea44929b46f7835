#include "run_judgement.h"

#include "core/end_reason.h"
#include "core/run_keys.h"
#include "core/statistics.h"
#include "core/tr.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

double percentile(std::vector<double> v, double p)
{
    std::sort(v.begin(), v.end());
    const std::size_t i = std::min(v.size() - 1, std::size_t(std::lround(p * double(v.size() - 1))));
    return v[i];
}

}  // namespace

bool touchedTissue(const Run& run)
{
    std::vector<double> f;
    f.reserve(run.force_N.size());
    for (double v : run.force_N)
        if (std::isfinite(v))
            f.push_back(v);
    if (f.size() < 10)
        return false;
    std::vector<double> diff;
    diff.reserve(f.size() - 1);
    for (std::size_t i = 1; i < f.size(); ++i)
        diff.push_back(std::abs(f[i] - f[i - 1]));
    // Differences of white noise have sqrt(2) its sigma.
    const double noise = 1.4826 * median(std::move(diff)) / std::sqrt(2.0);
    const double span = percentile(f, 0.99) - percentile(f, 0.01);
    return span > std::max(kMinContact_N, 8.0 * noise);
}

RunJudgement judgeRun(const Run& run)
{
    const std::optional<QString> raw = run.meta(key::end_reason);
    if (!raw)
        return {false, nb::TrCore::tr("no end reason: the recording was cut off")};
    const std::optional<EndReason> reason = endReasonFromFileName(raw->trimmed());
    if (!reason)
        return {false, nb::TrCore::tr("unknown end reason '%1'").arg(*raw)};
    switch (*reason) {
    case EndReason::ForceLimit:
    case EndReason::EmergencyStop:
    case EndReason::Fault:
    case EndReason::WriteError:
    case EndReason::Interrupted:
    case EndReason::Aborted:
    case EndReason::Recovered:
        // "ended early (recovered)": it read "ended by recovered", "ended by interrupted".
        return {false, nb::TrCore::tr("ended early (%1)").arg(displayName(*reason))};
    default:
        break;
    }
    if (!touchedTissue(run))
        return {false, nb::TrCore::tr("no tissue contact (the force never rose above its noise)")};
    return {};
}

QStringList robustOutlierReasons(const std::vector<double>& values, const QString& quantity, const QString& unit, double k,
                                 double relativeFloor, std::size_t minValues)
{
    QStringList reasons;
    for (std::size_t i = 0; i < values.size(); ++i)
        reasons << QString();
    if (values.size() < minValues)
        return reasons;
    const double m = median(values);
    std::vector<double> dev;
    for (double v : values)
        dev.push_back(std::abs(v - m));
    const double mad = 1.4826 * median(dev);
    const double limit = std::max(k * mad, relativeFloor * std::abs(m));
    for (std::size_t i = 0; i < values.size(); ++i)
        if (std::abs(values[i] - m) > limit)
            reasons[qsizetype(i)] = nb::TrCore::tr("%1 %2 %3 is %4 %3 from the median %5 %3 (limit %6 %3: %7 MADs or %8 %)")
                                        .arg(quantity)
                                        .arg(values[i], 0, 'g', 4)
                                        .arg(unit)
                                        .arg(std::abs(values[i] - m), 0, 'g', 3)
                                        .arg(m, 0, 'g', 4)
                                        .arg(limit, 0, 'g', 3)
                                        .arg(k)
                                        .arg(relativeFloor * 100.0);
    return reasons;
}

}  // namespace nb
