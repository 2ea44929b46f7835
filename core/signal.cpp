#include "signal.h"

#include <algorithm>
#include <cmath>

namespace nb {

std::vector<double> movingAverage(std::span<const double> x, int window)
{
    const std::size_t n = x.size();
    std::vector<double> out(n);
    if (n == 0)
        return out;
    const std::ptrdiff_t half = std::max(0, window / 2);
    // Prefix sums make each output O(1) so long runs stay cheap.
    std::vector<double> prefix(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        prefix[i + 1] = prefix[i] + x[i];
    for (std::size_t i = 0; i < n; ++i) {
        const auto ii = std::ptrdiff_t(i);
        const std::ptrdiff_t h = std::min({half, ii, std::ptrdiff_t(n) - 1 - ii});
        out[i] = (prefix[std::size_t(ii + h + 1)] - prefix[std::size_t(ii - h)]) / double(2 * h + 1);
    }
    return out;
}

std::vector<double> derivative(std::span<const double> time_s, std::span<const double> x)
{
    const std::size_t n = std::min(time_s.size(), x.size());
    std::vector<double> d(n, 0.0);
    if (n < 2)
        return d;
    auto slope = [&](std::size_t a, std::size_t b) {
        const double dt = time_s[b] - time_s[a];
        return dt != 0.0 ? (x[b] - x[a]) / dt : 0.0;
    };
    d[0] = slope(0, 1);
    d[n - 1] = slope(n - 2, n - 1);
    for (std::size_t i = 1; i + 1 < n; ++i)
        d[i] = slope(i - 1, i + 1);
    return d;
}

int windowForDuration(std::span<const double> time_s, double seconds)
{
    if (time_s.size() < 2)
        return 1;
    std::vector<double> dt;
    dt.reserve(time_s.size() - 1);
    for (std::size_t i = 1; i < time_s.size(); ++i)
        dt.push_back(time_s[i] - time_s[i - 1]);
    std::nth_element(dt.begin(), dt.begin() + std::ptrdiff_t(dt.size() / 2), dt.end());
    const double step = dt[dt.size() / 2];
    if (!(step > 0.0))
        return 1;
    return std::max(1, int(std::lround(seconds / step)));
}

std::vector<HalfCycle> halfCycles(std::span<const double> v, double band)
{
    std::vector<HalfCycle> out;
    int dir = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const int d = v[i] > band / 2 ? 1 : (v[i] < -band / 2 ? -1 : 0);
        if (d == 0 || d == dir)
            continue;
        // The turning point is where the velocity crossed zero before this sample.
        std::size_t turn = i;
        while (turn > start && v[turn - 1] * d > 0)
            --turn;
        if (dir != 0)
            out.push_back({start, turn, dir});
        start = turn;
        dir = d;
    }
    if (dir != 0) {
        std::size_t end = v.size();
        while (end > start + 1 && std::abs(v[end - 1]) < band / 2)
            --end;  // the needle at rest after the last stroke belongs to no phase
        out.push_back({start, end, dir});
    }
    return out;
}

}  // namespace nb
