#include "plan_session.h"
#include "core/run_file.h"

#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace nb {

QString planFileName() { return QStringLiteral("plan.json"); }

QString planFilePath(const QString& sessionDir) { return QDir(sessionDir).filePath(planFileName()); }

PlanResumption resumePlan(Plan& plan, const QString& sessionDir)
{
    PlanResumption out;
    // Killed after its run had ended and been tagged, before plan.json said so: keep it.
    for (std::size_t i = 0; i < plan.runs.size(); ++i) {
        const PlannedRun& r = plan.runs[i];
        if (r.status != PlanRunStatus::Running || r.attempts.empty())
            continue;
        const QString file = QDir(sessionDir).filePath(r.attempts.back().runFile);
        try {
            const Run run = readRunFile(file).run;
            const QString end = run.meta(QStringLiteral("end_reason")).value_or(QString());
            // Its video too, when it has one: killed while that was rendered, it is done again.
            const QString video = r.attempts.back().videoFile;
            if (run.meta(QStringLiteral("plan_run")) == QString::number(r.number) &&
                run.meta(QStringLiteral("plan_attempt")) == QString::number(r.attempts.size()) && isCompletingEndReason(end) &&
                (video.isEmpty() || QFileInfo::exists(QDir(sessionDir).filePath(video)))) {
                finishAttempt(plan, int(i), end, QFileInfo(file).lastModified().toUTC());
                out.endedBefore.emplace_back(r.number, r.attempts.back().runFile);
            }
        } catch (const RunFileError&) {
            // Absent or cut off: the run is done again.
        }
    }
    out.interrupted = recoverInterruptedRuns(plan);
    return out;
}

}  // namespace nb

namespace nb {

double estimatedPlanTimeLeft_s(const Plan& plan)
{
    // Starts of the attempts made, in time order; gaps over an hour are breaks, not pace.
    std::vector<QDateTime> starts;
    for (const PlannedRun& r : plan.runs)
        for (const PlanAttempt& a : r.attempts)
            if (a.started.isValid())
                starts.push_back(a.started);
    std::sort(starts.begin(), starts.end());
    std::vector<double> gaps;
    for (std::size_t i = 1; i < starts.size(); ++i) {
        const double gap_s = starts[i - 1].msecsTo(starts[i]) / 1000.0;
        if (gap_s > 0.0 && gap_s < 3600.0)
            gaps.push_back(gap_s);
    }
    const double motion_s = remainingPlanDuration_s(plan);
    if (gaps.empty())
        return motion_s;
    // The median gap: a crash and its restart, or a short break, is one long gap and not the
    // pace (the mean went from 7 to 54 min left over two runs of 30 s).
    std::sort(gaps.begin(), gaps.end());
    const std::size_t n = gaps.size();
    const double pace_s = n % 2 ? gaps[n / 2] : 0.5 * (gaps[n / 2 - 1] + gaps[n / 2]);
    const int left = int(std::count_if(plan.runs.begin(), plan.runs.end(), [](const PlannedRun& r) { return !r.completed(); }));
    return std::max(motion_s, left * pace_s);
}

}  // namespace nb
