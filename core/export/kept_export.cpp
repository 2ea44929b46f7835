#include "kept_export.h"

#include "core/tr.h"
#include "export_error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace nb {

namespace {

const QString kKeptFolder = QStringLiteral(".needlebench-earlier-export");

}  // namespace

KeptExport::KeptExport(const QStringList& files)
{
    for (const QString& file : files) {
        const QFileInfo info(file);
        const QDir dir(info.absolutePath());
        const QString folder = dir.filePath(kKeptFolder);
        if (!folders_.contains(folder)) {
            // One left by an export that was killed holds nothing of this one.
            QDir(folder).removeRecursively();
            if (!dir.mkdir(kKeptFolder)) {
                restore({});
                throw ExportError(file, nb::TrCore::tr("cannot keep the earlier export aside while the new one is written "
                                                       "(cannot create %1): nothing was written")
                                            .arg(QDir::toNativeSeparators(folder)));
            }
            folders_ << folder;
        }
        const QString copy = QDir(folder).filePath(info.fileName());
        if (::link(QFile::encodeName(info.absoluteFilePath()).constData(), QFile::encodeName(copy).constData()) != 0
            && !QFile::copy(info.absoluteFilePath(), copy)) {
            const QString why = QString::fromLocal8Bit(std::strerror(errno));
            restore({});
            throw ExportError(file, nb::TrCore::tr("cannot keep the earlier export aside while the new one is written (%1): "
                                                   "nothing was written")
                                        .arg(why));
        }
        kept_.emplace_back(info.absoluteFilePath(), copy);
    }
}

KeptExport::~KeptExport()
{
    if (!settled_)
        restore({});
}

void KeptExport::release()
{
    settled_ = true;
    for (const QString& folder : folders_)
        QDir(folder).removeRecursively();
}

bool KeptExport::restore(const QStringList& written)
{
    settled_ = true;
    bool whole = true;
    QStringList earlier;
    for (const auto& [file, copy] : kept_) {
        earlier << file;
        // A rename needs no space, and replaces what the new export put there in one step.
        whole &= std::rename(QFile::encodeName(copy).constData(), QFile::encodeName(file).constData()) == 0;
    }
    for (const QString& w : written)
        if (!earlier.contains(QFileInfo(w).absoluteFilePath()))
            QFile::remove(w);
    for (const QString& folder : folders_)
        QDir(folder).removeRecursively();
    return whole;
}

}  // namespace nb
