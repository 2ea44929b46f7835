#pragma once
// The one shape of every error NeedleBench reports: what it concerns (a file, a device, a
// fit) and what is wrong, in words the user can act on. Each room derives its own kind so
// callers can catch what they can handle, and everything else catches nb::Error.

#include <QString>
#include <stdexcept>

namespace nb {

class Error : public std::runtime_error {
public:
    Error(QString subject, QString reason)
        : std::runtime_error(compose(subject, reason).toStdString()), subject_(std::move(subject)),
          reason_(std::move(reason))
    {
    }
    // The file, device or quantity concerned; may be empty.
    const QString& subject() const { return subject_; }
    const QString& reason() const { return reason_; }
    // "subject: reason", or the reason alone when there is no subject.
    QString message() const { return QString::fromStdString(what()); }

private:
    static QString compose(const QString& subject, const QString& reason)
    {
        return subject.isEmpty() ? reason : subject + QStringLiteral(": ") + reason;
    }
    QString subject_;
    QString reason_;
};

}  // namespace nb
