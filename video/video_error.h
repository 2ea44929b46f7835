#pragma once
// A video that cannot be opened or read: names the file and what is wrong.

#include "core/error.h"

namespace nb::video {

class VideoError : public Error {
public:
    VideoError(QString file, QString reason) : Error(std::move(file), std::move(reason)) {}
    const QString& file() const { return subject(); }
};

// A frame that lies in a damaged stretch of its file: the decoder refused packets there and
// gave out the frames after it. The frames around it are readable; a pass over the video
// leaves it out, as a dropped frame.
class DamagedFrame : public VideoError {
public:
    using VideoError::VideoError;
};

}  // namespace nb::video
