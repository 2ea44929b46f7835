#pragma once
// The simulated insertion axis: a trajectory generator (linear with acceleration ramps,
// sinusoid) feeding a PID position loop around a mass-damper plant, read back through a
// quantising encoder. Plain physics, no threads; stepped by the rig.

#include "devices/sim/rig_config.h"
#include "devices/stage.h"

namespace nb::devices::sim {

class StageDynamics {
public:
    explicit StageDynamics(const StageConfig& config) : c_(config) {}

    void setGains(const PidGains& g) { c_.gains = g; }
    void moveLinear(const LinearMotion& m);
    void moveSine(const SineMotion& m);
    void stop();           // decelerate the reference to rest
    void emergencyStop();  // hold where the axis is now
    void zero();           // the current position becomes 0
    void step(double dt);

    double position_mm() const { return x_ - zeroOffset_; }
    double absolute_mm() const { return x_; }  // tip position in the world (tissue frame)
    double velocity_mm_s() const { return v_; }
    double acceleration_mm_s2() const { return a_; }
    double encoder_mm() const;
    // Until the reference has arrived and the axis has settled on it.
    bool moving() const { return mode_ != Mode::Hold || !settled_; }
    double reference_mm() const { return r_ - zeroOffset_; }
    double minPosition_mm() const { return c_.minPosition_mm; }
    double maxPosition_mm() const { return c_.maxPosition_mm; }

private:
    enum class Mode { Hold, Linear, Sine, Decel };
    StageConfig c_;
    Mode mode_ = Mode::Hold;
    double x_ = 0.0, v_ = 0.0, a_ = 0.0;  // plant (absolute mm)
    double r_ = 0.0, rv_ = 0.0;           // reference (absolute mm)
    double integral_ = 0.0;
    bool settled_ = true;
    double zeroOffset_ = 0.0;
    double target_ = 0.0, speed_ = 0.0;   // linear
    double centre_ = 0.0, amplitude_ = 0.0, omega_ = 0.0, tau_ = 0.0, duration_ = 0.0;  // sine
};

}  // namespace nb::devices::sim
