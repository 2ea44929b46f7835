#pragma once
// The engine's per-sample work, without threads or devices: a sensor batch and the stage's
// read-back go in, calibrated samples and what they set off come out. Counts gaps, puts the
// stage position on the sample clock, converts volts to force, averages the bias, guards the
// force limits and watches for a puncture. Tests push batches through it synchronously.

#include "devices/force_sensor.h"
#include "devices/ground_truth.h"
#include "devices/recorder.h"
#include "devices/stage.h"

#include "core/live_events.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace nb::devices {

// Which force the limit guards, by what the stage is doing.
enum class ForceGuard {
    Off,        // nothing moves and nothing records
    Insertion,  // going deeper: the insertion limit on the force pushing back
    Withdrawal, // coming out: the withdrawal limit on |F|, so the needle can always get out
    Both,       // sine, jog deeper, a recording at rest: the insertion limit on |F|
};

struct ProcessorEvent {
    enum class Kind { BiasDone, ForceLimit, Puncture, Contact };
    Kind kind;
    double time_s = 0.0;       // device time
    double force_N = 0.0;
    double position_mm = 0.0;
    double limit_N = 0.0;      // ForceLimit: the limit crossed
    bool overRange = false;    // ForceLimit: the reading reached the end of the sensor's input
    double bias_V = 0.0;       // BiasDone
    std::uint64_t count = 0;   // BiasDone: samples averaged; Puncture: punctures so far
};

struct ProcessorCounters {
    std::uint64_t samples = 0;  // since the stream started
    std::uint64_t dropped = 0;  // sensor gaps
    std::uint64_t late = 0;     // samples that arrived over a period late (host-paced clocks)
};

class SampleProcessor {
public:
    // `hostPaced`: the device clock runs in real time, so arrival lateness means something.
    SampleProcessor(double rateHz, bool hostPaced, std::shared_ptr<const GroundTruthSource> truth = {});

    void setRate(double rateHz) { rate_ = rateHz; }
    double rate() const { return rate_; }
    // The stream restarted (new sample counter) or the stage was zeroed.
    void restartStream();
    void forgetStageHistory() { prevStageTime_ = -1.0; stageTime_ = -1.0; }

    void setSlope(double slope_V_per_g) { slope_ = slope_V_per_g; }
    double slope() const { return slope_; }
    // Averages the voltage from the next sample on for `window_s` (device time), then
    // reports BiasDone and converts with the new V0.
    void startBias(double window_s);
    bool biasing() const { return biasing_; }
    bool biased() const { return biased_; }
    double bias_V() const { return v0_; }

    void setLimits(double insertion_N, double withdrawal_N);
    // The sensor's input range (±V; 0: not known). A guarded reading at its end trips the limit
    // as one over it does: the force is at least what is read, and may be any higher. A limit
    // beyond what the load cell can read never tripped (8 N against 7.79 N at +10 V on the
    // nominal calibration: a needle driven 20 mm into bone was saved as completed).
    void setInputRange(double range_V) { range_V_ = range_V; }
    // The largest force the sensor reads each way with the bias and slope now set (infinite
    // when the range is not known, 0 before a slope).
    double readableForce_N(int sign) const;
    double insertionLimit() const { return insertLimit_; }
    double withdrawalLimit() const { return withdrawLimit_; }
    void setGuard(ForceGuard guard) { guard_ = guard; }
    ForceGuard guard() const { return guard_; }
    // The force left before the guard now in force stops the stage: the insertion limit less F
    // while going in, the limit less |F| otherwise; with no guard (at rest, not recording) the
    // insertion limit less |F|, the next move's. A pull on the needle read as more margin than
    // the limit itself ("11 N (100 %)" against 8 N).
    double margin_N(double force_N) const;
    // After a trip the limit stays quiet until re-armed (the stop itself is over the limit).
    bool tripped() const { return tripped_; }
    void rearm() { tripped_ = false; }

    // Live contact/puncture on a linear insertion; off by default (null detector). The first
    // puncture must collapse the force by half its rise (a capsule gives way to the cutting
    // level; a diamond tip's pre-puncture notch is a fifth); later ones, interior structures
    // in tissue already cut, by `options.dropFraction`.
    void watchPunctures(bool on, LiveEventOptions options = {});
    int punctures() const { return punctures_; }

    // One sensor batch, with the stage read back after it (`stage` is put on the batch's last
    // sample) and the host time it arrived. Appends to `samples` and `events`.
    void process(std::span<const VoltageSample> batch, const StageState& stage, double arrival_s,
                 std::vector<Sample>& samples, std::vector<ProcessorEvent>& events);

    const ProcessorCounters& counters() const { return counters_; }
    double lastTime_s() const { return lastTime_; }
    const Sample& last() const { return last_; }

private:
    double positionAt(double t, const StageState& stage) const;
    bool overLimit(double force_N, double* limit) const;
    bool atRangeEnd(double volts) const;

    double rate_;
    bool hostPaced_;
    std::shared_ptr<const GroundTruthSource> truth_;
    ProcessorCounters counters_;
    std::uint64_t expected_ = 0;
    bool any_ = false;
    double hostOrigin_ = 0.0;  // host time minus device time, smallest seen
    double lastTime_ = 0.0;
    Sample last_;
    // The last two stage read-backs, each on the device time of its batch's last sample.
    double stageTime_ = -1.0, stagePos_ = 0.0, prevStageTime_ = -1.0, prevStagePos_ = 0.0;
    // Calibration.
    double slope_ = 0.0, v0_ = 0.0;
    bool biasing_ = false, biased_ = false, biasArmed_ = false;
    double biasWindow_ = 0.0, biasEnd_ = 0.0, biasSum_ = 0.0;
    std::uint64_t biasCount_ = 0;
    // Limits.
    double insertLimit_ = 8.0, withdrawLimit_ = 8.0;
    double range_V_ = 0.0;
    ForceGuard guard_ = ForceGuard::Off;
    bool tripped_ = false;
    // Punctures.
    std::optional<LiveEventDetector> detector_;
    int punctures_ = 0;
    double laterDropFraction_ = 0.2;
    double detectorT0_ = 0.0;
};

}  // namespace nb::devices
