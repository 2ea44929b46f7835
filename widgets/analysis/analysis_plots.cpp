#include "analysis_plots.h"
#include "core/local_number.h"
#include "core/data_names.h"
#include "core/tr.h"

#include "core/models.h"
#include "core/signal.h"
#include "core/export/dataset.h"
#include "core/labels.h"

#include <QLocale>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <qcustomplot.h>

namespace nb {

namespace {
// Where the legend sits over the data, while it does: the Analysis tab moves it under the plot
// (legendBelow), after which the inset has nothing to align and Qt Custom Plot warned, 81 times.
void alignLegend(QCustomPlot* plot, Qt::Alignment where)
{
    QCPLayoutInset* inset = plot->axisRect()->insetLayout();
    if (plot->legend && plot->legend->layout() == inset && inset->elementCount() > 0)
        inset->setInsetAlignment(0, where);
}
}  // namespace

namespace {

void reset(QCustomPlot* plot, const QString& title, const QString& x, const QString& y)
{
    plot->clearGraphs();
    plot->clearItems();
    plot->clearPlottables();
    if (plot->plotLayout()->rowCount() > 1 && qobject_cast<QCPTextElement*>(plot->plotLayout()->element(0, 0)))
        static_cast<QCPTextElement*>(plot->plotLayout()->element(0, 0))->setText(title);
    else {
        plot->plotLayout()->insertRow(0);
        plot->plotLayout()->addElement(0, 0, new QCPTextElement(plot, title, QFont(plot->font().family(), 11, QFont::Bold)));
    }
    plot->xAxis->setLabel(x);
    plot->yAxis->setLabel(y);
    plot->legend->setVisible(true);
    plot->legend->setFont(QFont(plot->font().family(), 8));
    plot->legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);  // plotPhases lays it out in a row
    alignLegend(plot, Qt::AlignTop | Qt::AlignLeft);
    plot->setObjectName(title);
}

QCPGraph* scatter(QCustomPlot* plot, const QVector<double>& x, const QVector<double>& y, const QColor& c, double size,
                  const QString& name)
{
    QCPGraph* g = plot->addGraph();
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, c, size));
    g->setPen(QPen(c));
    g->setData(x, y, true);
    g->setName(name);
    g->setAdaptiveSampling(false);  // every recorded point is shown
    return g;
}

QCPGraph* line(QCustomPlot* plot, const QVector<double>& x, const QVector<double>& y, const QPen& pen, const QString& name)
{
    QCPGraph* g = plot->addGraph();
    g->setPen(pen);
    g->setData(x, y, true);
    g->setName(name);
    return g;
}

// Okabe & Ito's colour-blind-safe palette (vermillion kept for outliers).
QColor runColor(int i)
{
    static const QColor palette[] = {QColor(0, 114, 178), QColor(230, 159, 0), QColor(0, 158, 115), QColor(204, 121, 167),
                                     QColor(86, 180, 233), QColor(0, 0, 0), QColor(240, 228, 66)};
    return palette[i % 7];
}

const QColor kOutlier(213, 94, 0);

QColor phaseColor(const QString& phase)
{
    if (phase == QLatin1String("a"))
        return QColor(230, 159, 0, 90);     // orange
    if (phase == QLatin1String("b1"))
        return QColor(86, 180, 233, 100);   // sky blue
    if (phase == QLatin1String("b2"))
        return QColor(0, 158, 115, 90);     // bluish green
    if (phase == QLatin1String("c"))
        return QColor(204, 121, 167, 90);   // reddish purple
    return QColor(200, 200, 200, 70);
}

// The data's range plus a margin on every side, so that no point or peak touches the frame.
void fitRanges(QCustomPlot* plot, double margin = 0.05)
{
    plot->rescaleAxes();
    for (QCPAxis* a : {plot->xAxis, plot->yAxis}) {
        const QCPRange r = a->range();
        const double pad = r.size() > 0 ? r.size() * margin : std::max(1e-9, std::abs(r.center()) * margin + 1e-9);
        a->setRange(r.lower - pad, r.upper + pad);
    }
}

}  // namespace

void plotStiffness(QCustomPlot* plot, const SessionAnalysis& a, const QString& group)
{
    reset(plot, nb::TrViews::tr("Stiffness before puncture: %1").arg(group.isEmpty() ? nb::TrViews::tr("no tissue given") : group),
          nb::TrViews::tr("depth past contact [mm]"), nb::TrViews::tr("force [N]"));
    const StiffnessGroupResult* g = nullptr;
    for (const auto& candidate : a.stiffnessGroups)
        if (candidate.group == group)
            g = &candidate;
    if (!g) {
        plot->replot();
        return;
    }
    double maxDepth = 0.0;
    int k = 0;
    bool outlierNamed = false;
    for (std::size_t i : g->runs) {
        const StiffnessRunResult& s = a.stiffness[i];
        // At most ~150 dots per run: thousands of 2 px dots merge into one line under the fits
        // and neither the runs nor an outlier can be told apart.
        const std::size_t n = s.segment.depth_mm.size();
        const std::size_t stride = std::max<std::size_t>(1, n / 150);
        QVector<double> x, y;
        for (std::size_t j = 0; j < n; j += stride) {
            x << s.segment.depth_mm[j];
            y << s.segment.force_N[j];
        }
        for (double d : x)
            maxDepth = std::max(maxDepth, d);
        const QColor c = s.outlier ? kOutlier : runColor(k++);
        QCPGraph* dots = scatter(plot, x, y, c, 5.0, s.outlier ? nb::TrViews::tr("%1 (outlier)").arg(s.run) : s.run);
        if (s.outlier) {
            outlierNamed = true;
            dots->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, c, 6.0));  // told apart by shape too
        }
        QVector<double> fx, fy;
        const double end = x.isEmpty() ? 0.0 : x.last();
        for (int j = 0; j <= 60; ++j) {
            fx << end * j / 60.0;
            fy << s.fit.quadratic.model(fx.last());
        }
        QCPGraph* fit = line(plot, fx, fy, QPen(c.lighter(120), 1.0), QString());
        fit->removeFromLegend();
    }
    (void)outlierNamed;
    QVector<double> px, py;
    for (int j = 0; j <= 100; ++j) {
        px << maxDepth * j / 100.0;
        py << g->summary.pooled.quadratic.model(px.last());
    }
    const StiffnessModel& m = g->summary.pooled.quadratic.model;
    line(plot, px, py, QPen(Qt::black, 2.0, Qt::DashLine),
         // On three lines: one long line is wider than a one-column figure.
         nb::TrViews::tr("pooled fit:\nF = %1 x + %2 x²\n(F in N, x in mm)").arg(QLocale().toString(m.a1_N_per_mm, 'f', 4), QLocale().toString(m.a2_N_per_mm2, 'f', 4)));
    fitRanges(plot);
    plot->replot();
}

void plotFrictionVelocity(QCustomPlot* plot, const DatasetRun& run, const FrictionRunResult& f)
{
    // Velocity in mm/s, as in the run files.
    reset(plot, nb::TrViews::tr("Friction against velocity: %1").arg(run.name), nb::TrViews::tr("velocity [mm/s]"), nb::TrViews::tr("friction force [N]"));
    if (!f.ok() || run.run.size() < 3) {
        plot->replot();
        return;
    }
    // As the fit sees it: smoothed position differentiated, the known mass's inertia removed.
    const int w = windowForDuration(run.run.time_s, 0.02);
    const auto pos = movingAverage(run.run.position_mm, w);
    const auto vel = movingAverage(derivative(run.run.time_s, pos), w);
    const auto acc = movingAverage(derivative(run.run.time_s, vel), w);
    const auto force = movingAverage(run.run.force_N, w);
    const KarnoppModel& k = f.fit.model;
    const double half_mm_s = k.band_m_s * 1000.0 / 2.0;
    // The samples the fit slides on: outside the zero-velocity band, and in phase c when the
    // run is labelled (see fitFriction); the others are drawn, lighter, as not fitted.
    const QStringList phases = phasePerSample(run.labels, run.run.time_s);
    bool labelled = false;
    for (const QString& p : phases)
        labelled = labelled || !p.isEmpty();
    QVector<double> x, y, xo, yo;
    const std::size_t trim = std::min<std::size_t>(100, run.run.size() / 4);
    for (std::size_t i = trim; i + trim < run.run.size(); ++i) {
        const double v = vel[i];
        const double F = force[i] - kNeedleHolderMass_kg * acc[i] / 1000.0;
        const bool fitted = std::abs(v) > half_mm_s && (!labelled || phases[qsizetype(i)] == QLatin1String("c"));
        (fitted ? x : xo) << v;
        (fitted ? y : yo) << F;
    }
    scatter(plot, xo, yo, QColor(150, 150, 150, 110), 2.0, nb::TrViews::tr("recorded, not fitted"));
    scatter(plot, x, y, QColor(0, 114, 178, 160), 2.5, nb::TrViews::tr("recorded, fitted"));
    double vmax = 0.0;
    for (const QVector<double>* xs : {&x, &xo})
        for (double v : *xs)
            vmax = std::max(vmax, std::abs(v));
    QVector<double> mx, my;
    // The sliding branches; inside the band the model follows the applied force up to D.
    for (int j = 0; j <= 50; ++j) {
        const double v = -vmax + (vmax - half_mm_s) * j / 50.0;
        mx << v;
        my << k(v / 1000.0, 0.0);
    }
    mx << -half_mm_s << 0.0 << 0.0 << half_mm_s;
    my << k.Dn_N << k.Dn_N << k.Dp_N << k.Dp_N;
    for (int j = 0; j <= 50; ++j) {
        const double v = half_mm_s + (vmax - half_mm_s) * j / 50.0;
        mx << v;
        my << k(v / 1000.0, 0.0);
    }
    QCPCurve* curve = new QCPCurve(plot->xAxis, plot->yAxis);
    curve->setData(mx, my);
    curve->setPen(QPen(QColor(213, 94, 0), 2.5));
    curve->setName(nb::TrViews::tr("Karnopp fit (%1 Hz)").arg(localNumber(f.fit.frequency_hz, 2)));
    // Slow withdrawal with little friction is where the data leave room for the legend.
    alignLegend(plot, Qt::AlignBottom | Qt::AlignRight);
    fitRanges(plot);
    plot->replot();
}

void plotPhases(QCustomPlot* plot, const DatasetRun& run)
{
    reset(plot, nb::TrViews::tr("Labelled phases: %1").arg(run.name), nb::TrViews::tr("time [s]"), nb::TrViews::tr("force [N]"));
    // Insertion and withdrawal told apart by line style (solid, dashed), not colour alone.
    const QStringList tracks = labelsPerSample(run.labels, run.run.time_s, QStringLiteral("withdrawal"));
    QVector<double> t(run.run.time_s.begin(), run.run.time_s.end());
    QVector<double> in(qsizetype(run.run.size()), qQNaN()), out(qsizetype(run.run.size()), qQNaN());
    bool anyOut = false;
    for (qsizetype i = 0; i < t.size(); ++i) {
        const bool withdrawing = !tracks.value(i).isEmpty();
        anyOut = anyOut || withdrawing;
        (withdrawing ? out : in)[i] = run.run.force_N[std::size_t(i)];
        // Join the two at each switch so the trace stays continuous.
        if (i > 0 && withdrawing != !tracks.value(i - 1).isEmpty())
            (withdrawing ? out : in)[i - 1] = run.run.force_N[std::size_t(i - 1)];
    }
    line(plot, t, in, QPen(QColor(0, 0, 0), 1.0), anyOut ? nb::TrViews::tr("force, insertion") : nb::TrViews::tr("force"));
    if (anyOut)
        line(plot, t, out, QPen(QColor(0, 0, 0), 1.0, Qt::DashLine), nb::TrViews::tr("force, withdrawal"));
    fitRanges(plot);
    QStringList named;
    for (const Label& l : run.labels) {
        if (!l.isPoint() && !named.contains(l.label))
            named << l.label;
        if (l.isPoint()) {
            auto* v = new QCPItemStraightLine(plot);
            v->point1->setCoords(l.start_s, 0);
            v->point2->setCoords(l.start_s, 1);
            v->setPen(QPen(Qt::darkGray, 1, Qt::DashLine));
            continue;
        }
        auto* r = new QCPItemRect(plot);
        r->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
        r->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
        r->topLeft->setCoords(l.start_s, 0.0);
        r->bottomRight->setCoords(l.end_s, 1.0);
        r->setPen(Qt::NoPen);
        r->setBrush(phaseColor(l.label));
        r->setLayer(QStringLiteral("background"));
    }
    // Legend entries in the phases' own order (a, b1, b2, c), not that of the first label seen.
    std::sort(named.begin(), named.end());
    for (const QString& phase : named) {
        // An empty graph carrying the phase's colour.
        QCPGraph* key = plot->addGraph();
        key->setName(nb::TrViews::tr("phase %1").arg(phase));
        key->setPen(QPen(phaseColor(phase).darker(120), 8));
    }
    // The force fills the whole width: the legend goes in one row in headroom above it.
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    const QCPRange y = plot->yAxis->range();
    plot->yAxis->setRange(y.lower, y.upper + 0.18 * y.size());
    plot->replot();
}

void plotValidation(QCustomPlot* plot, const ValidationResult& v)
{
    reset(plot,
          v.ok() ? nb::TrViews::tr("Model against recording: %1 (rms %2 N)").arg(v.run).arg(localNumber(v.rms_N, 3))
                 : nb::TrViews::tr("Model against recording: %1 (%2)").arg(v.run, v.error),
          nb::TrViews::tr("needle position [mm]"), nb::TrViews::tr("force [N]"));
    QVector<double> x(v.recorded.position_mm.begin(), v.recorded.position_mm.end());
    QVector<double> y(v.recorded.force_N.begin(), v.recorded.force_N.end());
    // Position is not monotonic on withdrawal: a curve keeps the sample order.
    auto* rec = new QCPCurve(plot->xAxis, plot->yAxis);
    rec->setData(x, y);
    rec->setPen(QPen(QColor(0, 114, 178), 1.5));
    rec->setName(nb::TrViews::tr("recorded"));
    if (v.ok()) {
        QVector<double> sx(v.simulated.position_mm.begin(), v.simulated.position_mm.end());
        QVector<double> sy(v.simulated.force_N.begin(), v.simulated.force_N.end());
        auto* sim = new QCPCurve(plot->xAxis, plot->yAxis);
        sim->setData(sx, sy);
        // Dashed on top: where model and recording agree both stay visible.
        sim->setPen(QPen(QColor(213, 94, 0), 2.0, Qt::DashLine));
        sim->setName(nb::TrViews::tr("summed model"));
    }
    // After the puncture the force stays low: the top right is free for the legend.
    alignLegend(plot, Qt::AlignTop | Qt::AlignRight);
    fitRanges(plot);
    plot->replot();
}

void plotByFactor(QCustomPlot* plot, const std::vector<RunFactorValues>& runs, const std::vector<FactorCell>& cells,
                  const QString& factor, const FactorQuantity& q)
{
    const QString unit = q.unit.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(q.unit);
    reset(plot, nb::TrViews::tr("%1 by %2: mean ± std, n per level").arg(q.title, factorDisplayName(factor)), factorDisplayName(factor), q.title + unit);
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    QVector<double> runX, runY, meanX, meanY, spread;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const FactorCell& c = cells[i];
        const QString level = c.levels.isEmpty() || c.levels.first().isEmpty() ? nb::TrViews::tr("(none)") : c.levels.first();
        const auto it = c.stats.find(q.key);
        const std::size_t n = it == c.stats.end() ? 0 : it->second.n;
        ticker->addTick(double(i), QStringLiteral("%1\nn = %2").arg(level).arg(n));
        if (n > 0) {
            meanX << double(i);
            meanY << it->second.mean;
            spread << (std::isfinite(it->second.stdDev) ? it->second.stdDev : 0.0);  // one run: no bar
        }
        // The runs of this level, spread a little sideways so that equal values stay visible.
        std::vector<double> values;
        for (const RunFactorValues& r : runs) {
            const auto level = r.levels.find(factor);
            const auto v = r.values.find(q.key);
            if (level != r.levels.end() && level->second == (c.levels.isEmpty() ? QString() : c.levels.first()) && v != r.values.end())
                values.push_back(v->second);
        }
        for (std::size_t k = 0; k < values.size(); ++k) {
            runX << double(i) + (values.size() > 1 ? 0.24 * (double(k) / double(values.size() - 1) - 0.5) : 0.0);
            runY << values[k];
        }
    }
    scatter(plot, runX, runY, QColor(150, 150, 150), 5.0, nb::TrViews::tr("runs"));
    QCPGraph* means = scatter(plot, meanX, meanY, QColor(31, 119, 180), 9.0, nb::TrViews::tr("mean ± std"));
    auto* bars = new QCPErrorBars(plot->xAxis, plot->yAxis);
    bars->removeFromLegend();
    bars->setDataPlottable(means);
    bars->setData(spread);
    bars->setPen(QPen(QColor(31, 119, 180), 1.5));
    plot->xAxis->setTicker(ticker);
    plot->xAxis->setRange(-0.6, std::max<double>(0.6, double(cells.size()) - 0.4));
    if (runY.isEmpty()) {
        plot->yAxis->setRange(0.0, 1.0);
    } else {
        double lo = *std::min_element(runY.begin(), runY.end()), hi = *std::max_element(runY.begin(), runY.end());
        for (int i = 0; i < meanY.size(); ++i) {
            lo = std::min(lo, meanY[i] - spread[i]);
            hi = std::max(hi, meanY[i] + spread[i]);
        }
        const double pad = hi > lo ? 0.08 * (hi - lo) : std::max(1e-9, 0.1 * std::abs(hi));
        plot->yAxis->setRange(lo - pad, hi + pad);
    }
    plot->replot();
}

}  // namespace nb
