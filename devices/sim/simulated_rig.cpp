#include "simulated_rig.h"
#include "core/tr.h"

#include "devices/device_error.h"
#include "core/model_json.h"
#include "devices/sim/capsule_design.h"
#include "devices/sim/rig_world.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <thread>

namespace nb::devices::sim {

namespace {
constexpr double kPhysicsStep_s = 1.0e-4;
constexpr double kSilentTimeout_s = 0.1;        // the sensor reports silence after this
constexpr double kControllerWatchdog_s = 0.1;   // the controller holds when the host goes quiet

void sleepUntil(std::chrono::steady_clock::time_point when)
{
    // steady_clock is CLOCK_MONOTONIC on Linux: an absolute sleep does not accumulate drift.
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(when.time_since_epoch()).count();
    timespec ts{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}
}  // namespace

// ---- World -----------------------------------------------------------------------------

SimulatedRig::World::World(const RigConfig& config, const TissuePreset& tissue)
    : c_(config), tissue_(tissue), rng_(config.seed), stage_(config.stage), sampleTruth_(kTruthRing)
{
    if (c_.setup == Setup::Platform)
        platform_.emplace(tissue_, c_);
    else
        organ_.emplace(tissue_, c_, rng_);
    if (organ_ && tissue_.capsule) {
        const CapsuleDesign& d = organ_->design();
        truth_.capsule = CapsuleTruth{organ_->site(), organ_->plannedPunctureDepth_mm(), organ_->stiffnessScale(),
                                      d.base, d.tent_N};
    }
    wall0_ = std::chrono::steady_clock::now();
}

QString SimulatedRig::World::stageName() const { return nb::TrDevices::tr("simulated stage"); }
QString SimulatedRig::World::sensorName() const { return nb::TrDevices::tr("simulated load cell"); }

double SimulatedRig::World::wallSim() const
{
    return wallSim0_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
}

void SimulatedRig::World::applyFaults()
{
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (t_ + 1e-12 < it->at) {
            ++it;
            continue;
        }
        switch (it->f) {
        case Fault::None:
            sensorSilent_ = sensorError_ = stageSilent_ = stageRejects_ = false;
            watchdogFired_ = false;
            break;
        case Fault::SensorSilent: sensorSilent_ = true; break;
        case Fault::SensorError: sensorError_ = true; break;
        case Fault::StageSilent:
            stageSilent_ = true;
            stageSilentAt_ = t_;
            break;
        case Fault::StageRejects: stageRejects_ = true; break;
        }
        if (it->f != Fault::None)
            truth_.events.push_back({QStringLiteral("fault"), t_, stage_.absolute_mm(), force_});
        it = pending_.erase(it);
    }
    if (stageSilent_ && !watchdogFired_ && t_ - stageSilentAt_ >= kControllerWatchdog_s) {
        // The controller's own communication watchdog: it holds position when the host has
        // been unable to reach it (the host cannot stop what it cannot talk to).
        watchdogFired_ = true;
        if (stage_.moving()) {
            stage_.emergencyStop();
            truth_.events.push_back({QStringLiteral("controller_watchdog_stop"), t_, stage_.absolute_mm(), force_});
        }
    }
}

void SimulatedRig::World::advanceTo(double t)
{
    while (t_ < t - 1e-12) {
        const double dt = std::min(kPhysicsStep_s, t - t_);
        stage_.step(dt);
        t_ += dt;
        const double tip = stage_.absolute_mm();
        const double v = stage_.velocity_mm_s();
        double f = 0.0;
        if (organ_) {
            f = organ_->step(t_, dt, tip, v, truth_);
            tissue_mm_ = organ_->surface_mm();
        } else {
            f = platform_->step(t_, dt, v, stage_.acceleration_mm_s2(), truth_);
            tissue_mm_ = platform_->slab_mm();
        }
        // The load cell also carries the needle holder (inertia) and any calibration mass.
        force_ = f + kNeedleHolderMass_kg * stage_.acceleration_mm_s2() / 1000.0 + loadMass_g_ * kGravity_m_s2 / 1000.0;
        applyFaults();
    }
}

double SimulatedRig::World::sample(double t)
{
    advanceTo(t);
    const SensorChainConfig& s = c_.sensor;
    double v = s.offset_V + s.drift_V_per_s * t + s.gain * s.sensitivity_V_per_N * force_ + s.noise_V * noise_(rng_);
    const double lsb = 2.0 * s.adcRange_V / std::ldexp(1.0, s.adcBits);
    v = std::clamp(std::round(v / lsb) * lsb, -s.adcRange_V, s.adcRange_V - lsb);
    return v;
}

void SimulatedRig::World::stageCommand(const char* what, const std::function<void(StageDynamics&)>& apply,
                                       bool isEmergency)
{
    std::lock_guard lock(m_);
    if (stageSilent_)
        throw DeviceError(stageName(), nb::TrDevices::tr("no reply for 100 ms to '%1' (cable unplugged?)").arg(QLatin1String(what)));
    // The emergency stop is honoured even when ordinary commands are refused.
    if (stageRejects_ && !isEmergency) {
        truth_.events.push_back({QStringLiteral("command_rejected"), t_, stage_.absolute_mm(), force_});
        throw DeviceError(stageName(), nb::TrDevices::tr("rejected '%1': controller reports a fault (RJ)").arg(QLatin1String(what)));
    }
    if (!enabled_ && !isEmergency)
        throw DeviceError(stageName(), nb::TrDevices::tr("rejected '%1': driver disabled").arg(QLatin1String(what)));
    apply(stage_);
    if (isEmergency)
        truth_.events.push_back({QStringLiteral("emergency_stop"), t_, stage_.absolute_mm(), force_});
}

void SimulatedRig::World::stageEnable(bool on)
{
    std::lock_guard lock(m_);
    if (stageSilent_)
        throw DeviceError(stageName(), nb::TrDevices::tr("no reply for 100 ms (cable unplugged?)"));
    if (stageRejects_)
        throw DeviceError(stageName(), nb::TrDevices::tr("rejected 'driver enable': controller reports a fault (RJ)"));
    if (!on)
        stage_.emergencyStop();
    enabled_ = on;
    homed_ = false;
}

StageState SimulatedRig::World::stageState()
{
    std::lock_guard lock(m_);
    if (c_.realtime)
        advanceTo(std::max(t_, wallSim()));
    if (stageSilent_)
        throw DeviceError(stageName(), nb::TrDevices::tr("no reply for 100 ms (cable unplugged?)"));
    return {stage_.encoder_mm(), stage_.velocity_mm_s(), enabled_, stage_.moving(), homed_};
}

double SimulatedRig::World::sensorStart(double rateHz)
{
    std::lock_guard lock(m_);
    if (sensorError_)
        throw DeviceError(sensorName(), nb::TrDevices::tr("stream start failed: LIBUSB_ERROR_IO"));
    rate_ = std::clamp(rateHz, 1.0, 50000.0);
    t0_ = t_;
    next_ = 0;
    silentSince_ = -1.0;
    streaming_ = true;
    if (c_.realtime) {
        wall0_ = std::chrono::steady_clock::now();
        wallSim0_ = t_;
    }
    return rate_;
}

void SimulatedRig::World::sensorStop()
{
    std::lock_guard lock(m_);
    streaming_ = false;
}

void SimulatedRig::World::sensorRead(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout)
{
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        std::unique_lock lock(m_);
        if (!streaming_)
            throw DeviceError(sensorName(), nb::TrDevices::tr("read while not streaming"));
        const double tNext = t0_ + static_cast<double>(next_) / rate_;
        const double now = c_.realtime ? wallSim() : tNext;
        if (sensorError_)
            throw DeviceError(sensorName(), nb::TrDevices::tr("stream error: USB transfer failed (LIBUSB_ERROR_IO)"));
        if (sensorSilent_) {
            // Nothing arrives; the world goes on. Samples due meanwhile are lost.
            if (silentSince_ < 0)
                silentSince_ = t_;
            const double until = c_.realtime ? now : t_ + std::chrono::duration<double>(timeout).count();
            advanceTo(std::max(t_, until));
            next_ = static_cast<std::uint64_t>(std::ceil((t_ - t0_) * rate_));
            if (t_ - silentSince_ >= kSilentTimeout_s)
                throw DeviceError(sensorName(), nb::TrDevices::tr("no samples for %1 ms (cable unplugged?)").arg(qRound((t_ - silentSince_) * 1000)));
            lock.unlock();
            if (c_.realtime)
                std::this_thread::sleep_for(std::min(timeout, std::chrono::milliseconds(10)));
            if (std::chrono::steady_clock::now() >= deadline || !c_.realtime)
                return;
            continue;
        }
        silentSince_ = -1.0;
        std::size_t produced = 0;
        // In real time, everything due; as fast as possible, one sample per read so that the
        // engine reacts to each sample before the world moves on.
        while (t0_ + static_cast<double>(next_) / rate_ <= now + 1e-12) {
            const double ts = t0_ + static_cast<double>(next_) / rate_;
            const double volts = sample(ts);
            sampleTruth_[next_ % kTruthRing] = {force_, tissue_mm_, platform_ ? platform_->truePhase() : TruePhase::None};
            out.push_back({next_, ts - t0_, volts});
            ++next_;
            ++produced;
            if (!c_.realtime || sensorSilent_ || sensorError_)
                break;
        }
        if (produced > 0)
            return;
        if (std::chrono::steady_clock::now() >= deadline)
            return;
        // Sleep until the next sample is due (or the timeout).
        const auto due = wall0_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(tNext - wallSim0_));
        lock.unlock();
        sleepUntil(std::min(due, deadline));
    }
}

double SimulatedRig::World::setLoadMass_g(double g)
{
    std::lock_guard lock(m_);
    loadMass_g_ = g;
    // Samples up to the world's time are already taken: the mass is in every one after it.
    return t_ - t0_;
}

void SimulatedRig::World::injectFault(Fault f, double at_s)
{
    std::lock_guard lock(m_);
    pending_.push_back({f, at_s});
    applyFaults();
}

double SimulatedRig::World::time_s() const
{
    std::lock_guard lock(m_);
    return t_;
}

GroundTruth SimulatedRig::World::truth() const
{
    std::lock_guard lock(m_);
    GroundTruth g = truth_;
    if (platform_) {
        // The phase still open ends where the needle last moved.
        FrictionPlatform copy = *platform_;
        copy.closePhases(t_, g);
    }
    return g;
}

SampleTruth SimulatedRig::World::sampleTruth(std::uint64_t index) const
{
    std::lock_guard lock(m_);
    if (index >= next_ || next_ - index > kTruthRing)
        return {};
    return sampleTruth_[index % kTruthRing];
}

// ---- Devices ---------------------------------------------------------------------------

namespace {

class SimStage : public Stage {
public:
    explicit SimStage(std::shared_ptr<SimulatedRig> rig) : rig_(std::move(rig)), w_(rig_->world()) {}
    QString name() const override { return w_.stageName(); }
    void enable(bool on) override { w_.stageEnable(on); }
    void zero() override { w_.stageCommand("set pos 0", [](StageDynamics& s) { s.zero(); }); }
    void moveLinear(const LinearMotion& m) override
    {
        checkTarget(m.target_mm);
        w_.stageCommand("move abs", [m](StageDynamics& s) { s.moveLinear(m); });
    }
    void moveSine(const SineMotion& m) override
    {
        const StageState st = w_.stageState();
        checkTarget(st.position_mm + std::fabs(m.amplitude_mm));
        checkTarget(st.position_mm - std::fabs(m.amplitude_mm));
        w_.stageCommand("move sin", [m](StageDynamics& s) { s.moveSine(m); });
    }
    void stop() override { w_.stageCommand("stop", [](StageDynamics& s) { s.stop(); }); }
    void emergencyStop() override { w_.stageCommand("estop", [](StageDynamics& s) { s.emergencyStop(); }, true); }
    StageState state() override { return w_.stageState(); }
    void setGains(const PidGains& g) override
    {
        w_.stageCommand("set gains", [g](StageDynamics& s) { s.setGains(g); });
    }
    double minPosition_mm() const override { return rig_->config().stage.minPosition_mm; }
    double maxPosition_mm() const override { return rig_->config().stage.maxPosition_mm; }

private:
    void checkTarget(double mm) const
    {
        if (mm < minPosition_mm() || mm > maxPosition_mm())
            throw DeviceError(name(), nb::TrDevices::tr("target %1 mm is outside the travel (%2 to %3 mm)")
                                          .arg(mm, 0, 'f', 3)
                                          .arg(minPosition_mm())
                                          .arg(maxPosition_mm()));
    }
    std::shared_ptr<SimulatedRig> rig_;  // keeps the world alive
    SimulatedRig::World& w_;
};

class SimSensor : public ForceSensor {
public:
    explicit SimSensor(std::shared_ptr<SimulatedRig> rig) : rig_(std::move(rig)), w_(rig_->world()) {}
    QString name() const override { return w_.sensorName(); }
    double start(double rateHz) override { return w_.sensorStart(rateHz); }
    void stop() override { w_.sensorStop(); }
    void read(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout) override { w_.sensorRead(out, timeout); }
    double inputRange_V() const override { return rig_->config().sensor.adcRange_V; }

private:
    std::shared_ptr<SimulatedRig> rig_;
    SimulatedRig::World& w_;
};

}  // namespace

// ---- SimulatedRig ----------------------------------------------------------------------

SimulatedRig::SimulatedRig(RigConfig config) : config_(std::move(config))
{
    auto preset = tissuePreset(config_.tissue, config_.tip);
    if (!preset)
        throw std::invalid_argument(
            nb::TrDevices::tr("unknown tissue '%1' (known: %2)").arg(config_.tissue, tissueNames().join(QStringLiteral(", "))).toStdString());
    tissue_ = *preset;
    world_ = std::make_unique<World>(config_, tissue_);
}

SimulatedRig::~SimulatedRig() = default;

double SimulatedRig::setLoadMass_g(double grams) { return world_->setLoadMass_g(grams); }
void SimulatedRig::injectFault(Fault fault, double at_s) { world_->injectFault(fault, at_s); }
double SimulatedRig::simTime_s() const { return world_->time_s(); }
GroundTruth SimulatedRig::truth() const { return world_->truth(); }
SampleTruth SimulatedRig::sampleTruth(std::uint64_t index) const { return world_->sampleTruth(index); }
std::unique_ptr<Stage> SimulatedRig::makeStage() { return std::make_unique<SimStage>(shared_from_this()); }
std::unique_ptr<ForceSensor> SimulatedRig::makeSensor() { return std::make_unique<SimSensor>(shared_from_this()); }

QJsonObject SimulatedRig::truthJson() const
{
    const GroundTruth g = truth();
    QJsonObject model{
        {QStringLiteral("tissue"), tissue_.name},
        {QStringLiteral("tip"), tipName(config_.tip)},
        {QStringLiteral("capsule"), tissue_.capsule},
        {QStringLiteral("a1_N_per_mm"), tissue_.stiffness.a1_N_per_mm},
        {QStringLiteral("a2_N_per_mm2"), tissue_.stiffness.a2_N_per_mm2},
        {QStringLiteral("mean_puncture_depth_mm"), tissue_.punctureDepth_mm},
        {QStringLiteral("cutting_N"), tissue_.cutting_N},
        {QStringLiteral("relax_fraction"), tissue_.relaxFraction},
        {QStringLiteral("surface_mm"), config_.surface_mm},
        {QStringLiteral("thickness_mm"), config_.thickness_mm},
        {QStringLiteral("needle_holder_mass_kg"), kNeedleHolderMass_kg},
        {QStringLiteral("sensor_slope_V_per_g"), config_.sensor.slope_V_per_g()},
    };
    const KarnoppPerLength& f = tissue_.friction;
    model.insert(QStringLiteral("friction_per_length"),
                 toJson(f));
    if (config_.boneDepth_mm)
        model.insert(QStringLiteral("bone_depth_mm"), *config_.boneDepth_mm);
    if (config_.setup == Setup::Platform)
        model.insert(QStringLiteral("plate"), QJsonObject{{QStringLiteral("gap_mm"), config_.plateGap_mm},
                                                          {QStringLiteral("soft_mm"), FrictionPlatform::kSoft_mm},
                                                          {QStringLiteral("soft_N_per_m"), FrictionPlatform::kSoft_N_per_m},
                                                          {QStringLiteral("stiff_N_per_m"), FrictionPlatform::kStiff_N_per_m},
                                                          {QStringLiteral("tissue_mass_kg"), tissue_.tissueMass_kg}});
    if (tissue_.capsule)
        model.insert(QStringLiteral("mean_puncture_force_N"), tissue_.punctureForce_N);
    if (g.capsule) {
        // What this run's capsule was: its site, and the curve under the tenting (see
        // capsule_design.h); a1/a2 above are the pooled values the sites reproduce together.
        model.insert(QStringLiteral("capsule_site"),
                     QJsonObject{{QStringLiteral("site"), g.capsule->site},
                                 {QStringLiteral("sites"), CapsuleDesign::kSites},
                                 {QStringLiteral("puncture_depth_mm"), g.capsule->punctureDepth_mm},
                                 {QStringLiteral("stiffness_scale"), g.capsule->stiffnessScale},
                                 {QStringLiteral("base_a1_N_per_mm"), g.capsule->base.a1_N_per_mm},
                                 {QStringLiteral("base_a2_N_per_mm2"), g.capsule->base.a2_N_per_mm2},
                                 {QStringLiteral("tent_N"), g.capsule->tent_N},
                                 {QStringLiteral("tent_fraction"), CapsuleDesign::kTentFraction}});
    }

    auto orNull = [](double t, double v) { return t < 0 ? QJsonValue() : QJsonValue(v); };
    QJsonObject out{
        {QStringLiteral("seed"), QString::number(config_.seed)},
        {QStringLiteral("model"), model},
        {QStringLiteral("contact_mm"), orNull(g.contact_s, g.contact_mm)},
        {QStringLiteral("contact_s"), orNull(g.contact_s, g.contact_s)},
        {QStringLiteral("puncture_mm"), orNull(g.puncture_s, g.puncture_mm)},
        {QStringLiteral("puncture_s"), orNull(g.puncture_s, g.puncture_s)},
        {QStringLiteral("puncture_force_N"), orNull(g.puncture_s, g.punctureForce_N)},
        {QStringLiteral("relaxed_mm"), orNull(g.puncture_s, g.relaxed_mm)},
        {QStringLiteral("relaxed_s"), orNull(g.relaxed_s, g.relaxed_s)},
    };
    QJsonArray events;
    for (const TruthEvent& e : g.events)
        events.append(QJsonObject{{QStringLiteral("name"), e.name},
                                  {QStringLiteral("time_s"), e.time_s},
                                  {QStringLiteral("position_mm"), e.position_mm},
                                  {QStringLiteral("force_N"), e.force_N}});
    out.insert(QStringLiteral("events"), events);
    QJsonArray phases;
    for (const TruthPhase& p : g.phases)
        phases.append(QJsonObject{{QStringLiteral("track"), p.track},
                                  {QStringLiteral("label"), p.label},
                                  {QStringLiteral("start_s"), p.start_s},
                                  {QStringLiteral("end_s"), p.end_s}});
    out.insert(QStringLiteral("phases"), phases);
    return out;
}

}  // namespace nb::devices::sim
