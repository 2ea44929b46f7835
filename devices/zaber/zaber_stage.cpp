#include "zaber_stage.h"
#include "core/tr.h"

#include "devices/device_error.h"

#include <QCoreApplication>
#include <QDebug>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace nb::devices {

using namespace zaber;
using Clock = std::chrono::steady_clock;

namespace {

// How far ahead on the sine each waypoint lies: several read-backs (the engine reads the stage
// once per batch of samples, every 10-20 ms), so that the stage is steered again well before it
// arrives, and short enough that the chase cuts little off the sine's turning points.
constexpr double kSineLookahead_s = 0.08;

double nowSeconds()
{
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

}  // namespace

ZaberStage::ZaberStage(ZaberConfig config) : config_(std::move(config))
{
    const Message version = request("get version");
    firmware_ = QString::fromLatin1(version.data);
    const Message pos = request("get pos");
    lastPos_ = config_.units.mm(pos.data.toDouble());
    // The port is used by the acquisition thread, not the one opening the stage: a serial
    // port's notifiers belong to the thread that opened it, so it is reopened there.
    port_.reset();
}

void ZaberStage::ensurePort()
{
    if (port_ && port_->thread() == QThread::currentThread())
        return;
    if (port_)
        port_.release()->deleteLater();  // belongs to another thread's event loop
    pending_.clear();
    port_ = std::make_unique<QSerialPort>();
    port_->setPortName(config_.port);
    port_->setBaudRate(QSerialPort::Baud115200);
    port_->setDataBits(QSerialPort::Data8);
    port_->setParity(QSerialPort::NoParity);
    port_->setStopBits(QSerialPort::OneStop);
    port_->setFlowControl(QSerialPort::NoFlowControl);
    if (!port_->open(QIODevice::ReadWrite)) {
        const QString why = port_->errorString();
        port_.reset();
        fail(nb::TrDevices::tr("cannot open the serial port: %1").arg(why));
    }
    port_->clear();
}

ZaberStage::~ZaberStage()
{
    if (port_ && sineActive_) {
        try {
            request("stop");
        } catch (const std::exception&) {
            // Closing after a fault: nothing more to do.
        }
    }
}

QString ZaberStage::name() const
{
    return nb::TrDevices::tr("Zaber stage on %1").arg(config_.port);
}

void ZaberStage::fail(const QString& reason) const
{
    throw DeviceError(name(), reason);
}

QStringList ZaberStage::takeAlerts()
{
    return std::exchange(alerts_, {});
}

std::optional<Message> ZaberStage::readMessage(Clock::time_point deadline)
{
    for (;;) {
        const qsizetype nl = pending_.indexOf('\n');
        if (nl >= 0) {
            const QByteArray line = pending_.left(nl);
            pending_.remove(0, nl + 1);
            if (line.trimmed().isEmpty())
                continue;
            if (auto m = parse(line))
                return m;
            qWarning().noquote() << name() << nb::TrDevices::tr("ignored a garbled line: %1").arg(QString::fromLatin1(line.trimmed()));
            continue;
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0)
            return std::nullopt;
        if (!port_->waitForReadyRead(int(left))) {
            if (port_->error() != QSerialPort::NoError && port_->error() != QSerialPort::TimeoutError)
                fail(nb::TrDevices::tr("serial port failed: %1 (cable unplugged?)").arg(port_->errorString()));
            if (Clock::now() >= deadline)
                return std::nullopt;
        }
        pending_ += port_->readAll();
    }
}

void ZaberStage::checkFlags(const Message& m)
{
    const QString fault = faultText(m.warning);
    if (!fault.isEmpty()) {
        sineActive_ = false;
        fail(nb::TrDevices::tr("controller fault %1: %2").arg(QString::fromLatin1(m.warning), fault));
    }
}

Message ZaberStage::request(const QByteArray& text)
{
    ensurePort();
    if (port_->write(command(config_.device, config_.axis, text)) < 0)
        fail(nb::TrDevices::tr("writing to the serial port failed: %1").arg(port_->errorString()));
    const auto deadline = Clock::now() + config_.replyTimeout;
    // Writes on a serial port complete asynchronously; flush so the command leaves now.
    port_->flush();
    for (;;) {
        const auto m = readMessage(deadline);
        if (!m)
            fail(nb::TrDevices::tr("no reply to '%1' within %2 ms (cable unplugged or controller off?)")
                     .arg(QString::fromLatin1(text))
                     .arg(config_.replyTimeout.count()));
        if (m->type == '!') {
            alerts_ << QString::fromLatin1(format(*m));
            checkFlags(*m);
            continue;
        }
        if (m->type != '@' || m->device != config_.device || (m->axis != config_.axis && m->axis != 0))
            continue;
        if (m->rejected) {
            if (m->data == "DRIVERDISABLED")
                enabled_ = false;
            fail(nb::TrDevices::tr("'%1' rejected: %2").arg(QString::fromLatin1(text), rejectionText(m->data)));
        }
        checkFlags(*m);
        return *m;
    }
}

void ZaberStage::enable(bool on)
{
    if (!on)
        sineActive_ = false;
    request(on ? "driver enable" : "driver disable");
    enabled_ = on;
    if (!on)
        homed_ = false;
}

void ZaberStage::zero()
{
    request("set pos 0");
    homed_ = true;
    lastPos_ = 0.0;
    lastPos_s_ = -1.0;
}

void ZaberStage::moveLinear(const LinearMotion& motion)
{
    if (motion.target_mm < config_.minPosition_mm || motion.target_mm > config_.maxPosition_mm)
        fail(nb::TrDevices::tr("target %1 mm is outside the travel %2..%3 mm")
                 .arg(motion.target_mm)
                 .arg(config_.minPosition_mm)
                 .arg(config_.maxPosition_mm));
    const double speed = std::min(std::abs(motion.velocity_mm_s), config_.maxSpeed_mm_s);
    if (speed <= 0.0)
        fail(nb::TrDevices::tr("speed must be positive"));
    sineActive_ = false;
    request("set maxspeed " + QByteArray::number(qlonglong(config_.units.speedData(speed))));
    request("move abs " + QByteArray::number(qlonglong(config_.units.steps(motion.target_mm))));
}

void ZaberStage::moveSine(const SineMotion& motion)
{
    const double peakSpeed = 2.0 * std::numbers::pi * motion.frequency_hz * motion.amplitude_mm;
    if (motion.frequency_hz <= 0.0 || motion.cycles <= 0 || peakSpeed > config_.maxSpeed_mm_s)
        fail(nb::TrDevices::tr("sine %1 mm at %2 Hz needs %3 mm/s, above the %4 mm/s limit")
                 .arg(motion.amplitude_mm)
                 .arg(motion.frequency_hz)
                 .arg(peakSpeed, 0, 'f', 1)
                 .arg(config_.maxSpeed_mm_s));
    const Message pos = request("get pos");
    sineCentre_ = config_.units.mm(pos.data.toDouble());
    if (sineCentre_ - motion.amplitude_mm < config_.minPosition_mm || sineCentre_ + motion.amplitude_mm > config_.maxPosition_mm)
        fail(nb::TrDevices::tr("sine of %1 mm around %2 mm leaves the travel").arg(motion.amplitude_mm).arg(sineCentre_));
    sine_ = motion;
    sineStart_s_ = nowSeconds();
    sineActive_ = true;
    steerSine(sineStart_s_, sineCentre_);
}

void ZaberStage::steerSine(double now_s, double position_mm)
{
    const double w = 2.0 * std::numbers::pi * sine_.frequency_hz;
    const double t = now_s - sineStart_s_;
    if (t >= sine_.cycles / sine_.frequency_hz) {
        sineActive_ = false;
        request("set maxspeed " + QByteArray::number(qlonglong(config_.units.speedData(sine_.amplitude_mm * w))));
        request("move abs " + QByteArray::number(qlonglong(config_.units.steps(sineCentre_))));
        return;
    }
    // The sine is streamed as a chase of waypoints on it: each read-back sends the stage to where
    // the sine will be a short while ahead (or to the turning point, where one comes first), at
    // the speed that gets it there then. The controller stops at the waypoint by itself, so a
    // host that stops steering (a stalled thread, a busy machine, a crash) leaves the needle
    // inside the sine's travel. A stream of velocities ran on at the last one: 1.73 mm on a sine
    // of ±1 mm, seen on a busy machine.
    const double halfPeriod_s = 0.5 / sine_.frequency_hz;
    const double nextTurn_s = (std::floor((t - 0.5 * halfPeriod_s) / halfPeriod_s) + 1.5) * halfPeriod_s;
    const double at_s = std::min({t + kSineLookahead_s, nextTurn_s, sine_.cycles / sine_.frequency_hz});
    const double waypoint = sineCentre_ + sine_.amplitude_mm * std::sin(w * at_s);
    // Not faster than the lookahead allows when the turning point is all but reached.
    const double speed = std::min(std::abs(waypoint - position_mm) / std::max(at_s - t, kSineLookahead_s / 8.0), config_.maxSpeed_mm_s);
    // The controller takes no speed below one unit of its own.
    request("set maxspeed " + QByteArray::number(std::max<qlonglong>(1, qlonglong(config_.units.speedData(speed)))));
    request("move abs " + QByteArray::number(qlonglong(config_.units.steps(waypoint))));
}

void ZaberStage::stop()
{
    sineActive_ = false;
    request("stop");
}

void ZaberStage::emergencyStop()
{
    sineActive_ = false;
    request("estop");
}

StageState ZaberStage::state()
{
    const Message m = request("get pos");
    const double now = nowSeconds();
    bool ok = false;
    const double steps = m.data.toDouble(&ok);
    if (!ok)
        fail(nb::TrDevices::tr("position reply is not a number: '%1'").arg(QString::fromLatin1(m.data)));
    const double pos = config_.units.mm(steps);
    if (lastPos_s_ >= 0 && now > lastPos_s_)
        velocity_ = (pos - lastPos_) / (now - lastPos_s_);
    lastPos_ = pos;
    lastPos_s_ = now;
    if (!m.busy)
        velocity_ = 0.0;
    if (sineActive_)
        steerSine(now, pos);
    return {pos, velocity_, enabled_, m.busy || sineActive_, homed_};
}

}  // namespace nb::devices
