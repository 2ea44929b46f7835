#pragma once
// A LabJack U6 on an umockdev testbed: the device's sysfs entry and descriptors, and an
// ioctl handler answering usbdevfs URBs the way the U6 firmware would (ConfigU6, ReadCal,
// StreamConfig/Start/Stop, a clock-paced stream carrying a load-cell signal), with fault
// switches. The process must run under libumockdev-preload (see umockdev_harness.h).

#include "devices/labjack_u6/u6_calibration.h"
#include "devices/labjack_u6/u6_protocol.h"

#include <QString>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>

typedef struct _UMockdevTestbed UMockdevTestbed;
typedef struct _UMockdevIoctlBase UMockdevIoctlBase;
typedef struct _UMockdevIoctlClient UMockdevIoctlClient;
typedef struct _UMockdevIoctlData UMockdevIoctlData;

namespace nb::test {

class U6Emulator {
public:
    struct Options {
        std::uint32_t serial = 360012345;
        int bus = 1, address = 7;
        devices::u6::Calibration calibration;     // what its memory holds
        std::function<double(double t_s)> volts;   // the signal at the input, by device time
    };
    explicit U6Emulator(Options options);
    ~U6Emulator();
    U6Emulator(const U6Emulator&) = delete;
    U6Emulator& operator=(const U6Emulator&) = delete;

    // Adds the device to `testbed` and answers its ioctls; false with `why` on failure.
    bool attach(UMockdevTestbed* testbed, QString* why);
    QString devnode() const;

    // Fault switches, callable from any thread.
    void setStalled(bool on) { stalled_ = on; }       // answers nothing at all
    void unplug() { unplugged_ = true; }              // every request fails with ENODEV
    void dropNextPackets(int n) { dropPackets_ = n; } // sent into the void: counter gap
    void corruptNextPackets(int n) { corruptPackets_ = n; }
    void injectOverflow(std::uint32_t scans) { overflowScans_ = scans; }

    // Observations.
    bool streaming() const { return streaming_; }
    int stopsWhileIdle() const { return stopsWhileIdle_; }   // answered with error 52
    std::uint64_t packetsSent() const { return packetsSent_; }
    devices::u6::StreamSettings settings() const;
    double signalAt(double t) const { return options_.volts(t); }
    const Options& options() const { return options_; }

private:
    struct Urb {
        UMockdevIoctlData* urb = nullptr;
        UMockdevIoctlData* buffer = nullptr;
        unsigned long address = 0;
        int endpoint = 0;
        int length = 0;
        int filled = 0;
    };
    static int onIoctl(UMockdevIoctlBase* base, UMockdevIoctlClient* client, void* self);
    bool handle(UMockdevIoctlClient* client);
    void command(const devices::u6::Bytes& packet);
    void pump();
    void finish(Urb& u, int status);
    devices::u6::Bytes nextStreamPacket();

    Options options_;
    UMockdevIoctlBase* handler_ = nullptr;
    QString devnode_;
    mutable std::mutex mutex_;
    std::deque<Urb> pending_;
    std::deque<Urb> reapable_;
    std::deque<devices::u6::Bytes> replies_;
    devices::u6::StreamSettings settings_;
    std::atomic<bool> streaming_{false};
    std::chrono::steady_clock::time_point streamStart_;
    std::uint64_t packetIndex_ = 0;
    std::uint64_t scan_ = 0;
    std::uint32_t pendingRecovery_ = 0;
    std::atomic<bool> stalled_{false}, unplugged_{false};
    std::atomic<int> dropPackets_{0}, corruptPackets_{0};
    std::atomic<std::uint32_t> overflowScans_{0};
    std::atomic<int> stopsWhileIdle_{0};
    std::atomic<std::uint64_t> packetsSent_{0};
};

}  // namespace nb::test
