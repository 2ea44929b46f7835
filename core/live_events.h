#pragma once
// Contact and puncture while a linear insertion is under way, from the samples as they arrive,
// so that the operator sees them marked while the needle still moves. Cruder than
// detectEvents() on the whole run, which replaces these marks when the run ends: the contact
// is where the force leaves the band it kept in air, the puncture a sharp drop from the peak.

#include <QString>
#include <deque>
#include <span>
#include <vector>

namespace nb {

struct LiveEventOptions {
    double learn_s = 0.25;        // force in air learnt over this long, after the start-up transient
    double skip_s = 0.05;         // the move's start (inertial wiggle) is not learnt
    double smoothing_s = 0.01;    // moving average before any decision
    double contactSigmas = 6.0;   // leaving the band: this many noise sigmas of the smoothed force ...
    double minContact_N = 0.01;   // ... and at least this much
    double contactHold_s = 0.02;  // for this long
    double minDrop_N = 0.05;      // a puncture drops by this much at least ...
    double dropFraction = 0.2;    // ... and by this fraction of the rise since contact
    double dropWithin_s = 0.15;   // from a peak no older than this
};

struct LiveEvent {
    QString name;  // "contact" | "puncture" (data, not translated)
    double time_s = 0.0;
    double position_mm = 0.0;
    double force_N = 0.0;  // above the force in air
};

class LiveEventDetector {
public:
    explicit LiveEventDetector(LiveEventOptions options = {}) : o_(options) {}

    // The next samples of the run, in time order; returns the events they complete.
    std::vector<LiveEvent> feed(std::span<const double> time_s, std::span<const double> position_mm,
                                std::span<const double> force_N);
    // After a puncture, watch for the next one (a deeper structure) from the present force on.
    void continueAfterPuncture();
    // How deep a drop must be, as a fraction of the rise since contact, to count as a puncture.
    void setDropFraction(double fraction) { o_.dropFraction = fraction; }
    bool contacted() const { return contacted_; }
    bool punctured() const { return punctured_; }
    double airForce_N() const { return offset_; }
    double noise_N() const { return noise_; }

private:
    struct Point {
        double t, x, f;  // f smoothed
    };
    std::vector<LiveEvent> step(double t, double x, double f);

    LiveEventOptions o_;
    double t0_ = 0.0;
    bool started_ = false;
    // Learning the force in air: mean, and noise from successive differences.
    double sum_ = 0.0, sumDiff2_ = 0.0, prevRaw_ = 0.0;
    long n_ = 0, nDiff_ = 0;
    bool learnt_ = false;
    double offset_ = 0.0, noise_ = 0.0;
    // Smoothing window (raw samples) and recent smoothed history (for backdating).
    std::deque<double> window_;
    std::deque<double> windowT_;
    double windowSum_ = 0.0;
    std::deque<Point> recent_;
    double lastInBand_t = 0.0, lastInBand_x = 0.0;
    double outSince_ = -1.0;
    bool contacted_ = false, punctured_ = false, settling_ = false;
    Point peak_{0, 0, -1e300};
};

}  // namespace nb
