#pragma once
// Inside the simulated rig: the world's state and its clock, shared by the simulated stage
// and sensor. Every method locks; none sleeps while holding the lock.

#include "devices/sim/friction_platform.h"
#include "devices/sim/organ_tissue.h"
#include "devices/sim/simulated_rig.h"
#include "devices/sim/stage_dynamics.h"

#include <chrono>
#include <functional>
#include <vector>
#include <mutex>
#include <optional>
#include <random>

namespace nb::devices::sim {

class SimulatedRig::World {
public:
    World(const RigConfig& config, const TissuePreset& tissue);

    // Stage side. Each throws DeviceError like a real controller would.
    void stageCommand(const char* what, const std::function<void(StageDynamics&)>& apply, bool isEmergency = false);
    void stageEnable(bool on);
    StageState stageState();

    // Sensor side.
    double sensorStart(double rateHz);
    void sensorStop();
    void sensorRead(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout);

    double setLoadMass_g(double g);
    void injectFault(Fault f, double at_s);
    double time_s() const;
    GroundTruth truth() const;
    SampleTruth sampleTruth(std::uint64_t index) const;
    QString stageName() const;
    QString sensorName() const;

private:
    void advanceTo(double t);  // locked
    void applyFaults();        // locked
    double sample(double t);   // locked: volts at time t
    double wallSim() const;    // the sim time that wall-clock time has reached (real-time mode)

    mutable std::mutex m_;
    RigConfig c_;
    TissuePreset tissue_;
    std::mt19937_64 rng_;
    std::normal_distribution<double> noise_{0.0, 1.0};
    StageDynamics stage_;
    std::optional<OrganTissue> organ_;
    std::optional<FrictionPlatform> platform_;
    GroundTruth truth_;
    double t_ = 0.0;
    double force_ = 0.0;       // true force on the load cell, N
    double tissue_mm_ = 0.0;
    bool enabled_ = false, homed_ = false;
    double loadMass_g_ = 0.0;
    // Sensor stream.
    bool streaming_ = false;
    double rate_ = 500.0, t0_ = 0.0;
    std::uint64_t next_ = 0;
    double silentSince_ = -1.0;
    std::chrono::steady_clock::time_point wall0_;
    double wallSim0_ = 0.0;
    // Faults.
    struct Pending { Fault f; double at; };
    std::vector<Pending> pending_;
    bool sensorSilent_ = false, sensorError_ = false, stageSilent_ = false, stageRejects_ = false;
    double stageSilentAt_ = -1.0;
    bool watchdogFired_ = false;
    // Truth of the last samples by index.
    static constexpr std::size_t kTruthRing = 1 << 16;
    std::vector<SampleTruth> sampleTruth_;
};

}  // namespace nb::devices::sim
