#include "video_error.h"

#include <QCoreApplication>

namespace nb::video {

static QString compose(const QString& file, const QString& reason)
{
    return QCoreApplication::translate("video", "%1: %2").arg(file, reason);
}

VideoError::VideoError(QString file, QString reason)
    : std::runtime_error(compose(file, reason).toStdString()), file_(std::move(file)), reason_(std::move(reason))
{
}

QString VideoError::message() const { return compose(file_, reason_); }

}  // namespace nb::video
