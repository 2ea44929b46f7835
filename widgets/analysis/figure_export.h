#pragma once
// A plot saved as a figure: PNG (savePng), PDF (savePdf) or SVG (QSvgGenerator), chosen by
// the file's suffix, at a fixed size so figures do not depend on the window.

#include <QString>
#include <QStringList>

class QCustomPlot;

namespace nb {

// Throws ExportError (core/export/export_error.h) for an unknown suffix or a failed write.
// The file appears complete or not at all.
void saveFigure(QCustomPlot* plot, const QString& path, int width = 900, int height = 600);

// Sizes a journal takes: one column (85 mm) and two columns (175 mm) wide.
struct JournalFigureSize {
    double width_mm;
    double height_mm;
};
inline constexpr JournalFigureSize kOneColumn{85.0, 62.0};
inline constexpr JournalFigureSize kTwoColumns{175.0, 100.0};

// The figure as a journal wants it, in every format: PNG (300 dpi), PDF and SVG (vector) at
// two columns under `pngPath`'s name (BASE.png, BASE.pdf, BASE.svg) and at one column beside
// (BASE_85mm.png/.pdf/.svg). Text is 7 pt (ticks, legend) to 9 pt (title), lines 0.75-1.5 pt,
// whatever the plot uses on screen; the plot is left as it was. Returns the files written.
// Throws ExportError.
QStringList saveJournalFigures(QCustomPlot* plot, const QString& pngPath);

}  // namespace nb
