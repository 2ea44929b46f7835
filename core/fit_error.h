#pragma once
// The error every fit and detector throws when its input cannot give an answer (too few
// samples, no puncture, no motion). The message is for the user; callers prefix the file.

#include "core/error.h"

namespace nb {

class FitError : public Error {
public:
    explicit FitError(const QString& message) : Error(QString(), message) {}
};

}  // namespace nb
