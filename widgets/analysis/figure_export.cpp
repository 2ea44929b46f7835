#include "figure_export.h"
#include "core/tr.h"

#include "core/export/export_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSvgGenerator>
#include <qcustomplot.h>

namespace nb {

void saveFigure(QCustomPlot* plot, const QString& path, int width, int height)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    // Render to a temporary beside the target and rename, so a failed or interrupted write
    // never leaves a truncated figure under the real name.
    const QString temp = QFileInfo(path).dir().filePath(QStringLiteral(".%1.part.%2").arg(QFileInfo(path).completeBaseName(), suffix));
    bool ok = false;
    if (suffix == QLatin1String("png")) {
        ok = plot->savePng(temp, width, height, 1.0, -1, 96);
    } else if (suffix == QLatin1String("pdf")) {
        ok = plot->savePdf(temp, width, height, QCP::epNoCosmetic, QStringLiteral("NeedleBench"), plot->objectName());
    } else if (suffix == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setFileName(temp);
        svg.setSize(QSize(width, height));
        svg.setViewBox(QRect(0, 0, width, height));
        svg.setTitle(plot->objectName());
        QCPPainter painter;
        if (painter.begin(&svg)) {
            plot->toPainter(&painter, width, height);
            ok = painter.end();
        }
    } else {
        throw ExportError(path, nb::TrViews::tr("unknown figure format '%1' (png, svg or pdf)").arg(suffix));
    }
    if (!ok || !QFileInfo(temp).exists() || QFileInfo(temp).size() == 0) {
        QFile::remove(temp);
        throw ExportError(path, nb::TrViews::tr("could not render the figure"));
    }
    QFile::remove(path);
    if (!QFile::rename(temp, path)) {
        QFile::remove(temp);
        throw ExportError(path, nb::TrViews::tr("cannot write the figure"));
    }
}

}  // namespace nb
