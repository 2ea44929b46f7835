#pragma once
// What every exporter throws and how long exports report progress and get cancelled.

#include <QString>
#include <functional>
#include <stdexcept>

namespace nb {

// An export that failed: names the file written and what went wrong. Nothing is left at the
// destination path (exporters write a temporary first and rename it only on success).
class ExportError : public std::runtime_error {
public:
    ExportError(QString file, QString reason)
        : std::runtime_error((file + QStringLiteral(": ") + reason).toStdString()), file_(std::move(file)),
          reason_(std::move(reason))
    {
    }
    const QString& file() const { return file_; }
    const QString& reason() const { return reason_; }
    QString message() const { return QString::fromStdString(what()); }

private:
    QString file_;
    QString reason_;
};

// Called now and then with work done out of total; returning false cancels the export, which
// then removes its temporary file and returns false. A null function never cancels.
using ExportProgress = std::function<bool(qint64 done, qint64 total)>;

inline bool keepGoing(const ExportProgress& p, qint64 done, qint64 total) { return !p || p(done, total); }

}  // namespace nb
