#pragma once
// The acquisition engine: owns the devices, samples continuously on its own thread by the
// device clock (live view even when not recording), runs the operator's interlocks, records
// runs through the Recorder, and stops the stage on the force limit and on device faults.
//
// Public slots may be called from any thread: they are queued to the engine thread.
// Signals are emitted from the engine thread (connect with the default AutoConnection).

#include "core/end_reason.h"
#include "core/run.h"
#include "devices/device_set.h"
#include "devices/interlocks.h"
#include "devices/recorder.h"
#include "devices/spsc_ring.h"
#include "devices/stage.h"

#include <QObject>
#include <QString>
#include <atomic>
#include <cstdint>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace nb::devices {

struct ProcessorEvent;

struct RunPlan {
    enum class Motion { Linear, Sine };
    Motion motion = Motion::Linear;
    LinearMotion linear;
    SineMotion sine;
    QString outPath;
    Metadata metadata;            // protocol, tissue, ... (the engine adds rate, device, calibration)
    bool endWhenMotionDone = true; // false: keeps recording after the move until endRun()
    // Moves here first, unrecorded, and starts recording on arrival (a sine's centre inside
    // the tissue). Unset: the run starts where the stage is.
    std::optional<double> startAt_mm;
    double approachVelocity_mm_s = 5.0;
    // Linear insertions: stop after this many punctures (0: never), or slow to this velocity
    // after the first (0: keep going). Decided on the acquisition thread from the live force.
    int stopAtPuncture = 0;
    double slowAfterPuncture_mm_s = 0.0;
};

struct RunSummary {
    QString path;
    EndReason endReason = EndReason::Completed;
    std::uint64_t samples = 0;   // rows written
    std::uint64_t dropped = 0;   // samples lost (sensor gaps + recorder ring overruns)
    QString fault;
    double startPosition_mm = 0.0;  // where the stage stood when the run began
};

struct EngineStatus {
    bool running = false;        // the sampling thread is up and the sensor streaming
    bool stageEnabled = false, biased = false, zeroed = false, moving = false, recording = false;
    bool latched = false;        // an emergency stop holds until the stage is enabled again
    bool approaching = false;    // moving to a run's start position, not yet recording
    bool jogging = false;        // an unrecorded move the operator asked for
    double rateHz = 0.0;
    double force_N = 0.0, position_mm = 0.0, velocity_mm_s = 0.0, volts = 0.0;
    double deviceTime_s = 0.0;
    double runTime_s = 0.0;
    double forceLimit_N = 0.0;
    double withdrawForceLimit_N = 0.0;
    double forceMargin_N = 0.0;       // left before the limit in force now stops the stage
    double forceMarginOf_N = 0.0;     // that limit
    std::optional<double> contactDepth_mm;  // where the last insertion met tissue, since the last zero
    std::optional<double> lastRunStart_mm;  // where the last run began: "withdraw to the start"
    double bias_V = 0.0, slope_V_per_g = 0.0;
    QString calibrationName;
    std::uint64_t samples = 0;   // since the engine started
    std::uint64_t dropped = 0;   // sensor gaps
    std::uint64_t overruns = 0;  // live + recorder ring overruns
    std::uint64_t latePeriods = 0;
    bool forceLimitTripped = false;
    bool loaded = false;         // |F| above the noise band (biased and calibrated)
    QString fault;               // empty when healthy
    QString realtimeWarning;     // empty when SCHED_FIFO + mlockall were granted
    QString runPath;
    std::uint64_t punctures = 0; // during the open run
    // Biases and zeroes done since the engine started: "done since the last run" for a checklist.
    std::uint64_t biasCount = 0, zeroCount = 0;

    // What the operator may do now, as far as the engine can tell (the window adds what it
    // knows: the session, the motion fields).
    InterlockState interlocks() const;
};

struct EngineConfig {
    double rateHz = 500.0;               // 100 .. 10000
    double forceLimit_N = 8.0;           // below the 10 N capacity; guards insertion
    double withdrawForceLimit_N = 9.5;   // |F| while the needle comes out (never below the insertion limit)
    double noiseBand_N = 0.05;           // |F| above this is "loaded": bias and zero are refused
    bool realtimeScheduling = true;      // SCHED_FIFO when permitted (off for as-fast-as-possible sims)
    std::size_t liveCapacity = 1 << 15;
    double statusRateHz = 25.0;
    double bias_s = 0.5;                 // tare averaging window
    bool liveView = true;                // false: nothing drains liveRing() (headless), don't feed it
    double forceLimitRecord_s = 0.2;     // keeps recording this long after a force-limit stop
};

class AcquisitionEngine : public QObject {
    Q_OBJECT
public:
    explicit AcquisitionEngine(DeviceSet devices, EngineConfig config = {}, QObject* parent = nullptr);
    ~AcquisitionEngine() override;  // ends an open run ("stopped"), stops the stage, joins

    // Starts the sampling thread (idempotent).
    void start();
    // Stops sampling; an open run ends with "stopped".
    void shutdown();

    // Single consumer: the GUI thread (drain at 25-60 Hz).
    SpscRing<Sample>& liveRing() { return live_; }
    QString deviceDescription() const { return description_; }
    // What the device set can do beyond its stage and sensor (null when it cannot).
    std::shared_ptr<CalibrationLoad> calibrationLoad() const { return calibrationLoad_; }
    std::shared_ptr<GroundTruthSource> groundTruth() const { return truth_; }
    // The sensor chain's nominal calibration (V/g), 0 when the devices do not know it.
    double nominalSlope_V_per_g() const { return nominalSlope_; }
    // Thread-safe snapshot (also sent by statusChanged).
    EngineStatus status() const;
    // Linux thread ids for CPU accounting (0 when not running).
    int acquisitionThreadId() const { return tid_.load(); }
    int recorderThreadId() const;
    // Called on the engine thread for every sensor batch: device time of its last sample and
    // the host's monotonic time when it arrived (bench jitter figures). Set before start().
    void setArrivalProbe(std::function<void(double deviceTime_s, double hostTime_s)> probe);

public slots:
    // Enabling also releases an emergency-stop latch: the operator's deliberate reset.
    void enableStage(bool on);
    // `insist`: the operator confirmed a bias or zero the interlocks advised against.
    void biasSensor(bool insist = false);
    void zeroStage(bool insist = false);
    // Each change is said (message()) unless `quietly`: the window's own settings at start are
    // no news, and their echo replaced what the status line had to say.
    void setForceLimit(double newtons, bool quietly = false);
    void setWithdrawForceLimit(double newtons, bool quietly = false);
    void setCalibration(double slope_V_per_g, const QString& name);
    // Back to the device's nominal calibration (none when it has none): a session without a
    // calibration of its own must not inherit the last session's.
    void useNominalCalibration();
    void startRun(const nb::devices::RunPlan& plan);
    // Out to `target_mm` (default 0), never recorded unless a run is open; guarded by the
    // withdrawal limit, so a force-limit stop never traps the needle.
    void withdraw(double velocity_mm_s, double target_mm = 0.0);
    // Unrecorded moves: by `delta_mm`, or to a position, within the stage's travel.
    void jog(double delta_mm, double velocity_mm_s);
    void moveTo(double position_mm, double velocity_mm_s);
    void stopMotion();
    void endRun();
    void emergencyStop();
    // The program is told to end (a signal): stop the motion, close the run as `interrupted`
    // with `extra` in its footer (signal: SIGTERM).
    void interrupt(const nb::Metadata& extra = {});

signals:
    void statusChanged(const nb::devices::EngineStatus& status);
    void runStarted(const QString& path);
    // A stop at puncture or a slow-down after one (stopped = the stage was stopped).
    void punctureDetected(double position_mm, double force_N, int count, bool stopped);
    void runEnded(const nb::devices::RunSummary& summary);
    void faultOccurred(const QString& device, const QString& reason);
    void forceLimitTripped(double force_N, double position_mm);
    // startRun() refused (not enabled/biased/zeroed, already recording, bad plan...).
    void runRefused(const QString& reason);
    void message(const QString& text);

private:
    struct State;
    void post(std::function<void()> command);
    void threadMain();
    void finishRun(EndReason reason, const QString& fault, const Metadata& extra = {});
    void raiseFault(const QString& device, const QString& reason, bool sensor);
    void openRun(const RunPlan& plan);
    void beginMove(const LinearMotion& motion, bool recordedInsertion);
    void handle(const ProcessorEvent& e);
    void warnOfUnreadableLimit();
    void endRunOnMotion(bool batchHadSamples);
    void publishStatus();
    EngineStatus snapshot() const;

    std::shared_ptr<GroundTruthSource> truth_;
    std::shared_ptr<CalibrationLoad> calibrationLoad_;
    double nominalSlope_ = 0.0;
    bool hostPaced_ = true;
    QString description_;
    QString fileDescription_;  // the same in English, for run files
    EngineConfig config_;
    SpscRing<Sample> live_;
    std::unique_ptr<State> state_;  // owned by the engine thread
    std::thread thread_;
    std::atomic<bool> quit_{false};
    std::atomic<int> tid_{0};
    mutable std::mutex mutex_;      // guards commands_, status_
    std::deque<std::function<void()>> commands_;
    std::condition_variable wake_;  // a command arrived, or quit
    EngineStatus status_;
};

}  // namespace nb::devices

Q_DECLARE_METATYPE(nb::devices::RunPlan)
Q_DECLARE_METATYPE(nb::devices::RunSummary)
Q_DECLARE_METATYPE(nb::devices::EngineStatus)
