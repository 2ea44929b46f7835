#pragma once
// Writing a file whole or not at all through QSaveFile.

#include <QSaveFile>

namespace nb {

// Commits `file`: true when every byte written is on the disk under the file's name. Qt 6.4's
// commit() renames the file into place even when writing its last buffered bytes failed: on a
// full disk a 4 kB labels file was replaced by an empty one and commit() said true. The bytes
// are flushed first; when that fails the file is left uncommitted (QSaveFile drops it when it
// goes) and `file.errorString()` says why.
inline bool commitWhole(QSaveFile& file) { return file.flush() && file.commit(); }

}  // namespace nb
