#pragma once
// An earlier export's files kept aside until the new export is whole. An export that failed
// half-way (a full disk, a cancel) left the folder half the old export and half the new, with
// nothing to say which (probe). Each file is hard-linked into a hidden folder beside it (no space
// needed), put back over what the new export wrote if it fails, and let go when it succeeds.

#include <QString>
#include <QStringList>
#include <utility>
#include <vector>

namespace nb {

class KeptExport {
public:
    // Keeps each of `files`. Throws ExportError naming the file that cannot be kept (a file
    // system without hard links, a full disk for a copy): then nothing has been written.
    explicit KeptExport(const QStringList& files);
    KeptExport(const KeptExport&) = delete;
    KeptExport& operator=(const KeptExport&) = delete;
    // Neither settled: put back, as after a failure that wrote nothing.
    ~KeptExport();

    // The new export is whole: the kept files go.
    void release();
    // The new export failed: the files it wrote that were not the earlier export's are removed,
    // and the earlier export's put back. True when the folder is the earlier export again.
    bool restore(const QStringList& written);

private:
    std::vector<std::pair<QString, QString>> kept_;  // file, kept copy
    QStringList folders_;                            // the hidden folders made
    bool settled_ = false;
};

}  // namespace nb
