#pragma once
// LabJack U6 low-level USB protocol: packet building, checksums and reply decoding.
// Pure functions over byte vectors so the driver, the emulator and the tests share one
// definition of the wire format (devices.md; LabJack U6 User's Guide, section 5).

#include <QString>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace nb::devices::u6 {

using Bytes = std::vector<std::uint8_t>;

constexpr std::uint16_t kVendorId = 0x0CD5;
constexpr std::uint16_t kProductId = 0x0006;
constexpr std::uint8_t kEpCommandOut = 0x01;
constexpr std::uint8_t kEpCommandIn = 0x82;
constexpr std::uint8_t kEpStreamIn = 0x83;
constexpr int kMaxPacket = 64;
constexpr int kMaxSamplesPerPacket = 25;

constexpr std::uint8_t kExtended = 0xF8;
constexpr std::uint8_t kExtConfigU6 = 0x08;
constexpr std::uint8_t kExtReadCal = 0x2D;
constexpr std::uint8_t kExtStreamConfig = 0x11;
constexpr std::uint8_t kStreamStart = 0xA8;
constexpr std::uint8_t kStreamStop = 0xB0;
constexpr std::uint8_t kStreamDataCmd = 0xF9;
constexpr std::uint8_t kStreamDataExt = 0xC0;

// Device error codes the driver treats specially.
constexpr std::uint8_t kErrStreamNotRunning = 52;
constexpr std::uint8_t kErrStreamOverflow = 59;     // device buffer overflowed, auto-recovery active
constexpr std::uint8_t kErrStreamRecovered = 60;    // recovery done; bytes 6..9 carry scans lost

// Sum of bytes folded twice into 8 bits (the U6's "checksum8").
std::uint8_t checksum8(std::span<const std::uint8_t> bytes);
std::uint16_t checksum16(std::span<const std::uint8_t> bytes);

// Fills in both checksums of an extended packet (bytes 0, 4, 5) / the one of a normal packet.
void sealExtended(Bytes& packet);
void sealNormal(Bytes& packet);
// True when the checksums stored in the packet match its contents.
bool extendedChecksumOk(std::span<const std::uint8_t> packet);
bool normalChecksumOk(std::span<const std::uint8_t> packet);

Bytes configU6Command();
Bytes readCalCommand(int block);
Bytes streamStartCommand();
Bytes streamStopCommand();

struct StreamChannel {
    int channel = 0;          // AIN number (positive input when differential)
    bool differential = true; // measures AIN(n) - AIN(n+1)
    int gainIndex = 0;        // 0: x1 (+-10 V), 1: x10, 2: x100, 3: x1000
};

struct StreamSettings {
    std::vector<StreamChannel> channels{StreamChannel{}};
    int resolutionIndex = 1;
    int samplesPerPacket = 25;
    int settlingFactor = 0;
    bool clock48MHz = false;
    bool divideBy256 = false;
    std::uint16_t scanInterval = 4000;   // clock ticks between scans

    double clockHz() const { return (clock48MHz ? 48e6 : 4e6) / (divideBy256 ? 256.0 : 1.0); }
    double scanRateHz() const { return clockHz() / scanInterval; }
};

// Picks clock and interval for the scan rate nearest `rateHz` (4 MHz clock, /256 below ~61 Hz).
StreamSettings settingsForRate(double rateHz, StreamSettings base = {});
// Samples per packet that keeps packets flowing at least ~50 times a second at low rates.
int samplesPerPacketFor(double rateHz, int channels);

Bytes streamConfigCommand(const StreamSettings& s);
std::optional<StreamSettings> parseStreamConfigCommand(std::span<const std::uint8_t> packet);

struct DeviceInfo {
    std::uint32_t serial = 0;
    int productId = 0;
    double firmware = 0.0;
    double hardware = 0.0;
};

// A decoded command reply; `error` is a human-readable reason when the packet is malformed.
struct Reply {
    bool ok = false;
    std::uint8_t errorCode = 0;
    QString error;
};

Reply checkExtendedReply(std::span<const std::uint8_t> reply, std::uint8_t extCmd, int expectedLength);
Reply checkNormalReply(std::span<const std::uint8_t> reply, std::uint8_t cmd);
std::optional<DeviceInfo> parseConfigU6Reply(std::span<const std::uint8_t> reply, QString* why);
// The 32 data bytes of a ReadCal reply, or nothing (with `why`) if it is malformed.
std::optional<std::array<std::uint8_t, 32>> parseReadCalReply(std::span<const std::uint8_t> reply, QString* why);

// Builders for the replies (used by the emulator and the tests).
Bytes configU6Reply(const DeviceInfo& info);
Bytes readCalReply(std::span<const std::uint8_t, 32> block, std::uint8_t errorCode = 0);
Bytes extendedReply(std::uint8_t extCmd, std::uint8_t errorCode);
Bytes normalReply(std::uint8_t cmd, std::uint8_t errorCode);

struct StreamPacket {
    std::uint8_t counter = 0;
    std::uint8_t errorCode = 0;
    std::uint32_t scansLost = 0;    // valid with kErrStreamRecovered
    std::uint8_t backlog = 0;
    std::vector<std::uint16_t> samples;
};

int streamPacketSize(int samplesPerPacket);
// Decodes one StreamData packet; nothing (with `why`) on a wrong header or checksum.
std::optional<StreamPacket> parseStreamPacket(std::span<const std::uint8_t> packet, int samplesPerPacket,
                                              QString* why);
Bytes streamPacket(const StreamPacket& p);

}  // namespace nb::devices::u6
