#pragma once
// A video that cannot be opened or read: names the file and what is wrong.

#include "core/error.h"

namespace nb::video {

class VideoError : public Error {
public:
    VideoError(QString file, QString reason) : Error(std::move(file), std::move(reason)) {}
    const QString& file() const { return subject(); }
};

}  // namespace nb::video
