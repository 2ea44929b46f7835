#include "csv_text.h"
#include "core/tr.h"
#include "core/save_file.h"

#include "export_error.h"

#include <QCoreApplication>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/disk_space.h"

namespace nb {

QByteArray csvField(const QString& text)
{
    QByteArray s = text.toUtf8();
    if (!s.contains(',') && !s.contains('"') && !s.contains('\n') && !s.contains('\r'))
        return s;
    s.replace("\"", "\"\"");
    return '"' + s + '"';
}

QByteArray csvNumber(double value, int decimals)
{
    if (std::isnan(value))
        return {};
    return QByteArray::number(value, 'f', decimals);
}

QString writeFailure(const QFileDevice& file, const QString& path)
{
    // QSaveFile reports a failed flush at commit as "Unknown error": say what it usually is.
    const auto free = freeBytes(path);
    if (free && *free < 64 * 1024)
        return nb::TrCore::tr("cannot write: no space left on the disk (%1 kB free)").arg(*free / 1024);
    const QString why = file.errorString();
    return nb::TrCore::tr("cannot write: %1")
        .arg(why.isEmpty() || why == QLatin1String("Unknown error") ? QString::fromLocal8Bit(std::strerror(errno)) : why);
}

void writeFileAtomically(const QString& path, const QByteArray& bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw ExportError(path, writeFailure(file, path));
    if (file.write(bytes) != bytes.size() || !commitWhole(file))
        throw ExportError(path, writeFailure(file, path));
}

}  // namespace nb
