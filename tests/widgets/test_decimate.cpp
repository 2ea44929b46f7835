// The min/max-per-column reduction and the live plot widget that uses it.
#include "core/decimate.h"
#include "widgets/force_plots.h"

#include <QtTest>
#include <cmath>
#include <qcustomplot.h>

class TestDecimate : public QObject {
    Q_OBJECT
private slots:
    void keepsEveryPeak()
    {
        const std::size_t n = 200000;
        std::vector<double> t(n), f(n);
        for (std::size_t i = 0; i < n; ++i) {
            t[i] = double(i) * 1e-4;
            f[i] = std::sin(t[i]);
        }
        f[123457] = 9.0;   // a one-sample spike (needle hits bone)
        f[4321] = -7.0;
        const std::span<const double> ch[] = {f};
        const auto idx = nb::minMaxIndices(t, ch, t.front(), t.back(), 1000);
        QVERIFY(idx.size() <= 4 * 1000 + 4);
        QVERIFY(idx.size() >= 1000);
        QVERIFY(std::is_sorted(idx.begin(), idx.end()));
        QVERIFY(std::adjacent_find(idx.begin(), idx.end()) == idx.end());
        QVERIFY(std::find(idx.begin(), idx.end(), 123457u) != idx.end());
        QVERIFY(std::find(idx.begin(), idx.end(), 4321u) != idx.end());
        QCOMPARE(idx.front(), 0u);
        QCOMPARE(idx.back(), n - 1);
    }

    void visibleSpanOnlyPlusNeighbours()
    {
        std::vector<double> t(10000), f(10000);
        for (std::size_t i = 0; i < t.size(); ++i) {
            t[i] = double(i);
            f[i] = double(i % 7);
        }
        const std::span<const double> ch[] = {f};
        const auto idx = nb::minMaxIndices(t, ch, 5000.0, 5999.0, 50);
        QCOMPARE(idx.front(), 4999u);  // one sample before, so the line reaches the edge
        QCOMPARE(idx.back(), 6000u);
        // Small spans are passed through unreduced.
        const auto all = nb::minMaxIndices(t, ch, 10.0, 20.0, 50);
        QCOMPARE(all.size(), 13u);
    }

    void curveKeepsExtremesOfBothChannels()
    {
        const std::size_t n = 100000;
        std::vector<double> t(n), x(n), f(n);
        for (std::size_t i = 0; i < n; ++i) {
            t[i] = double(i) / 1000.0;
            x[i] = 10.0 * std::sin(t[i]);
            f[i] = 0.1 * std::cos(3.0 * t[i]);
        }
        x[50001] = 99.0;
        f[70001] = -5.0;
        const std::span<const double> ch[] = {x, f};
        const auto idx = nb::minMaxIndices(t, ch, t.front(), t.back(), 300);
        QVERIFY(idx.size() <= 6 * 300 + 6);
        QVERIFY(std::find(idx.begin(), idx.end(), 50001u) != idx.end());
        QVERIFY(std::find(idx.begin(), idx.end(), 70001u) != idx.end());
        std::vector<double> gathered;
        nb::gather(x, idx, gathered);
        QCOMPARE(*std::max_element(gathered.begin(), gathered.end()), 99.0);
    }

    void emptyAndDegenerate()
    {
        const std::vector<double> none;
        const std::span<const double> ch[] = {none};
        QVERIFY(nb::minMaxIndices(none, ch, 0, 1, 100).empty());
        const std::vector<double> one{1.0};
        const std::span<const double> ch1[] = {one};
        QCOMPARE(nb::minMaxIndices(one, ch1, 0, 2, 100).size(), 1u);
        QVERIFY(nb::minMaxIndices(one, ch1, 0, 2, 0).empty());
    }

    void plotWidgetDrawsReducedDataWithLimitAndEvents()
    {
        nb::ForcePlots plots;
        plots.resize(1200, 700);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        const std::size_t n = 300000;  // 30 s at 10 kHz
        std::vector<double> t(n), x(n), f(n);
        for (std::size_t i = 0; i < n; ++i) {
            t[i] = double(i) / 10000.0;
            x[i] = 4.0 * t[i];
            f[i] = 0.01 * x[i] * x[i] / 10.0;
        }
        f[n - 5000] = 6.5;  // inside the followed window
        plots.appendSamples(t, x, f);
        plots.setForceLimit(8.0);
        plots.addEvent(12.0, QStringLiteral("puncture"));
        plots.refresh();
        QCOMPARE(plots.framesDrawn(), 1);
        const int width = plots.forceTimePlot()->axisRect()->width();
        QVERIFY(plots.pointsDrawnForceTime() > 0);
        QVERIFY(plots.pointsDrawnForceTime() <= std::size_t(4 * width + 4));
        QVERIFY(plots.pointsDrawnForcePosition() <= std::size_t(6 * plots.forcePositionPlot()->axisRect()->width() + 6));
        // Following: the last 10 s are in view, the spike is drawn, the limit is in range.
        QCOMPARE(plots.forceTimePlot()->xAxis->range().upper, t.back());
        QVERIFY(plots.forceTimePlot()->yAxis->range().contains(8.0));
        auto* graph = plots.forceTimePlot()->graph(0);
        bool spike = false;
        for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
            spike = spike || it->value == 6.5;
        QVERIFY(spike);
        QCOMPARE(plots.eventCount(), 1);

        // Pausing freezes what is shown; nothing is lost and it appears on resume.
        plots.setPaused(true);
        plots.append(30.0, 120.0, 1.0);
        plots.refresh();
        QCOMPARE(plots.forceTimePlot()->xAxis->range().upper, t.back());
        plots.setPaused(false);
        plots.refresh();
        QCOMPARE(plots.forceTimePlot()->xAxis->range().upper, 30.0);
        QCOMPARE(plots.sampleCount(), n + 1);

        // A wheel zoom by the operator stops following.
        QVERIFY(plots.follows());
        QWheelEvent wheel(QPointF(300, 150), plots.forceTimePlot()->mapToGlobal(QPointF(300, 150)), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(plots.forceTimePlot(), &wheel);
        QVERIFY(!plots.follows());
        // Zoomed in, the visible part is drawn in full detail.
        plots.forceTimePlot()->xAxis->setRange(20.0, 20.01);
        plots.forceTimePlot()->replot();
        QCOMPARE(plots.pointsDrawnForceTime(), 103u);
    }
};

QTEST_MAIN(TestDecimate)
#include "test_decimate.moc"
