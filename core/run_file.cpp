#include "run_file.h"
#include "core/disk_space.h"
#include "core/excerpt.h"
#include "core/tr.h"
#include "core/run_plausibility.h"
#include "core/save_file.h"
#include "core/spreadsheet_separator.h"

#include <QSet>
#include <cerrno>
#include <cstring>
#include <new>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <charconv>
#include <climits>
#include <cmath>
#include <limits>
#include <new>

namespace nb {

namespace {

constexpr const char* kRequired[] = {"time_s", "position_mm", "force_N"};

// Splits one CSV line on commas (the format has no quoting: metadata lives in `#` lines,
// text columns hold labels without commas). Trims surrounding blanks.
void splitFields(std::string_view line, std::vector<std::string_view>& fields)
{
    fields.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        std::string_view f = line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                 : comma - start);
        while (!f.empty() && (f.front() == ' ' || f.front() == '\t'))
            f.remove_prefix(1);
        while (!f.empty() && (f.back() == ' ' || f.back() == '\t'))
            f.remove_suffix(1);
        fields.push_back(f);
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
}

bool parseNumber(std::string_view s, double& out)
{
    if (s.empty())
        return false;
    if (s.front() == '+')
        s.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

void parseMetaLine(std::string_view line, Metadata& into)
{
    line.remove_prefix(1);  // '#'
    const auto colon = line.find(':');
    if (colon == std::string_view::npos)
        return;  // a plain comment
    const QString key = QString::fromUtf8(line.substr(0, colon)).trimmed();
    const QString value = QString::fromUtf8(line.substr(colon + 1)).trimmed();
    if (!key.isEmpty() && !key.contains(QLatin1Char(' ')))
        into.set(key, value);
}

enum class Kind { Time, Position, Force, Numeric, Text, Ignored };

}  // namespace

RunFileError::RunFileError(QString file, int line, QString reason)
    : Error(line > 0 ? QStringLiteral("%1:%2").arg(file).arg(line) : file, std::move(reason)), file_(std::move(file)),
      line_(line)
{
}

const QStringList& knownNumericColumns()
{
    static const QStringList names{
        QStringLiteral("velocity_mm_s"),     QStringLiteral("acceleration_mm_s2"),
        QStringLiteral("voltage_V"),         QStringLiteral("seq"),
        QStringLiteral("device_time_s"),     QStringLiteral("stage_position_mm"),
        QStringLiteral("tissue_position_mm"), QStringLiteral("force_limit_N"),
    };
    return names;
}

const QStringList& knownTextColumns()
{
    static const QStringList names{QStringLiteral("phase"), QStringLiteral("event")};
    return names;
}

RunReadResult readRunFile(const QString& path, const RunReadOptions& options)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot open: %1").arg(file.errorString()));
    try {
        return parseRunText(file.readAll(), path, options);
    } catch (const std::bad_alloc&) {
        // What was read is freed by now. A file too large for memory was said as "internal
        // error: out of memory", without its name.
        throw RunFileError(path, 0, nb::TrCore::tr("too large to read into memory (%1 MB)").arg(double(file.size()) / 1e6, 0, 'f', 0));
    }
}

RunReadResult parseRunText(const QByteArray& bytes, const QString& name, const RunReadOptions& options)
{
    RunReadResult result;
    Run& run = result.run;
    std::string_view text(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    if (text.starts_with("\xEF\xBB\xBF"))
        text.remove_prefix(3);
    if (text.find('\0') != std::string_view::npos)
        throw RunFileError(name, 0, nb::TrCore::tr("binary data, not a text run file"));

    std::vector<Kind> kinds;
    QStringList columnNames;
    // Indices into run.numeric / run.text in file-column order (indices, not pointers:
    // those vectors grow while the header is read).
    std::vector<std::size_t> numericTargets;
    std::vector<std::size_t> textTargets;
    std::vector<std::string_view> fields;
    bool haveHeader = false;
    bool dataEnded = false;
    int lineNo = 0;
    std::size_t pos = 0;
    double lastTime = -std::numeric_limits<double>::infinity();

    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        const bool lastLineUnterminated = end == std::string_view::npos;
        if (lastLineUnterminated)
            end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        std::string_view trimmed = line;
        while (!trimmed.empty() && (trimmed.front() == ' ' || trimmed.front() == '\t'))
            trimmed.remove_prefix(1);
        if (trimmed.empty())
            continue;
        if (trimmed.front() == '#') {
            parseMetaLine(trimmed, haveHeader && run.size() > 0 ? run.footer : run.metadata);
            if (haveHeader && run.size() > 0)
                dataEnded = true;
            continue;
        }

        splitFields(trimmed, fields);
        if (!haveHeader) {
            haveHeader = true;
            QStringList& names = columnNames;
            for (auto f : fields)
                names << QString::fromUtf8(f);
            // A file saved by a spreadsheet set to a comma-decimal region has its columns
            // split by ';' (or a tab): say so, not only that a column is missing.
            if (names.size() == 1)
                if (const QString problem = otherSeparatorProblem(names.front(), QStringLiteral("time_s")); !problem.isEmpty())
                    throw RunFileError(name, lineNo, problem);
            for (const char* req : kRequired)
                if (!names.contains(QLatin1String(req)))
                    throw RunFileError(name, lineNo,
                                       nb::TrCore::tr("header has no '%1' column (found: %2)")
                                           .arg(QLatin1String(req), excerpt(names.join(QLatin1String(", ")), 120)));
            QStringList ignored;
            QSet<QString> seen;
            for (const QString& n : names) {
                if (seen.contains(n))
                    throw RunFileError(name, lineNo, nb::TrCore::tr("column '%1' appears twice").arg(excerpt(n)));
                seen.insert(n);
                if (n == QLatin1String("time_s"))
                    kinds.push_back(Kind::Time);
                else if (n == QLatin1String("position_mm"))
                    kinds.push_back(Kind::Position);
                else if (n == QLatin1String("force_N"))
                    kinds.push_back(Kind::Force);
                else if (knownNumericColumns().contains(n)) {
                    kinds.push_back(Kind::Numeric);
                    run.addNumericColumn(n);
                    numericTargets.push_back(run.numeric.size() - 1);
                } else if (knownTextColumns().contains(n)) {
                    kinds.push_back(Kind::Text);
                    run.addTextColumn(n);
                    textTargets.push_back(run.text.size() - 1);
                } else {
                    kinds.push_back(Kind::Ignored);
                    ignored << n;
                }
            }
            if (!ignored.isEmpty())
                result.warnings << nb::TrCore::tr("%1: ignored unknown columns: %2").arg(name, excerpt(ignored.join(QLatin1String(", ")), 120));
            continue;
        }

        if (dataEnded)
            throw RunFileError(name, lineNo, nb::TrCore::tr("sample row after the closing metadata"));
        if (fields.size() != kinds.size()) {
            if (lastLineUnterminated && options.dropTruncatedLastRow) {
                result.warnings << nb::TrCore::tr("%1:%2: dropped a partial last row (recording was interrupted)")
                                       .arg(name)
                                       .arg(lineNo);
                break;
            }
            throw RunFileError(name, lineNo,
                               nb::TrCore::tr("expected %1 fields, found %2%3")
                                   .arg(kinds.size())
                                   .arg(fields.size())
                                   .arg(lastLineUnterminated ? nb::TrCore::tr(" (file ends mid-row: interrupted recording?)")
                                                             : QString()));
        }
        std::size_t ni = 0, ti = 0;
        for (std::size_t c = 0; c < fields.size(); ++c) {
            const Kind k = kinds[c];
            if (k == Kind::Ignored)
                continue;
            if (k == Kind::Text) {
                run.text[textTargets[ti++]].second.push_back(QString::fromUtf8(fields[c]));
                continue;
            }
            double v = std::numeric_limits<double>::quiet_NaN();
            if (!parseNumber(fields[c], v)) {
                const bool optionalEmpty = k == Kind::Numeric && fields[c].empty();
                if (!optionalEmpty) {
                    if (lastLineUnterminated && options.dropTruncatedLastRow) {
                        result.warnings << nb::TrCore::tr("%1:%2: dropped a partial last row (recording was interrupted)")
                                               .arg(name)
                                               .arg(lineNo);
                        goto done;
                    }
                    throw RunFileError(name, lineNo,
                                       nb::TrCore::tr("column %1 ('%2'): '%3' is not a number")
                                           .arg(c + 1)
                                           .arg(excerpt(columnNames[static_cast<qsizetype>(c)]))
                                           .arg(excerpt(QByteArray::fromRawData(fields[c].data(), qsizetype(fields[c].size())))));
                }
            }
            switch (k) {
            case Kind::Time:
                if (!(v > lastTime))
                    throw RunFileError(name, lineNo,
                                       nb::TrCore::tr("time_s %1 does not increase (previous %2)").arg(v).arg(lastTime));
                lastTime = v;
                run.time_s.push_back(v);
                break;
            case Kind::Position: run.position_mm.push_back(v); break;
            case Kind::Force: run.force_N.push_back(v); break;
            case Kind::Numeric: run.numeric[numericTargets[ni++]].second.push_back(v); break;
            default: break;
            }
        }
    }
done:
    if (!haveHeader)
        throw RunFileError(name, 0, bytes.isEmpty() ? nb::TrCore::tr("file is empty") : nb::TrCore::tr("no header row"));
    // A dropped partial row may have left some columns one longer than others.
    const std::size_t n = run.time_s.size();
    run.position_mm.resize(std::min(run.position_mm.size(), n));
    run.force_N.resize(std::min(run.force_N.size(), n));
    for (auto& [_, c] : run.numeric)
        c.resize(std::min(c.size(), n));
    for (auto& [_, c] : run.text)
        c.resize(std::min(c.size(), n));
    result.warnings << implausibleRun(run, name);
    return result;
}

namespace {

int decimalsFor(const QString& column)
{
    if (column == QLatin1String("seq"))
        return 0;
    if (column == QLatin1String("voltage_V"))
        return 8;
    if (column.endsWith(QLatin1String("time_s")))
        return 7;
    return 6;
}

void appendNumber(QByteArray& out, double v, int decimals)
{
    if (!std::isfinite(v))
        return;  // empty field: missing value
    char buf[64];
    std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    if (r.ec != std::errc())  // too large for fixed notation: the shortest exact form instead
        r = std::to_chars(buf, buf + sizeof buf, v);
    if (r.ec == std::errc())
        out.append(buf, r.ptr - buf);
}

QByteArray metadataBlock(const Metadata& m)
{
    QByteArray out;
    for (const auto& [k, v] : m.entries()) {
        QString value = v;
        value.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
        out += "# " + k.toUtf8() + ": " + value.toUtf8() + '\n';
    }
    return out;
}

}  // namespace

void writeRunFile(const QString& path, const Run& run)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
    QByteArray out = metadataBlock(run.metadata);
    QStringList header{QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N")};
    std::vector<int> decimals{decimalsFor(header[0]), 6, 6};
    for (const auto& [n, _] : run.numeric) {
        header << n;
        decimals.push_back(decimalsFor(n));
    }
    for (const auto& [n, _] : run.text)
        header << n;
    out += header.join(QLatin1Char(',')).toUtf8() + '\n';
    const std::size_t n = run.size();
    for (std::size_t i = 0; i < n; ++i) {
        appendNumber(out, run.time_s[i], decimals[0]);
        out += ',';
        appendNumber(out, i < run.position_mm.size() ? run.position_mm[i] : NAN, 6);
        out += ',';
        appendNumber(out, i < run.force_N.size() ? run.force_N[i] : NAN, 6);
        std::size_t c = 3;
        for (const auto& [_, col] : run.numeric) {
            out += ',';
            appendNumber(out, i < col.size() ? col[i] : NAN, decimals[c++]);
        }
        for (const auto& [_, col] : run.text) {
            out += ',';
            if (i < col.size())
                out += col[i].toUtf8();
        }
        out += '\n';
        if (out.size() > (1 << 20)) {
            file.write(out);
            out.clear();
        }
    }
    out += metadataBlock(run.footer);
    file.write(out);
    if (!commitWhole(file)) {
        // QSaveFile says "Unknown error" for a failed flush; a full disk is the usual cause.
        const auto free = freeBytes(path);
        throw RunFileError(path, 0, free && *free < 64 * 1024 ? nb::TrCore::tr("cannot write: no space left on the disk")
                                                              : nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
    }
}

namespace {

// Room kept allocated beyond the data for the footer (a few hundred bytes) with a wide
// margin; reserved ahead in steps so that fallocate runs a few times a second at most.
constexpr qint64 kFooterReserve = 16 * 1024;
constexpr qint64 kReserveStep = 256 * 1024;

QString systemError(int err) { return QString::fromLocal8Bit(std::strerror(err)); }

}  // namespace

RunFileWriter::~RunFileWriter()
{
    if (fd_ >= 0) {
        try {
            writeBuffer();
        } catch (const RunFileError&) {
        }
        if (regular_)
            ::ftruncate(fd_, committed_);
        ::close(fd_);
        fd_ = -1;
    }
}

void RunFileWriter::open(const QString& path, const Metadata& metadata, const QStringList& numericColumns,
                         const QStringList& textColumns)
{
    if (fd_ >= 0)
        throw RunFileError(path, 0, nb::TrCore::tr("a run file is already open (%1)").arg(path_));
    path_ = path;
    const QByteArray native = QFile::encodeName(path);
    // Not O_TRUNC: the file may be another writer's, to be refused untouched.
    const int fd = ::open(native.constData(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
        throw RunFileError(path, 0, nb::TrCore::tr("cannot write: %1").arg(systemError(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        ::close(fd);
        if (err == EWOULDBLOCK)
            throw RunFileError(path, 0, nb::TrCore::tr("another process is recording to this file; it was left untouched"));
        throw RunFileError(path, 0, nb::TrCore::tr("cannot lock: %1").arg(systemError(err)));
    }
    // A device or pipe (/dev/null, a FIFO) is written to as it is: nothing to cut or reserve.
    struct stat st {};
    regular_ = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    if (regular_ && ::ftruncate(fd, 0) != 0) {
        const int err = errno;
        ::close(fd);
        throw RunFileError(path, 0, nb::TrCore::tr("cannot write: %1").arg(systemError(err)));
    }
    fd_ = fd;
    decimals_.clear();
    for (const QString& c : numericColumns)
        decimals_.push_back(decimalsFor(c));
    textCount_ = static_cast<std::size_t>(textColumns.size());
    rows_ = bufferedRows_ = rowsOnDisk_ = 0;
    committed_ = reserved_ = 0;
    canReserve_ = regular_;
    failed_ = false;
    buffer_ = metadataBlock(metadata);
    buffer_ += (numericColumns + textColumns).join(QLatin1Char(',')).toUtf8() + '\n';
    try {
        flush();
    } catch (const RunFileError&) {
        ::close(fd_);
        fd_ = -1;
        throw;
    }
}

void RunFileWriter::writeRow(std::span<const double> numbers, std::span<const QString> texts)
{
    if (failed_)
        return;
    for (std::size_t i = 0; i < decimals_.size(); ++i) {
        if (i)
            buffer_ += ',';
        appendNumber(buffer_, i < numbers.size() ? numbers[i] : NAN, decimals_[i]);
    }
    for (std::size_t i = 0; i < textCount_; ++i) {
        buffer_ += ',';
        if (i < texts.size())
            buffer_ += texts[i].toUtf8();
    }
    buffer_ += '\n';
    ++rows_;
    ++bufferedRows_;
    if (buffer_.size() > (1 << 18))
        writeBuffer();
}

void RunFileWriter::fail(const QString& reason)
{
    failed_ = true;
    buffer_.clear();
    bufferedRows_ = 0;
    throw RunFileError(path_, 0, reason);
}

void RunFileWriter::reserve(qint64 needed)
{
    if (!canReserve_ || needed <= reserved_)
        return;
    const qint64 target = needed + kReserveStep;
    if (::fallocate(fd_, FALLOC_FL_KEEP_SIZE, reserved_, target - reserved_) == 0) {
        reserved_ = target;
        return;
    }
    const int err = errno;
    if (err == EOPNOTSUPP || err == ENOSYS || err == EINVAL || err == ENODEV || err == ESPIPE) {
        canReserve_ = false;  // this file system cannot: plain writes, footer as space allows
        return;
    }
    if (err == ENOSPC || err == EDQUOT) {
        // Try the exact need before giving up: the reserve step is only a convenience.
        if (::fallocate(fd_, FALLOC_FL_KEEP_SIZE, reserved_, needed - reserved_) == 0) {
            reserved_ = needed;
            return;
        }
    }
    fail(nb::TrCore::tr("write failed after %1 rows: %2").arg(rowsOnDisk_).arg(systemError(err)));
}

void RunFileWriter::writeOrTruncate(const QByteArray& bytes)
{
    const char* p = bytes.constData();
    qint64 left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(left));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int err = n < 0 ? errno : ENOSPC;
            // Cut back to the last whole row: a reader sees a shorter run, never half a row.
            if (regular_ && ::ftruncate(fd_, committed_) == 0)
                ::lseek(fd_, committed_, SEEK_SET);
            fail(nb::TrCore::tr("write failed after %1 rows: %2").arg(rowsOnDisk_).arg(systemError(err)));
        }
        p += n;
        left -= n;
    }
    committed_ += bytes.size();
}

void RunFileWriter::writeBuffer()
{
    if (buffer_.isEmpty() || fd_ < 0)
        return;
    if (failed_) {
        buffer_.clear();
        bufferedRows_ = 0;
        return;
    }
    // The data may use the space up to the footer's reserve, never the reserve itself.
    reserve(committed_ + buffer_.size() + kFooterReserve);
    writeOrTruncate(buffer_);
    rowsOnDisk_ += bufferedRows_;
    bufferedRows_ = 0;
    buffer_.clear();
}

void RunFileWriter::flush()
{
    writeBuffer();
}

void RunFileWriter::close(const Metadata& footer)
{
    if (fd_ < 0)
        return;
    QString error;
    try {
        writeBuffer();
    } catch (const RunFileError& e) {
        error = e.reason();
    }
    // The footer goes in whatever happened to the rows (its space was reserved up front).
    try {
        const QByteArray tail = metadataBlock(footer);
        if (!tail.isEmpty()) {
            failed_ = false;  // one more attempt, into the reserve
            writeOrTruncate(tail);
        }
    } catch (const RunFileError& e) {
        if (error.isEmpty())
            error = e.reason();
    }
    // Give back the reserve beyond the end of the file.
    if (regular_)
        ::ftruncate(fd_, committed_);
    ::close(fd_);
    fd_ = -1;
    if (!error.isEmpty())
        throw RunFileError(path_, 0, error);
}

}  // namespace nb
