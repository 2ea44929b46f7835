#include "u6_protocol.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace nb::devices::u6 {

namespace {

void put16(Bytes& b, std::size_t at, std::uint16_t v)
{
    b[at] = std::uint8_t(v & 0xff);
    b[at + 1] = std::uint8_t(v >> 8);
}

std::uint16_t get16(std::span<const std::uint8_t> b, std::size_t at)
{
    return std::uint16_t(b[at] | (b[at + 1] << 8));
}

std::uint32_t get32(std::span<const std::uint8_t> b, std::size_t at)
{
    return std::uint32_t(b[at]) | (std::uint32_t(b[at + 1]) << 8) | (std::uint32_t(b[at + 2]) << 16) |
           (std::uint32_t(b[at + 3]) << 24);
}

Bytes extendedPacket(std::uint8_t extCmd, int dataBytes)
{
    // Extended packets carry whole 16-bit words of data.
    const int words = (dataBytes + 1) / 2;
    Bytes p(std::size_t(6 + 2 * words), 0);
    p[1] = kExtended;
    p[2] = std::uint8_t(words);
    p[3] = extCmd;
    return p;
}

}  // namespace

std::uint8_t checksum8(std::span<const std::uint8_t> bytes)
{
    unsigned s = 0;
    for (std::uint8_t b : bytes)
        s += b;
    s = (s & 0xff) + (s >> 8);
    s = (s & 0xff) + (s >> 8);
    return std::uint8_t(s);
}

std::uint16_t checksum16(std::span<const std::uint8_t> bytes)
{
    unsigned s = 0;
    for (std::uint8_t b : bytes)
        s += b;
    return std::uint16_t(s & 0xffff);
}

void sealExtended(Bytes& p)
{
    put16(p, 4, checksum16(std::span(p).subspan(6)));
    p[0] = checksum8(std::span(p).subspan(1, 5));
}

void sealNormal(Bytes& p)
{
    p[0] = checksum8(std::span(p).subspan(1));
}

bool extendedChecksumOk(std::span<const std::uint8_t> p)
{
    if (p.size() < 6)
        return false;
    return get16(p, 4) == checksum16(p.subspan(6)) && p[0] == checksum8(p.subspan(1, 5));
}

bool normalChecksumOk(std::span<const std::uint8_t> p)
{
    return p.size() >= 2 && p[0] == checksum8(p.subspan(1));
}

Bytes configU6Command()
{
    Bytes p = extendedPacket(kExtConfigU6, 20);  // write mask 0: read only
    sealExtended(p);
    return p;
}

Bytes readCalCommand(int block)
{
    Bytes p = extendedPacket(kExtReadCal, 2);
    p[7] = std::uint8_t(block);
    sealExtended(p);
    return p;
}

Bytes streamStartCommand()
{
    Bytes p{0, kStreamStart};
    sealNormal(p);
    return p;
}

Bytes streamStopCommand()
{
    Bytes p{0, kStreamStop};
    sealNormal(p);
    return p;
}

StreamSettings settingsForRate(double rateHz, StreamSettings s)
{
    s.clock48MHz = false;
    s.divideBy256 = false;
    double ticks = 4e6 / std::max(rateHz, 1e-3);
    if (ticks > 65535.0) {
        s.divideBy256 = true;
        ticks = 4e6 / 256.0 / std::max(rateHz, 1e-3);
    }
    s.scanInterval = std::uint16_t(std::clamp(std::lround(ticks), 1L, 65535L));
    s.samplesPerPacket = samplesPerPacketFor(s.clockHz() / s.scanInterval, int(s.channels.size()));
    return s;
}

int samplesPerPacketFor(double rateHz, int channels)
{
    const double samplesPerSecond = rateHz * std::max(1, channels);
    return std::clamp(int(samplesPerSecond / 50.0), 1, kMaxSamplesPerPacket);
}

Bytes streamConfigCommand(const StreamSettings& s)
{
    const int n = int(s.channels.size());
    Bytes p = extendedPacket(kExtStreamConfig, 8 + 2 * n);
    p[6] = std::uint8_t(n);
    p[7] = std::uint8_t(s.resolutionIndex);
    p[8] = std::uint8_t(s.samplesPerPacket);
    p[10] = std::uint8_t(s.settlingFactor);
    p[11] = std::uint8_t((s.clock48MHz ? 0x08 : 0x00) | (s.divideBy256 ? 0x02 : 0x00));
    put16(p, 12, s.scanInterval);
    for (int i = 0; i < n; ++i) {
        const StreamChannel& c = s.channels[std::size_t(i)];
        p[std::size_t(14 + 2 * i)] = std::uint8_t(c.channel);
        p[std::size_t(15 + 2 * i)] = std::uint8_t((c.differential ? 0x80 : 0x00) | ((c.gainIndex & 0x3) << 4));
    }
    sealExtended(p);
    return p;
}

std::optional<StreamSettings> parseStreamConfigCommand(std::span<const std::uint8_t> p)
{
    if (p.size() < 14 || p[1] != kExtended || p[3] != kExtStreamConfig || !extendedChecksumOk(p))
        return std::nullopt;
    const int n = p[6];
    if (n < 1 || p.size() < std::size_t(14 + 2 * n) || p[2] != 4 + n)
        return std::nullopt;
    StreamSettings s;
    s.channels.clear();
    s.resolutionIndex = p[7];
    s.samplesPerPacket = p[8];
    s.settlingFactor = p[10];
    s.clock48MHz = p[11] & 0x08;
    s.divideBy256 = p[11] & 0x02;
    s.scanInterval = get16(p, 12);
    for (int i = 0; i < n; ++i) {
        const std::uint8_t opt = p[std::size_t(15 + 2 * i)];
        s.channels.push_back({p[std::size_t(14 + 2 * i)], bool(opt & 0x80), (opt >> 4) & 0x3});
    }
    return s;
}

Reply checkExtendedReply(std::span<const std::uint8_t> r, std::uint8_t extCmd, int expectedLength)
{
    Reply out;
    if (int(r.size()) < expectedLength) {
        out.error = nb::TrDevices::tr("short reply (%1 of %2 bytes)").arg(r.size()).arg(expectedLength);
        return out;
    }
    r = r.first(std::size_t(expectedLength));
    if (r[1] == 0xB8) {  // the U6 answers a bad checksum with a "bad checksum" packet
        out.error = nb::TrDevices::tr("the device reported a checksum error in our command");
        return out;
    }
    if (r[1] != kExtended || r[3] != extCmd || 6 + 2 * r[2] != expectedLength) {
        out.error = nb::TrDevices::tr("unexpected reply header %1 %2 %3")
                        .arg(r[1], 2, 16, QLatin1Char('0'))
                        .arg(r[2], 2, 16, QLatin1Char('0'))
                        .arg(r[3], 2, 16, QLatin1Char('0'));
        return out;
    }
    if (!extendedChecksumOk(r)) {
        out.error = nb::TrDevices::tr("reply checksum mismatch");
        return out;
    }
    out.errorCode = r[6];
    out.ok = true;
    return out;
}

Reply checkNormalReply(std::span<const std::uint8_t> r, std::uint8_t cmd)
{
    Reply out;
    if (r.size() < 4) {
        out.error = nb::TrDevices::tr("short reply (%1 of 4 bytes)").arg(r.size());
        return out;
    }
    r = r.first(4);
    if (r[1] != std::uint8_t(cmd + 1)) {
        out.error = nb::TrDevices::tr("unexpected reply %1 to command %2")
                        .arg(r[1], 2, 16, QLatin1Char('0'))
                        .arg(cmd, 2, 16, QLatin1Char('0'));
        return out;
    }
    if (!normalChecksumOk(r)) {
        out.error = nb::TrDevices::tr("reply checksum mismatch");
        return out;
    }
    out.errorCode = r[2];
    out.ok = true;
    return out;
}

std::optional<DeviceInfo> parseConfigU6Reply(std::span<const std::uint8_t> r, QString* why)
{
    const Reply rep = checkExtendedReply(r, kExtConfigU6, 38);
    if (!rep.ok || rep.errorCode != 0) {
        if (why)
            *why = rep.ok ? nb::TrDevices::tr("ConfigU6 failed with device error %1").arg(rep.errorCode) : rep.error;
        return std::nullopt;
    }
    DeviceInfo d;
    d.firmware = r[10] + r[9] / 100.0;
    d.hardware = r[14] + r[13] / 100.0;
    d.serial = get32(r, 15);
    d.productId = get16(r, 19);
    return d;
}

std::optional<std::array<std::uint8_t, 32>> parseReadCalReply(std::span<const std::uint8_t> r, QString* why)
{
    const Reply rep = checkExtendedReply(r, kExtReadCal, 40);
    if (!rep.ok || rep.errorCode != 0) {
        if (why)
            *why = rep.ok ? nb::TrDevices::tr("reading calibration failed with device error %1").arg(rep.errorCode) : rep.error;
        return std::nullopt;
    }
    std::array<std::uint8_t, 32> block{};
    std::copy_n(r.begin() + 8, 32, block.begin());
    return block;
}

Bytes configU6Reply(const DeviceInfo& info)
{
    Bytes p = extendedPacket(kExtConfigU6, 32);
    const int fw = int(std::lround(info.firmware * 100));
    const int hw = int(std::lround(info.hardware * 100));
    p[9] = std::uint8_t(fw % 100);
    p[10] = std::uint8_t(fw / 100);
    p[13] = std::uint8_t(hw % 100);
    p[14] = std::uint8_t(hw / 100);
    for (int i = 0; i < 4; ++i)
        p[std::size_t(15 + i)] = std::uint8_t(info.serial >> (8 * i));
    put16(p, 19, std::uint16_t(info.productId));
    sealExtended(p);
    return p;
}

Bytes readCalReply(std::span<const std::uint8_t, 32> block, std::uint8_t errorCode)
{
    Bytes p = extendedPacket(kExtReadCal, 34);
    p[6] = errorCode;
    std::copy(block.begin(), block.end(), p.begin() + 8);
    sealExtended(p);
    return p;
}

Bytes extendedReply(std::uint8_t extCmd, std::uint8_t errorCode)
{
    Bytes p = extendedPacket(extCmd, 2);
    p[6] = errorCode;
    sealExtended(p);
    return p;
}

Bytes normalReply(std::uint8_t cmd, std::uint8_t errorCode)
{
    Bytes p{0, std::uint8_t(cmd + 1), errorCode, 0};
    sealNormal(p);
    return p;
}

int streamPacketSize(int samplesPerPacket)
{
    return 14 + 2 * samplesPerPacket;
}

std::optional<StreamPacket> parseStreamPacket(std::span<const std::uint8_t> p, int n, QString* why)
{
    auto fail = [&](const QString& reason) {
        if (why)
            *why = reason;
        return std::nullopt;
    };
    if (int(p.size()) < streamPacketSize(n))
        return fail(nb::TrDevices::tr("short stream packet (%1 bytes)").arg(p.size()));
    p = p.first(std::size_t(streamPacketSize(n)));
    if (p[1] != kStreamDataCmd || p[3] != kStreamDataExt || p[2] != 4 + n)
        return fail(nb::TrDevices::tr("not a stream data packet"));
    if (!extendedChecksumOk(p))
        return fail(nb::TrDevices::tr("stream packet checksum mismatch"));
    StreamPacket s;
    s.counter = p[10];
    s.errorCode = p[11];
    if (s.errorCode == kErrStreamRecovered)
        s.scansLost = get32(p, 6);
    s.samples.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        s.samples[std::size_t(i)] = get16(p, std::size_t(12 + 2 * i));
    s.backlog = p[std::size_t(12 + 2 * n)];
    return s;
}

Bytes streamPacket(const StreamPacket& s)
{
    const int n = int(s.samples.size());
    Bytes p(std::size_t(streamPacketSize(n)), 0);
    p[1] = kStreamDataCmd;
    p[2] = std::uint8_t(4 + n);
    p[3] = kStreamDataExt;
    for (int i = 0; i < 4; ++i)
        p[std::size_t(6 + i)] = std::uint8_t(s.scansLost >> (8 * i));
    p[10] = s.counter;
    p[11] = s.errorCode;
    for (int i = 0; i < n; ++i)
        put16(p, std::size_t(12 + 2 * i), s.samples[std::size_t(i)]);
    p[std::size_t(12 + 2 * n)] = s.backlog;
    sealExtended(p);
    return p;
}

}  // namespace nb::devices::u6
