#pragma once
// Writes one run file on its own thread from a ring of samples, flushing at least every
// 100 ms so that a crash (even kill -9) loses at most the last 100 ms.
//
// A write error (disk full, removed media, permissions) is never swallowed: failed() turns
// true at once for the engine to poll (it stops the motion and closes the run with
// end_reason write_error), error() says why, the rows before it stay whole and the footer
// still goes in (its space is reserved). Free space is checked before the run and watched
// during it: spaceWarning() says when the disk will be full within a minute.

#include "core/run.h"
#include "devices/ground_truth.h"
#include "devices/spsc_ring.h"

#include <QString>
#include <QStringList>
#include <atomic>
#include <cstdint>
#include <limits>
#include <mutex>
#include <thread>

namespace nb::devices {

// One acquired sample. `seq` is the sensor's sample counter; `time_s` its device clock.
struct Sample {
    std::uint64_t seq = 0;
    double time_s = 0.0;
    double position_mm = 0.0;
    double force_N = 0.0;
    double volts = 0.0;
    double velocity_mm_s = 0.0;
    // Only from a device set with a ground-truth source (NaN / None otherwise).
    double tissue_position_mm = std::numeric_limits<double>::quiet_NaN();
    TruePhase phase = TruePhase::None;
};

class Recorder {
public:
    static constexpr int kFlushPeriod_ms = 50;

    Recorder();
    ~Recorder();  // closes an open file with end_reason "aborted"
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    // Opens the file (throws RunFileError: not writable, locked by another writer, less
    // than kMinFreeBytesToRecord free) and starts the writer thread.
    // `truthColumns` adds tissue_position_mm and phase.
    void open(const QString& path, const Metadata& metadata, bool truthColumns);
    // Producer side (the acquisition thread): false when the ring was full (sample lost).
    bool push(const Sample& s) { return ring_.push(s); }
    // Drains everything pushed so far, appends the footer and closes. Blocking.
    void close(const Metadata& footer);
    bool isOpen() const { return running_.load(); }
    QString path() const;
    std::uint64_t written() const { return written_.load(); }
    std::uint64_t overruns() const { return ring_.overruns(); }
    // A write error seen by the writer thread (disk full...), empty if none.
    QString error() const;
    // Cheap to poll on every batch: true once a write has failed.
    bool failed() const { return failed_.load(std::memory_order_acquire); }
    // Set once while recording when the disk will be full within kLowSpaceWarning_s at the
    // current rate (empty otherwise); seconds left, +inf when unknown.
    QString spaceWarning() const;
    double secondsOfSpaceLeft() const { return spaceLeft_s_.load(); }
    // The space warning once, the first time it is asked for after it was raised (empty
    // otherwise): cheap to poll on every batch.
    QString takeSpaceWarning();
    // Linux thread id of the writer thread (for CPU accounting), 0 when not running.
    int threadId() const { return tid_.load(); }

private:
    void writerLoop();
    void watchSpace();
    SpscRing<Sample> ring_;
    std::thread thread_;
    std::atomic<bool> running_{false};
    std::atomic<bool> stopRequested_{false};
    std::atomic<std::uint64_t> written_{0};
    std::atomic<int> tid_{0};
    std::atomic<bool> failed_{false};
    std::atomic<bool> spaceWarningPending_{false};
    std::atomic<double> spaceLeft_s_{0.0};
    mutable std::mutex mutex_;  // guards path_, error_, spaceWarning_
    QString path_;
    QString error_;
    QString spaceWarning_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace nb::devices
