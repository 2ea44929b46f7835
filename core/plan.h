#pragma once
// An experiment plan: the runs of a design generated from factors and their levels, in an
// order (as listed, randomised with a recorded seed, or blocked by site), each with the
// operator's instruction and its status. Stored as plan.json in the session, a file a person
// can read and write:
//
//   {
//     "format": "needlebench-plan", "version": 1,
//     "name": "friction under imaging", "template": "friction-imaging",
//     "order": "listed", "seed": 1,
//     "defaults": {"protocol": "friction", "motion": "sine", "tissue": "liver7", "tip": "diamond",
//                  "amplitude_mm": 10, "cycles": 7, "video": true},
//     "factors": [{"name": "site", "levels": [1, 2, 3, 4, 5]},
//                 {"name": "frequency_hz", "levels": [0.2, 0.5, 0.8]}],
//     "runs": [{"number": 1, "factors": {"site": 1, "frequency_hz": 0.2}, "settings": {"seed": 1001},
//               "instruction": "Mount liver7. Fit the diamond tip. Move the slab to site 1.",
//               "status": "done", "attempts": [{"run_file": "run_001_sine.csv", "result": "completed", ...}]},
//              ...]
//   }
//
// A run's settings are the defaults, overlaid by its factor levels, overlaid by its own
// "settings" (e.g. "stop_at": "puncture", "slow_after_puncture_mm_s": 1, "seed"). Status:
// pending, running (an attempt started and has not ended: after a crash it is taken as
// interrupted), done, skipped (with "reason"), redone (done, after an earlier attempt that
// was interrupted, failed or discarded by the operator). The attempt that counts is the last.

#include "core/run.h"

#include <QDateTime>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <optional>
#include <stdexcept>
#include <vector>

namespace nb {

// A plan file that cannot be read or written, or a plan that is not valid: names the file
// (may be empty for a plan in memory), the field (e.g. "runs[3].factors.frequency_hz") and
// what is wrong.
class PlanError : public std::runtime_error {
public:
    PlanError(QString file, QString field, QString reason);
    const QString& file() const { return file_; }
    const QString& field() const { return field_; }
    const QString& reason() const { return reason_; }
    QString message() const;

private:
    QString file_, field_, reason_;
};

enum class PlanOrder { Listed, Random, Blocked };
enum class PlanRunStatus { Pending, Running, Done, Skipped, Redone };

QString planOrderName(PlanOrder order);
std::optional<PlanOrder> planOrderFromName(const QString& name);
QString planRunStatusName(PlanRunStatus status);
std::optional<PlanRunStatus> planRunStatusFromName(const QString& name);

struct PlanFactor {
    QString name;
    std::vector<QJsonValue> levels;  // numbers or strings
    // The level is changed by the operator's hands (site, tip, tissue, slab), so a change
    // gets an instruction. Known settings decide themselves; declared for custom factors.
    bool operatorSet = false;
};

struct PlanAttempt {
    QString runFile;    // relative to the session folder
    QString videoFile;  // relative; empty without video
    QString result;     // the run's end reason (completed, force_limit, fault, ...), "interrupted", or "" while running
    QString discarded;  // why the operator discarded it (redo); empty when not
    QDateTime started, ended;
};

struct PlannedRun {
    int number = 0;              // 1-based, in run order
    QJsonObject factors;         // the factor levels of this run
    QJsonObject settings;        // per-run settings over the defaults (seed, stop_at, ...)
    QString instruction;         // for the operator before this run; empty when nothing to do by hand
    PlanRunStatus status = PlanRunStatus::Pending;
    QString reason;              // why skipped
    std::vector<PlanAttempt> attempts;

    bool completed() const;      // done, redone or skipped: the plan moves past it
    // The attempt that counts (done/redone), or nullptr.
    const PlanAttempt* currentAttempt() const;
};

struct Plan {
    QString name;
    QString templateName;
    QString description;
    PlanOrder order = PlanOrder::Listed;
    quint64 seed = 1;
    QJsonObject defaults;
    std::vector<PlanFactor> factors;
    std::vector<PlannedRun> runs;

    // Defaults, then the run's factor levels, then its own settings.
    QJsonObject settingsFor(const PlannedRun& run) const;
    // Index of the first run not completed; -1 when all are.
    int firstIncomplete() const;
    int countWith(PlanRunStatus status) const;
    // True when both describe the same runs with the same settings (statuses aside).
    bool sameDesign(const Plan& other) const;
};

// The settings a plan knows (others must be declared as factors). Their values are checked.
const QStringList& knownPlanSettings();
// Known settings whose change needs the operator's hands.
bool isOperatorSetting(const QString& key);
// Checks one setting's value; returns an error text (empty when fine).
QString checkPlanSetting(const QString& key, const QJsonValue& value);

// A template: defaults and factors; expanding it gives the runs.
struct PlanTemplate {
    QString name;         // e.g. "friction-imaging"
    QString title;        // e.g. "friction under imaging"
    QString description;  // one line, from the thesis's protocol
    QJsonObject defaults;
    std::vector<PlanFactor> factors;
};

// The thesis's protocols (models.md 9).
const std::vector<PlanTemplate>& planTemplates();
const PlanTemplate* findPlanTemplate(const QString& name);

// Full factorial over the factors, the first factor varying slowest ("listed"); "random"
// shuffles all runs with `seed`; "blocked" keeps each site's runs together (sites as listed)
// and shuffles within a site with `seed`. Each run gets the seed `seed * 1000 + number` for the
// simulated rig and its instruction. Throws PlanError (e.g. "blocked" without a site factor).
Plan generatePlan(const PlanTemplate& design, PlanOrder order, quint64 seed);

// What the operator must do by hand before `next` after `previous` (nullptr: the first run).
QString operatorInstruction(const Plan& plan, const PlannedRun* previous, const PlannedRun& next);
// Sets every run's instruction from the run before it.
void refreshInstructions(Plan& plan);

// A level as text: 0.5, "diamond".
QString levelText(const QJsonValue& value);
// One line naming a run by its factors: "friction 0.5 Hz site 3".
QString describeRun(const Plan& plan, const PlannedRun& run);

// Status changes. `index` into plan.runs.
// A run left "running" by a crash: its last attempt becomes "interrupted", the run pending.
// Returns the numbers of the runs so recovered.
std::vector<int> recoverInterruptedRuns(Plan& plan);
void beginAttempt(Plan& plan, int index, const QString& runFile, const QString& videoFile, const QDateTime& now);
// `endReason` as the engine reports it; completed, force_limit and a stop at puncture count
// as done, others (fault, stopped, interrupted) leave the run pending.
void finishAttempt(Plan& plan, int index, const QString& endReason, const QDateTime& now);
bool isCompletingEndReason(const QString& endReason);
void skipRun(Plan& plan, int index, const QString& reason);
// Discards the counted attempt (with `reason`) so the run is done again.
void redoRun(Plan& plan, int index, const QString& reason);

// The run file's metadata for a plan run: `factor_<name>: level` for each of its factors (so
// every export carries them), plan_name, plan_template, plan_file, plan_run, plan_runs,
// plan_attempt (the attempt's number, 1 for the first) and plan_order.
Metadata planRunMetadata(const Plan& plan, const PlannedRun& run, const QString& planFile);

// `proposedPath` (a session's next run file, run_NNN_motion.csv) renumbered past every run
// file an attempt of the plan names: an attempt killed before its file existed must not
// share its name with the next one.
QString unusedRunPath(const Plan& plan, const QString& proposedPath);

// How long a run moves, from its settings: depth / velocity for a linear insertion, cycles /
// frequency for a sine (the simulate command's defaults where a setting is absent). Operator
// time between runs is not included.
double expectedRunDuration_s(const QJsonObject& settings);
// The sum over the runs not completed.
double remainingPlanDuration_s(const Plan& plan);

QJsonObject planToJson(const Plan& plan);
// The file's text: planToJson with keys in a reading order and short parts on one line.
QByteArray planJsonText(const Plan& plan);
// Throws PlanError naming `fileForMessages` and the field.
Plan planFromJson(const QJsonObject& object, const QString& fileForMessages);
Plan readPlanFile(const QString& path);
// Atomic (temporary file, then rename). Throws PlanError.
void writePlanFile(const QString& path, const Plan& plan);

}  // namespace nb
