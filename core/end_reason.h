#pragma once
// Why a recording ended: the footer's `end_reason`, the run list's state and every export
// speak of the same few reasons, so they are one type with one spelling in files.

#include <QString>
#include <optional>

namespace nb {

enum class EndReason {
    Completed,      // the motion ran to its end
    Stopped,        // the operator ended the run (End run, Stop then End)
    MotionStopped,  // the stage stopped by itself before the motion's end (limit switch, stall)
    EmergencyStop,  // the operator's emergency stop
    ForceLimit,     // the force limit stopped the stage
    Puncture,       // stopped at a detected puncture, as the run asked
    Fault,          // a device failed
    WriteError,     // the run file could not be written (disk full, removed media)
    Interrupted,    // the program was told to end (SIGTERM, SIGINT, SIGHUP)
    Aborted,        // the recorder was destroyed with the file open
    Recovered,      // found without a footer and closed when the session was opened again
};

// The file spelling: "completed", "force_limit", ...
QString fileName(EndReason reason);
// nullopt for an unknown spelling (a newer program's file, or a hand-edited one).
std::optional<EndReason> endReasonFromFileName(const QString& name);
// For people, translated: "completed", "emergency stop", ...
QString displayName(EndReason reason);
// Whether the run's data can be analysed as a whole insertion (nothing cut it short).
bool endedNormally(EndReason reason);

}  // namespace nb
