#pragma once
// Summary statistics shared by the fits (goodness of fit, per-group means).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace nb {

inline double mean(std::span<const double> x)
{
    if (x.empty())
        return 0.0;
    double s = 0.0;
    for (double v : x)
        s += v;
    return s / double(x.size());
}

// Sample standard deviation (n - 1), 0 for fewer than two values: the tables report it so.
inline double sampleStdDev(std::span<const double> x)
{
    if (x.size() < 2)
        return 0.0;
    const double m = mean(x);
    double s = 0.0;
    for (double v : x)
        s += (v - m) * (v - m);
    return std::sqrt(s / double(x.size() - 1));
}

// The middle value (the mean of the two middle ones for an even count), 0 for none.
inline double median(std::vector<double> x)
{
    if (x.empty())
        return 0.0;
    std::sort(x.begin(), x.end());
    const std::size_t n = x.size();
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

// A normal scatter's sigma from absolute deviations (1.4826 times their median), which a few
// wild values do not move.
inline double robustSigma(std::vector<double> absoluteDeviations)
{
    return 1.4826 * median(std::move(absoluteDeviations));
}

// White noise's sigma from the absolute second differences of its readings (each adds six
// readings' variance), robust as above: a smooth motion under the noise hardly moves it.
inline double noiseFromSecondDifferences(std::vector<double> absoluteSecondDifferences)
{
    return robustSigma(std::move(absoluteSecondDifferences)) / std::sqrt(6.0);
}

// Root mean square of residuals.
inline double rms(std::span<const double> residuals)
{
    if (residuals.empty())
        return 0.0;
    double s = 0.0;
    for (double r : residuals)
        s += r * r;
    return std::sqrt(s / double(residuals.size()));
}

// Coefficient of determination 1 - SS_res / SS_tot (1 when the data are constant and fit exactly).
inline double rSquared(std::span<const double> observed, std::span<const double> residuals)
{
    const double m = mean(observed);
    double tot = 0.0, res = 0.0;
    for (double v : observed)
        tot += (v - m) * (v - m);
    for (double r : residuals)
        res += r * r;
    if (tot <= 0.0)
        return res <= 0.0 ? 1.0 : 0.0;
    return 1.0 - res / tot;
}

}  // namespace nb
