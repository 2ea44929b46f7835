#pragma once
// Exports write NAME.part and rename it into place when done; one killed half-way leaves the
// .part behind. Those are removed the next time something is exported into the folder,
// unless another process still holds the file (it is writing it).

#include <QString>
#include <QStringList>

namespace nb {

// Removes `*.part` files in `folder` that no process holds locked; returns their paths.
QStringList removeStaleParts(const QString& folder);

}  // namespace nb
