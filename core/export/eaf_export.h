#pragma once
// ELAN annotation file (.eaf, EAF 3.0) for one run: a tier per label track, the run's force
// CSV as a linked file and, when the run names one, its video as the media file (offset by the
// sync offset), so the labels can be checked and edited in ELAN beside the video.

#include "dataset.h"
#include "export_error.h"

#include <QByteArray>

namespace nb {

struct EafLinks {
    QString forceCsvPath;  // linked as a secondary file; empty to leave out
    QString videoPath;     // the media file; empty to leave out
    // Where the document goes: the relative links (which ELAN tries first) start there, so
    // a folder moved with its files keeps its video and CSV. Set by writeEaf.
    QString documentPath;
};

// The document. ELAN needs end > start, so a point event becomes a 1 ms annotation.
QByteArray eafDocument(const DatasetRun& run, const EafLinks& links);

// Writes it atomically. Throws ExportError.
void writeEaf(const QString& path, const DatasetRun& run, const EafLinks& links);

}  // namespace nb
