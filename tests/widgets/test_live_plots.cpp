// The live plots observe the live-run model: what the model holds is what they draw, its
// marks are their event marks, and a new run clears them. Driven synchronously through a real
// ring and real QCustomPlot widgets (offscreen).
#include "devices/live_run.h"
#include "widgets/force_plots.h"

#include <qcustomplot.h>

#include <QtTest>

using namespace nb::devices;

namespace {

void pushRamp(SpscRing<Sample>& ring, std::uint64_t& seq, int n)
{
    for (int i = 0; i < n; ++i, ++seq) {
        Sample s;
        s.seq = seq;
        s.time_s = 5.0 + double(seq) / 1000.0;
        s.position_mm = double(seq) * 0.002;
        s.force_N = 0.001 * double(seq % 100);
        QVERIFY(ring.push(s));
    }
}

}  // namespace

class TestLivePlots : public QObject {
    Q_OBJECT
private slots:
    void plotsShowWhatTheModelHolds()
    {
        SpscRing<Sample> ring(1 << 14);
        std::uint64_t seq = 0;
        LiveRun live;
        live.setSource(&ring);
        nb::ForcePlots plots;
        plots.resize(900, 600);
        plots.observe(&live);

        pushRamp(ring, seq, 400);
        const int framesBefore = plots.framesDrawn();
        live.pull();
        QCOMPARE(plots.sampleCount(), std::size_t(400));
        QCOMPARE(plots.times().data(), live.series().time_s.data());  // one copy of the data: the model's
        QVERIFY(plots.framesDrawn() > framesBefore);                  // each pull redraws
        QVERIFY(plots.pointsDrawnForceTime() > 0);

        // Fed directly while observing: ignored, the model is the one source.
        plots.append(99.0, 1.0, 1.0);
        QCOMPARE(plots.sampleCount(), std::size_t(400));

        // The model's marks are the plots' event marks, with their translated text.
        live.mark(LiveMarkKind::Withdraw);
        live.mark(LiveMarkKind::EmergencyStop);
        QCOMPARE(plots.eventLabels(), (QStringList{nb::ForcePlots::markLabel(LiveMarkKind::Withdraw),
                                                    nb::ForcePlots::markLabel(LiveMarkKind::EmergencyStop)}));
        QCOMPARE(plots.eventLabels().at(1), QStringLiteral("E-STOP"));

        // A run begins: samples and marks are gone from the plots as from the model.
        live.beginRun(false);
        QCOMPARE(plots.sampleCount(), std::size_t(0));
        QCOMPARE(plots.eventCount(), 0);
        pushRamp(ring, seq, 50);
        live.pull();
        QCOMPARE(plots.sampleCount(), std::size_t(50));
    }

    // The newest samples are drawn at the plots' right edge: a mark made there (an emergency
    // stop) has its label inside each plot, read leftwards, not cut off at the edge ("E-ST").
    void aMarkAtTheNewestSampleIsReadInFull()
    {
        SpscRing<Sample> ring(1 << 14);
        std::uint64_t seq = 0;
        LiveRun live;
        live.setSource(&ring);
        nb::ForcePlots plots;
        plots.resize(900, 600);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.observe(&live);
        for (int i = 0; i < 6; ++i) {  // 30 s: the time plots follow their last seconds
            pushRamp(ring, seq, 5000);
            live.pull();
        }
        live.mark(LiveMarkKind::EmergencyStop);
        pushRamp(ring, seq, 1);
        live.pull();
        int labels = 0;
        for (QCustomPlot* plot : {plots.forceTimePlot(), plots.positionTimePlot(), plots.forcePositionPlot()}) {
            const QRect inside = plot->axisRect()->rect();
            for (int i = 0; i < plot->itemCount(); ++i) {
                auto* text = qobject_cast<QCPItemText*>(plot->item(i));
                if (!text || text->text() != nb::ForcePlots::markLabel(LiveMarkKind::EmergencyStop))
                    continue;
                ++labels;
                const QPointF right = text->position->pixelPosition();
                const double width = QFontMetricsF(text->font()).horizontalAdvance(text->text());
                const double from = text->positionAlignment() & Qt::AlignRight ? right.x() - width : right.x();
                QVERIFY2(from >= inside.left() && from + width <= inside.right() + 1,
                         qPrintable(QStringLiteral("label from %1 to %2 px, plot %3 to %4 px")
                                        .arg(from).arg(from + width).arg(inside.left()).arg(inside.right())));
            }
        }
        QCOMPARE(labels, 3);
    }

    void pausedPlotsCatchUpWithoutLoss()
    {
        SpscRing<Sample> ring(1 << 14);
        std::uint64_t seq = 0;
        LiveRun live;
        live.setSource(&ring);
        nb::ForcePlots plots;
        plots.observe(&live);
        pushRamp(ring, seq, 100);
        live.pull();
        plots.setPaused(true);
        const std::size_t drawn = plots.pointsDrawnForceTime();
        pushRamp(ring, seq, 300);
        live.pull();
        QCOMPARE(plots.pointsDrawnForceTime(), drawn);  // the view holds still ...
        QCOMPARE(live.series().size(), std::size_t(400));  // ... while nothing is lost
        plots.setPaused(false);
        plots.refresh();
        QVERIFY(plots.pointsDrawnForceTime() > drawn);
    }

    void aModelThatGoesAwayLeavesThePlotsStandingAlone()
    {
        nb::ForcePlots plots;
        {
            SpscRing<Sample> ring(64);
            std::uint64_t seq = 0;
            LiveRun live;
            live.setSource(&ring);
            plots.observe(&live);
            pushRamp(ring, seq, 10);
            live.pull();
            QCOMPARE(plots.sampleCount(), std::size_t(10));
        }
        QCOMPARE(plots.sampleCount(), std::size_t(0));
        plots.append(1.0, 2.0, 3.0);
        QCOMPARE(plots.sampleCount(), std::size_t(1));
    }
};

QTEST_MAIN(TestLivePlots)
#include "test_live_plots.moc"
