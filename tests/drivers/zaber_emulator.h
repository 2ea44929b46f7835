#pragma once
// A Zaber controller (one axis, ASCII protocol) on a pseudo-terminal: raw mode, reachable
// through a symlink like /dev/serial/by-id. Kinematics run on the monotonic clock; it
// rejects what a real controller rejects (disabled driver, out-of-range data, unknown
// commands) and has fault switches (silence, unplug, stall alert, line noise).

#include "devices/zaber/zaber_protocol.h"

#include <QString>
#include <QTemporaryDir>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

namespace nb::test {

class ZaberEmulator {
public:
    struct Options {
        devices::zaber::Units units{10000.0, 1.6384};   // 0.1 um micro-steps
        double minPosition_mm = -12.0;
        double maxPosition_mm = 160.0;
        double maxSpeed_mm_s = 40.0;
        QByteArray version = "7.25";
    };
    explicit ZaberEmulator(Options options);
    ZaberEmulator() : ZaberEmulator(Options{}) {}
    ~ZaberEmulator();
    ZaberEmulator(const ZaberEmulator&) = delete;
    ZaberEmulator& operator=(const ZaberEmulator&) = delete;

    bool ok() const { return master_ >= 0; }
    QString path() const { return link_; }   // the symlink to hand to the driver

    void setSilent(bool on) { silent_ = on; }
    void unplug();
    void raiseStallFault();                  // stops, sends `!01 1 IDLE FS`, flags later replies
    void sendNoise() { noise_ = true; }      // a garbled line before the next reply

    double position_mm() const;
    int commands() const { return commands_; }
    int velocityCommands() const { return velocityCommands_; }
    int absoluteMoves() const { return absoluteMoves_; }

private:
    void run();
    QByteArray answer(const QByteArray& line);
    void advance(std::chrono::steady_clock::time_point now);
    void write(const QByteArray& bytes);

    Options options_;
    QTemporaryDir dir_;
    QString link_;
    int master_ = -1, slave_ = -1;
    std::thread thread_;
    std::atomic<bool> quit_{false}, silent_{false}, noise_{false};
    std::atomic<int> commands_{0}, velocityCommands_{0}, absoluteMoves_{0};
    mutable std::mutex mutex_;
    enum class Mode { Idle, Absolute, Velocity } mode_ = Mode::Idle;
    double pos_ = 0.0;             // micro-steps
    double target_ = 0.0;
    double velocity_ = 0.0;        // micro-steps/s
    double maxspeed_ = 0.0;        // micro-steps/s
    bool enabled_ = false;
    QByteArray fault_;             // warning flag once a fault was raised
    std::chrono::steady_clock::time_point last_;
};

}  // namespace nb::test
