#pragma once
// One run on the simulated rig, the way `simulate` makes it: the rig from a request, the
// operator's sequence through the real engine and recorder, the ground truth on the run's time
// axis, and the rendered imaging video. `simulate`, `demo` and `plan run` call this function;
// none of them drives another through argv.

#include "core/run.h"
#include "devices/run_once.h"
#include "devices/sim/rig_config.h"

#include <QJsonObject>
#include <QString>
#include <optional>

namespace nb::cli {

struct SimulatedRunRequest {
    QString protocol;                 // stiffness | internal | friction | prostate
    devices::sim::RigConfig rig;
    double rateHz = 500.0;
    double velocity_mm_s = 4.0;
    double depth_mm = 40.0;
    devices::SineMotion sine;
    double maxForce_N = 8.0;
    QString out, truth;               // the run file; the truth JSON (optional)
    // The rendered imaging view (optional): started this long before the recording.
    QString video;
    double videoOffset_s = 0.0;
    int videoWidth = 720, videoHeight = 480;
    unsigned videoSeed = 1;
    // Linear insertions: stop after N punctures (0: never); slow to V after the first (0: no).
    int stopAtPuncture = 0;
    double slowAfterPuncture_mm_s = 0.0;
    Metadata extraMetadata;           // e.g. a plan's factor levels, written with the run
};

struct SimulatedRunResult {
    std::optional<devices::RunSummary> summary;  // empty when nothing was recorded
    QString error;            // what failed (no run, or truth/video after it), for the user
    QJsonObject truth;        // on the run's time axis, with `video` when one was rendered
    QJsonObject json;         // what `simulate` prints
    int videoFrames = 0;
    double videoOffset_s = 0.0;  // true offset of the rendered video (video time - run time)
};

// The run's metadata from the request (protocol, tissue, tip, seed, motion, clock).
Metadata simulatedRunMetadata(const SimulatedRunRequest& request);

SimulatedRunResult simulateRun(const SimulatedRunRequest& request, const devices::RunOnceOptions& options = {});

}  // namespace nb::cli
