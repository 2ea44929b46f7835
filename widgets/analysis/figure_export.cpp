#include "figure_export.h"
#include "core/tr.h"

#include "core/export/export_error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSvgGenerator>
#include <qcustomplot.h>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {

// Renders to a temporary beside the target and renames, so a failed or interrupted write
// never leaves a truncated figure under the real name. `width`, `height` in the plot's logical
// units; a PNG is scaled by `pngScale` and stamped with `dpi`.
void render(QCustomPlot* plot, const QString& path, int width, int height, double pngScale, int dpi, int svgResolution)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QString temp = QFileInfo(path).dir().filePath(QStringLiteral(".%1.part.%2").arg(QFileInfo(path).completeBaseName(), suffix));
    bool ok = false;
    if (suffix == QLatin1String("png")) {
        ok = plot->savePng(temp, width, height, pngScale, -1, dpi);
    } else if (suffix == QLatin1String("pdf")) {
        ok = plot->savePdf(temp, width, height, QCP::epNoCosmetic, QStringLiteral("NeedleBench"), plot->objectName());
    } else if (suffix == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setFileName(temp);
        svg.setResolution(svgResolution);
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

// Journal text sizes while a figure is written; the screen's come back afterwards. Sizes
// are set in the plot's logical units, which the journal renderer makes points.
class JournalStyle {
public:
    explicit JournalStyle(QCustomPlot* plot) : plot_(plot)
    {
        for (QCPAxis* a : {plot->xAxis, plot->yAxis, plot->xAxis2, plot->yAxis2}) {
            axes_.push_back({a, a->labelFont(), a->tickLabelFont(), a->basePen(), a->tickPen(), a->subTickPen()});
            a->setLabelFont(sized(a->labelFont(), 8, false));
            a->setTickLabelFont(sized(a->tickLabelFont(), 7, false));
            a->setLabelPadding(3);
            a->setTickLabelPadding(2);
            auto thin = [](QPen p) {
                p.setWidthF(0.6);
                return p;
            };
            a->setBasePen(thin(a->basePen()));
            a->setTickPen(thin(a->tickPen()));
            a->setSubTickPen(thin(a->subTickPen()));
        }
        legendFont_ = plot->legend->font();
        plot->legend->setFont(sized(legendFont_, 7, false));
        for (int i = 0; i < plot->legend->itemCount(); ++i)
            if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->legend->item(i)))
                item->setFont(sized(item->font(), 7, false));
        legendIcon_ = plot->legend->iconSize();
        plot->legend->setIconSize(14, 7);
        if (plot->plotLayout()->rowCount() > 1)
            if (auto* title = qobject_cast<QCPTextElement*>(plot->plotLayout()->element(0, 0))) {
                title_ = title;
                titleFont_ = title->font();
                titleText_ = title->text();
                title->setFont(sized(titleFont_, 9, true));
            }
        for (int i = 0; i < plot->plottableCount(); ++i) {
            QCPAbstractPlottable* p = plot->plottable(i);
            pens_.push_back({p, p->pen()});
            QPen q = p->pen();
            q.setWidthF(std::clamp(q.widthF() * 0.6, 0.75, 1.5));
            p->setPen(q);
            if (auto* g = qobject_cast<QCPGraph*>(p)) {
                QCPScatterStyle st = g->scatterStyle();
                scatters_.push_back({g, st});
                if (!st.isNone()) {
                    st.setSize(std::clamp(st.size() * 0.6, 1.2, 3.0));
                    g->setScatterStyle(st);
                }
            }
        }
    }
    // A title wider than the figure is broken at its ": " or " (" (a one-column figure has
    // room for about 50 characters at 9 pt).
    void fitTitle(int width_pt)
    {
        if (!title_)
            return;
        QString text = titleText_;
        const QFontMetricsF metrics(title_->font());
        for (const QString& at : {QStringLiteral(" ("), QStringLiteral(": ")}) {
            if (metrics.horizontalAdvance(text.section(QLatin1Char('\n'), 0, 0)) <= width_pt * 0.95)
                break;
            const qsizetype i = text.lastIndexOf(at);
            if (i > 0)
                text = text.left(i + (at == QLatin1String(": ") ? 1 : 0)) + QLatin1Char('\n') + text.mid(i + 1 + (at == QLatin1String(": ") ? 1 : 0));
        }
        title_->setText(text);
    }

    ~JournalStyle()
    {
        if (title_)
            title_->setText(titleText_);
        for (const AxisState& s : axes_) {
            s.axis->setLabelFont(s.label);
            s.axis->setTickLabelFont(s.tick);
            s.axis->setBasePen(s.base);
            s.axis->setTickPen(s.tickPen);
            s.axis->setSubTickPen(s.subTick);
            s.axis->setLabelPadding(5);
            s.axis->setTickLabelPadding(5);
        }
        plot_->legend->setFont(legendFont_);
        for (int i = 0; i < plot_->legend->itemCount(); ++i)
            if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(i)))
                item->setFont(legendFont_);
        plot_->legend->setIconSize(legendIcon_);
        if (title_)
            title_->setFont(titleFont_);
        for (const auto& [p, pen] : pens_)
            p->setPen(pen);
        for (const auto& [g, st] : scatters_)
            g->setScatterStyle(st);
        plot_->replot();
    }

private:
    static QFont sized(QFont f, int size, bool bold)
    {
        f.setPixelSize(size);
        f.setBold(bold);
        return f;
    }
    struct AxisState {
        QCPAxis* axis;
        QFont label, tick;
        QPen base, tickPen, subTick;
    };
    QCustomPlot* plot_;
    std::vector<AxisState> axes_;
    QFont legendFont_, titleFont_;
    QString titleText_;
    QSize legendIcon_;
    QCPTextElement* title_ = nullptr;
    std::vector<std::pair<QCPAbstractPlottable*, QPen>> pens_;
    std::vector<std::pair<QCPGraph*, QCPScatterStyle>> scatters_;
};

}  // namespace

void saveFigure(QCustomPlot* plot, const QString& path, int width, int height)
{
    render(plot, path, width, height, 1.0, 96, 96);
}

QStringList saveJournalFigures(QCustomPlot* plot, const QString& pngPath)
{
    const QFileInfo fi(pngPath);
    const QString base = fi.dir().filePath(fi.completeBaseName());
    QStringList written;
    JournalStyle style(plot);
    constexpr double kPointsPerMm = 72.0 / 25.4;
    constexpr int kDpi = 300;
    for (const auto& [size, suffix] : {std::pair{kTwoColumns, QString()}, std::pair{kOneColumn, QStringLiteral("_85mm")}}) {
        // One logical unit = 1 pt: the PDF page and the SVG at 72 units per inch are exactly
        // the size asked for, the PNG is scaled to 300 dpi.
        const int w = int(std::lround(size.width_mm * kPointsPerMm));
        const int h = int(std::lround(size.height_mm * kPointsPerMm));
        style.fitTitle(w);
        for (const char* ext : {"png", "pdf", "svg"}) {
            const QString path = base + suffix + QLatin1Char('.') + QLatin1String(ext);
            render(plot, path, w, h, kDpi / 72.0, kDpi, 72);
            written << path;
        }
    }
    return written;
}

}  // namespace nb
