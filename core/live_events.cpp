#include "live_events.h"

#include <algorithm>
#include <cmath>

namespace nb {

std::vector<LiveEvent> LiveEventDetector::feed(std::span<const double> time_s, std::span<const double> position_mm,
                                               std::span<const double> force_N)
{
    std::vector<LiveEvent> out;
    const std::size_t n = std::min({time_s.size(), position_mm.size(), force_N.size()});
    for (std::size_t i = 0; i < n; ++i)
        for (LiveEvent& e : step(time_s[i], position_mm[i], force_N[i]))
            out.push_back(std::move(e));
    return out;
}

std::vector<LiveEvent> LiveEventDetector::step(double t, double x, double f)
{
    if (!std::isfinite(t) || !std::isfinite(x) || !std::isfinite(f))
        return {};
    if (!started_) {
        started_ = true;
        t0_ = t;
    }
    const double age = t - t0_;

    // The force in air: after the start-up transient, for learn_s.
    if (!learnt_) {
        if (age >= o_.skip_s) {
            if (n_ > 0) {
                sumDiff2_ += (f - prevRaw_) * (f - prevRaw_);
                ++nDiff_;
            }
            sum_ += f;
            prevRaw_ = f;
            ++n_;
        }
        if (age < o_.skip_s + o_.learn_s || n_ < 8)
            return {};
        learnt_ = true;
        offset_ = sum_ / double(n_);
        noise_ = std::sqrt(sumDiff2_ / double(std::max<long>(1, nDiff_)) / 2.0);
    }

    // Smoothed force over the last smoothing_s.
    window_.push_back(f);
    windowT_.push_back(t);
    windowSum_ += f;
    while (windowT_.size() > 1 && t - windowT_.front() > o_.smoothing_s) {
        windowSum_ -= window_.front();
        window_.pop_front();
        windowT_.pop_front();
    }
    const double fs = windowSum_ / double(window_.size()) - offset_;
    recent_.push_back({t, x, fs});
    while (recent_.size() > 2 && t - recent_.front().t > 1.0)
        recent_.pop_front();
    if (punctured_)
        return {};

    std::vector<LiveEvent> events;
    const double band = std::max(o_.minContact_N, o_.contactSigmas * noise_ / std::sqrt(double(window_.size())));
    if (!contacted_) {
        if (fs <= 0.0) {  // where the force last sat at its level in air
            lastInBand_t = t;
            lastInBand_x = x;
        }
        if (fs > band) {
            if (outSince_ < 0)
                outSince_ = t;
            if (t - outSince_ >= o_.contactHold_s) {
                // The rise began where the force last sat in the band.
                contacted_ = true;
                events.push_back({QStringLiteral("contact"), lastInBand_t, lastInBand_x, 0.0});
                peak_ = {t, x, fs};
            }
        } else {
            outSince_ = -1.0;
        }
        return events;
    }

    // After a puncture the force is still falling: follow it down, and look for the next
    // peak only once it rises again.
    if (settling_) {
        if (fs <= peak_.f) {
            peak_ = {t, x, fs};
            return events;
        }
        settling_ = false;
    }
    if (fs >= peak_.f) {
        peak_ = {t, x, fs};
        return events;
    }
    const double drop = peak_.f - fs;
    if (t - peak_.t <= o_.dropWithin_s && drop >= std::max(o_.minDrop_N, o_.dropFraction * peak_.f)) {
        punctured_ = true;
        events.push_back({QStringLiteral("puncture"), peak_.t, peak_.x, peak_.f});
    } else if (t - peak_.t > o_.dropWithin_s) {
        // A slow decline (relaxation under a stopped needle) is no puncture: follow it down.
        peak_ = {t, x, fs};
        for (const Point& p : recent_)
            if (t - p.t <= o_.dropWithin_s && p.f > peak_.f)
                peak_ = p;
    }
    return events;
}

void LiveEventDetector::continueAfterPuncture()
{
    punctured_ = false;
    settling_ = true;
    if (!recent_.empty())
        peak_ = recent_.back();
}

}  // namespace nb
