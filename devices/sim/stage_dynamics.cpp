#include "stage_dynamics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nb::devices::sim {

void StageDynamics::moveLinear(const LinearMotion& m)
{
    target_ = std::clamp(m.target_mm, c_.minPosition_mm, c_.maxPosition_mm) + zeroOffset_;
    speed_ = std::clamp(std::fabs(m.velocity_mm_s), 1e-6, c_.maxVelocity_mm_s);
    mode_ = Mode::Linear;
}

void StageDynamics::moveSine(const SineMotion& m)
{
    centre_ = r_;
    amplitude_ = m.amplitude_mm;
    omega_ = 2.0 * std::numbers::pi * m.frequency_hz;
    tau_ = 0.0;
    duration_ = m.cycles / std::max(m.frequency_hz, 1e-9);
    mode_ = Mode::Sine;
}

void StageDynamics::stop()
{
    if (mode_ != Mode::Hold)
        mode_ = Mode::Decel;
}

void StageDynamics::emergencyStop()
{
    mode_ = Mode::Hold;
    r_ = x_;
    rv_ = 0.0;
    integral_ = 0.0;
}

void StageDynamics::zero()
{
    zeroOffset_ = x_;
}

double StageDynamics::encoder_mm() const
{
    const double q = c_.encoderResolution_mm;
    return std::round(position_mm() / q) * q;
}

void StageDynamics::step(double dt)
{
    const double acc = c_.acceleration_mm_s2;
    switch (mode_) {
    case Mode::Hold:
        rv_ = 0.0;
        break;
    case Mode::Linear: {
        const double remaining = target_ - r_;
        const double dir = remaining >= 0 ? 1.0 : -1.0;
        const double want = dir * std::min(speed_, std::sqrt(2.0 * acc * std::fabs(remaining)));
        rv_ += std::clamp(want - rv_, -acc * dt, acc * dt);
        r_ += rv_ * dt;
        if ((target_ - r_) * dir <= 0.0 || (std::fabs(target_ - r_) < 1e-6 && std::fabs(rv_) < 1e-3)) {
            r_ = target_;
            rv_ = 0.0;
            mode_ = Mode::Hold;
        }
        break;
    }
    case Mode::Sine:
        tau_ += dt;
        if (tau_ >= duration_) {
            r_ = centre_ + amplitude_ * std::sin(omega_ * duration_);
            rv_ = 0.0;
            mode_ = Mode::Hold;
        } else {
            r_ = centre_ + amplitude_ * std::sin(omega_ * tau_);
            rv_ = amplitude_ * omega_ * std::cos(omega_ * tau_);
        }
        break;
    case Mode::Decel:
        if (std::fabs(rv_) <= acc * dt) {
            rv_ = 0.0;
            mode_ = Mode::Hold;
        } else {
            rv_ -= (rv_ > 0 ? 1.0 : -1.0) * acc * dt;
        }
        r_ += rv_ * dt;
        break;
    }
    // Travel limits bound the reference (the controller refuses to drive past them).
    r_ = std::clamp(r_, c_.minPosition_mm + zeroOffset_, c_.maxPosition_mm + zeroOffset_);

    const double e = r_ - x_;
    integral_ += e * dt;
    const double u = c_.gains.kp * e + c_.gains.ki * integral_ + c_.gains.kd * (rv_ - v_);
    // Semi-implicit Euler: stable for the stiff loop at the 0.1 ms step.
    a_ = (u - c_.damping * v_) / c_.mass;
    v_ += a_ * dt;
    x_ += v_ * dt;
    settled_ = std::fabs(r_ - x_) < 0.002 && std::fabs(v_) < 0.05;
}

}  // namespace nb::devices::sim
