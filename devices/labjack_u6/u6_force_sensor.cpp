#include "u6_force_sensor.h"
#include "core/tr.h"

#include "devices/device_error.h"

#include <QCoreApplication>
#include <QDebug>
#include <libusb.h>

#include <algorithm>
#include <cmath>

namespace nb::devices {

using namespace u6;

namespace {

QString usbText(int code)
{
    return QString::fromLatin1(libusb_error_name(code));
}

struct Context {
    libusb_context* ctx = nullptr;
    Context()
    {
        if (int rc = libusb_init(&ctx); rc != 0)
            throw DeviceError(QStringLiteral("LabJack U6"), nb::TrDevices::tr("cannot start libusb: %1").arg(usbText(rc)));
    }
    ~Context() { libusb_exit(ctx); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

// One exchange on the command endpoints of an opened, claimed handle.
int exchange(libusb_device_handle* h, const Bytes& packet, Bytes& reply, unsigned timeoutMs, QString* why)
{
    int done = 0;
    int rc = libusb_bulk_transfer(h, kEpCommandOut, const_cast<std::uint8_t*>(packet.data()), int(packet.size()),
                                  &done, timeoutMs);
    if (rc != 0) {
        *why = nb::TrDevices::tr("sending a command failed: %1").arg(usbText(rc));
        return rc;
    }
    reply.assign(kMaxPacket, 0);
    rc = libusb_bulk_transfer(h, kEpCommandIn, reply.data(), int(reply.size()), &done, timeoutMs);
    if (rc != 0) {
        *why = rc == LIBUSB_ERROR_TIMEOUT ? nb::TrDevices::tr("no reply for %1 ms (cable unplugged?)").arg(timeoutMs)
                                          : nb::TrDevices::tr("reading a reply failed: %1").arg(usbText(rc));
        return rc;
    }
    reply.resize(std::size_t(done));
    return 0;
}

bool isU6(libusb_device* dev)
{
    libusb_device_descriptor d{};
    return libusb_get_device_descriptor(dev, &d) == 0 && d.idVendor == kVendorId && d.idProduct == kProductId;
}

// Opens and claims `dev`; on success returns the handle and fills `info`.
libusb_device_handle* openAndIdentify(libusb_device* dev, DeviceInfo& info, unsigned timeoutMs, QString* why)
{
    libusb_device_handle* h = nullptr;
    if (int rc = libusb_open(dev, &h); rc != 0) {
        *why = rc == LIBUSB_ERROR_ACCESS ? nb::TrDevices::tr("no permission to open it (install the udev rule for 0cd5:0006)")
                                         : nb::TrDevices::tr("cannot open it: %1").arg(usbText(rc));
        return nullptr;
    }
    libusb_set_auto_detach_kernel_driver(h, 1);
    if (int rc = libusb_claim_interface(h, 0); rc != 0) {
        *why = rc == LIBUSB_ERROR_BUSY ? nb::TrDevices::tr("in use by another program") : nb::TrDevices::tr("cannot claim it: %1").arg(usbText(rc));
        libusb_close(h);
        return nullptr;
    }
    Bytes reply;
    if (exchange(h, configU6Command(), reply, timeoutMs, why) == 0) {
        if (auto parsed = parseConfigU6Reply(reply, why)) {
            info = *parsed;
            return h;
        }
    }
    libusb_release_interface(h, 0);
    libusb_close(h);
    return nullptr;
}

}  // namespace

struct U6ForceSensor::Usb {
    Context context;
    libusb_device_handle* handle = nullptr;
    ~Usb()
    {
        if (handle) {
            libusb_release_interface(handle, 0);
            libusb_close(handle);
        }
    }
};

std::vector<U6Found> findU6Devices()
{
    std::vector<U6Found> found;
    Context c;
    libusb_device** list = nullptr;
    const ssize_t n = libusb_get_device_list(c.ctx, &list);
    for (ssize_t i = 0; i < n; ++i) {
        if (!isU6(list[i]))
            continue;
        U6Found f;
        f.bus = libusb_get_bus_number(list[i]);
        f.address = libusb_get_device_address(list[i]);
        DeviceInfo info;
        if (libusb_device_handle* h = openAndIdentify(list[i], info, 500, &f.problem)) {
            f.serial = QString::number(info.serial);
            libusb_release_interface(h, 0);
            libusb_close(h);
        }
        found.push_back(f);
    }
    if (n > 0)
        libusb_free_device_list(list, 1);
    return found;
}

U6ForceSensor::U6ForceSensor(U6Config config) : config_(std::move(config)), usb_(std::make_unique<Usb>())
{
    const QString who = config_.serial.isEmpty() ? QStringLiteral("LabJack U6")
                                                 : QStringLiteral("LabJack U6 #%1").arg(config_.serial);
    libusb_device** list = nullptr;
    const ssize_t n = libusb_get_device_list(usb_->context.ctx, &list);
    QStringList problems;
    for (ssize_t i = 0; i < n && !usb_->handle; ++i) {
        if (!isU6(list[i]))
            continue;
        QString why;
        DeviceInfo info;
        libusb_device_handle* h = openAndIdentify(list[i], info, unsigned(config_.commandTimeout.count()), &why);
        if (!h) {
            problems << nb::TrDevices::tr("bus %1 device %2: %3")
                            .arg(libusb_get_bus_number(list[i]))
                            .arg(libusb_get_device_address(list[i]))
                            .arg(why);
            continue;
        }
        if (!config_.serial.isEmpty() && QString::number(info.serial) != config_.serial) {
            libusb_release_interface(h, 0);
            libusb_close(h);
            continue;
        }
        usb_->handle = h;
        info_ = info;
    }
    if (n > 0)
        libusb_free_device_list(list, 1);
    if (!usb_->handle)
        throw DeviceError(who, problems.isEmpty() ? nb::TrDevices::tr("not found on USB (is it plugged in?)") : problems.join(QStringLiteral("; ")));

    std::array<std::array<std::uint8_t, 32>, kCalBlocks> blocks{};
    for (int b = 0; b < kCalBlocks; ++b) {
        QString why;
        const auto block = parseReadCalReply(command(readCalCommand(b), 40), &why);
        if (!block)
            fail(nb::TrDevices::tr("reading calibration block %1: %2").arg(b).arg(why));
        blocks[std::size_t(b)] = *block;
    }
    cal_ = Calibration::fromBlocks(blocks);
    for (int g = 0; g < 4; ++g) {
        const GainCalibration& gc = cal_.gains[std::size_t(g)];
        const double nominal = Calibration::nominal().gains[std::size_t(g)].positiveSlope;
        if (!(gc.positiveSlope > 0.5 * nominal && gc.positiveSlope < 2 * nominal))
            fail(nb::TrDevices::tr("calibration memory looks corrupt (gain %1 slope %2 V/count)").arg(g).arg(gc.positiveSlope));
    }
}

U6ForceSensor::~U6ForceSensor()
{
    try {
        stop();
    } catch (const std::exception&) {
        // Destruction after a fault: the device is already gone or silent.
    }
}

QString U6ForceSensor::name() const
{
    return QStringLiteral("LabJack U6 #%1").arg(info_.serial);
}

void U6ForceSensor::fail(const QString& reason) const
{
    throw DeviceError(name(), reason);
}

void U6ForceSensor::warn(const QString& text)
{
    qWarning().noquote() << name() + QStringLiteral(": ") + text;
    if (warnings_.size() < 1000)
        warnings_ << text;
}

QStringList U6ForceSensor::takeWarnings()
{
    return std::exchange(warnings_, {});
}

Bytes U6ForceSensor::command(const Bytes& packet, int replyLength)
{
    Bytes reply;
    QString why;
    const int rc = exchange(usb_->handle, packet, reply, unsigned(config_.commandTimeout.count()), &why);
    if (rc == LIBUSB_ERROR_NO_DEVICE)
        fail(nb::TrDevices::tr("unplugged (the USB device is gone)"));
    if (rc != 0)
        fail(why);
    if (int(reply.size()) < replyLength)
        fail(nb::TrDevices::tr("short reply (%1 of %2 bytes)").arg(reply.size()).arg(replyLength));
    return reply;
}

double U6ForceSensor::start(double rateHz)
{
    if (streaming_)
        stop();
    // A stream left running by a crashed program would make StreamConfig fail; stopping one
    // that is not running answers error 52, which is expected here.
    const Reply stopped = checkNormalReply(command(streamStopCommand(), 4), kStreamStop);
    if (!stopped.ok)
        fail(stopped.error);
    if (stopped.errorCode != 0 && stopped.errorCode != kErrStreamNotRunning)
        fail(nb::TrDevices::tr("StreamStop failed with device error %1").arg(stopped.errorCode));
    // Drop stale stream packets from such a stream.
    {
        std::uint8_t junk[kMaxPacket * 16];
        int got = 0;
        while (libusb_bulk_transfer(usb_->handle, kEpStreamIn, junk, sizeof junk, &got, 20) == 0 && got > 0) {
        }
    }

    StreamSettings base;
    base.channels = {{config_.channel, config_.differential, config_.gainIndex}};
    base.resolutionIndex = config_.resolutionIndex;
    base.settlingFactor = config_.settlingFactor;
    settings_ = settingsForRate(rateHz, base);
    Reply r = checkExtendedReply(command(streamConfigCommand(settings_), 8), kExtStreamConfig, 8);
    if (!r.ok)
        fail(r.error);
    if (r.errorCode != 0)
        fail(nb::TrDevices::tr("StreamConfig rejected with device error %1 (rate %2 Hz too high for this resolution?)")
                 .arg(r.errorCode)
                 .arg(rateHz));
    r = checkNormalReply(command(streamStartCommand(), 4), kStreamStart);
    if (!r.ok)
        fail(r.error);
    if (r.errorCode != 0)
        fail(nb::TrDevices::tr("StreamStart failed with device error %1").arg(r.errorCode));

    const int size = streamPacketSize(settings_.samplesPerPacket);
    // Full-size packets can be read several per transfer (about 20 ms worth); a shorter
    // packet ends a USB transfer, so those come one by one.
    const double packetsPerSecond = settings_.scanRateHz() * double(settings_.channels.size()) / settings_.samplesPerPacket;
    packetsPerTransfer_ = size == kMaxPacket ? std::clamp(int(packetsPerSecond / 50.0), 1, 32) : 1;
    buffer_.assign(std::size_t(kMaxPacket * packetsPerTransfer_), 0);
    streaming_ = true;
    haveCounter_ = false;
    nextIndex_ = 0;
    packets_ = lostPackets_ = badPackets_ = overflows_ = lostSamples_ = 0;
    badInARow_ = 0;
    lastData_ = std::chrono::steady_clock::now();
    return settings_.scanRateHz();
}

void U6ForceSensor::stop()
{
    if (!streaming_ || !usb_->handle)
        return;
    streaming_ = false;
    const Reply r = checkNormalReply(command(streamStopCommand(), 4), kStreamStop);
    if (r.ok && r.errorCode != 0 && r.errorCode != kErrStreamNotRunning)
        warn(nb::TrDevices::tr("StreamStop answered device error %1").arg(r.errorCode));
}

void U6ForceSensor::read(std::vector<VoltageSample>& out, std::chrono::milliseconds timeout)
{
    if (!streaming_)
        fail(nb::TrDevices::tr("read while not streaming"));
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    const std::size_t before = out.size();
    const int size = streamPacketSize(settings_.samplesPerPacket);
    const int want = size == kMaxPacket ? int(buffer_.size()) : size;
    do {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        int got = 0;
        const int rc = libusb_bulk_transfer(usb_->handle, kEpStreamIn, buffer_.data(), want, &got,
                                            unsigned(std::max<long long>(1, left.count())));
        if (got > 0) {
            lastData_ = std::chrono::steady_clock::now();
            consume(buffer_.data(), got, out);
        }
        if (rc == LIBUSB_ERROR_NO_DEVICE) {
            streaming_ = false;
            fail(nb::TrDevices::tr("unplugged during the stream (USB device gone); samples up to %1 s were received")
                     .arg(double(nextIndex_) / settings_.scanRateHz(), 0, 'f', 3));
        }
        if (rc != 0 && rc != LIBUSB_ERROR_TIMEOUT && rc != LIBUSB_ERROR_OVERFLOW)
            fail(nb::TrDevices::tr("stream read failed: %1").arg(usbText(rc)));
        if (rc == LIBUSB_ERROR_OVERFLOW)
            warn(nb::TrDevices::tr("USB transfer overflow"));
        const auto silent = std::chrono::steady_clock::now() - lastData_;
        if (silent >= config_.stallTimeout)
            fail(nb::TrDevices::tr("no stream data for %1 ms (cable unplugged or device stalled?)")
                     .arg(std::chrono::duration_cast<std::chrono::milliseconds>(silent).count()));
    } while (out.size() == before && std::chrono::steady_clock::now() < deadline);
}

void U6ForceSensor::consume(const std::uint8_t* data, int length, std::vector<VoltageSample>& out)
{
    const int size = streamPacketSize(settings_.samplesPerPacket);
    const int channels = int(settings_.channels.size());
    const double rate = settings_.scanRateHz();
    if (length % size != 0)
        warn(nb::TrDevices::tr("stream transfer of %1 bytes is not whole packets; the rest is dropped").arg(length));
    for (int at = 0; at + size <= length; at += size) {
        QString why;
        const auto p = parseStreamPacket(std::span(data + at, std::size_t(size)), settings_.samplesPerPacket, &why);
        if (!p) {
            ++badPackets_;
            warn(nb::TrDevices::tr("dropped a stream packet: %1").arg(why));
            // The counter of the next good packet tells how much this cost.
            if (++badInARow_ >= 20)
                fail(nb::TrDevices::tr("%1 corrupt stream packets in a row (%2)").arg(badInARow_).arg(why));
            continue;
        }
        badInARow_ = 0;
        ++packets_;
        if (haveCounter_) {
            const int gap = std::uint8_t(p->counter - std::uint8_t(lastCounter_ + 1));
            if (gap != 0) {
                lostPackets_ += std::uint64_t(gap);
                const std::uint64_t scans = std::uint64_t(gap * settings_.samplesPerPacket / channels);
                lostSamples_ += scans;
                nextIndex_ += scans;
                warn(nb::TrDevices::tr("%1 stream packet(s) lost before packet %2 (%3 samples)").arg(gap).arg(p->counter).arg(scans));
            }
        }
        haveCounter_ = true;
        lastCounter_ = p->counter;
        backlog_ = p->backlog;
        if (p->errorCode == kErrStreamOverflow) {
            ++overflows_;
            warn(nb::TrDevices::tr("device stream buffer overflowed (backlog %1); the device is recovering").arg(p->backlog));
        } else if (p->errorCode == kErrStreamRecovered) {
            lostSamples_ += p->scansLost;
            nextIndex_ += p->scansLost;
            warn(nb::TrDevices::tr("device recovered from an overflow; %1 samples were lost").arg(p->scansLost));
        } else if (p->errorCode != 0) {
            fail(nb::TrDevices::tr("stream error %1 reported by the device").arg(p->errorCode));
        }
        for (int i = 0; i < settings_.samplesPerPacket; i += channels) {
            const std::uint64_t index = nextIndex_++;
            out.push_back({index, double(index) / rate, cal_.volts(p->samples[std::size_t(i)], settings_.channels[0].gainIndex)});
        }
    }
}

double U6ForceSensor::inputRange_V() const
{
    return 10.0 / std::pow(10.0, std::clamp(config_.gainIndex, 0, 3));
}

}  // namespace nb::devices
