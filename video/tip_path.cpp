#include "tip_path.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace nb::video {

namespace {
constexpr float kNone = -std::numeric_limits<float>::infinity();
// A change of velocity is kept in a signed char: at most twice this.
constexpr int kMostVelocity = 60;

// Frames of 30 frames/s per frame of the video, within what a signed char's velocities allow.
double perFrame(double frame_s)
{
    return std::clamp(std::isfinite(frame_s) && frame_s > 0 ? 30.0 * frame_s : 1.0, 0.25,
                      double(kMostVelocity) / TipPath::kMaxVelocity);
}
}  // namespace

TipPath::TipPath(int length, int lag, double frame_s)
    : length_(std::max(1, length)),
      lag_(std::max(0, lag)),
      maxVelocity_(std::clamp(int(std::lround(kMaxVelocity * perFrame(frame_s))), 1, kMostVelocity)),
      accelerationCost_(float(kAccelerationCost / (perFrame(frame_s) * perFrame(frame_s)))),
      from_(std::size_t(lag_ + 1))
{
}

std::optional<int> TipPath::push(const std::vector<double>& score)
{
    const std::size_t states = std::size_t(2 * maxVelocity_ + 1) * std::size_t(length_);
    scores_.resize(std::size_t(length_));
    for (int i = 0; i < length_; ++i) {
        const double s = std::size_t(i) < score.size() ? score[std::size_t(i)] : 0.0;
        scores_[std::size_t(i)] = std::isfinite(s) ? float(std::clamp(s, -kScoreCap, kScoreCap)) : 0.0f;
    }
    std::vector<signed char>& from = from_[std::size_t(pushed_ % (lag_ + 1))];
    from.assign(states, 0);
    if (pushed_ == 0) {
        // The first frame: any velocity.
        best_.resize(states);
        for (int v = -maxVelocity_; v <= maxVelocity_; ++v)
            std::copy(scores_.begin(), scores_.end(), best_.begin() + std::ptrdiff_t(stateIndex(v, 0)));
    } else {
        // The velocity changes at a cost per sample per frame of change; the tip then moves by
        // its new velocity: state (v, i) comes from (u, i − v) for the u that scores best after
        // paying for the change from u to v. That best u is found for every v at once by a
        // pass up the velocities and one down (an L1 distance transform), so any change of
        // velocity costs no more time than a small one. (The buffers are kept from frame to
        // frame: allocated anew, they cost as much as the search.)
        std::vector<float>& reach = reach_;
        reach.assign(best_.begin(), best_.end());
        std::vector<std::int32_t>& origin = origin_;
        origin.resize(states);
        for (int v = -maxVelocity_; v <= maxVelocity_; ++v)
            std::fill_n(origin.begin() + std::ptrdiff_t(stateIndex(v, 0)), length_, v);
        const float cost = accelerationCost_;
        // Branch-free, on rows that never overlap, origins as wide as scores: the compiler does
        // it four samples at a time (at -O3, video/CMakeLists.txt), and the search takes half
        // the time it did.
        auto relax = [&](int v, int neighbour) {
            float* __restrict to = &reach[std::size_t(stateIndex(v, 0))];
            const float* __restrict by = &reach[std::size_t(stateIndex(neighbour, 0))];
            std::int32_t* __restrict o = &origin[std::size_t(stateIndex(v, 0))];
            const std::int32_t* __restrict ob = &origin[std::size_t(stateIndex(neighbour, 0))];
            const float c = cost;
            for (int p = 0, n = length_; p < n; ++p) {
                const float moved = by[p] - c, here = to[p];
                const std::int32_t better = -std::int32_t(here < moved);  // all ones or none
                to[p] = std::max(here, moved);
                o[p] = (ob[p] & better) | (o[p] & ~better);
            }
        };
        for (int v = -maxVelocity_ + 1; v <= maxVelocity_; ++v)
            relax(v, v - 1);
        for (int v = maxVelocity_ - 1; v >= -maxVelocity_; --v)
            relax(v, v + 1);
        std::vector<float>& next = next_;
        next.assign(states, kNone);
        for (int v = -maxVelocity_; v <= maxVelocity_; ++v) {
            // State (v, i) comes from (v, i − v), v states before it.
            const std::size_t row = std::size_t(stateIndex(v, 0));
            const int first = std::max(0, v), end = std::min(length_, length_ + v);
            float* to = &next[row];
            signed char* f = &from[row];
            const float* by = &reach[row] - v;
            const std::int32_t* ob = &origin[row] - v;
            for (int i = first; i < end; ++i) {
                to[i] = by[i] + scores_[std::size_t(i)];
                f[i] = static_cast<signed char>(v - ob[i]);
            }
        }
        std::swap(best_, next);
    }
    // Kept near zero so that an hour of frames does not run out of float precision. The best
    // state, where the course is traced back from, stays the best after the shift.
    const auto topAt = std::max_element(best_.begin(), best_.end());
    bestState_ = std::size_t(topAt - best_.begin());
    const float top = *topAt;
    if (std::isfinite(top))
        for (float& b : best_)
            b -= top;
    ++pushed_;
    if (pushed_ - decided_ <= lag_)
        return std::nullopt;
    const std::vector<int> course = backtrack(lag_ + 1);
    ++decided_;
    return course.front();
}

std::vector<int> TipPath::finish()
{
    std::vector<int> rest = backtrack(pushed_ - decided_);
    decided_ = pushed_;
    return rest;
}

// The positions over the last `frames` frames pushed, on the best course to the newest.
std::vector<int> TipPath::backtrack(int frames) const
{
    if (frames <= 0 || best_.empty())
        return {};
    const std::size_t at = bestState_;
    int v = int(at) / length_ - maxVelocity_, i = int(at) % length_;
    std::vector<int> course(static_cast<std::size_t>(frames));
    for (int k = frames - 1; k >= 0; --k) {
        course[std::size_t(k)] = i;
        if (k == 0)
            break;
        const int frame = pushed_ - frames + k;
        const int change = from_[std::size_t(frame % (lag_ + 1))][std::size_t(stateIndex(v, i))];
        i -= v;
        v -= change;
    }
    return course;
}

}  // namespace nb::video
