#pragma once
// Polled stage positions (monotonic host time) put onto the force sample clock by linear
// interpolation: a Zaber controller reports position only when asked, at 50-100 Hz, while
// the load cell is sampled by the DAQ's own clock at up to kHz rates.

#include <QString>
#include <deque>
#include <optional>

namespace nb::devices::zaber {

class PositionTrack {
public:
    // Polls must arrive in time order; an out-of-order poll is ignored.
    void add(double host_s, double position_mm);
    // Position at `host_s`, interpolated between the polls around it. Before the first poll
    // or more than `maxGap_s` after the last one there is no honest answer: nothing.
    std::optional<double> at(double host_s, double maxGap_s = 0.1) const;
    // Forgets polls no longer needed for times >= host_s (keeps one before it).
    void dropBefore(double host_s);
    std::size_t size() const { return polls_.size(); }
    // The measured poll rate over the kept polls, 0 with fewer than two.
    double rateHz() const;

private:
    struct Poll {
        double t, x;
    };
    std::deque<Poll> polls_;
};

// The run metadata value for `position_source`, e.g. "zaber polled 50 Hz, interpolated".
QString positionSourceText(double pollRateHz);

}  // namespace nb::devices::zaber
