#pragma once
// Which operator control may be used now, and if not, why: a pure function of the rig's
// state. The engine refuses what it forbids and the panel greys out what it forbids, so the
// two can never disagree. Every pitfall of the 2002 panel (models.md section 8) is a rule
// here: no motion without enable, bias and zero; no insertion without a calibration, a force
// limit and a place to save the run; no unrecorded motion that looks like an experiment; no
// run closed by a stop; one mode at a time; and the needle can always be brought out.

#include <QString>

namespace nb {

struct InterlockState {
    bool devicesRunning = false;  // the sensor is streaming (engine up)
    QString fault;                // a device fault; empty when healthy
    bool stageEnabled = false;
    bool latched = false;         // an emergency stop holds until the operator enables again
    bool biased = false;
    bool zeroed = false;
    // Zeroed at least once on these devices: position 0 is the operator's start, still, after an
    // emergency stop's reset or a re-enable has asked for a fresh zero.
    bool startKnown = false;
    bool moving = false;
    bool recording = false;
    bool calibrated = false;      // an active calibration is set on the engine
    double forceLimit_N = 0.0;
    bool sessionOpen = false;
    QString motionProblem;        // why the chosen motion parameters are invalid; empty when valid
    QString planHold;             // what the plan being walked needs before its next run (its checklist); empty when nothing
    bool calibrating = false;     // the calibration wizard is open: the masses it asks for load the sensor
    // Bias and zero make sense only with the needle free: not while the force is above the
    // noise band, nor past the depth where the last insertion met tissue.
    bool loaded = false;
    bool inTissue = false;
    double force_N = 0.0;         // now: a run that starts near the force limit would stop at once
};

// A run does not start with the force at this fraction of the limit or above.
inline constexpr double kStartForceFraction = 0.8;

struct Permission {
    bool enabled = false;
    QString reason;            // why not (empty when enabled)
    bool overridable = false;  // refused, but the operator may insist (bias or zero under load)
};

enum class Control {
    Enable,        // toggles the stage drive
    Bias,
    Zero,
    MotionSettings,
    StartInsertion,
    Withdraw,      // and "withdraw to the start position"
    Jog,           // step or go to a position, never recorded
    StopMotion,
    EndRun,
    ForceLimit,
    Calibrate,     // opening the calibration wizard, choosing a calibration
    ChangeSetup,   // switching session, devices or language
    Quit,
    EmergencyStop,
};

Permission permission(Control control, const InterlockState& state);

// Whether Esc is the emergency stop now (and taken from whatever has the focus): while the
// stage moves or a run records. At rest Esc keeps its usual meaning (closes a dialog or menu).
bool escapeStops(const InterlockState& state);

}  // namespace nb
