#include "end_reason.h"

#include "core/tr.h"

#include <array>
#include <utility>

namespace nb {

namespace {
constexpr std::array<std::pair<EndReason, const char*>, 11> kNames{{
    {EndReason::Completed, "completed"},
    {EndReason::Stopped, "stopped"},
    {EndReason::MotionStopped, "motion_stopped"},
    {EndReason::EmergencyStop, "emergency_stop"},
    {EndReason::ForceLimit, "force_limit"},
    {EndReason::Puncture, "puncture"},
    {EndReason::Fault, "fault"},
    {EndReason::WriteError, "write_error"},
    {EndReason::Interrupted, "interrupted"},
    {EndReason::Aborted, "aborted"},
    {EndReason::Recovered, "recovered"},
}};
}  // namespace

QString fileName(EndReason reason)
{
    for (const auto& [r, name] : kNames)
        if (r == reason)
            return QString::fromLatin1(name);
    return {};
}

std::optional<EndReason> endReasonFromFileName(const QString& name)
{
    for (const auto& [r, n] : kNames)
        if (name == QLatin1String(n))
            return r;
    return std::nullopt;
}

QString displayName(EndReason reason)
{
    switch (reason) {
    case EndReason::Completed: return nb::TrCore::tr("completed");
    case EndReason::Stopped: return nb::TrCore::tr("ended by operator");
    case EndReason::MotionStopped: return nb::TrCore::tr("motion stopped");
    case EndReason::EmergencyStop: return nb::TrCore::tr("emergency stop");
    case EndReason::ForceLimit: return nb::TrCore::tr("force limit");
    case EndReason::Puncture: return nb::TrCore::tr("stopped at puncture");
    case EndReason::Fault: return nb::TrCore::tr("device fault");
    case EndReason::WriteError: return nb::TrCore::tr("write error");
    case EndReason::Interrupted: return nb::TrCore::tr("interrupted");
    case EndReason::Aborted: return nb::TrCore::tr("aborted");
    case EndReason::Recovered: return nb::TrCore::tr("recovered");
    }
    return {};
}

bool endedNormally(EndReason reason)
{
    return reason == EndReason::Completed || reason == EndReason::Stopped || reason == EndReason::Puncture;
}

}  // namespace nb
