#include "zaber_emulator.h"

#include <QFile>
#include <QList>
#include <algorithm>
#include <cmath>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace nb::test {

using namespace devices::zaber;

ZaberEmulator::ZaberEmulator(Options options) : options_(std::move(options))
{
    maxspeed_ = options_.units.microstepsPerMm * 10.0;
    char name[256] = {};
    if (openpty(&master_, &slave_, name, nullptr, nullptr) != 0)
        return;
    termios t{};
    tcgetattr(slave_, &t);
    cfmakeraw(&t);
    tcsetattr(slave_, TCSANOW, &t);
    link_ = dir_.filePath(QStringLiteral("ttyZaber0"));
    QFile::link(QString::fromLocal8Bit(name), link_);
    last_ = std::chrono::steady_clock::now();
    thread_ = std::thread([this] { run(); });
}

ZaberEmulator::~ZaberEmulator()
{
    quit_ = true;
    if (thread_.joinable())
        thread_.join();
    if (master_ >= 0)
        ::close(master_);
    if (slave_ >= 0)
        ::close(slave_);
}

void ZaberEmulator::unplug()
{
    quit_ = true;
    if (thread_.joinable())
        thread_.join();
    QFile::remove(link_);
    // Closing both sides hangs up the line: the driver's reads and writes fail.
    ::close(master_);
    ::close(slave_);
    master_ = slave_ = -1;
}

void ZaberEmulator::raiseStallFault()
{
    std::lock_guard lock(mutex_);
    advance(std::chrono::steady_clock::now());
    mode_ = Mode::Idle;
    fault_ = "FS";
    write("!01 1 IDLE FS\r\n");
}

double ZaberEmulator::position_mm() const
{
    std::lock_guard lock(mutex_);
    return options_.units.mm(pos_);
}

void ZaberEmulator::write(const QByteArray& bytes)
{
    if (master_ >= 0 && ::write(master_, bytes.constData(), size_t(bytes.size())) < 0) {
        // The other side is gone; nothing to tell.
    }
}

void ZaberEmulator::advance(std::chrono::steady_clock::time_point now)
{
    const double dt = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    const double lo = options_.units.steps(options_.minPosition_mm), hi = options_.units.steps(options_.maxPosition_mm);
    if (mode_ == Mode::Absolute) {
        const double step = maxspeed_ * dt;
        if (std::abs(target_ - pos_) <= step) {
            pos_ = target_;
            mode_ = Mode::Idle;
        } else {
            pos_ += target_ > pos_ ? step : -step;
        }
    } else if (mode_ == Mode::Velocity) {
        pos_ += velocity_ * dt;
        if (pos_ < lo || pos_ > hi) {  // a limit sensor stops the axis
            pos_ = std::clamp(pos_, lo, hi);
            mode_ = Mode::Idle;
        }
    }
}

void ZaberEmulator::run()
{
    QByteArray buffer;
    while (!quit_) {
        pollfd p{master_, POLLIN, 0};
        if (::poll(&p, 1, 5) <= 0)
            continue;
        char chunk[512];
        const ssize_t n = ::read(master_, chunk, sizeof chunk);
        if (n <= 0)
            continue;
        buffer.append(chunk, n);
        qsizetype nl;
        while ((nl = buffer.indexOf('\n')) >= 0) {
            const QByteArray line = buffer.left(nl).trimmed();
            buffer.remove(0, nl + 1);
            if (line.isEmpty() || silent_)
                continue;
            QByteArray reply;
            {
                std::lock_guard lock(mutex_);
                advance(std::chrono::steady_clock::now());
                reply = answer(line);
            }
            if (reply.isEmpty())
                continue;
            if (noise_.exchange(false))
                write("@0#\x7f garbage\r\n");
            write(reply + "\r\n");
        }
    }
}

QByteArray ZaberEmulator::answer(const QByteArray& line)
{
    ++commands_;
    if (!line.startsWith('/'))
        return {};
    QList<QByteArray> words = line.mid(1).split(' ');
    words.removeAll(QByteArray());
    int device = 0, axis = 0;
    if (!words.isEmpty() && !words.front().isEmpty() && words.front().at(0) >= '0' && words.front().at(0) <= '9')
        device = words.takeFirst().toInt();
    if (device != 0 && device != 1)
        return {};  // another controller's address: not ours to answer
    if (!words.isEmpty() && words.front().toInt() > 0)
        axis = words.takeFirst().toInt();
    if (axis > 1)
        return format({'@', 1, axis, true, false, "--", "BADAXIS"});
    const QByteArray cmd = words.join(' ');
    Message m{'@', 1, axis, false, mode_ != Mode::Idle, fault_.isEmpty() ? QByteArray("--") : fault_, "0"};
    auto reject = [&](const QByteArray& why) {
        m.rejected = true;
        m.data = why;
        return format(m);
    };
    auto number = [&](int i, bool* ok) { return words.size() > i ? words[i].toDouble(ok) : (*ok = false, 0.0); };
    bool ok = false;
    const double lo = options_.units.steps(options_.minPosition_mm), hi = options_.units.steps(options_.maxPosition_mm);
    const double speedLimit = options_.units.speedData(options_.maxSpeed_mm_s);
    if (cmd == "get pos") {
        m.data = QByteArray::number(qlonglong(std::llround(pos_)));
    } else if (cmd == "get version") {
        m.data = options_.version;
    } else if (cmd == "get maxspeed") {
        m.data = QByteArray::number(qlonglong(std::llround(maxspeed_ * options_.units.speedScale)));
    } else if (cmd == "driver enable") {
        enabled_ = true;
        fault_.clear();
        m.warning = "--";
    } else if (cmd == "driver disable") {
        enabled_ = false;
        mode_ = Mode::Idle;
    } else if (cmd == "stop" || cmd == "estop") {
        mode_ = Mode::Idle;  // no deceleration ramp in this model
        m.busy = false;
    } else if (words.size() == 3 && words[0] == "set" && words[1] == "pos") {
        const double v = number(2, &ok);
        if (!ok)
            return reject("BADDATA");
        if (mode_ != Mode::Idle)
            return reject("STATUSBUSY");
        pos_ = v;
        target_ = v;
    } else if (words.size() == 3 && words[0] == "set" && words[1] == "maxspeed") {
        const double v = number(2, &ok);
        if (!ok || v <= 0 || v > speedLimit)
            return reject("BADDATA");
        maxspeed_ = v / options_.units.speedScale;
    } else if (words.size() == 3 && words[0] == "move" && (words[1] == "abs" || words[1] == "vel")) {
        const double v = number(2, &ok);
        if (!ok)
            return reject("BADDATA");
        if (!enabled_)
            return reject("DRIVERDISABLED");
        if (words[1] == "abs") {
            if (v < lo || v > hi)
                return reject("BADDATA");
            ++absoluteMoves_;
            target_ = v;
            mode_ = Mode::Absolute;
        } else {
            if (std::abs(v) > speedLimit)
                return reject("BADDATA");
            ++velocityCommands_;
            velocity_ = v / options_.units.speedScale;
            mode_ = v == 0 ? Mode::Idle : Mode::Velocity;
        }
        m.busy = mode_ != Mode::Idle;
    } else if (cmd.isEmpty()) {
        // A bare "/" is a ping: every device answers.
    } else {
        return reject("BADCOMMAND");
    }
    return format(m);
}

}  // namespace nb::test
