#pragma once
// What the operator watches while the rig runs: the samples since the run started (between
// runs, the last minute of the live signal) and the marks on them (contact, puncture, the
// operator's stops, faults). The engine's live ring is drained here and nowhere else; the
// plots and the calibration wizard observe this model instead of each reading the engine.
// pull() is synchronous, so tests push a block into a ring and pull it through without a
// thread or a timer.

#include "devices/recorder.h"
#include "devices/spsc_ring.h"
#include "core/live_events.h"

#include <QObject>
#include <QString>
#include <optional>
#include <span>
#include <vector>

namespace nb::devices {

// Samples on the run's clock (seconds since the run began), in time order.
struct LiveSeries {
    std::vector<double> time_s, position_mm, force_N, volts;
    std::size_t size() const { return time_s.size(); }
    void clear();
};

enum class LiveMarkKind {
    Contact,           // detected while a linear run records, refined from the file when it ends
    Puncture,
    MinorPuncture,     // an internal structure (from the whole run only)
    Withdraw,          // the operator's commands
    Stop,
    EmergencyStop,
    Fault,             // what the engine reported
    ForceLimit,
};

struct LiveMark {
    LiveMarkKind kind;
    double time_s = 0.0;  // on the run's clock
};

class LiveRun : public QObject {
    Q_OBJECT
public:
    // `keep_s`: between runs the live signal is kept this long, then starts over.
    explicit LiveRun(double keep_s = 60.0, QObject* parent = nullptr);

    // The ring that pull() drains (the engine's live ring; null detaches). Not owned. Another
    // engine's clock starts again from zero: the series starts over on it.
    void setSource(SpscRing<Sample>* ring);
    // Drains the source and appends what it held; emits samplesAppended, then pulled.
    void pull();
    // Appends samples as pull() does (for a source that is not a ring).
    void append(std::span<const Sample> samples);

    // A run began recording at the latest sample: the series starts over on its clock.
    // `detectEvents`: mark contact and puncture live (linear insertions).
    void beginRun(bool detectEvents);
    // The run ended and is on disk: contact and puncture are placed again from the whole run
    // as recorded (every sample, not what was drawn). Returns a message when the file could
    // not be read back; no puncture in the run is not a problem.
    QString endRun(const QString& runPath);
    bool recording() const { return recording_; }

    // An operator's command or an engine report, at the latest sample.
    void mark(LiveMarkKind kind);

    const LiveSeries& series() const { return series_; }
    const std::vector<LiveMark>& marks() const { return marks_; }
    // The device time at which the series' clock reads zero.
    double clockOrigin_s() const { return t0_; }
    // The latest sample's time on the series' clock.
    double now_s() const { return lastDevice_s_ - t0_; }

signals:
    // Every sample and mark was forgotten (a run began, or the live minute rolled over).
    void reset();
    // Samples [first, series().size()) are new.
    void samplesAppended(std::size_t first);
    void marksChanged();
    // One pull() has been handled: a good moment to redraw.
    void pulled();

private:
    void startOver();

    SpscRing<Sample>* source_ = nullptr;
    std::vector<Sample> drained_;
    LiveSeries series_;
    std::vector<LiveMark> marks_;
    double keep_s_;
    double t0_ = 0.0;
    double lastDevice_s_ = 0.0;
    bool haveSample_ = false;
    bool recording_ = false;
    std::optional<LiveEventDetector> detector_;
};

}  // namespace nb::devices
