#pragma once
// The U6's factory calibration: 32.32 fixed-point constants read from its memory, and the
// conversion of raw 16-bit ADC counts to volts per gain.

#include <array>
#include <cstdint>
#include <span>

namespace nb::devices::u6 {

constexpr int kCalBlocks = 10;

// 8 bytes little endian: low 32 bits the unsigned fraction, high 32 bits the signed integer part.
double fixed3232ToDouble(std::span<const std::uint8_t, 8> bytes);
std::array<std::uint8_t, 8> doubleToFixed3232(double value);

struct GainCalibration {
    double positiveSlope = 0.0;  // V/count above the centre
    double negativeSlope = 0.0;  // V/count below the centre (a positive number)
    double centre = 0.0;         // counts at 0 V
};

struct Calibration {
    std::array<GainCalibration, 4> gains{};  // x1, x10, x100, x1000

    // The values a nominal U6 ships with (U6 User's Guide, Table 5.4-1).
    static Calibration nominal();
    // Decodes blocks 0..3 (4 constants of 8 bytes each per block).
    static Calibration fromBlocks(std::span<const std::array<std::uint8_t, 32>> blocks);
    std::array<std::array<std::uint8_t, 32>, kCalBlocks> toBlocks() const;

    double volts(std::uint16_t raw, int gainIndex) const;
    // Inverse of volts(), rounded and clamped to the ADC range (used by the emulator).
    std::uint16_t counts(double volts, int gainIndex) const;
};

}  // namespace nb::devices::u6
