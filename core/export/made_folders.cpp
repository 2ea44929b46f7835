#include "made_folders.h"

#include <QDir>
#include <QFileInfo>

#include <ranges>

namespace nb {

QStringList makeFolders(const QString& dir, bool* ok)
{
    QStringList missing;
    for (QString d = QDir::cleanPath(QFileInfo(dir).absoluteFilePath()); !QFileInfo::exists(d); d = QFileInfo(d).path()) {
        missing.prepend(d);
        if (QFileInfo(d).path() == d)  // the root itself is missing: nothing to make it in
            break;
    }
    *ok = QDir().mkpath(dir);
    if (!*ok) {
        removeEmptyFolders(missing);
        return {};
    }
    return missing;
}

void removeEmptyFolders(const QStringList& made)
{
    for (const QString& d : made | std::views::reverse)
        QDir().rmdir(d);  // refuses a folder that is not empty
}

}  // namespace nb
