#pragma once
// Which operator control may be used now, and if not, why: a pure function of the rig's
// state, so the whole sequence can be tested without widgets. Every pitfall of the 2002
// panel (models.md section 8) is a rule here: no motion without enable, bias and zero; no
// insertion without a calibration, a force limit and a place to save the run; no
// unrecorded motion that looks like an experiment; no run closed by a stop.

#include <QString>

namespace nb {

struct InterlockState {
    bool devicesRunning = false;  // the sensor is streaming (engine up)
    QString fault;                // a device fault; empty when healthy
    bool stageEnabled = false;
    bool biased = false;
    bool zeroed = false;
    bool moving = false;
    bool recording = false;
    bool calibrated = false;      // an active calibration is set on the engine
    double forceLimit_N = 0.0;
    bool sessionOpen = false;
    QString motionProblem;        // why the chosen motion parameters are invalid; empty when valid
};

struct Permission {
    bool enabled = false;
    QString reason;  // why not (empty when enabled)
};

enum class Control {
    Enable,        // toggles the stage drive
    Bias,
    Zero,
    MotionSettings,
    StartInsertion,
    Withdraw,
    StopMotion,
    EndRun,
    ForceLimit,
    Calibrate,
    EmergencyStop,
};

Permission permission(Control control, const InterlockState& state);

}  // namespace nb
