// The tip's course search (video/tip_path) on its own: microseconds a frame for a strip of 480
// samples at 30 frames/s, scores of unit noise with a faint tip (3 sigma) moving through them.
// The sync runs one search per candidate line, so this is paid per line per frame.
#include "video/tip_path.h"

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

int main()
{
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 1.0);
    const int length = 480, frames = 1500, repeats = 3;
    std::vector<std::vector<double>> scores(frames, std::vector<double>(length));
    for (int k = 0; k < frames; ++k)
        for (int i = 0; i < length; ++i)
            scores[std::size_t(k)][std::size_t(i)] = noise(rng) + (i == (100 + k / 5) % length ? 3.0 : 0.0);
    long checksum = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r) {
        nb::video::TipPath path(length, 48, 1.0 / 30.0);
        for (const std::vector<double>& s : scores)
            if (const auto decided = path.push(s))
                checksum += *decided;
        for (int p : path.finish())
            checksum += p;
    }
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    std::printf("tip path: %.1f us a frame (%d samples, %d frames, %d repeats); course checksum %ld\n", us / (repeats * frames), length,
                frames, repeats, checksum);
}
