#include "interlocks.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>

namespace nb {

namespace {

Permission allow() { return {true, {}}; }
Permission deny(const QString& reason) { return {false, reason, false}; }
Permission insistable(const QString& reason) { return {false, reason, true}; }

// While a run records or the stage moves the rig is in one mode; changing what it runs on
// would mix two.
Permission oneMode(const InterlockState& s, const QString& what)
{
    if (s.recording)
        return deny(nb::TrDevices::tr("A run is recording: end it before %1.").arg(what));
    if (s.moving)
        return deny(nb::TrDevices::tr("The stage is moving: stop it before %1.").arg(what));
    return allow();
}

}  // namespace

Permission permission(Control control, const InterlockState& s)
{
    if (control == Control::EmergencyStop)
        return allow();  // always, whatever else is wrong
    if (control == Control::StopMotion)
        return s.moving ? allow() : deny(nb::TrDevices::tr("The stage is not moving."));
    if (control == Control::ChangeSetup)
        return oneMode(s, nb::TrDevices::tr("changing the session, devices or language"));
    if (control == Control::Quit)
        return oneMode(s, nb::TrDevices::tr("quitting"));

    // The fault first: it is the cause when the devices have stopped as well.
    if (!s.fault.isEmpty() && control != Control::EndRun && control != Control::ForceLimit)
        return deny(nb::TrDevices::tr("Device fault: %1").arg(s.fault));
    if (!s.devicesRunning)
        return deny(nb::TrDevices::tr("The devices are not running."));

    switch (control) {
    case Control::Enable:
        if (s.latched)
            return allow();  // re-enabling on purpose is what releases the latch
        if (s.moving)
            return deny(nb::TrDevices::tr("Stop the motion first."));
        if (s.recording && s.stageEnabled)
            return deny(nb::TrDevices::tr("End the run first: disabling the drive would end the experiment unrecorded."));
        return allow();
    case Control::Bias:
        if (s.moving)
            return deny(nb::TrDevices::tr("Bias needs the stage at rest."));
        if (s.recording)
            return deny(nb::TrDevices::tr("Biasing during a run would shift its forces; end the run first."));
        if (s.loaded)
            return insistable(nb::TrDevices::tr("The force is above the noise band: bias with the needle free of tissue."));
        if (s.inTissue)
            return insistable(nb::TrDevices::tr("The needle is past the depth where it met tissue: withdraw it before biasing."));
        return allow();
    case Control::Zero:
        if (!s.stageEnabled)
            return deny(nb::TrDevices::tr("Enable the stage first."));
        if (s.moving)
            return deny(nb::TrDevices::tr("Zeroing needs the stage at rest."));
        if (s.recording)
            return deny(nb::TrDevices::tr("Zeroing during a run would shift its positions; end the run first."));
        if (s.inTissue)
            return insistable(nb::TrDevices::tr("The needle is past the depth where it met tissue: zero with the tip at the start position."));
        if (s.loaded)
            return insistable(nb::TrDevices::tr("The force is above the noise band: zero with the needle free of tissue."));
        return allow();
    case Control::MotionSettings:
        if (s.recording || s.moving)
            return deny(nb::TrDevices::tr("The motion of a run is fixed while it records or moves."));
        return allow();
    case Control::StartInsertion:
        if (s.latched)
            return deny(nb::TrDevices::tr("Emergency stop: enable the stage again to reset it."));
        if (!s.sessionOpen)
            return deny(nb::TrDevices::tr("Open or create a session first: the run needs a folder."));
        if (!s.stageEnabled)
            return deny(nb::TrDevices::tr("Enable the stage first."));
        if (!s.biased)
            return deny(nb::TrDevices::tr("Bias the force sensor first (needle free of tissue)."));
        if (!s.zeroed)
            return deny(nb::TrDevices::tr("Zero the stage position first."));
        if (!s.calibrated)
            return deny(nb::TrDevices::tr("No active calibration: calibrate the sensor or choose a calibration."));
        // The wizard's masses on the sensor would be recorded as the run's force, and a
        // calibration saved mid-run would apply to part of it.
        if (s.calibrating)
            return deny(nb::TrDevices::tr("The calibration wizard is open: finish or close it before a run."));
        if (s.forceLimit_N <= 0.0)
            return deny(nb::TrDevices::tr("Set a maximum-force limit first."));
        if (s.recording)
            return deny(nb::TrDevices::tr("A run is already recording: end it first."));
        // After the limit tripped the needle is still in the tissue, loaded: a run started there
        // stops at once and leaves a run of a few samples.
        if (std::abs(s.force_N) >= kStartForceFraction * s.forceLimit_N)
            return deny(nb::TrDevices::tr("The force is %1 N, near the %2 N limit: withdraw the needle first.")
                            .arg(QLocale().toString(s.force_N, 'f', 2), QLocale().toString(s.forceLimit_N, 'f', 2)));
        if (s.moving)
            return deny(nb::TrDevices::tr("The stage is moving."));
        if (!s.motionProblem.isEmpty())
            return deny(s.motionProblem);
        if (!s.planHold.isEmpty())
            return deny(s.planHold);
        return allow();
    case Control::Withdraw:
        if (s.latched)
            return deny(nb::TrDevices::tr("Emergency stop: enable the stage again to reset it."));
        if (!s.stageEnabled)
            return deny(nb::TrDevices::tr("Enable the stage first."));
        // Out towards the last zero needs no fresh one: a withdrawal never goes deeper than
        // where the needle is, and after an emergency stop the needle must come out.
        if (!s.zeroed && !s.startKnown)
            return deny(nb::TrDevices::tr("Zero the stage position first."));
        if (s.moving)
            return deny(nb::TrDevices::tr("Stop the motion first."));
        return allow();
    case Control::Jog:
        if (s.latched)
            return deny(nb::TrDevices::tr("Emergency stop: enable the stage again to reset it."));
        if (!s.stageEnabled)
            return deny(nb::TrDevices::tr("Enable the stage first."));
        if (s.recording)
            return deny(nb::TrDevices::tr("Jogging is never recorded: end the run first."));
        if (s.moving)
            return deny(nb::TrDevices::tr("Stop the motion first."));
        return allow();
    case Control::EndRun:
        if (!s.recording)
            return deny(nb::TrDevices::tr("No run is recording."));
        if (s.moving)
            return deny(nb::TrDevices::tr("Stop the motion first: End run closes the file, it does not stop the stage."));
        return allow();
    case Control::ForceLimit:
        return allow();
    case Control::Calibrate:
        if (s.recording)
            return deny(nb::TrDevices::tr("Calibration changes the forces of a run; end the run first."));
        if (s.moving)
            return deny(nb::TrDevices::tr("The stage is moving."));
        return allow();
    case Control::StopMotion:
    case Control::EmergencyStop:
    case Control::ChangeSetup:
    case Control::Quit:
        break;
    }
    return allow();
}

bool escapeStops(const InterlockState& s) { return s.moving || s.recording; }

}  // namespace nb
