#pragma once
// A load cell read through a LabJack U6 over libusb-1.0: hardware-timed stream of one
// (differential) analog input, counts converted to volts with the device's own calibration.
// Samples are timed by the device clock (t = index / f_scan); lost packets, overflows and
// device errors are counted, bad packets are dropped, and a silent or unplugged device
// throws a DeviceError naming it ("LabJack U6 #360012345: ...").

#include "devices/force_sensor.h"
#include "devices/labjack_u6/u6_calibration.h"
#include "devices/labjack_u6/u6_protocol.h"

#include <QStringList>
#include <chrono>
#include <memory>

namespace nb::devices {

struct U6Config {
    QString serial;                // empty: the only (first) U6 found
    int channel = 0;               // AIN0 (- AIN1 when differential)
    bool differential = true;
    int gainIndex = 2;             // x100: +-100 mV, a bridge load cell without an amplifier
    int resolutionIndex = 1;
    int settlingFactor = 0;
    std::chrono::milliseconds commandTimeout{500};
    std::chrono::milliseconds stallTimeout{1000};  // no stream data this long: the device failed
};

struct U6Found {
    QString serial;       // empty when the device could not be asked (busy, no permission)
    int bus = 0, address = 0;
    QString problem;      // why it could not be asked
};

// Every U6 on the USB buses (asks each for its serial number).
std::vector<U6Found> findU6Devices();

class U6ForceSensor : public ForceSensor {
public:
    // Opens and claims the device, reads its configuration and calibration. Throws DeviceError.
    explicit U6ForceSensor(U6Config config = {});
    ~U6ForceSensor() override;

    QString name() const override;
    double start(double rateHz) override;
    void stop() override;
    void read(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout) override;
    std::uint64_t deviceLostSamples() const override { return lostSamples_; }
    double inputRange_V() const override;  // by the gain: ±10 V at x1 to ±10 mV at x1000

    const u6::DeviceInfo& info() const { return info_; }
    const u6::Calibration& calibration() const { return cal_; }
    const u6::StreamSettings& settings() const { return settings_; }
    std::uint64_t packets() const { return packets_; }
    std::uint64_t lostPackets() const { return lostPackets_; }
    std::uint64_t badPackets() const { return badPackets_; }
    std::uint64_t overflows() const { return overflows_; }
    int lastBacklog() const { return backlog_; }
    // What went wrong but did not stop the stream, oldest first (drained by the caller).
    QStringList takeWarnings();

private:
    struct Usb;
    u6::Bytes command(const u6::Bytes& packet, int replyLength);
    [[noreturn]] void fail(const QString& reason) const;
    void consume(const std::uint8_t* data, int length, std::vector<VoltageSample>& out);
    void warn(const QString& text);

    U6Config config_;
    std::unique_ptr<Usb> usb_;
    u6::DeviceInfo info_;
    u6::Calibration cal_;
    u6::StreamSettings settings_;
    bool streaming_ = false;
    bool haveCounter_ = false;
    std::uint8_t lastCounter_ = 0;
    std::uint64_t nextIndex_ = 0;
    std::uint64_t packets_ = 0, lostPackets_ = 0, badPackets_ = 0, overflows_ = 0, lostSamples_ = 0;
    int badInARow_ = 0;
    int backlog_ = 0;
    int packetsPerTransfer_ = 1;
    std::chrono::steady_clock::time_point lastData_;
    std::vector<std::uint8_t> buffer_;
    QStringList warnings_;
};

}  // namespace nb::devices
