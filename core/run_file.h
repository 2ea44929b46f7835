#pragma once
// The run file: NeedleBench's interchange format for one run.
//
//   # protocol: stiffness          <- metadata, `# key: value`, before the header
//   # rate_hz: 500
//   time_s,position_mm,force_N,velocity_mm_s,seq
//   0.000000,0.000000,0.001200,4.000000,0
//   ...
//   # end_reason: completed       <- footer metadata, appended when a recording ends
//
// UTF-8, comma separated, one header row. Required columns: time_s, position_mm, force_N.
// Known optional columns are kept; unknown ones are ignored (and named in the warnings).
// A BOM and CRLF line ends are accepted. pandas reads it with `comment='#'`.

#include "core/error.h"
#include "run.h"

#include <QFile>
#include <QString>
#include <QStringList>
#include <span>
#include <stdexcept>

namespace nb {

// A file that cannot be read as a run: says which file, which line (1-based, 0 when
// the problem is not tied to a line) and what is wrong.
class RunFileError : public Error {
public:
    RunFileError(QString file, int line, QString reason);
    const QString& file() const { return file_; }
    int line() const { return line_; }

private:
    QString file_;
    int line_;
};

struct RunReadOptions {
    // A recording cut off by a crash may end in a partial row; recovery drops it
    // (with a warning) instead of refusing the whole file.
    bool dropTruncatedLastRow = false;
};

struct RunReadResult {
    Run run;
    QStringList warnings;
};

// Throws RunFileError.
RunReadResult readRunFile(const QString& path, const RunReadOptions& options = {});
RunReadResult parseRunText(const QByteArray& bytes, const QString& nameForMessages,
                           const RunReadOptions& options = {});

// Writes a whole run atomically (temporary file, then rename). Throws RunFileError.
void writeRunFile(const QString& path, const Run& run);

// Optional columns the reader keeps (all others are ignored).
const QStringList& knownNumericColumns();
const QStringList& knownTextColumns();

// Streams rows to a run file; used by the recorder, which flushes as it goes so that a
// crash loses at most the unflushed tail. Not thread-safe: one writer thread.
class RunFileWriter {
public:
    RunFileWriter() = default;
    ~RunFileWriter();
    RunFileWriter(const RunFileWriter&) = delete;
    RunFileWriter& operator=(const RunFileWriter&) = delete;

    // Creates (truncates) the file and writes metadata and the header row.
    // Numeric columns come first in each row, then text columns. Throws RunFileError.
    void open(const QString& path, const Metadata& metadata, const QStringList& numericColumns,
              const QStringList& textColumns = {});
    void writeRow(std::span<const double> numbers, std::span<const QString> texts = {});
    // Pushes buffered rows to the operating system (survives a kill of this process).
    void flush();
    // Appends footer metadata lines, flushes and closes.
    void close(const Metadata& footer = {});
    bool isOpen() const { return file_.isOpen(); }
    const QString& path() const { return path_; }
    qint64 rowsWritten() const { return rows_; }

private:
    void writeBuffer();
    QFile file_;
    QString path_;
    std::vector<int> decimals_;
    std::size_t textCount_ = 0;
    QByteArray buffer_;
    qint64 rows_ = 0;
};

}  // namespace nb
