#include "disk_space.h"

#include <QFileInfo>
#include <QStorageInfo>
#include <limits>

namespace nb {

std::optional<qint64> freeBytes(const QString& path)
{
    QFileInfo info(path);
    // A file not yet created: ask about the folder it goes to.
    const QString where = info.exists() ? info.absoluteFilePath() : info.absolutePath();
    QStorageInfo storage(where);
    if (!storage.isValid() || !storage.isReady())
        return std::nullopt;
    const qint64 available = storage.bytesAvailable();
    return available < 0 ? std::nullopt : std::optional<qint64>(available);
}

double secondsUntilFull(qint64 free_bytes, double bytes_per_s)
{
    if (!(bytes_per_s > 0.0))
        return std::numeric_limits<double>::infinity();
    return static_cast<double>(std::max<qint64>(free_bytes, 0)) / bytes_per_s;
}

}  // namespace nb
