#pragma once
// A load cell read through a DAQ: hardware-timed voltage samples stamped by the device clock.
// Called only from the acquisition thread; errors are thrown as DeviceError.

#include <QString>
#include <chrono>
#include <cstdint>
#include <vector>

namespace nb::devices {

struct VoltageSample {
    std::uint64_t index = 0;   // the device's sample counter since start (gaps = lost samples)
    double deviceTime_s = 0.0; // index / rate on the device clock, never host arrival time
    double volts = 0.0;
};

class ForceSensor {
public:
    virtual ~ForceSensor() = default;
    virtual QString name() const = 0;
    // Starts hardware-timed sampling at `rateHz`; returns the rate actually configured.
    virtual double start(double rateHz) = 0;
    virtual void stop() = 0;
    // Appends every sample that has arrived, waiting up to `timeout` for at least one.
    // Throws DeviceError when the device fails or stays silent past its own timeout.
    virtual void read(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout) = 0;
    // Samples the device itself reports lost (buffer overflow), cumulative since start().
    virtual std::uint64_t deviceLostSamples() const { return 0; }
    // The input's range, ±volts (0: not known). A reading at its end is no measure of the force:
    // the force may be any higher (SampleProcessor stops the stage there).
    virtual double inputRange_V() const { return 0.0; }
};

}  // namespace nb::devices
