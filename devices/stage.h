#pragma once
// One translational insertion axis. Positions in mm, growing as the needle goes deeper.
// Called only from the acquisition thread; errors are thrown as DeviceError.

#include <QString>

namespace nb::devices {

// PID position-loop gains: configuration per controller (thesis Table 1), not constants.
struct PidGains {
    double kp = 0.0, ki = 0.0, kd = 0.0;
};

struct LinearMotion {
    double velocity_mm_s = 4.0;  // magnitude; direction follows the target
    double target_mm = 30.0;     // absolute position to stop at
};

struct SineMotion {
    double amplitude_mm = 10.0;
    double frequency_hz = 0.5;
    int cycles = 7;              // x(t) = centre + A sin(2 pi f t), starting at the current position
};

struct StageState {
    double position_mm = 0.0;    // read back (encoder), not the commanded position
    double velocity_mm_s = 0.0;
    bool enabled = false;
    bool moving = false;
    bool homed = false;          // zero position set since enabling
};

class Stage {
public:
    virtual ~Stage() = default;
    virtual QString name() const = 0;
    virtual void enable(bool on) = 0;
    // The current position becomes 0.
    virtual void zero() = 0;
    virtual void moveLinear(const LinearMotion& motion) = 0;
    virtual void moveSine(const SineMotion& motion) = 0;
    // Decelerates to rest.
    virtual void stop() = 0;
    // Stops at once (fastest the controller can); used by the force limit and on faults.
    virtual void emergencyStop() = 0;
    // Polls the controller; cheap enough to call at 50-100 Hz.
    virtual StageState state() = 0;
    virtual void setGains(const PidGains&) {}
    virtual double minPosition_mm() const { return -10.0; }
    virtual double maxPosition_mm() const { return 150.0; }
};

}  // namespace nb::devices
