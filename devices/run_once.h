#pragma once
// The operator's sequence for one headless run: enable, bias (needle at rest, out of tissue),
// zero, start the moment the interlocks are met, wait for the end. `simulate`, `acquire`,
// `plan run` and the engine tests all run it, so they all run the same sequence.

#include "devices/acquisition_engine.h"

#include <QString>
#include <functional>
#include <optional>

namespace nb::devices {

struct RunOnceOptions {
    // Called about every 20 ms (real time) or 5 ms (a self-paced clock) with the engine's status.
    std::function<void(const EngineStatus&)> onTick;
    std::function<void(const QString& path)> onStarted;
    int readyTimeout_ms = 10000;         // for the devices to become ready (real clocks)
    int runTimeout_ms = 30 * 60 * 1000;  // then the run is ended
    // Asked on every tick: how often the program was told to end (signals) and what the
    // footer should say about it. The first request ends the run as `interrupted`; a second
    // one, or one before the run started, gives up waiting at once.
    struct Interruption {
        int count = 0;
        Metadata footer;
    };
    std::function<Interruption()> interruption;
};

struct RunOnceResult {
    std::optional<RunSummary> summary;  // empty when no run was recorded
    QString error;                      // why not (refused, a fault before the start, a time-out)
    EngineStatus last;                  // the engine's status at the end
};

// `engine` must not be started yet: the sequence is queued before its first sample, so that on
// a simulated clock every invocation starts at the same simulated time. Shuts the engine down.
RunOnceResult runOnce(AcquisitionEngine& engine, const RunPlan& plan, const RunOnceOptions& options = {});

}  // namespace nb::devices
