#pragma once
// A video that cannot be opened or read: names the file and what is wrong.

#include <QString>
#include <stdexcept>

namespace nb::video {

class VideoError : public std::runtime_error {
public:
    VideoError(QString file, QString reason);
    const QString& file() const { return file_; }
    const QString& reason() const { return reason_; }
    QString message() const;

private:
    QString file_;
    QString reason_;
};

}  // namespace nb::video
