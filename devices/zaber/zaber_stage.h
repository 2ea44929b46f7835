#pragma once
// A Zaber linear stage over the ASCII protocol on a serial port (115200 8N1, QSerialPort).
// Lives on the acquisition thread: every call is a blocking request/reply with a timeout.
// Rejections and fault flags become DeviceErrors naming the port; alerts are noted.

#include "devices/stage.h"
#include "devices/zaber/zaber_protocol.h"

#include <QSerialPort>
#include <QStringList>
#include <chrono>
#include <memory>

namespace nb::devices {

struct ZaberConfig {
    QString port;                  // /dev/ttyUSB0, or a symlink
    int device = 1;
    int axis = 1;
    zaber::Units units;
    std::chrono::milliseconds replyTimeout{500};
    double maxSpeed_mm_s = 20.0;   // limit for every move, including withdrawals
    double minPosition_mm = -10.0;
    double maxPosition_mm = 150.0;
};

class ZaberStage : public Stage {
public:
    // Opens the port and checks a controller answers. Throws DeviceError.
    explicit ZaberStage(ZaberConfig config);
    ~ZaberStage() override;

    QString name() const override;
    void enable(bool on) override;
    void zero() override;
    void moveLinear(const LinearMotion& motion) override;
    // Host-streamed: each state() sends the stage on to a waypoint a little ahead on x(t), where
    // it stops by itself if no state() follows.
    void moveSine(const SineMotion& motion) override;
    void stop() override;
    void emergencyStop() override;
    StageState state() override;
    double minPosition_mm() const override { return config_.minPosition_mm; }
    double maxPosition_mm() const override { return config_.maxPosition_mm; }

    // One request/reply, for tests and the benchmark. Throws on rejection or timeout.
    zaber::Message request(const QByteArray& text);
    QStringList takeAlerts();
    QString firmware() const { return firmware_; }

private:
    [[noreturn]] void fail(const QString& reason) const;
    void ensurePort();
    std::optional<zaber::Message> readMessage(std::chrono::steady_clock::time_point deadline);
    void checkFlags(const zaber::Message& m);
    void steerSine(double now_s, double position_mm);

    ZaberConfig config_;
    std::unique_ptr<QSerialPort> port_;
    QByteArray pending_;
    QString firmware_;
    QStringList alerts_;
    bool enabled_ = false;
    bool homed_ = false;
    bool sineActive_ = false;
    SineMotion sine_;
    double sineCentre_ = 0.0;
    double sineStart_s_ = 0.0;
    double lastPos_ = 0.0, lastPos_s_ = -1.0, velocity_ = 0.0;
};

}  // namespace nb::devices
