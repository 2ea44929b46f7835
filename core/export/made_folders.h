#pragma once
// The folders an export makes, so that one that fails or is cancelled takes away those it left
// empty: on a full disk an empty csv/ folder was all that was left, and looked like an export.

#include <QString>
#include <QStringList>

namespace nb {

// Makes `dir` and its missing parents. Returns the folders it made, outermost first, or
// nothing with `ok` false when one could not be made (those made before are taken away).
QStringList makeFolders(const QString& dir, bool* ok);

// Removes those of `made` that are empty, innermost first; a folder with anything in it stays.
void removeEmptyFolders(const QStringList& made);

}  // namespace nb
