#pragma once
// A plot saved as a figure: PNG (savePng), PDF (savePdf) or SVG (QSvgGenerator), chosen by
// the file's suffix, at a fixed size so figures do not depend on the window.

#include <QString>

class QCustomPlot;

namespace nb {

// Throws ExportError (core/export/export_error.h) for an unknown suffix or a failed write.
// The file appears complete or not at all.
void saveFigure(QCustomPlot* plot, const QString& path, int width = 900, int height = 600);

}  // namespace nb
