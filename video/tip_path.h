#pragma once
// The tip's likeliest course along a needle strip through a noisy video: where single frames
// are too noisy to show a faint tip (its edge 2-3 σ, as high as the strongest noise along the
// strip), the edge adds up along the course it takes from frame to frame, and noise does not.
// A Viterbi search over (position, velocity) in samples and samples per frame: the course
// gains each frame's score where it passes and pays for every change of velocity. Decided
// with a fixed lag, so that an hour's video needs no more memory than a minute's.

#include <cstdint>
#include <optional>
#include <vector>

namespace nb::video {

class TipPath {
public:
    // `length`: samples along the strip; `lag`: frames seen after a frame before it is decided;
    // `frame_s`: the video's frame interval, which scales the bounds below (set for 30 frames/s).
    explicit TipPath(int length, int lag = 48, double frame_s = 1.0 / 30.0);

    // Adds the next frame's scores (the tip's edge response at each sample, in units of its
    // noise). Returns the position of frame `decided()` when it is decided by this frame.
    std::optional<int> push(const std::vector<double>& score);
    // The positions of the frames not yet decided, in order (call once, at the end).
    std::vector<int> finish();
    // How many frames have been decided.
    int decided() const { return decided_; }

    // At 30 frames/s. A needle moves as far in a second at any frame rate: seen at 15 frames/s
    // it moves twice as far a frame and turns four times as much. With these bounds as they
    // stand, a sine of 0.91 Hz and 63 px seen at 15 frames/s (24 px a frame at its fastest,
    // turning by up to 9 a frame) cost more to follow than its faint tip scored, and the
    // course kept to a still edge (probe seed 161803 case 14, the sync 161 frames off).
    static constexpr int kMaxVelocity = 16;  // samples per frame either way
    // Per sample per frame of velocity change, and no bound on the change: a sine of 0.73 Hz
    // and 30 px seen at 15 frames/s turns by 2.8 samples a frame, each frame (probe seed
    // 314159 case 4; a bound of 2 left its course at the turns 50 samples short).
    static constexpr double kAccelerationCost = 0.5;
    static constexpr double kScoreCap = 5.0;  // one frame's say, either way

private:
    int stateIndex(int velocity, int position) const { return (velocity + maxVelocity_) * length_ + position; }
    std::vector<int> backtrack(int frames) const;

    int length_;
    int lag_;
    int maxVelocity_;
    float accelerationCost_;
    int pushed_ = 0;
    int decided_ = 0;
    std::vector<float> best_;  // per state, the best course's score (the highest is 0)
    std::size_t bestState_ = 0;  // the first state of the highest score
    // Per frame (a ring of lag + 1), per state: the velocity change that led there.
    std::vector<std::vector<signed char>> from_;
    std::vector<float> scores_, reach_, next_;  // one frame's work, kept from frame to frame
    std::vector<std::int32_t> origin_;  // per state, the velocity its best course came with
};

}  // namespace nb::video
