// umockdev (GLib) before any Qt header: Qt's "signals" macro breaks gio's headers.
#include <umockdev.h>

#include "u6_emulator.h"

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <sys/ioctl.h>
#include <linux/usbdevice_fs.h>

namespace nb::test {

using namespace devices::u6;

namespace {

// Device, configuration, interface and the three bulk endpoints of a U6 (full speed).
constexpr const char* kDescriptors =
    "1201000200000040d50c0600000101020301"
    "090227000101008032"
    "0904000003ff000000"
    "07050102400000"
    "07058202400000"
    "07058302400000";

std::uint8_t* bytesOf(UMockdevIoctlData* d)
{
    return d->data;
}

usbdevfs_urb* urbOf(UMockdevIoctlData* d)
{
    return reinterpret_cast<usbdevfs_urb*>(d->data);
}

}  // namespace

U6Emulator::U6Emulator(Options options) : options_(std::move(options))
{
    if (!options_.volts)
        options_.volts = [](double) { return 0.0; };
}

U6Emulator::~U6Emulator()
{
    std::lock_guard lock(mutex_);
    for (auto* q : {&pending_, &reapable_})
        for (Urb& u : *q) {
            if (u.buffer)
                umockdev_ioctl_data_unref(u.buffer);
            umockdev_ioctl_data_unref(u.urb);
        }
    if (handler_)
        g_object_unref(handler_);
}

QString U6Emulator::devnode() const
{
    return devnode_;
}

bool U6Emulator::attach(UMockdevTestbed* testbed, QString* why)
{
    const QString bus = QString::number(options_.bus).rightJustified(3, QLatin1Char('0'));
    const QString dev = QString::number(options_.address).rightJustified(3, QLatin1Char('0'));
    devnode_ = QStringLiteral("/dev/bus/usb/%1/%2").arg(bus, dev);
    const QString description =
        QStringLiteral("P: /devices/pci0000:00/0000:00:14.0/usb%1/%1-%2\n"
                       "N: bus/usb/%3/%4\n"
                       "E: BUSNUM=%3\nE: DEVNUM=%4\nE: DEVNAME=%5\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n"
                       "E: PRODUCT=cd5/6/100\nE: SUBSYSTEM=usb\nE: ID_VENDOR_ID=0cd5\nE: ID_MODEL_ID=0006\n"
                       "A: bConfigurationValue=1\nA: bDeviceClass=00\nA: bNumConfigurations=1\nA: bNumInterfaces= 1\n"
                       "A: busnum=%1\nA: devnum=%2\nA: idVendor=0cd5\nA: idProduct=0006\nA: speed=12\n"
                       "A: manufacturer=LabJack\nA: product=LabJack U6\nA: serial=%6\n"
                       "H: descriptors=%7\n")
            .arg(options_.bus)
            .arg(options_.address)
            .arg(bus, dev, devnode_)
            .arg(options_.serial)
            .arg(QString::fromLatin1(kDescriptors));
    GError* error = nullptr;
    if (!umockdev_testbed_add_from_string(testbed, description.toUtf8().constData(), &error)) {
        *why = QString::fromUtf8(error->message);
        g_error_free(error);
        return false;
    }
    handler_ = umockdev_ioctl_base_new();
    g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(&U6Emulator::onIoctl), this);
    if (!umockdev_testbed_attach_ioctl(testbed, devnode_.toUtf8().constData(), handler_, &error)) {
        *why = QString::fromUtf8(error->message);
        g_error_free(error);
        return false;
    }
    return true;
}

StreamSettings U6Emulator::settings() const
{
    std::lock_guard lock(mutex_);
    return settings_;
}

int U6Emulator::onIoctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, void* self)
{
    return static_cast<U6Emulator*>(self)->handle(client);
}

bool U6Emulator::handle(UMockdevIoctlClient* client)
{
    const unsigned long request = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
    std::lock_guard lock(mutex_);
    if (unplugged_) {
        umockdev_ioctl_client_complete(client, -1, ENODEV);
        return true;
    }
    GError* error = nullptr;
    auto resolve = [&](UMockdevIoctlData* d, std::size_t offset, std::size_t len) {
        UMockdevIoctlData* r = umockdev_ioctl_data_resolve(d, offset, len, &error);
        if (error) {
            g_warning("U6 emulator: %s", error->message);
            g_clear_error(&error);
        }
        return r;
    };
    switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
        UMockdevIoctlData* d = resolve(arg, 0, sizeof(std::uint32_t));
        if (!d)
            break;
        const std::uint32_t caps = USBDEVFS_CAP_NO_PACKET_SIZE_LIM;
        std::memcpy(bytesOf(d), &caps, sizeof caps);
        umockdev_ioctl_data_unref(d);
        umockdev_ioctl_client_complete(client, 0, 0);
        return true;
    }
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_DISCONNECT_CLAIM:
    case USBDEVFS_CLEAR_HALT:
    case USBDEVFS_RESETEP:
    case USBDEVFS_SETINTERFACE:
        umockdev_ioctl_client_complete(client, 0, 0);
        return true;
    case USBDEVFS_GETDRIVER:
    case USBDEVFS_IOCTL:
        umockdev_ioctl_client_complete(client, -1, ENODATA);  // no kernel driver bound
        return true;
    case USBDEVFS_SUBMITURB: {
        UMockdevIoctlData* d = resolve(arg, 0, sizeof(usbdevfs_urb));
        if (!d)
            break;
        usbdevfs_urb* urb = urbOf(d);
        Urb u;
        u.urb = d;
        u.address = d->client_addr;
        u.endpoint = urb->endpoint;
        u.length = urb->buffer_length;
        if (u.length > 0)
            u.buffer = resolve(d, offsetof(usbdevfs_urb, buffer), std::size_t(u.length));
        if (urb->type != USBDEVFS_URB_TYPE_BULK || (u.length > 0 && !u.buffer)) {
            if (u.buffer)
                umockdev_ioctl_data_unref(u.buffer);
            umockdev_ioctl_data_unref(d);
            umockdev_ioctl_client_complete(client, -1, EINVAL);
            return true;
        }
        if (!(u.endpoint & 0x80) && !stalled_) {
            command(Bytes(bytesOf(u.buffer), bytesOf(u.buffer) + u.length));
            u.filled = u.length;
            finish(u, 0);
            reapable_.push_back(u);
        } else {
            pending_.push_back(u);
        }
        umockdev_ioctl_client_complete(client, 0, 0);
        return true;
    }
    case USBDEVFS_DISCARDURB: {
        unsigned long address = 0;
        std::memcpy(&address, arg->data, sizeof address);
        auto it = std::find_if(pending_.begin(), pending_.end(), [&](const Urb& u) { return u.address == address; });
        if (it == pending_.end()) {
            umockdev_ioctl_client_complete(client, -1, EINVAL);
            return true;
        }
        Urb u = *it;
        pending_.erase(it);
        finish(u, -ENOENT);  // keeps what was already transferred, like the kernel
        reapable_.push_back(u);
        umockdev_ioctl_client_complete(client, 0, 0);
        return true;
    }
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY: {
        pump();
        if (reapable_.empty()) {
            umockdev_ioctl_client_complete(client, -1, EAGAIN);
            return true;
        }
        UMockdevIoctlData* d = resolve(arg, 0, sizeof(void*));
        if (!d)
            break;
        Urb u = reapable_.front();
        reapable_.pop_front();
        umockdev_ioctl_data_set_ptr(d, 0, u.urb);
        umockdev_ioctl_client_complete(client, 0, 0);
        umockdev_ioctl_data_unref(d);
        if (u.buffer)
            umockdev_ioctl_data_unref(u.buffer);
        umockdev_ioctl_data_unref(u.urb);
        return true;
    }
    default:
        break;
    }
    umockdev_ioctl_client_complete(client, -1, ENOTTY);
    return true;
}

void U6Emulator::finish(Urb& u, int status)
{
    usbdevfs_urb* urb = urbOf(u.urb);
    urb->status = status;
    urb->actual_length = u.filled;
}

void U6Emulator::command(const Bytes& p)
{
    auto reply = [&](Bytes r) { replies_.push_back(std::move(r)); };
    if (p.size() >= 2 && p[1] == kExtended) {
        if (!extendedChecksumOk(p) || p.size() < 6) {
            reply(Bytes{0xB8, 0xB8});  // the firmware's "bad checksum" answer
            return;
        }
        switch (p[3]) {
        case kExtConfigU6:
            reply(configU6Reply({options_.serial, 6, 1.43, 2.00}));
            return;
        case kExtReadCal: {
            const int block = p.size() > 7 ? p[7] : 0;
            const auto blocks = options_.calibration.toBlocks();
            if (block >= kCalBlocks) {
                std::array<std::uint8_t, 32> none{};
                reply(readCalReply(none, 1));
            } else {
                reply(readCalReply(blocks[std::size_t(block)]));
            }
            return;
        }
        case kExtStreamConfig: {
            const auto s = parseStreamConfigCommand(p);
            // The U6 refuses a new configuration while streaming, and packets above 25 samples.
            if (!s || streaming_ || s->samplesPerPacket < 1 || s->samplesPerPacket > kMaxSamplesPerPacket) {
                reply(extendedReply(kExtStreamConfig, streaming_ ? 48 : 40));
                return;
            }
            settings_ = *s;
            reply(extendedReply(kExtStreamConfig, 0));
            return;
        }
        default:
            reply(extendedReply(p[3], 1));
            return;
        }
    }
    if (p.size() >= 2 && normalChecksumOk(p)) {
        if (p[1] == kStreamStart) {
            if (streaming_) {
                reply(normalReply(kStreamStart, 48));
                return;
            }
            streaming_ = true;
            streamStart_ = std::chrono::steady_clock::now();
            packetIndex_ = 0;
            scan_ = 0;
            pendingRecovery_ = 0;
            reply(normalReply(kStreamStart, 0));
            return;
        }
        if (p[1] == kStreamStop) {
            if (!streaming_)
                ++stopsWhileIdle_;
            reply(normalReply(kStreamStop, streaming_ ? 0 : kErrStreamNotRunning));
            streaming_ = false;
            return;
        }
    }
    reply(Bytes{0xB8, 0xB8});
}

Bytes U6Emulator::nextStreamPacket()
{
    const int channels = int(settings_.channels.size());
    const double rate = settings_.scanRateHz();
    StreamPacket p;
    p.counter = std::uint8_t(packetIndex_ & 0xff);
    if (const std::uint32_t lost = overflowScans_.exchange(0); lost > 0) {
        // This packet is the last one out before the buffer overflowed; the scans behind it
        // are discarded and the next packet reports how many.
        p.errorCode = kErrStreamOverflow;
        pendingRecovery_ = lost;
    } else if (pendingRecovery_ > 0) {
        scan_ += pendingRecovery_;
        p.errorCode = kErrStreamRecovered;
        p.scansLost = pendingRecovery_;
        pendingRecovery_ = 0;
    }
    for (int i = 0; i < settings_.samplesPerPacket; ++i) {
        const std::uint64_t scan = scan_ + std::uint64_t(i / channels);
        const auto& ch = settings_.channels[std::size_t(i % channels)];
        p.samples.push_back(options_.calibration.counts(options_.volts(double(scan) / rate), ch.gainIndex));
    }
    scan_ += std::uint64_t(settings_.samplesPerPacket / channels);
    ++packetIndex_;
    Bytes bytes = streamPacket(p);
    if (corruptPackets_ > 0) {
        --corruptPackets_;
        bytes[20] ^= 0x5A;
    }
    return bytes;
}

void U6Emulator::pump()
{
    if (stalled_)
        return;
    const auto now = std::chrono::steady_clock::now();
    const int size = streamPacketSize(settings_.samplesPerPacket);
    std::uint64_t due = 0;
    if (streaming_) {
        const double elapsed = std::chrono::duration<double>(now - streamStart_).count();
        const double packetsPerSecond =
            settings_.scanRateHz() * double(settings_.channels.size()) / settings_.samplesPerPacket;
        due = std::uint64_t(elapsed * packetsPerSecond);
    }
    for (auto it = pending_.begin(); it != pending_.end();) {
        Urb& u = *it;
        bool done = false;
        if (u.endpoint == kEpCommandIn) {
            if (!replies_.empty()) {
                const Bytes r = replies_.front();
                replies_.pop_front();
                u.filled = std::min(int(r.size()), u.length);
                std::copy_n(r.begin(), u.filled, bytesOf(u.buffer));
                done = true;
            }
        } else if (u.endpoint == kEpStreamIn && streaming_) {
            // A full-size packet does not end a USB transfer; a short one does.
            while (packetIndex_ < due && u.filled + size <= u.length && !done) {
                const Bytes p = nextStreamPacket();
                if (dropPackets_ > 0) {
                    --dropPackets_;
                    continue;
                }
                std::copy(p.begin(), p.end(), bytesOf(u.buffer) + u.filled);
                u.filled += size;
                ++packetsSent_;
                if (size < kMaxPacket)
                    done = true;
            }
            if (u.filled + size > u.length && u.filled > 0)
                done = true;
        } else if (!(u.endpoint & 0x80)) {
            command(Bytes(bytesOf(u.buffer), bytesOf(u.buffer) + u.length));  // was held by a stall
            u.filled = u.length;
            done = true;
        }
        if (done) {
            finish(u, 0);
            reapable_.push_back(u);
            it = pending_.erase(it);
        } else {
            ++it;
        }
    }
}

}  // namespace nb::test
