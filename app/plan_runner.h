#pragma once
// Executes one run of an experiment plan: the ONE place where `plan run` reaches the
// acquisition path. The simulated rig runs through simulateRun (as `simulate`), with the plan's
// metadata and stop_at / slow_after_puncture_mm_s passed in; real devices through the `acquire`
// command in-process, the plan's metadata then written into the run file's header.

#include "commands.h"
#include "core/run.h"
#include "devices/acquisition_engine.h"
#include "devices/device_spec.h"
#include "devices/run_once.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <functional>

namespace nb::cli {

struct PlannedRunRequest {
    QJsonObject settings;  // the run's effective settings (Plan::settingsFor)
    QString runFile;       // absolute paths
    QString videoFile;     // empty: no video
    QString truthFile;     // empty: none (the simulated rig only)
    Metadata metadata;     // factor_<name>, plan_* lines for the run file's header
    QString daq, stage;    // device specs; both empty or "sim": the simulated rig
    // A signal during a simulated run (the `acquire` command watches its own): the run stops
    // and is closed as "interrupted".
    std::function<devices::RunOnceOptions::Interruption()> interruption;
};

struct PlannedRunOutcome {
    bool ok = false;         // a run file was written and closed
    QString endReason;       // completed, force_limit, fault, ... (empty when no run)
    QString error;           // what went wrong, for the operator
    double videoOffset_s = 0.0;
};

PlannedRunOutcome runPlannedRun(const PlannedRunRequest& request);

// The motion of a run from its settings, with the simulate command's defaults for what they
// leave out (velocity 4 mm/s, 2.5 for the internal protocol; depth 40 mm; sine 10 mm, 0.5 Hz,
// 7 cycles), and its stop at puncture / slow-down. No path, no metadata. The window's plan
// walker sets the control panel from it; `plan run` on the simulated rig moves by it.
devices::RunPlan runPlanForSettings(const QJsonObject& settings);

// The simulated rig a run's settings ask for, as `plan run` makes it: tissue (by protocol when
// absent), tip (the preset's usual one when absent), seed, and the friction platform for the
// friction protocol, the whole organ otherwise. `base` gives what the settings do not.
devices::SimulatedRigSpec simulatedRigForSettings(const QJsonObject& settings, devices::SimulatedRigSpec base);

// The `simulate` / `acquire` arguments for a run's settings (exposed for tests and --help).
QStringList plannedRunArguments(const PlannedRunRequest& request, bool simulated);

// Inserts `# key: value` lines before the run file's column header (atomically). Returns an
// error text, empty on success.
QString addRunFileMetadata(const QString& path, const Metadata& metadata);

}  // namespace nb::cli
