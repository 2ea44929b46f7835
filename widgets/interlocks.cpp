#include "interlocks.h"
#include "core/tr.h"

#include <QCoreApplication>

namespace nb {

namespace {

Permission allow() { return {true, {}}; }
Permission deny(const QString& reason) { return {false, reason}; }

}  // namespace

Permission permission(Control control, const InterlockState& s)
{
    if (control == Control::EmergencyStop)
        return allow();  // always, whatever else is wrong
    if (control == Control::StopMotion)
        return s.moving ? allow() : deny(nb::TrViews::tr("The stage is not moving."));

    // The fault first: it is the cause when the devices have stopped as well.
    if (!s.fault.isEmpty() && control != Control::EndRun && control != Control::ForceLimit)
        return deny(nb::TrViews::tr("Device fault: %1").arg(s.fault));
    if (!s.devicesRunning)
        return deny(nb::TrViews::tr("The devices are not running."));

    switch (control) {
    case Control::Enable:
        if (s.moving)
            return deny(nb::TrViews::tr("Stop the motion first."));
        if (s.recording && s.stageEnabled)
            return deny(nb::TrViews::tr("End the run first: disabling the drive would end the experiment unrecorded."));
        return allow();
    case Control::Bias:
        if (s.moving)
            return deny(nb::TrViews::tr("Bias needs the stage at rest."));
        if (s.recording)
            return deny(nb::TrViews::tr("Biasing during a run would shift its forces; end the run first."));
        return allow();
    case Control::Zero:
        if (!s.stageEnabled)
            return deny(nb::TrViews::tr("Enable the stage first."));
        if (s.moving)
            return deny(nb::TrViews::tr("Zeroing needs the stage at rest."));
        if (s.recording)
            return deny(nb::TrViews::tr("Zeroing during a run would shift its positions; end the run first."));
        return allow();
    case Control::MotionSettings:
        if (s.recording || s.moving)
            return deny(nb::TrViews::tr("The motion of a run is fixed while it records or moves."));
        return allow();
    case Control::StartInsertion:
        if (!s.sessionOpen)
            return deny(nb::TrViews::tr("Open or create a session first: the run needs a folder."));
        if (!s.stageEnabled)
            return deny(nb::TrViews::tr("Enable the stage first."));
        if (!s.biased)
            return deny(nb::TrViews::tr("Bias the force sensor first (needle free of tissue)."));
        if (!s.zeroed)
            return deny(nb::TrViews::tr("Zero the stage position first."));
        if (!s.calibrated)
            return deny(nb::TrViews::tr("No active calibration: calibrate the sensor or choose a calibration."));
        if (s.forceLimit_N <= 0.0)
            return deny(nb::TrViews::tr("Set a maximum-force limit first."));
        if (s.recording)
            return deny(nb::TrViews::tr("A run is already recording: end it first."));
        if (s.moving)
            return deny(nb::TrViews::tr("The stage is moving."));
        if (!s.motionProblem.isEmpty())
            return deny(s.motionProblem);
        return allow();
    case Control::Withdraw:
        if (!s.stageEnabled)
            return deny(nb::TrViews::tr("Enable the stage first."));
        if (!s.zeroed)
            return deny(nb::TrViews::tr("Zero the stage position first."));
        if (s.moving)
            return deny(nb::TrViews::tr("Stop the motion first."));
        return allow();
    case Control::EndRun:
        if (!s.recording)
            return deny(nb::TrViews::tr("No run is recording."));
        if (s.moving)
            return deny(nb::TrViews::tr("Stop the motion first: End run closes the file, it does not stop the stage."));
        return allow();
    case Control::ForceLimit:
        return allow();
    case Control::Calibrate:
        if (s.recording)
            return deny(nb::TrViews::tr("Calibration changes the forces of a run; end the run first."));
        if (s.moving)
            return deny(nb::TrViews::tr("The stage is moving."));
        return allow();
    case Control::StopMotion:
    case Control::EmergencyStop:
        break;
    }
    return allow();
}

}  // namespace nb
