#pragma once
// Configuration of the simulated rig: tissue, needle tip, setup, stage plant and position
// loop, sensor chain. Value type, all defaults physically plausible.

#include "devices/stage.h"
#include "devices/sim/tissue_presets.h"

#include <QString>
#include <cstdint>
#include <optional>

namespace nb::devices::sim {

// The position loop: a mass-damper plant under PID. Table 1's gains belong to another
// robot's units, so these are chosen for ~25 Hz bandwidth: a few µm of lag at 4 mm/s and a
// little overshoot when a move ends.
struct StageConfig {
    PidGains gains{24674.0, 150000.0, 120.0};  // per mm of error, on a unit-mass plant
    double mass = 1.0;
    double damping = 40.0;
    double encoderResolution_mm = 0.0015;     // thesis: 1.5 µm
    double minPosition_mm = -10.0;
    double maxPosition_mm = 150.0;
    double maxVelocity_mm_s = 50.0;
    double acceleration_mm_s2 = 400.0;        // trajectory ramps for linear moves
};

// Load cell -> instrumentation amplifier -> ADC. Volts = offset + drift t + gain * S * F + noise.
struct SensorChainConfig {
    double sensitivity_V_per_N = 0.0123;  // thesis: 12.3 mV/N
    double gain = 100.0;
    double offset_V = 0.42;
    double drift_V_per_s = 2.0e-5;
    double noise_V = 0.0015;              // rms at the ADC input
    double adcRange_V = 10.0;             // ±range
    int adcBits = 16;
    double slope_V_per_g() const { return sensitivity_V_per_N * gain * 9.81 / 1000.0; }
};

enum class Setup {
    Organ,     // a whole organ (or capsule-free tissue) on the bench: linear insertions
    Platform,  // a slab between two plates with holes: the friction platform
};

struct RigConfig {
    QString tissue = QStringLiteral("liver1");
    Tip tip = Tip::Beveled;
    Setup setup = Setup::Organ;
    std::uint64_t seed = 1;
    double surface_mm = 5.0;            // where the tip meets the surface (stage zero = start)
    double thickness_mm = 30.0;         // the slab on the platform
    double plateGap_mm = 1.5;           // free travel of the slab before it meets a plate
    double stickBand_mm_s = 2.5;        // the slab sticks while |relative velocity| is below this (±Δv/2)
    std::optional<double> boneDepth_mm; // past the surface; very stiff
    bool realtime = true;               // false: as fast as possible on a simulated clock
    StageConfig stage;
    SensorChainConfig sensor;
};

}  // namespace nb::devices::sim
