#pragma once
// What a device set may offer beyond a stage and a force sensor. A simulator knows the truth
// behind every sample and can hang calibration masses itself; a real rig offers neither. The
// engine, the recorder and the window ask for a capability, never for a simulator.

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <limits>

namespace nb::devices {

// The friction phase a sample truly belongs to (models.md §5), when the device set knows it.
enum class TruePhase : std::uint8_t { None, A, B1, B2, C };

// The run file's spelling: "", "a", "b1", "b2", "c".
inline const QString& phaseName(TruePhase p)
{
    static const QString names[] = {QString(), QStringLiteral("a"), QStringLiteral("b1"), QStringLiteral("b2"),
                                    QStringLiteral("c")};
    return names[static_cast<int>(p)];
}

struct SampleTruth {
    double force_N = std::numeric_limits<double>::quiet_NaN();
    double tissue_mm = std::numeric_limits<double>::quiet_NaN();
    TruePhase phase = TruePhase::None;
};

// Ground truth of a run: each sample's, and the whole model with its events (`simulate --truth`).
class GroundTruthSource {
public:
    virtual ~GroundTruthSource() = default;
    // Truth of the sample with this sensor index, while it is recent (the last ~64k samples).
    virtual SampleTruth sampleTruth(std::uint64_t sensorIndex) const = 0;
    virtual QJsonObject truthJson() const = 0;
};

// Hangs a known mass on the load cell (a calibration rig with a motorised hanger, or the
// simulator). The calibration wizard uses it to walk its masses without the operator.
class CalibrationLoad {
public:
    virtual ~CalibrationLoad() = default;
    // Grams, 0 = nothing. Returns the sensor stream's device time after which every sample
    // carries the new mass.
    virtual double setLoadMass_g(double grams) = 0;
};

}  // namespace nb::devices
