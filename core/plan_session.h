#pragma once
// A plan kept in its session folder as plan.json, and how it resumes after the program died
// mid-run: `plan run` and the window's plan walker open it the same way.

#include "core/plan.h"

#include <QString>
#include <utility>
#include <vector>

namespace nb {

// The file name of a session's plan (relative to the session folder, as plan_file says).
QString planFileName();
QString planFilePath(const QString& sessionDir);

struct PlanResumption {
    // Runs whose attempt had ended and been written before the program died, though plan.json
    // still said "running": kept as done. Number and run file.
    std::vector<std::pair<int, QString>> endedBefore;
    // Runs left "running" whose attempt died with the program: now interrupted, run pending.
    std::vector<int> interrupted;
};

// Settles every run left "running" in `plan` (whose run files lie in `sessionDir`): an attempt
// whose run file names this run and attempt and ended by itself counts; any other becomes
// interrupted and its run runs again. Recover the session's cut-off run files first
// (Session::recoverInterrupted), so that their end reason is known.
PlanResumption resumePlan(Plan& plan, const QString& sessionDir);

}  // namespace nb

namespace nb {

// Time left in a plan, for the operator: the runs not completed times the time one run took
// from start to start in this plan so far (the median, so the operator's own steps count and a
// restart does not), or the motion time alone (remainingPlanDuration_s) before two runs.
double estimatedPlanTimeLeft_s(const Plan& plan);

}  // namespace nb
