#include "position_track.h"

#include <algorithm>
#include <cmath>

namespace nb::devices::zaber {

void PositionTrack::add(double t, double x)
{
    if (!polls_.empty() && t <= polls_.back().t)
        return;
    polls_.push_back({t, x});
}

std::optional<double> PositionTrack::at(double t, double maxGap_s) const
{
    if (polls_.empty() || t < polls_.front().t)
        return std::nullopt;
    if (t >= polls_.back().t) {
        if (t - polls_.back().t > maxGap_s)
            return std::nullopt;
        return polls_.back().x;  // hold the last reading rather than extrapolate a stop
    }
    auto hi = std::upper_bound(polls_.begin(), polls_.end(), t, [](double v, const Poll& p) { return v < p.t; });
    auto lo = std::prev(hi);
    const double w = (t - lo->t) / (hi->t - lo->t);
    return lo->x + w * (hi->x - lo->x);
}

void PositionTrack::dropBefore(double t)
{
    while (polls_.size() > 2 && polls_[1].t <= t)
        polls_.pop_front();
}

double PositionTrack::rateHz() const
{
    if (polls_.size() < 2)
        return 0.0;
    return double(polls_.size() - 1) / (polls_.back().t - polls_.front().t);
}

QString positionSourceText(double pollRateHz)
{
    return QStringLiteral("zaber polled %1 Hz, interpolated").arg(std::lround(pollRateHz));
}

}  // namespace nb::devices::zaber
