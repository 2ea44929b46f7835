#include "acquisition_engine.h"

#include "core/models.h"
#include "core/run_file.h"
#include "devices/device_error.h"
#include "devices/realtime.h"
#include "devices/sim/simulated_rig.h"

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

double hostNow() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }
}  // namespace

struct AcquisitionEngine::State {
    DeviceSet dev;
    // Calibration and interlocks.
    double slope = 0.0;
    QString calibrationName;
    double v0 = 0.0;
    bool biased = false, enabled = false, zeroed = false;
    bool biasing = false;
    double biasSum = 0.0, biasEnd = 0.0;
    std::uint64_t biasCount = 0;
    double forceLimit = 8.0;
    // Devices' health.
    bool sensorOk = false;
    double sensorRetryAt = 0.0;  // host time
    bool stageOk = true;
    double stageRetryAt = 0.0;
    QString fault;
    QString realtimeWarning;
    // Stream bookkeeping.
    double rate = 500.0;
    std::uint64_t expected = 0;  // next sensor index
    bool any = false;
    std::uint64_t samples = 0, dropped = 0, late = 0;
    double hostOrigin = 0.0;     // host time minus device time, smallest seen
    double lastTime = 0.0;
    Sample last;
    StageState stage;
    double stageTime = -1.0, stagePosAtTime = 0.0, prevStagePos = 0.0, prevStageTime = -1.0;
    // The open run.
    Recorder recorder;
    bool runOpen = false;
    QString runPath;
    double runStart = 0.0;       // device time of the run's first sample
    bool runMotion = false, endWhenDone = true, sawMoving = false;
    std::uint64_t droppedAtStart = 0;
    std::uint64_t lateAtStart = 0;
    std::uint64_t recOverrunsAtStart = 0;
    std::uint64_t runPushed = 0;
    bool tripped = false;
    double tripForce = 0.0, tripPosition = 0.0, tripTime = 0.0;
    double pendingEndAt = -1.0;  // device time
    QString pendingEndReason;
    // Status: at the status rate, and at once when an interlock or the run changes.
    Clock::time_point nextStatus;
    bool statusDirty = false;
    std::function<void(double, double)> probe;
};

AcquisitionEngine::AcquisitionEngine(DeviceSet devices, EngineConfig config, QObject* parent)
    : QObject(parent),
      rig_(devices.rig),
      description_(devices.description),
      config_(config),
      live_(config.liveCapacity),
      state_(std::make_unique<State>())
{
    qRegisterMetaType<nb::devices::EngineStatus>();
    qRegisterMetaType<nb::devices::RunSummary>();
    qRegisterMetaType<nb::devices::RunPlan>();
    config_.rateHz = std::clamp(config_.rateHz, 100.0, 10000.0);
    state_->dev = std::move(devices);
    state_->slope = state_->dev.nominalSlope_V_per_g;
    state_->calibrationName = state_->slope > 0 ? tr("nominal (device)") : QString();
    state_->forceLimit = config_.forceLimit_N;
    state_->rate = config_.rateHz;
    status_.rateHz = config_.rateHz;
    status_.forceLimit_N = config_.forceLimit_N;
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
// Each lambda below runs inside threadMain(), which turns a DeviceError into a fault.

void AcquisitionEngine::enableStage(bool on)
{
    post([this, on] {
        State& s = *state_;
        s.dev.stage->enable(on);
        s.enabled = on;
        s.zeroed = false;  // enabling may move the axis: the operator zeroes again
        s.stageOk = true;
        if (on && s.sensorOk && !s.fault.isEmpty()) {
            s.fault.clear();
            emit message(tr("stage enabled; fault cleared"));
        } else {
            emit message(on ? tr("stage enabled") : tr("stage disabled"));
        }
    });
}

void AcquisitionEngine::biasSensor()
{
    post([this] {
        State& s = *state_;
        if (s.stage.moving) {
            emit message(tr("bias refused: the stage is moving (bias with the needle at rest, out of tissue)"));
            return;
        }
        s.biasing = true;
        s.biasSum = 0.0;
        s.biasCount = 0;
        s.biasEnd = s.lastTime + config_.bias_s;
        emit message(tr("biasing the force sensor: averaging %1 s").arg(config_.bias_s));
    });
}

void AcquisitionEngine::zeroStage()
{
    post([this] {
        State& s = *state_;
        if (s.stage.moving) {
            emit message(tr("zero refused: the stage is moving"));
            return;
        }
        s.dev.stage->zero();
        s.zeroed = true;
        s.prevStageTime = -1.0;
        emit message(tr("stage position zeroed"));
    });
}

void AcquisitionEngine::setForceLimit(double newtons)
{
    post([this, newtons] {
        if (!(newtons > 0.0)) {
            emit message(tr("force limit must be positive (got %1 N)").arg(newtons));
            return;
        }
        state_->forceLimit = newtons;
        emit message(tr("force limit %1 N").arg(newtons));
    });
}

void AcquisitionEngine::setCalibration(double slope_V_per_g, const QString& name)
{
    post([this, slope_V_per_g, name] {
        if (!(slope_V_per_g > 0.0) || !std::isfinite(slope_V_per_g)) {
            emit message(tr("calibration refused: slope must be positive (got %1 V/g)").arg(slope_V_per_g));
            return;
        }
        state_->slope = slope_V_per_g;
        state_->calibrationName = name;
        emit message(tr("calibration '%1': %2 V/g").arg(name).arg(slope_V_per_g, 0, 'g', 6));
    });
}

void AcquisitionEngine::startRun(const RunPlan& plan)
{
    post([this, plan] {
        State& s = *state_;
        QString refusal;
        if (!s.fault.isEmpty())
            refusal = tr("a device is faulted (%1); fix it and enable the stage again").arg(s.fault);
        else if (!s.sensorOk)
            refusal = tr("the force sensor is not streaming");
        else if (!s.enabled)
            refusal = tr("enable the stage first");
        else if (s.biasing)
            refusal = tr("wait until biasing has finished");
        else if (!s.biased)
            refusal = tr("bias the force sensor first (needle at rest, out of tissue)");
        else if (!s.zeroed)
            refusal = tr("zero the stage position first");
        else if (s.runOpen)
            refusal = tr("a run is already being recorded (%1)").arg(s.runPath);
        else if (s.stage.moving)
            refusal = tr("the stage is still moving");
        else if (plan.outPath.isEmpty())
            refusal = tr("no output file given");
        if (!refusal.isEmpty()) {
            emit runRefused(tr("run not started: %1").arg(refusal));
            emit message(tr("run not started: %1").arg(refusal));
            return;
        }
        Metadata meta = plan.metadata;
        meta.set(QStringLiteral("rate_hz"), s.rate);
        meta.set(QStringLiteral("device"), description_);
        meta.set(QStringLiteral("calibration"), s.calibrationName);
        meta.set(QStringLiteral("slope_V_per_g"), QString::number(s.slope, 'g', 8));
        meta.set(QStringLiteral("bias_V"), QString::number(s.v0, 'f', 6));
        meta.set(QStringLiteral("force_limit_N"), s.forceLimit);
        meta.set(QStringLiteral("motion"), plan.motion == RunPlan::Motion::Linear ? QStringLiteral("linear") : QStringLiteral("sine"));
        s.runStart = s.lastTime + 1.0 / s.rate;
        meta.set(QStringLiteral("run_start_device_time_s"), QString::number(s.runStart, 'f', 6));
        meta.set(QStringLiteral("position_source"), tr("stage read-back, interpolated to the sample clock"));
        try {
            s.recorder.open(plan.outPath, meta, rig_ != nullptr);
        } catch (const RunFileError& e) {
            const QString why = tr("run not started: %1").arg(e.message());
            emit runRefused(why);
            emit message(why);
            return;
        }
        s.runOpen = true;
        s.runPath = plan.outPath;
        s.droppedAtStart = s.dropped;
        s.lateAtStart = s.late;
        s.recOverrunsAtStart = s.recorder.overruns();
        s.runPushed = 0;
        s.tripped = false;
        s.pendingEndAt = -1.0;
        s.runMotion = true;
        s.endWhenDone = plan.endWhenMotionDone;
        s.sawMoving = false;
        emit runStarted(plan.outPath);
        emit message(tr("recording to %1").arg(plan.outPath));
        if (plan.motion == RunPlan::Motion::Linear)
            s.dev.stage->moveLinear(plan.linear);
        else
            s.dev.stage->moveSine(plan.sine);
    });
}

void AcquisitionEngine::withdraw(double velocity_mm_s)
{
    post([this, velocity_mm_s] {
        State& s = *state_;
        s.runMotion = false;
        s.tripped = false;
        s.dev.stage->moveLinear({std::fabs(velocity_mm_s), 0.0});
        emit message(s.runOpen ? tr("withdrawing to 0 mm; this is recorded in the open run %1").arg(s.runPath)
                               : tr("withdrawing to 0 mm (not recorded: no run open)"));
    });
}

void AcquisitionEngine::stopMotion()
{
    post([this] {
        State& s = *state_;
        s.runMotion = false;
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
            finishRun(QStringLiteral("stopped"), {});
    });
}

// [issue 15, data] endRun with a reason: how a signal (SIGTERM, SIGINT, SIGHUP) closes a run.
void AcquisitionEngine::endRun(const QString& reason, const Metadata& extra)
{
    post([this, reason, extra] {
        State& s = *state_;
        s.runMotion = false;
        if (s.stage.moving) {
            try {
                s.dev.stage->stop();
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), false);
            }
        }
        if (s.runOpen)
            finishRun(reason, {}, extra);
    });
}

void AcquisitionEngine::emergencyStop()
{
    post([this] {
        State& s = *state_;
        s.runMotion = false;
        s.dev.stage->emergencyStop();
        emit message(tr("emergency stop"));
        if (s.runOpen) {
            Metadata extra;
            extra.set(QStringLiteral("emergency_stop"), QStringLiteral("operator"));
            finishRun(QStringLiteral("stopped"), {}, extra);
        }
    });
}

// ---- the engine thread ------------------------------------------------------------------

void AcquisitionEngine::finishRun(const QString& reason, const QString& fault, const Metadata& extra)
{
    State& s = *state_;
    if (!s.runOpen)
        return;
    Metadata footer;
    footer.set(QStringLiteral("end_reason"), reason);
    const std::uint64_t gaps = s.dropped - s.droppedAtStart;
    const std::uint64_t overruns = s.recorder.overruns() - s.recOverrunsAtStart;
    footer.set(QStringLiteral("sensor_gaps"), static_cast<double>(gaps));
    footer.set(QStringLiteral("ring_overruns"), static_cast<double>(overruns));
    footer.set(QStringLiteral("dropped"), static_cast<double>(gaps + overruns));
    footer.set(QStringLiteral("late_periods"), static_cast<double>(s.late - s.lateAtStart));
    if (s.tripped) {
        footer.set(QStringLiteral("force_limit_tripped_s"), QString::number(s.tripTime - s.runStart, 'f', 6));
        footer.set(QStringLiteral("force_limit_force_N"), QString::number(s.tripForce, 'f', 4));
        footer.set(QStringLiteral("force_limit_position_mm"), QString::number(s.tripPosition, 'f', 4));
    }
    if (!fault.isEmpty())
        footer.set(QStringLiteral("fault"), fault);
    for (const auto& [k, v] : extra.entries())
        footer.set(k, v);
    footer.set(QStringLiteral("samples"), static_cast<double>(s.runPushed));
    s.recorder.close(footer);
    // [issue 15, data] The recorder may fail while draining its last rows: then the run
    // ended by a write error whatever the reason asked for (the recorder's footer says so).
    const bool writeFailed = s.recorder.failed();
    const QString endReason = writeFailed ? QStringLiteral("write_error") : reason;
    const std::uint64_t written = s.recorder.written();
    RunSummary summary{s.runPath, endReason, written, gaps + overruns, writeFailed && fault.isEmpty() ? s.recorder.error() : fault};
    s.runOpen = false;
    s.runMotion = false;
    s.pendingEndAt = -1.0;
    s.statusDirty = true;
    emit message(tr("run ended (%1): %2 samples, %3 dropped, %4").arg(endReason).arg(written).arg(gaps + overruns).arg(s.runPath));
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
    if (fresh) {
        emit faultOccurred(device, reason);
        emit message(tr("fault: %1").arg(text));
    }
    if (s.runOpen)
        finishRun(QStringLiteral("fault"), text);
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
            s.rate = s.dev.sensor->start(config_.rateHz);
            s.sensorOk = true;
            s.any = false;
            s.prevStageTime = -1.0;
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

    const bool hostPaced = !rig_ || rig_->config().realtime;
    std::vector<VoltageSample> batch;
    batch.reserve(4096);
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
        batch.clear();
        if (s.sensorOk) {
            try {
                s.dev.sensor->read(batch, kReadTimeout);
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), true);
            }
        } else {
            std::this_thread::sleep_for(kReadTimeout);
            if (hostNow() >= s.sensorRetryAt)
                startSensor();
        }
        const double arrival = hostNow();
        if (!batch.empty() && s.probe)
            s.probe(batch.back().deviceTime_s, arrival);

        // 3. The stage, read back once per batch.
        if (s.stageOk || arrival >= s.stageRetryAt) {
            try {
                s.stage = s.dev.stage->state();
                s.stageOk = true;
                if (!batch.empty()) {
                    s.prevStagePos = s.stageTime >= 0 ? s.stagePosAtTime : s.stage.position_mm;
                    s.prevStageTime = s.stageTime;
                    s.stageTime = batch.back().deviceTime_s;
                    s.stagePosAtTime = s.stage.position_mm;
                }
            } catch (const DeviceError& e) {
                if (s.stageOk)
                    raiseFault(e.device(), e.reason(), false);
                s.stageOk = false;
                s.stageRetryAt = arrival + kStageFaultPoll_s;
            }
        }

        // 4. Each sample: convert, check the limit, hand on.
        const double period = 1.0 / s.rate;
        for (const VoltageSample& v : batch) {
            if (s.any && v.index > s.expected)
                s.dropped += v.index - s.expected;
            s.expected = v.index + 1;
            if (!s.any || arrival - v.deviceTime_s < s.hostOrigin)
                s.hostOrigin = arrival - v.deviceTime_s;
            s.any = true;
            if (hostPaced && arrival - s.hostOrigin - v.deviceTime_s > period)
                ++s.late;
            ++s.samples;
            s.lastTime = v.deviceTime_s;

            Sample out;
            out.seq = v.index;
            out.time_s = v.deviceTime_s;
            out.volts = v.volts;
            // Position on the sample clock: linear between the last two read-backs.
            double pos = s.stage.position_mm;
            if (s.prevStageTime >= 0 && s.stageTime > s.prevStageTime && v.deviceTime_s < s.stageTime) {
                const double f = (v.deviceTime_s - s.prevStageTime) / (s.stageTime - s.prevStageTime);
                pos = s.prevStagePos + std::clamp(f, 0.0, 1.0) * (s.stagePosAtTime - s.prevStagePos);
            }
            out.position_mm = pos;
            out.velocity_mm_s = s.stage.velocity_mm_s;
            out.force_N = s.slope > 0 ? forceFromVolts(v.volts, s.v0, s.slope) : 0.0;

            if (s.biasing) {
                s.biasSum += v.volts;
                ++s.biasCount;
                if (v.deviceTime_s >= s.biasEnd && s.biasCount > 0) {
                    s.v0 = s.biasSum / static_cast<double>(s.biasCount);
                    s.biasing = false;
                    s.biased = true;
                    s.statusDirty = true;
                    emit message(tr("force sensor biased: V0 = %1 V (%2 samples)").arg(s.v0, 0, 'f', 5).arg(s.biasCount));
                }
            }

            // The force limit: the first sample over it stops the axis, before anything else.
            if (s.biased && !s.tripped && std::fabs(out.force_N) > s.forceLimit && (s.stage.moving || s.runOpen)) {
                s.tripped = true;
                s.statusDirty = true;
                s.tripForce = out.force_N;
                s.tripPosition = out.position_mm;
                s.tripTime = v.deviceTime_s;
                s.runMotion = false;
                try {
                    s.dev.stage->emergencyStop();
                } catch (const DeviceError& e) {
                    raiseFault(e.device(), e.reason(), false);
                }
                emit forceLimitTripped(out.force_N, out.position_mm);
                emit message(tr("force limit: %1 N > %2 N at %3 mm; stage stopped")
                                 .arg(out.force_N, 0, 'f', 3)
                                 .arg(s.forceLimit)
                                 .arg(out.position_mm, 0, 'f', 3));
                if (s.runOpen) {
                    // Record the stop itself, then close.
                    s.pendingEndAt = v.deviceTime_s + config_.forceLimitRecord_s;
                    s.pendingEndReason = QStringLiteral("force_limit");
                }
            }

            if (rig_) {
                const sim::SampleTruth t = rig_->sampleTruth(v.index);
                out.tissue_position_mm = t.tissue_mm;
                out.phase = t.phase;
            }
            s.last = out;
            if (config_.liveView)
                live_.push(out);
            if (s.runOpen) {
                Sample rec = out;
                rec.time_s = out.time_s - s.runStart;
                if (s.recorder.push(rec))
                    ++s.runPushed;
            }
        }

        // 5. Run bookkeeping.
        // [issue 15, data] A write error (disk full, media removed) ends the run at once:
        // stop the axis, close with end_reason write_error, tell the operator.
        if (s.runOpen && s.recorder.failed()) {
            s.runMotion = false;
            try {
                s.dev.stage->stop();
            } catch (const DeviceError& e) {
                raiseFault(e.device(), e.reason(), false);
            }
            const QString why = s.recorder.error();
            emit message(tr("recording failed, stage stopped: %1").arg(why));
            finishRun(QStringLiteral("write_error"), why);
        }
        if (const QString w = s.recorder.takeSpaceWarning(); !w.isEmpty())
            emit message(tr("warning: %1").arg(w));
        if (s.runOpen) {
            if (s.pendingEndAt >= 0 && s.lastTime >= s.pendingEndAt) {
                finishRun(s.pendingEndReason, {});
            } else if (s.runMotion) {
                if (s.stage.moving)
                    s.sawMoving = true;
                else if (s.sawMoving && !batch.empty()) {
                    // Only with samples in hand: the read-back that shows the stop is put on
                    // the last of them, so the run ends at the position where the axis did.
                    s.runMotion = false;
                    if (s.endWhenDone)
                        finishRun(QStringLiteral("completed"), {});
                }
            }
        }

        // 6. Status at ~25 Hz.
        const auto now = Clock::now();
        if (now >= s.nextStatus || s.statusDirty) {
            s.nextStatus = now + statusPeriod;
            s.statusDirty = false;
            EngineStatus st;
            st.running = s.sensorOk;
            st.stageEnabled = s.enabled;
            st.biased = s.biased;
            st.zeroed = s.zeroed;
            st.moving = s.stage.moving;
            st.recording = s.runOpen;
            st.rateHz = s.rate;
            st.force_N = s.last.force_N;
            st.position_mm = s.last.position_mm;
            st.velocity_mm_s = s.last.velocity_mm_s;
            st.volts = s.last.volts;
            st.deviceTime_s = s.lastTime;
            st.runTime_s = s.runOpen ? s.lastTime - s.runStart : 0.0;
            st.forceLimit_N = s.forceLimit;
            st.bias_V = s.v0;
            st.slope_V_per_g = s.slope;
            st.calibrationName = s.calibrationName;
            st.samples = s.samples;
            st.dropped = s.dropped;
            st.overruns = live_.overruns() + s.recorder.overruns();
            st.latePeriods = s.late;
            st.forceLimitTripped = s.tripped;
            st.fault = s.fault;
            st.realtimeWarning = s.realtimeWarning;
            st.runPath = s.runOpen ? s.runPath : QString();
            {
                std::lock_guard lock(mutex_);
                status_ = st;
            }
            emit statusChanged(st);
        }

        // 7. A simulated rig running as fast as possible has nothing to hurry through while
        // nothing happens: wait for the operator instead of racing its clock (and a core) ahead.
        if (!hostPaced && s.sensorOk && !s.runOpen && !s.biasing && !s.stage.moving) {
            std::unique_lock lock(mutex_);
            wake_.wait_for(lock, kIdleWait, [&] { return !commands_.empty() || quit_.load(); });
        }
    }

    // Shutting down: close the run, leave the axis at rest.
    if (s.runOpen)
        finishRun(QStringLiteral("stopped"), {});
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
