#pragma once
// What every exporter throws and how long exports report progress and get cancelled.

#include "core/error.h"

#include <QString>
#include <functional>

namespace nb {

// An export that failed: names the file written and what went wrong. Nothing is left at the
// destination path (exporters write a temporary first and rename it only on success).
class ExportError : public Error {
public:
    ExportError(QString file, QString reason) : Error(std::move(file), std::move(reason)) {}
    const QString& file() const { return subject(); }
};

// Called now and then with work done out of total; returning false cancels the export, which
// then removes its temporary file and returns false. A null function never cancels.
using ExportProgress = std::function<bool(qint64 done, qint64 total)>;

inline bool keepGoing(const ExportProgress& p, qint64 done, qint64 total) { return !p || p(done, total); }

}  // namespace nb
