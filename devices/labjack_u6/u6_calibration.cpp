#include "u6_calibration.h"

#include <algorithm>
#include <cmath>

namespace nb::devices::u6 {

double fixed3232ToDouble(std::span<const std::uint8_t, 8> b)
{
    std::uint32_t frac = 0, whole = 0;
    for (int i = 3; i >= 0; --i) {
        frac = (frac << 8) | b[std::size_t(i)];
        whole = (whole << 8) | b[std::size_t(i + 4)];
    }
    return double(std::int32_t(whole)) + double(frac) / 4294967296.0;
}

std::array<std::uint8_t, 8> doubleToFixed3232(double value)
{
    const double whole = std::floor(value);
    const auto frac = std::uint32_t(std::llround((value - whole) * 4294967296.0) & 0xffffffffLL);
    const auto w = std::uint32_t(std::int32_t(whole));
    std::array<std::uint8_t, 8> out{};
    for (int i = 0; i < 4; ++i) {
        out[std::size_t(i)] = std::uint8_t(frac >> (8 * i));
        out[std::size_t(i + 4)] = std::uint8_t(w >> (8 * i));
    }
    return out;
}

Calibration Calibration::nominal()
{
    Calibration c;
    double slope = 3.1580e-4;
    for (auto& g : c.gains) {
        g = {slope, slope, 33523.0};
        slope /= 10.0;
    }
    return c;
}

// Block layout: 0 = {x1 slope, x1 offset, x10 slope, x10 offset}, 1 = same for x100/x1000,
// 2 = {x1 negative slope, x1 centre, x10 negative slope, x10 centre}, 3 = same for x100/x1000.
// The offsets in blocks 0/1 describe the single-slope fit; the two-slope form around the
// centre is the more accurate one, so it is what volts() uses.
Calibration Calibration::fromBlocks(std::span<const std::array<std::uint8_t, 32>> blocks)
{
    auto constant = [&](int block, int k) {
        return fixed3232ToDouble(std::span<const std::uint8_t, 8>(blocks[std::size_t(block)].data() + 8 * k, 8));
    };
    Calibration c;
    for (int g = 0; g < 4; ++g) {
        const int block = g / 2, k = (g % 2) * 2;
        c.gains[std::size_t(g)].positiveSlope = constant(block, k);
        c.gains[std::size_t(g)].negativeSlope = constant(block + 2, k);
        c.gains[std::size_t(g)].centre = constant(block + 2, k + 1);
    }
    return c;
}

std::array<std::array<std::uint8_t, 32>, kCalBlocks> Calibration::toBlocks() const
{
    std::array<std::array<std::uint8_t, 32>, kCalBlocks> blocks{};
    auto put = [&](int block, int k, double v) {
        const auto f = doubleToFixed3232(v);
        std::copy(f.begin(), f.end(), blocks[std::size_t(block)].begin() + 8 * k);
    };
    for (int g = 0; g < 4; ++g) {
        const GainCalibration& gc = gains[std::size_t(g)];
        const int block = g / 2, k = (g % 2) * 2;
        put(block, k, gc.positiveSlope);
        put(block, k + 1, -gc.centre * gc.positiveSlope);
        put(block + 2, k, gc.negativeSlope);
        put(block + 2, k + 1, gc.centre);
    }
    return blocks;
}

double Calibration::volts(std::uint16_t raw, int gainIndex) const
{
    const GainCalibration& g = gains[std::size_t(std::clamp(gainIndex, 0, 3))];
    const double r = raw;
    return r >= g.centre ? (r - g.centre) * g.positiveSlope : -(g.centre - r) * g.negativeSlope;
}

std::uint16_t Calibration::counts(double v, int gainIndex) const
{
    const GainCalibration& g = gains[std::size_t(std::clamp(gainIndex, 0, 3))];
    const double raw = v >= 0 ? g.centre + v / g.positiveSlope : g.centre + v / g.negativeSlope;
    return std::uint16_t(std::clamp(std::lround(raw), 0L, 65535L));
}

}  // namespace nb::devices::u6
