#pragma once
#include "core/error.h"

namespace nb::devices {

// A device that failed: names the device and says what is wrong, in words an operator can
// act on ("LabJack U6 #320012345: no reply for 500 ms (cable unplugged?)").
class DeviceError : public Error {
public:
    DeviceError(QString device, QString reason) : Error(std::move(device), std::move(reason)) {}
    const QString& device() const { return subject(); }
};

}  // namespace nb::devices
