#include "stale_parts.h"

#include <QDir>
#include <QFile>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace nb {

QStringList removeStaleParts(const QString& folder)
{
    QStringList removed;
    const QDir dir(folder);
    for (const QString& name : dir.entryList({QStringLiteral("*.part")}, QDir::Files | QDir::Hidden)) {
        const QString path = dir.filePath(name);
        const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_CLOEXEC);
        if (fd < 0)
            continue;
        // HDF5 and our writers hold an exclusive flock while writing: a free lock means the
        // writer is gone.
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && QFile::remove(path))
            removed << path;
        ::close(fd);
    }
    return removed;
}

}  // namespace nb
