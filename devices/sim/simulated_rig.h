#pragma once
// The simulated rig: one physical world (stage, needle, tissue, load cell) shared by a
// simulated Stage and a simulated ForceSensor. The world advances when the sensor samples
// (each sample steps the physics to its time), on a real-time or simulated clock.
// Seeded and reproducible. Knows the ground truth and can inject device faults for tests.

#include "devices/device_set.h"
#include "devices/force_sensor.h"
#include "devices/ground_truth.h"
#include "devices/sim/rig_config.h"
#include "devices/stage.h"

#include <QJsonObject>
#include <QString>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace nb::devices::sim {

enum class Fault {
    None,
    SensorSilent,   // the DAQ stops answering (cable unplugged)
    SensorError,    // the DAQ reports an error
    StageSilent,    // the stage controller stops answering
    StageRejects,   // the stage controller rejects every command
};

// A labelled interval of the ground truth (same shape as core/labels.h rows).
struct TruthPhase {
    QString track;
    QString label;
    double start_s = 0.0;
    double end_s = 0.0;
};

struct TruthEvent {
    QString name;          // contact, pre_puncture, puncture, relaxed, internal_puncture, bone_contact, emergency_stop, fault
    double time_s = 0.0;
    double position_mm = 0.0;  // needle tip
    double force_N = 0.0;      // true force at the event
};

// The capsule of an organ run: which of the specimen's sites, and its curve (capsule_design.h).
struct CapsuleTruth {
    int site = 0;
    double punctureDepth_mm = 0.0;  // past contact
    double stiffnessScale = 1.0;
    StiffnessModel base;
    double tent_N = 0.0;
};

struct GroundTruth {
    double contact_mm = 0.0, contact_s = -1.0;       // x_s1
    double puncture_mm = 0.0, puncture_s = -1.0;     // x_s2 (surface at puncture)
    double relaxed_mm = 0.0, relaxed_s = -1.0;       // x_s3
    double punctureForce_N = 0.0;
    std::vector<TruthEvent> events;
    std::vector<TruthPhase> phases;
    std::optional<CapsuleTruth> capsule;
};

class SimulatedRig : public std::enable_shared_from_this<SimulatedRig>, public GroundTruthSource, public CalibrationLoad {
public:
    explicit SimulatedRig(RigConfig config);
    ~SimulatedRig() override;

    const RigConfig& config() const { return config_; }
    const TissuePreset& tissue() const { return tissue_; }

    // A mass hung on the load cell (calibration wizard); grams, 0 = nothing. Returns the sensor
    // stream's device time after which every sample carries it.
    double setLoadMass_g(double grams) override;
    // Takes effect at sim time `at_s` (or at once). Fault::None clears every fault.
    void injectFault(Fault fault, double at_s = 0.0);

    double simTime_s() const;
    GroundTruth truth() const;
    // Model parameters, events and phases; what `simulate --truth` writes.
    QJsonObject truthJson() const override;
    // Truth of the sample with this sensor index, while it is among the last ~64k.
    SampleTruth sampleTruth(std::uint64_t index) const override;

    std::unique_ptr<Stage> makeStage();
    std::unique_ptr<ForceSensor> makeSensor();

    // Used by the simulated devices (any thread, serialised inside).
    class World;
    World& world() { return *world_; }

private:
    RigConfig config_;
    TissuePreset tissue_;
    std::unique_ptr<World> world_;
};

// The rig's stage and sensor as a device set, with its truth and calibration load.
DeviceSet simulatedDeviceSet(const std::shared_ptr<SimulatedRig>& rig);
// A new rig made from `config`, as a device set.
DeviceSet makeSimulatedDevices(const RigConfig& config);

}  // namespace nb::devices::sim
