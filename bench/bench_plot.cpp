// Part 2 (live): the workbench's ForcePlots widget (three plots, 1400x700) fed a 10 kHz
// recording in 40 Hz chunks as the drain timer does; the time of each refresh as the run
// grows says whether 30 frames/s hold (budget 33 ms per frame, shared with the rest of the GUI).
//
// Part 1: replot time of the live plots, offscreen at 1200x600: the force-vs-time graph and the
// force-vs-position curve, with the min/max-per-pixel-column reduction (core/decimate.h)
// against the same plot handed every sample, in the same process. Target: 1e6 points
// reduced < 10 ms.
//
//   QT_QPA_PLATFORM=offscreen ./build-gui/bench/bench_plot [max_points]

#include "core/decimate.h"
#include "widgets/force_plots.h"

#include <QApplication>
#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <qcustomplot.h>
#include <random>
#include <vector>

namespace {

struct Series {
    std::vector<double> t, x, f;
};

// A sinusoidal friction run sampled at 10 kHz with sensor noise: a dense, noisy worst case.
Series makeSeries(std::size_t n)
{
    Series s;
    s.t.resize(n);
    s.x.resize(n);
    s.f.resize(n);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.02);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / 10000.0;
        s.t[i] = t;
        s.x[i] = 20.0 + 10.0 * std::sin(2.0 * M_PI * 0.5 * t);
        s.f[i] = 0.8 * std::cos(2.0 * M_PI * 0.5 * t) + 0.03 * s.x[i] + noise(rng);
    }
    return s;
}

template <typename F>
double medianMs(int repeats, F&& body)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        QElapsedTimer timer;
        timer.start();
        body();
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

double timePlot(QCustomPlot& plot, const Series& s, bool reduce, int repeats)
{
    QCPGraph* graph = plot.graph(0);
    plot.xAxis->setRange(s.t.front(), s.t.back());
    plot.yAxis->setRange(-1.5, 2.5);
    return medianMs(repeats, [&] {
        QVector<QCPGraphData> data;
        if (reduce) {
            const std::span<const double> channels[] = {s.f};
            const auto idx = nb::minMaxIndices(s.t, channels, s.t.front(), s.t.back(), plot.axisRect()->width());
            data.resize(qsizetype(idx.size()));
            for (std::size_t k = 0; k < idx.size(); ++k)
                data[qsizetype(k)] = {s.t[idx[k]], s.f[idx[k]]};
        } else {
            data.resize(qsizetype(s.t.size()));
            for (std::size_t k = 0; k < s.t.size(); ++k)
                data[qsizetype(k)] = {s.t[k], s.f[k]};
        }
        graph->data()->set(data, true);
        plot.replot(QCustomPlot::rpImmediateRefresh);
    });
}

double curvePlot(QCustomPlot& plot, const Series& s, bool reduce, int repeats)
{
    auto* curve = qobject_cast<QCPCurve*>(plot.plottable(0));
    plot.xAxis->setRange(8, 32);
    plot.yAxis->setRange(-1.5, 2.5);
    return medianMs(repeats, [&] {
        QVector<QCPCurveData> data;
        if (reduce) {
            const std::span<const double> channels[] = {s.x, s.f};
            const auto idx = nb::minMaxIndices(s.t, channels, s.t.front(), s.t.back(), plot.axisRect()->width());
            data.resize(qsizetype(idx.size()));
            for (std::size_t k = 0; k < idx.size(); ++k)
                data[qsizetype(k)] = {s.t[idx[k]], s.x[idx[k]], s.f[idx[k]]};
        } else {
            data.resize(qsizetype(s.t.size()));
            for (std::size_t k = 0; k < s.t.size(); ++k)
                data[qsizetype(k)] = {s.t[k], s.x[k], s.f[k]};
        }
        curve->data()->set(data, true);
        plot.replot(QCustomPlot::rpImmediateRefresh);
    });
}

// The reduction alone (no plot), to tell its cost from the drawing's.
double reduceOnly(const Series& s, int channels, int repeats)
{
    return medianMs(repeats, [&] {
        const std::span<const double> both[] = {s.x, s.f};
        const auto idx = nb::minMaxIndices(s.t, std::span<const std::span<const double>>(both).last(std::size_t(channels)),
                                           s.t.front(), s.t.back(), 1150);
        if (idx.empty())
            std::abort();
    });
}

}  // namespace

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const double maxPoints = argc > 1 ? std::atof(argv[1]) : 1e7;

    // Drawn as the workbench draws them: 1 px lines without antialiasing (force_plots.cpp).
    QCustomPlot timePlotWidget;
    timePlotWidget.resize(1200, 600);
    timePlotWidget.setNotAntialiasedElements(QCP::aePlottables);
    timePlotWidget.addGraph()->setAdaptiveSampling(false);
    timePlotWidget.show();
    QCustomPlot curveWidget;
    curveWidget.resize(1200, 600);
    curveWidget.setNotAntialiasedElements(QCP::aePlottables);
    new QCPCurve(curveWidget.xAxis, curveWidget.yAxis);
    curveWidget.show();
    app.processEvents();

    std::printf("replot 1200x600 offscreen, median of repeats, ms (reduce + hand over + draw)\n");
    std::printf("%-10s %-16s %12s %12s %8s %14s\n", "points", "plot", "reduced", "unreduced", "ratio", "reduce only");
    for (double n : {1e5, 1e6, 1e7}) {
        if (n > maxPoints)
            break;
        const Series s = makeSeries(std::size_t(n));
        const int repeats = n >= 1e7 ? 3 : 7;
        // Unreduced at 1e7 takes tens of seconds per frame; one frame is enough to show it.
        const int slowRepeats = n >= 1e7 ? 1 : (n >= 1e6 ? 3 : 5);
        const double tr = timePlot(timePlotWidget, s, true, repeats);
        const double tu = timePlot(timePlotWidget, s, false, slowRepeats);
        std::printf("%-10.0e %-16s %12.2f %12.2f %7.0fx %14.2f\n", n, "force-time", tr, tu, tu / tr, reduceOnly(s, 1, repeats));
        const double cr = curvePlot(curveWidget, s, true, repeats);
        const double cu = curvePlot(curveWidget, s, false, slowRepeats);
        std::printf("%-10.0e %-16s %12.2f %12.2f %7.0fx %14.2f\n", n, "force-position", cr, cu, cu / cr, reduceOnly(s, 2, repeats));
        std::fflush(stdout);
    }

    // Live: a 120 s run at 10 kHz, drained 40 times a second.
    nb::ForcePlots live;
    live.resize(1400, 700);
    live.show();
    app.processEvents();
    live.setForceLimit(8.0);
    const double rate = 10000.0, fps = 40.0;
    const std::size_t chunk = std::size_t(rate / fps);
    const Series run = makeSeries(std::size_t(120.0 * rate));
    std::printf("\nlive ForcePlots 1400x700, 10 kHz in %zu-sample chunks at %.0f Hz: refresh ms per frame\n", chunk, fps);
    std::printf("%-14s %10s %10s\n", "run so far", "median", "max");
    std::vector<double> frameMs;
    for (std::size_t at = 0; at + chunk <= run.t.size(); at += chunk) {
        QElapsedTimer timer;
        timer.start();
        live.appendSamples(std::span(run.t).subspan(at, chunk), std::span(run.x).subspan(at, chunk),
                           std::span(run.f).subspan(at, chunk));
        live.refresh();
        frameMs.push_back(double(timer.nsecsElapsed()) / 1e6);
        const double seconds = double(at + chunk) / rate;
        if (std::fmod(seconds, 30.0) < 1e-9) {
            std::vector<double> last(frameMs.end() - std::ptrdiff_t(std::min<std::size_t>(frameMs.size(), 40)), frameMs.end());
            std::sort(last.begin(), last.end());
            std::printf("%-12.0f s %10.2f %10.2f\n", seconds, last[last.size() / 2], last.back());
            std::fflush(stdout);
        }
    }
    return 0;
}
