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
#include <QtGlobal>
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
//
// What survives a failing disk: only whole rows reach the file (a failed or short write is
// cut back to the last whole row), space for the footer is reserved ahead of the data so
// that a full disk still gets its end reason, and the file is locked (flock) while it is
// written so that a second writer is refused instead of interleaving rows.
class RunFileWriter {
public:
    RunFileWriter() = default;
    ~RunFileWriter();
    RunFileWriter(const RunFileWriter&) = delete;
    RunFileWriter& operator=(const RunFileWriter&) = delete;

    // Creates (truncates) the file and writes metadata and the header row.
    // Numeric columns come first in each row, then text columns. Throws RunFileError, also
    // when another process is writing the same file (it is left untouched).
    void open(const QString& path, const Metadata& metadata, const QStringList& numericColumns,
              const QStringList& textColumns = {});
    // Buffers one row; may write (and throw RunFileError) when the buffer is large. After a
    // failure rows are no longer written (the file keeps the whole rows before it).
    void writeRow(std::span<const double> numbers, std::span<const QString> texts = {});
    // Pushes buffered rows to the operating system (survives a kill of this process).
    // Throws RunFileError; the file then ends with the last whole row written before.
    void flush();
    // Appends footer metadata lines, flushes and closes. Throws RunFileError when even the
    // footer could not be written (the file is closed and keeps its whole rows).
    void close(const Metadata& footer = {});
    bool isOpen() const { return fd_ >= 0; }
    const QString& path() const { return path_; }
    qint64 rowsWritten() const { return rows_; }
    // Rows that are whole on disk.
    qint64 rowsOnDisk() const { return rowsOnDisk_; }
    // Bytes of whole rows (and metadata) on disk.
    qint64 bytesOnDisk() const { return committed_; }
    bool failed() const { return failed_; }
    // The file descriptor while open (for fstatvfs), -1 otherwise.
    int handle() const { return fd_; }

private:
    void writeBuffer();
    void writeOrTruncate(const QByteArray& bytes);
    void reserve(qint64 needed);
    [[noreturn]] void fail(const QString& reason);
    int fd_ = -1;
    QString path_;
    std::vector<int> decimals_;
    std::size_t textCount_ = 0;
    QByteArray buffer_;
    qint64 rows_ = 0;
    qint64 bufferedRows_ = 0;
    qint64 rowsOnDisk_ = 0;
    qint64 committed_ = 0;  // file size up to the last whole row
    qint64 reserved_ = 0;   // allocated (fallocate KEEP_SIZE) up to here
    bool canReserve_ = true;
    bool regular_ = true;  // a regular file (not /dev/null, a FIFO): cut back and reserved
    bool failed_ = false;
};

}  // namespace nb
