#include "decimate.h"

#include <algorithm>
#include <cmath>

namespace nb {

std::vector<std::size_t> minMaxIndices(std::span<const double> time,
                                       std::span<const std::span<const double>> channels,
                                       double t0, double t1, int columns)
{
    std::vector<std::size_t> out;
    const std::size_t n = time.size();
    if (n == 0 || columns <= 0 || !(t1 >= t0))
        return out;
    auto first = std::size_t(std::lower_bound(time.begin(), time.end(), t0) - time.begin());
    auto last = std::size_t(std::upper_bound(time.begin(), time.end(), t1) - time.begin());  // one past
    if (first > 0)
        --first;
    if (last < n)
        ++last;
    if (last <= first)
        return out;

    // Small spans are drawn as they are: reduction would only cost time.
    const std::size_t budget = std::size_t(columns) * (2 + 2 * channels.size());
    if (last - first <= budget) {
        out.resize(last - first);
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = first + i;
        return out;
    }

    out.reserve(budget + 2);
    const double width = (t1 > t0) ? (t1 - t0) / columns : 1.0;
    const std::size_t nch = channels.size();
    std::vector<std::size_t> picks;
    picks.reserve(2 + 2 * nch);
    const double* tp = time.data();
    std::size_t i = first;
    while (i < last) {
        // Column of sample i ends at the next multiple of `width` past it; the samples
        // before t0 and after t1 form their own columns. The end is found by bisection and
        // each channel scanned in its own tight loop: this is the hot path of every redraw.
        const double end = t0 + (std::floor((tp[i] - t0) / width) + 1.0) * width;
        std::size_t j = std::size_t(std::lower_bound(tp + i + 1, tp + last, end) - tp);
        if (j == i)
            j = i + 1;
        picks.clear();
        picks.push_back(i);
        picks.push_back(j - 1);
        for (std::size_t c = 0; c < nch; ++c) {
            const double* v = channels[c].data();
            double vlo = v[i], vhi = v[i];
            std::size_t lo = i, hi = i;
            for (std::size_t k = i + 1; k < j; ++k) {
                const double x = v[k];
                if (x < vlo) {
                    vlo = x;
                    lo = k;
                }
                if (x > vhi) {
                    vhi = x;
                    hi = k;
                }
            }
            picks.push_back(lo);
            picks.push_back(hi);
        }
        std::sort(picks.begin(), picks.end());
        picks.erase(std::unique(picks.begin(), picks.end()), picks.end());
        out.insert(out.end(), picks.begin(), picks.end());
        i = j;
    }
    return out;
}

void gather(std::span<const double> source, std::span<const std::size_t> indices, std::vector<double>& out)
{
    out.resize(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k)
        out[k] = source[indices[k]];
}

}  // namespace nb
