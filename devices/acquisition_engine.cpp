#include "acquisition_engine.h"
#include "core/local_number.h"

#include <QLocale>

#include "core/data_names.h"

#include "core/run_file.h"
#include "core/run_keys.h"
#include "core/tr.h"
#include "devices/device_error.h"
#include "devices/realtime.h"
#include "devices/sample_processor.h"

#include <QCoreApplication>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sys/syscall.h>
#include <unistd.h>

namespace nb::devices {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kReadTimeout = std::chrono::milliseconds(20);
constexpr auto kIdleWait = std::chrono::milliseconds(20);
constexpr double kSensorRetry_s = 1.0;
constexpr double kStageFaultPoll_s = 0.5;
constexpr double kStopRecord_s = 0.2;  // a run stopped by the limit or a puncture records the stop itself

double hostNow() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }
}  // namespace

InterlockState EngineStatus::interlocks() const
{
    InterlockState s;
    s.devicesRunning = running;
    s.fault = fault;
    s.stageEnabled = stageEnabled;
    s.latched = latched;
    s.biased = biased;
    s.zeroed = zeroed;
    s.startKnown = zeroCount > 0;
    s.moving = moving || approaching;
    s.recording = recording;
    s.calibrated = slope_V_per_g > 0.0;
    s.forceLimit_N = forceLimit_N;
    s.sessionOpen = true;  // the engine records wherever it is told; the window knows better
    s.loaded = loaded;
    s.inTissue = contactDepth_mm && position_mm > *contactDepth_mm;
    s.force_N = force_N;
    return s;
}

// The engine thread's state. The per-sample work is the processor's; what is here is the
// operator's commands, the devices' health and the open run.
struct AcquisitionEngine::State {
    DeviceSet dev;
    std::unique_ptr<SampleProcessor> proc;
    QString calibrationName;
    bool enabled = false, zeroed = false, latched = false;
    std::uint64_t biasCount = 0, zeroCount = 0;
    double noiseBand_N = 0.05;
    std::optional<double> contactDepth_mm;
    std::optional<double> lastRunStart_mm;
    // Devices' health.
    bool sensorOk = false;
    double sensorRetryAt = 0.0;  // host time
    bool stageOk = true;
    double stageRetryAt = 0.0;
    QString fault;
    QString realtimeWarning;
    StageState stage;
    // A move the operator asked for outside a run (withdraw, jog): it ends when the stage stops.
    bool jogging = false, sawJogMoving = false;
    // A run waiting for the stage to reach its start position.
    std::optional<RunPlan> approach;
    bool sawApproachMoving = false;
    // The open run.
    Recorder recorder;
    bool runOpen = false;
    QString runPath;
    double runStart = 0.0;       // device time of the run's first sample
    double runStartPosition = 0.0;
    bool runMotion = false, endWhenDone = true, sawMoving = false, runIsInsertion = false;
    int stopAtPuncture = 0;
    double slowAfterPuncture = 0.0;
    LinearMotion runLinear;
    std::uint64_t droppedAtStart = 0, lateAtStart = 0, recOverrunsAtStart = 0, runPushed = 0;
    std::optional<ProcessorEvent> trip;
    std::optional<ProcessorEvent> punctureStop;
    double pendingEndAt = -1.0;  // device time
    EndReason pendingEndReason = EndReason::Completed;
    // Status: at the status rate, and at once when an interlock or the run changes.
    Clock::time_point nextStatus;
    bool statusDirty = false;
    std::function<void(double, double)> probe;
    std::vector<VoltageSample> batch;
    std::vector<Sample> samples;
    std::vector<ProcessorEvent> events;
};

AcquisitionEngine::AcquisitionEngine(DeviceSet devices, EngineConfig config, QObject* parent)
    : QObject(parent),
      truth_(devices.truth),
      calibrationLoad_(devices.calibrationLoad),
      nominalSlope_(devices.nominalSlope_V_per_g),
      hostPaced_(!devices.selfPacedClock),
      description_(devices.description),
      fileDescription_(devices.fileDescription.isEmpty() ? devices.description : devices.fileDescription),
      config_(config),
      live_(config.liveCapacity),
      state_(std::make_unique<State>())
{
    qRegisterMetaType<nb::devices::EngineStatus>();
    qRegisterMetaType<nb::devices::RunSummary>();
    qRegisterMetaType<nb::devices::RunPlan>();
    config_.rateHz = std::clamp(config_.rateHz, 100.0, 10000.0);
    State& s = *state_;
    s.dev = std::move(devices);
    s.proc = std::make_unique<SampleProcessor>(config_.rateHz, hostPaced_, truth_);
    s.proc->setSlope(nominalSlope_);
    s.proc->setLimits(config_.forceLimit_N, config_.withdrawForceLimit_N);
    // Stored in every run file: the same words in every language (views translate it).
    s.calibrationName = nominalSlope_ > 0 ? QString::fromLatin1(kNominalCalibration) : QString();
    s.noiseBand_N = config_.noiseBand_N;
    status_.rateHz = config_.rateHz;
    status_.forceLimit_N = config_.forceLimit_N;
    status_.withdrawForceLimit_N = s.proc->withdrawalLimit();
}

AcquisitionEngine::~AcquisitionEngine()
{
    shutdown();
}

void AcquisitionEngine::setArrivalProbe(std::function<void(double, double)> probe)
{
    state_->probe = std::move(probe);
}

int AcquisitionEngine::recorderThreadId() const
{
    return state_->recorder.threadId();
}

void AcquisitionEngine::start()
{
    if (thread_.joinable())
        return;
    quit_ = false;
    thread_ = std::thread([this] { threadMain(); });
}

void AcquisitionEngine::shutdown()
{
    if (!thread_.joinable())
        return;
    {
        std::lock_guard lock(mutex_);  // so that an idle wait cannot miss it
        quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

EngineStatus AcquisitionEngine::status() const
{
    std::lock_guard lock(mutex_);
    return status_;
}

void AcquisitionEngine::post(std::function<void()> command)
{
    {
        std::lock_guard lock(mutex_);
        commands_.push_back(std::move(command));
    }
    wake_.notify_one();
}

// ---- commands (run on the engine thread) ------------------------------------------------
// Each lambda below runs inside threadMain(), which turns a DeviceError into a fault. Each
// asks the same interlocks the panel shows, on the engine's own state.

void AcquisitionEngine::enableStage(bool on)
{
    post([this, on] {
        State& s = *state_;
        const bool wasLatched = s.latched;
        s.dev.stage->enable(on);
        s.enabled = on;
        s.zeroed = false;  // enabling may move the axis: the operator zeroes again
        s.stageOk = true;
        if (on)
            s.latched = false;
        if (on && s.sensorOk && !s.fault.isEmpty()) {
            s.fault.clear();
            emit message(tr("stage enabled; fault cleared"));
        } else if (on && wasLatched) {
            emit message(tr("stage enabled; emergency stop reset"));
        } else {
            emit message(on ? tr("stage enabled") : tr("stage disabled"));
        }
    });
}

void AcquisitionEngine::biasSensor(bool insist)
{
    post([this, insist] {
        State& s = *state_;
        const Permission p = permission(Control::Bias, snapshot().interlocks());
        if (!p.enabled && !(insist && p.overridable)) {
            emit message(tr("bias refused: %1").arg(p.reason));
            return;
        }
        s.proc->startBias(config_.bias_s);
        emit message(tr("biasing the force sensor: averaging %1 s").arg(config_.bias_s));
    });
}

void AcquisitionEngine::zeroStage(bool insist)
{
    post([this, insist] {
        State& s = *state_;
        const Permission p = permission(Control::Zero, snapshot().interlocks());
        if (!p.enabled && !(insist && p.overridable)) {
            emit message(tr("zero refused: %1").arg(p.reason));
            return;
        }
        s.dev.stage->zero();
        s.zeroed = true;
        ++s.zeroCount;
        s.contactDepth_mm.reset();  // depths before the zero mean nothing now
        s.lastRunStart_mm.reset();
        s.proc->forgetStageHistory();
        emit message(tr("stage position zeroed"));
    });
}

void AcquisitionEngine::setForceLimit(double newtons, bool quietly)
{
    post([this, newtons, quietly] {
        State& s = *state_;
        if (!(newtons > 0.0) || !std::isfinite(newtons)) {
            emit message(tr("force limit must be positive (got %1 N)").arg(newtons));
            return;
        }
        s.proc->setLimits(newtons, std::max(s.proc->withdrawalLimit(), newtons));
        if (!quietly)
            emit message(tr("force limit %1 N").arg(newtons));
        if (s.proc->biased())
            warnOfUnreadableLimit();
    });
}

// The limit set beyond what the load cell can read: said, as the stage stops at the end of the
// sensor's range instead (SampleProcessor::setInputRange).
void AcquisitionEngine::warnOfUnreadableLimit()
{
    const SampleProcessor& p = *state_->proc;
    const double readable = p.readableForce_N(+1);
    if (std::isfinite(readable) && readable > 0.0 && p.insertionLimit() > readable)
        emit message(tr("warning: the load cell reads up to %1 N (its ±%2 V input), less than the force limit of %3 N: "
                        "the stage stops there")
                         .arg(localNumber(readable, 2))
                         .arg(QLocale().toString(state_->dev.sensor->inputRange_V()))
                         .arg(QLocale().toString(p.insertionLimit())));
}

void AcquisitionEngine::setWithdrawForceLimit(double newtons, bool quietly)
{
    post([this, newtons, quietly] {
        State& s = *state_;
        if (!(newtons > 0.0) || !std::isfinite(newtons)) {
            emit message(tr("withdrawal force limit must be positive (got %1 N)").arg(newtons));
            return;
        }
        s.proc->setLimits(s.proc->insertionLimit(), newtons);
        if (!quietly)
            emit message(tr("withdrawal force limit %1 N").arg(QLocale().toString(s.proc->withdrawalLimit())));
    });
}

void AcquisitionEngine::setCalibration(double slope_V_per_g, const QString& name)
{
    post([this, slope_V_per_g, name] {
        if (!(slope_V_per_g > 0.0) || !std::isfinite(slope_V_per_g)) {
            emit message(tr("calibration refused: slope must be positive (got %1 V/g)").arg(slope_V_per_g));
            return;
        }
        // A run's forces are on one scale, the one its header names: a calibration changed
        // mid-run halved them from one sample to the next, and the limit with them.
        if (state_->runOpen) {
            emit message(tr("calibration refused: a run is recording; end the run first"));
            return;
        }
        state_->proc->setSlope(slope_V_per_g);
        state_->calibrationName = name;
        emit message(tr("calibration '%1': %2 V/g").arg(name, QLocale().toString(slope_V_per_g, 'g', 6)));
    });
}

void AcquisitionEngine::useNominalCalibration()
{
    post([this] {
        if (state_->runOpen) {
            emit message(tr("calibration refused: a run is recording; end the run first"));
            return;
        }
        state_->proc->setSlope(nominalSlope_);
        state_->calibrationName = nominalSlope_ > 0 ? QString::fromLatin1(kNominalCalibration) : QString();
    });
}

void AcquisitionEngine::startRun(const RunPlan& plan)
{
    post([this, plan] {
        State& s = *state_;
        InterlockState st = snapshot().interlocks();
        st.sessionOpen = !plan.outPath.isEmpty();
        Permission p = permission(Control::StartInsertion, st);
        if (p.enabled && s.approach)
            p = {false, tr("a run is already on its way to its start position"), false};
        if (!p.enabled) {
            const QString why = tr("run not started: %1").arg(p.reason);
            emit runRefused(why);
            emit message(why);
            return;
        }
        if (plan.startAt_mm && std::fabs(*plan.startAt_mm - s.stage.position_mm) > 0.01) {
            const double lo = s.dev.stage->minPosition_mm(), hi = s.dev.stage->maxPosition_mm();
            if (*plan.startAt_mm < lo || *plan.startAt_mm > hi) {
                const QString why = tr("run not started: the start position %1 mm is outside the travel (%2 to %3 mm)")
                                        .arg(*plan.startAt_mm).arg(lo).arg(hi);
                emit runRefused(why);
                emit message(why);
                return;
            }
            s.approach = plan;
            s.sawApproachMoving = false;
            beginMove({std::max(0.1, plan.approachVelocity_mm_s), *plan.startAt_mm}, false);
            emit message(tr("moving to the start position %1 mm (not recorded)").arg(localNumber(*plan.startAt_mm, 2)));
            return;
        }
        openRun(plan);
    });
}

void AcquisitionEngine::openRun(const RunPlan& plan)
{
    State& s = *state_;
    Metadata meta = plan.metadata;
    meta.set(key::rate_hz, s.proc->rate());
    // The file's words are English in every language (views translate them).
    meta.set(key::device, fileDescription_);
    meta.set(key::calibration, s.calibrationName);
    meta.set(key::slope_V_per_g, QString::number(s.proc->slope(), 'g', 8));
    meta.set(key::bias_V, QString::number(s.proc->bias_V(), 'f', 6));
    meta.set(key::force_limit_N, s.proc->insertionLimit());
    meta.set(key::withdraw_force_limit_N, s.proc->withdrawalLimit());
    meta.set(key::motion, plan.motion == RunPlan::Motion::Linear ? QStringLiteral("linear") : QStringLiteral("sine"));
    if (plan.motion == RunPlan::Motion::Sine)
        meta.set(key::centre_mm, QString::number(s.stage.position_mm, 'f', 4));
    if (plan.stopAtPuncture > 0)
        meta.set(QStringLiteral("stop_at"), QStringLiteral("puncture:%1").arg(plan.stopAtPuncture));
    if (plan.slowAfterPuncture_mm_s > 0)
        meta.set(QStringLiteral("slow_after_puncture_mm_s"), plan.slowAfterPuncture_mm_s);
    s.runStart = s.proc->lastTime_s() + 1.0 / s.proc->rate();
    meta.set(key::run_start_device_time_s, QString::number(s.runStart, 'f', 6));
    meta.set(key::position_source, QStringLiteral("stage read-back, interpolated to the sample clock"));
    try {
        s.recorder.open(plan.outPath, meta, truth_ != nullptr);
    } catch (const Error& e) {
        const QString why = tr("run not started: %1").arg(e.message());
        emit runRefused(why);
        emit message(why);
        return;
    }
    s.runOpen = true;
    s.runPath = plan.outPath;
    s.runStartPosition = s.stage.position_mm;
    s.lastRunStart_mm = s.stage.position_mm;
    s.droppedAtStart = s.proc->counters().dropped;
    s.lateAtStart = s.proc->counters().late;
    s.recOverrunsAtStart = s.recorder.overruns();
    s.runPushed = 0;
    s.trip.reset();
    s.punctureStop.reset();
    s.proc->rearm();
    s.pendingEndAt = -1.0;
    s.runMotion = true;
    s.endWhenDone = plan.endWhenMotionDone;
    s.sawMoving = false;
    s.jogging = false;
    s.stopAtPuncture = plan.stopAtPuncture;
    s.slowAfterPuncture = plan.slowAfterPuncture_mm_s;
    s.runLinear = plan.linear;
    emit runStarted(plan.outPath);
    emit message(tr("recording to %1").arg(plan.outPath));
    if (plan.motion == RunPlan::Motion::Linear) {
        const bool deeper = plan.linear.target_mm > s.stage.position_mm;
        s.runIsInsertion = deeper;
        // Contact and puncture are watched on every insertion: they tell where the tissue
        // begins (bias and zero advice) and serve a stop at puncture.
        s.proc->watchPunctures(deeper);
        s.proc->setGuard(deeper ? ForceGuard::Insertion : ForceGuard::Withdrawal);
        s.dev.stage->moveLinear(plan.linear);
    } else {
        s.runIsInsertion = false;
        s.proc->watchPunctures(false);
        s.proc->setGuard(ForceGuard::Both);
        s.dev.stage->moveSine(plan.sine);
    }
}

void AcquisitionEngine::beginMove(const LinearMotion& motion, bool recordedInsertion)
{
    State& s = *state_;
    const bool deeper = motion.target_mm > s.stage.position_mm;
    s.proc->rearm();
    s.proc->setGuard(deeper && !recordedInsertion ? ForceGuard::Both : deeper ? ForceGuard::Insertion : ForceGuard::Withdrawal);
    s.jogging = !s.approach;
    s.sawJogMoving = false;
    s.dev.stage->moveLinear(motion);
}

void AcquisitionEngine::withdraw(double velocity_mm_s, double target_mm)
{
    post([this, velocity_mm_s, target_mm] {
        State& s = *state_;
        const Permission p = permission(Control::Withdraw, snapshot().interlocks());
        if (!p.enabled) {
            emit message(tr("withdraw refused: %1").arg(p.reason));
            return;
        }
        const double target = std::min(target_mm, s.stage.position_mm);
        s.runMotion = false;
        s.approach.reset();
        s.trip.reset();
        beginMove({std::fabs(velocity_mm_s), target}, false);
        emit message(s.runOpen ? tr("withdrawing to %1 mm; this is recorded in the open run %2").arg(QLocale().toString(target, 'f', 2), s.runPath)
                               : tr("withdrawing to %1 mm (not recorded: no run open)").arg(QLocale().toString(target, 'f', 2)));
    });
}

void AcquisitionEngine::jog(double delta_mm, double velocity_mm_s)
{
    post([this, delta_mm, velocity_mm_s] {
        const double target = state_->stage.position_mm + delta_mm;
        moveTo(target, velocity_mm_s);
    });
}

void AcquisitionEngine::moveTo(double position_mm, double velocity_mm_s)
{
    post([this, position_mm, velocity_mm_s] {
        State& s = *state_;
        const Permission p = permission(Control::Jog, snapshot().interlocks());
        if (!p.enabled) {
            emit message(tr("move refused: %1").arg(p.reason));
            return;
        }
        const double lo = s.dev.stage->minPosition_mm(), hi = s.dev.stage->maxPosition_mm();
        if (!std::isfinite(position_mm) || position_mm < lo || position_mm > hi) {
            emit message(tr("move refused: %1 mm is outside the travel (%2 to %3 mm)").arg(position_mm).arg(lo).arg(hi));
            return;
        }
        beginMove({std::clamp(std::fabs(velocity_mm_s), 0.01, 50.0), position_mm}, false);
        emit message(tr("moving to %1 mm (not recorded)").arg(localNumber(position_mm, 2)));
    });
}

void AcquisitionEngine::stopMotion()
{
    post([this] {
        State& s = *state_;
        s.runMotion = false;
        s.approach.reset();
        s.jogging = false;
        s.dev.stage->stop();
        emit message(s.runOpen ? tr("motion stopped; still recording") : tr("motion stopped"));
    });
}

void AcquisitionEngine::endRun()
{
    post([this] {
        State& s = *state_;
        s.runMotion = false;
        if (s.stage.moving)
            s.dev.stage->stop();
        if (s.runOpen)
            finishRun(EndReason::Stopped, {});
    });
}

void AcquisitionEngine::interrupt(const Metadata& extra)
{
    post([this, extra] {
        State& s = *state_;
        s.runMotion = false;
        s.approach.reset();
        s.jogging = false;
        if (s.stage.moving)
            s.dev.stage->stop();
        if (s.runOpen)
            finishRun(EndReason::Interrupted, {}, extra);
    });
}

void AcquisitionEngine::emergencyStop()
{
    post([this] {
        State& s = *state_;
        s.runMotion = false;
        s.approach.reset();
        s.jogging = false;
        s.dev.stage->emergencyStop();
        // The latch: the drive stays off until the operator enables it on purpose.
        try {
            s.dev.stage->enable(false);
        } catch (const DeviceError& e) {
            emit message(tr("could not disable the stage after the emergency stop: %1").arg(e.message()));
        }
        s.enabled = false;
        s.latched = true;
        emit message(tr("emergency stop: the stage is disabled until you enable it again"));
        if (s.runOpen) {
            Metadata extra;
            extra.set(key::emergency_stop, QStringLiteral("operator"));
            finishRun(EndReason::EmergencyStop, {}, extra);
        }
    });
}

// ---- the engine thread ------------------------------------------------------------------

EngineStatus AcquisitionEngine::snapshot() const
{
    const State& s = *state_;
    const ProcessorCounters& c = s.proc->counters();
    const Sample& last = s.proc->last();
    EngineStatus st;
    st.running = s.sensorOk;
    st.stageEnabled = s.enabled;
    st.latched = s.latched;
    st.biased = s.proc->biased();
    st.zeroed = s.zeroed;
    st.biasCount = s.biasCount;
    st.zeroCount = s.zeroCount;
    st.moving = s.stage.moving;
    st.approaching = s.approach.has_value();
    st.jogging = s.jogging;
    st.recording = s.runOpen;
    st.rateHz = s.proc->rate();
    st.force_N = last.force_N;
    st.position_mm = last.position_mm;
    st.velocity_mm_s = last.velocity_mm_s;
    st.volts = last.volts;
    st.deviceTime_s = s.proc->lastTime_s();
    st.runTime_s = s.runOpen ? s.proc->lastTime_s() - s.runStart : 0.0;
    st.forceLimit_N = s.proc->insertionLimit();
    st.withdrawForceLimit_N = s.proc->withdrawalLimit();
    st.forceMargin_N = s.proc->margin_N(last.force_N);
    st.forceMarginOf_N = s.proc->guard() == ForceGuard::Withdrawal ? s.proc->withdrawalLimit() : s.proc->insertionLimit();
    st.loaded = s.proc->biased() && s.proc->slope() > 0 && std::fabs(last.force_N) > s.noiseBand_N;
    st.contactDepth_mm = s.contactDepth_mm;
    st.lastRunStart_mm = s.lastRunStart_mm;
    st.bias_V = s.proc->bias_V();
    st.slope_V_per_g = s.proc->slope();
    st.calibrationName = s.calibrationName;
    st.samples = c.samples;
    st.dropped = c.dropped;
    st.overruns = live_.overruns() + s.recorder.overruns();
    st.latePeriods = c.late;
    st.forceLimitTripped = s.proc->tripped();
    st.fault = s.fault;
    st.realtimeWarning = s.realtimeWarning;
    st.runPath = s.runOpen ? s.runPath : QString();
    st.punctures = s.runOpen ? static_cast<std::uint64_t>(s.proc->punctures()) : 0;
    return st;
}

void AcquisitionEngine::finishRun(EndReason reason, const QString& fault, const Metadata& extra)
{
    State& s = *state_;
    if (!s.runOpen)
        return;
    Metadata footer;
    footer.set(key::end_reason, fileName(reason));
    const std::uint64_t gaps = s.proc->counters().dropped - s.droppedAtStart;
    const std::uint64_t overruns = s.recorder.overruns() - s.recOverrunsAtStart;
    footer.set(key::sensor_gaps, static_cast<double>(gaps));
    footer.set(key::ring_overruns, static_cast<double>(overruns));
    footer.set(key::dropped, static_cast<double>(gaps + overruns));
    footer.set(key::late_periods, static_cast<double>(s.proc->counters().late - s.lateAtStart));
    if (s.trip) {
        footer.set(key::force_limit_tripped_s, QString::number(s.trip->time_s - s.runStart, 'f', 6));
        footer.set(key::force_limit_force_N, QString::number(s.trip->force_N, 'f', 4));
        footer.set(key::force_limit_position_mm, QString::number(s.trip->position_mm, 'f', 4));
        // The force was at least the reading there, and may have been any higher.
        if (s.trip->overRange)
            footer.set(key::force_over_range, QStringLiteral("true"));
    }
    if (s.punctureStop) {
        footer.set(QStringLiteral("puncture_stop_s"), QString::number(s.punctureStop->time_s - s.runStart, 'f', 6));
        footer.set(QStringLiteral("puncture_stop_position_mm"), QString::number(s.punctureStop->position_mm, 'f', 4));
    }
    if (!fault.isEmpty())
        footer.set(key::fault, fault);
    for (const auto& [k, v] : extra.entries())
        footer.set(k, v);
    footer.set(key::samples, static_cast<double>(s.runPushed));
    s.recorder.close(footer);
    // The recorder may fail while draining its last rows: then the run ended by a write
    // error whatever the reason asked for (the recorder's footer says so).
    const bool writeFailed = s.recorder.failed();
    const EndReason endReason = writeFailed ? EndReason::WriteError : reason;
    const std::uint64_t written = s.recorder.written();
    RunSummary summary{s.runPath, endReason, written, gaps + overruns,
                       writeFailed && fault.isEmpty() ? s.recorder.error() : fault, s.runStartPosition};
    s.runOpen = false;
    s.runMotion = false;
    s.pendingEndAt = -1.0;
    s.proc->watchPunctures(false);
    if (!s.stage.moving)
        s.proc->setGuard(ForceGuard::Off);
    s.statusDirty = true;
    emit message(tr("run ended (%1): %2 samples, %3 dropped, %4")
                     .arg(displayName(endReason))
                     .arg(written)
                     .arg(gaps + overruns)
                     .arg(s.runPath));
    emit runEnded(summary);
}

void AcquisitionEngine::raiseFault(const QString& device, const QString& reason, bool sensor)
{
    State& s = *state_;
    const QString text = QStringLiteral("%1: %2").arg(device, reason);
    if (sensor) {
        s.sensorOk = false;
        s.sensorRetryAt = hostNow() + kSensorRetry_s;
        try {
            s.dev.sensor->stop();
        } catch (const DeviceError&) {
        }
    }
    const bool fresh = s.fault != text;
    s.fault = text;
    // Stop the axis first: nothing else matters as much.
    try {
        s.dev.stage->emergencyStop();
    } catch (const DeviceError& e) {
        s.stageOk = false;
        s.stageRetryAt = hostNow() + kStageFaultPoll_s;
        if (fresh)
            emit message(tr("could not stop the stage: %1").arg(e.message()));
    }
    s.runMotion = false;
    s.approach.reset();
    s.jogging = false;
    if (fresh) {
        emit faultOccurred(device, reason);
        emit message(tr("fault: %1").arg(text));
    }
    if (s.runOpen)
        finishRun(EndReason::Fault, text);
}

void AcquisitionEngine::handle(const ProcessorEvent& e)
{
    State& s = *state_;
    switch (e.kind) {
    case ProcessorEvent::Kind::BiasDone:
        s.statusDirty = true;
        ++s.biasCount;
        emit message(tr("force sensor biased: V0 = %1 V (%2 samples)").arg(localNumber(e.bias_V, 5)).arg(e.count));
        warnOfUnreadableLimit();
        break;
    case ProcessorEvent::Kind::ForceLimit:
        s.statusDirty = true;
        s.runMotion = false;
        s.approach.reset();
        s.jogging = false;
        try {
            s.dev.stage->emergencyStop();
        } catch (const DeviceError& err) {
            raiseFault(err.device(), err.reason(), false);
        }
        emit forceLimitTripped(e.force_N, e.position_mm);
        if (e.overRange)
            emit message(tr("force limit: the load cell's reading reached the end of its input range at %1 N (%2 mm): "
                            "the force may be higher; stage stopped")
                             .arg(localNumber(e.force_N, 3))
                             .arg(localNumber(e.position_mm, 3)));
        else
            emit message(tr("force limit: %1 N > %2 N at %3 mm; stage stopped")
                             .arg(localNumber(e.force_N, 3))
                             .arg(e.limit_N)
                             .arg(localNumber(e.position_mm, 3)));
        if (s.runOpen && !s.trip) {
            s.trip = e;
            s.pendingEndAt = e.time_s + config_.forceLimitRecord_s;
            s.pendingEndReason = EndReason::ForceLimit;
        }
        break;
    case ProcessorEvent::Kind::Contact:
        if (s.runOpen && s.runIsInsertion && !s.contactDepth_mm)
            s.contactDepth_mm = e.position_mm;
        break;
    case ProcessorEvent::Kind::Puncture: {
        if (!s.runOpen || !s.runIsInsertion || !s.runMotion)
            break;
        const bool stop = s.stopAtPuncture > 0 && e.count >= static_cast<std::uint64_t>(s.stopAtPuncture);
        if (stop) {
            s.runMotion = false;
            s.dev.stage->emergencyStop();
            s.punctureStop = e;
            s.pendingEndAt = e.time_s + kStopRecord_s;
            s.pendingEndReason = EndReason::Puncture;
            emit message(tr("puncture %1 at %2 mm: stage stopped").arg(e.count).arg(localNumber(e.position_mm, 3)));
        } else if (s.slowAfterPuncture > 0 && e.count == 1) {
            LinearMotion slow = s.runLinear;
            slow.velocity_mm_s = s.slowAfterPuncture;
            s.dev.stage->moveLinear(slow);
            emit message(tr("puncture at %1 mm: slowing to %2 mm/s").arg(localNumber(e.position_mm, 3)).arg(s.slowAfterPuncture));
        }
        emit punctureDetected(e.position_mm, e.force_N, static_cast<int>(e.count), stop);
        s.statusDirty = true;
        break;
    }
    }
}

void AcquisitionEngine::endRunOnMotion(bool batchHadSamples)
{
    State& s = *state_;
    // An approach ends when the stage has come to rest at the start: then the run begins.
    if (s.approach) {
        if (s.stage.moving)
            s.sawApproachMoving = true;
        else if (s.sawApproachMoving && batchHadSamples) {
            RunPlan plan = *s.approach;
            s.approach.reset();
            s.jogging = false;
            openRun(plan);
        }
        return;
    }
    if (s.jogging && !s.runOpen) {
        if (s.stage.moving)
            s.sawJogMoving = true;
        else if (s.sawJogMoving) {
            s.jogging = false;
            s.proc->setGuard(ForceGuard::Off);
            s.statusDirty = true;
        }
    }
    if (!s.runOpen)
        return;
    if (s.pendingEndAt >= 0 && s.proc->lastTime_s() >= s.pendingEndAt) {
        finishRun(s.pendingEndReason, {});
    } else if (s.runMotion) {
        if (s.stage.moving)
            s.sawMoving = true;
        else if (s.sawMoving && batchHadSamples) {
            // Only with samples in hand: the read-back that shows the stop is put on the last
            // of them, so the run ends at the position where the axis did.
            s.runMotion = false;
            s.proc->setGuard(ForceGuard::Both);  // at rest but still recording
            if (s.endWhenDone)
                finishRun(EndReason::Completed, {});
        }
    }
}

void AcquisitionEngine::publishStatus()
{
    const EngineStatus st = snapshot();
    {
        std::lock_guard lock(mutex_);
        status_ = st;
    }
    emit statusChanged(st);
}

void AcquisitionEngine::threadMain()
{
    State& s = *state_;
    tid_ = static_cast<int>(::syscall(SYS_gettid));
    if (config_.realtimeScheduling) {
        const RealtimeResult rt = makeCurrentThreadRealtime();
        s.realtimeWarning = rt.warning;
        if (!rt.warning.isEmpty())
            emit message(tr("warning: %1").arg(rt.warning));
    } else {
        s.realtimeWarning = tr("real-time scheduling not requested");
    }
    auto startSensor = [&] {
        try {
            s.proc->setRate(s.dev.sensor->start(config_.rateHz));
            s.proc->setInputRange(s.dev.sensor->inputRange_V());
            s.sensorOk = true;
            s.proc->restartStream();
            // A standing fault stays until the operator enables the stage again.
        } catch (const DeviceError& e) {
            raiseFault(e.device(), e.reason(), true);
        }
    };
    startSensor();
    try {
        s.stage = s.dev.stage->state();
        s.enabled = s.stage.enabled;
    } catch (const DeviceError& e) {
        raiseFault(e.device(), e.reason(), false);
    }

    s.batch.reserve(4096);
    s.samples.reserve(4096);
    s.nextStatus = Clock::now();
    const auto statusPeriod = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / config_.statusRateHz));

    while (!quit_.load()) {
        // 1. Operator commands.
        std::deque<std::function<void()>> todo;
        {
            std::lock_guard lock(mutex_);
            todo.swap(commands_);
        }
        for (auto& c : todo) {
            try {
                c();
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), e.device() == s.dev.sensor->name());
            }
            s.statusDirty = true;
        }

        // 2. Samples.
        s.batch.clear();
        if (s.sensorOk) {
            try {
                s.dev.sensor->read(s.batch, kReadTimeout);
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), true);
            }
        } else {
            std::this_thread::sleep_for(kReadTimeout);
            if (hostNow() >= s.sensorRetryAt)
                startSensor();
        }
        const double arrival = hostNow();
        if (!s.batch.empty() && s.probe)
            s.probe(s.batch.back().deviceTime_s, arrival);

        // 3. The stage, read back once per batch.
        if (s.stageOk || arrival >= s.stageRetryAt) {
            try {
                s.stage = s.dev.stage->state();
                s.stageOk = true;
            } catch (const DeviceError& e) {
                if (s.stageOk)
                    raiseFault(e.device(), e.reason(), false);
                s.stageOk = false;
                s.stageRetryAt = arrival + kStageFaultPoll_s;
            }
        }

        // 4. The samples: converted and guarded by the processor, then handed on.
        s.samples.clear();
        s.events.clear();
        s.proc->process(s.batch, s.stage, arrival, s.samples, s.events);
        for (const ProcessorEvent& e : s.events)
            handle(e);
        for (const Sample& out : s.samples) {
            if (config_.liveView)
                live_.push(out);
            if (s.runOpen) {
                Sample rec = out;
                rec.time_s = out.time_s - s.runStart;
                if (s.recorder.push(rec))
                    ++s.runPushed;
            }
        }

        // 5. A write error (disk full, media removed) ends the run at once: stop the axis,
        // close with end_reason write_error, tell the operator.
        if (s.runOpen && s.recorder.failed()) {
            s.runMotion = false;
            try {
                s.dev.stage->stop();
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), false);
            }
            const QString why = s.recorder.error();
            emit message(tr("recording failed, stage stopped: %1").arg(why));
            finishRun(EndReason::WriteError, why);
        }
        if (const QString w = s.recorder.takeSpaceWarning(); !w.isEmpty())
            emit message(tr("warning: %1").arg(w));
        // Runs, approaches and jogs that end with the motion.
        endRunOnMotion(!s.batch.empty());

        // 6. Status at ~25 Hz.
        const auto now = Clock::now();
        if (now >= s.nextStatus || s.statusDirty) {
            s.nextStatus = now + statusPeriod;
            s.statusDirty = false;
            publishStatus();
        }

        // 7. A device clock that runs as fast as it is read has nothing to hurry through while
        // nothing happens: wait for the operator instead of racing it (and a core) ahead.
        if (!hostPaced_ && s.sensorOk && !s.runOpen && !s.proc->biasing() && !s.stage.moving && !s.approach) {
            std::unique_lock lock(mutex_);
            wake_.wait_for(lock, kIdleWait, [&] { return !commands_.empty() || quit_.load(); });
        }
    }

    // Shutting down: close the run, leave the axis at rest.
    if (s.runOpen)
        finishRun(EndReason::Stopped, {});
    try {
        if (s.stage.moving)
            s.dev.stage->stop();
    } catch (const DeviceError&) {
    }
    try {
        s.dev.sensor->stop();
    } catch (const DeviceError&) {
    }
    tid_ = 0;
}

}  // namespace nb::devices
