#pragma once
#include <QString>
#include <stdexcept>

namespace nb::devices {

// A device that failed: names the device and says what is wrong, in words an operator can
// act on ("LabJack U6 #320012345: no reply for 500 ms (cable unplugged?)").
class DeviceError : public std::runtime_error {
public:
    DeviceError(QString device, QString reason)
        : std::runtime_error(QStringLiteral("%1: %2").arg(device, reason).toStdString()),
          device_(std::move(device)), reason_(std::move(reason))
    {
    }
    const QString& device() const { return device_; }
    const QString& reason() const { return reason_; }
    QString message() const { return QString::fromStdString(what()); }

private:
    QString device_;
    QString reason_;
};

}  // namespace nb::devices
