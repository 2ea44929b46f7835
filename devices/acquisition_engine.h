#pragma once
// The acquisition engine: owns the devices, samples continuously on its own thread by the
// device clock (live view even when not recording), runs the operator's interlocks, records
// runs through the Recorder, and stops the stage on the force limit and on device faults.
//
// Public slots may be called from any thread: they are queued to the engine thread.
// Signals are emitted from the engine thread (connect with the default AutoConnection).

#include "core/run.h"
#include "devices/device_set.h"
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
#include <thread>

namespace nb::devices {

struct RunPlan {
    enum class Motion { Linear, Sine };
    Motion motion = Motion::Linear;
    LinearMotion linear;
    SineMotion sine;
    QString outPath;
    Metadata metadata;            // protocol, tissue, ... (the engine adds rate, device, calibration)
    bool endWhenMotionDone = true; // false: keeps recording after the move until endRun()
};

struct RunSummary {
    QString path;
    QString endReason;           // completed | stopped | force_limit | fault
    std::uint64_t samples = 0;   // rows written
    std::uint64_t dropped = 0;   // samples lost (sensor gaps + recorder ring overruns)
    QString fault;
};

struct EngineStatus {
    bool running = false;        // the sampling thread is up and the sensor streaming
    bool stageEnabled = false, biased = false, zeroed = false, moving = false, recording = false;
    double rateHz = 0.0;
    double force_N = 0.0, position_mm = 0.0, velocity_mm_s = 0.0, volts = 0.0;
    double deviceTime_s = 0.0;
    double runTime_s = 0.0;
    double forceLimit_N = 0.0;
    double bias_V = 0.0, slope_V_per_g = 0.0;
    QString calibrationName;
    std::uint64_t samples = 0;   // since the engine started
    std::uint64_t dropped = 0;   // sensor gaps
    std::uint64_t overruns = 0;  // live + recorder ring overruns
    std::uint64_t latePeriods = 0;
    bool forceLimitTripped = false;
    QString fault;               // empty when healthy
    QString realtimeWarning;     // empty when SCHED_FIFO + mlockall were granted
    QString runPath;
};

struct EngineConfig {
    double rateHz = 500.0;               // 100 .. 10000
    double forceLimit_N = 8.0;           // below the 10 N capacity
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
    // The simulated rig behind the devices, or null.
    std::shared_ptr<sim::SimulatedRig> rig() const { return rig_; }
    QString deviceDescription() const { return description_; }
    // Thread-safe snapshot (also sent by statusChanged).
    EngineStatus status() const;
    // Linux thread ids for CPU accounting (0 when not running).
    int acquisitionThreadId() const { return tid_.load(); }
    int recorderThreadId() const;
    // Called on the engine thread for every sensor batch: device time of its last sample and
    // the host's monotonic time when it arrived (bench jitter figures). Set before start().
    void setArrivalProbe(std::function<void(double deviceTime_s, double hostTime_s)> probe);

public slots:
    void enableStage(bool on);
    void biasSensor();
    void zeroStage();
    void setForceLimit(double newtons);
    void setCalibration(double slope_V_per_g, const QString& name);
    void startRun(const nb::devices::RunPlan& plan);
    void withdraw(double velocity_mm_s);
    void stopMotion();
    void endRun();
    // [issue 15, data] Stops motion and closes the run with this end reason (e.g.
    // "interrupted") and extra footer lines (e.g. signal: SIGTERM).
    void endRun(const QString& reason, const nb::Metadata& extra);
    void emergencyStop();

signals:
    void statusChanged(const nb::devices::EngineStatus& status);
    void runStarted(const QString& path);
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
    void finishRun(const QString& reason, const QString& fault, const Metadata& extra = {});
    void raiseFault(const QString& device, const QString& reason, bool sensor);

    std::shared_ptr<sim::SimulatedRig> rig_;
    QString description_;
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
