#include "csv_text.h"
#include "core/tr.h"

#include "export_error.h"

#include <QCoreApplication>
#include <QSaveFile>
#include <cmath>

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

void writeFileAtomically(const QString& path, const QByteArray& bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw ExportError(path, nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
    if (file.write(bytes) != bytes.size() || !file.commit())
        throw ExportError(path, nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
}

}  // namespace nb
