#pragma once
// The error every fit and detector throws when its input cannot give an answer (too few
// samples, no puncture, no motion). The message is for the user; callers prefix the file.

#include <QString>
#include <stdexcept>

namespace nb {

class FitError : public std::runtime_error {
public:
    explicit FitError(const QString& message) : std::runtime_error(message.toStdString()), message_(message) {}
    const QString& message() const { return message_; }

private:
    QString message_;
};

}  // namespace nb
