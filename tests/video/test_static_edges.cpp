// What is always there in a needle strip's edge response, gathered over every frame
// (StaticEdges, issue 13): edge responses made here frame by frame, a fixed texture plus noise
// and a tip's edge where the tip is, pushed in as the tracker pushes them. The low percentile
// read from the histograms matches the one the frames themselves give, and the tip's own edge
// does not leak into it.
#include "video/static_edges.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace {

// The value with frames·15/100 values below it (as the tracker's start-up takes it).
double lowPercentile(std::vector<double> column)
{
    const std::size_t k = column.size() * 15 / 100;
    std::nth_element(column.begin(), column.begin() + std::ptrdiff_t(k), column.end());
    return column[k];
}

}  // namespace

class TestStaticEdges : public QObject {
    Q_OBJECT

private slots:
    // A texture of ±10 σ under unit noise, with a first estimate 2 σ off either way: over 2000
    // frames the percentile is within a twentieth of σ of the frames' own, at every sample. The
    // same edges handed over in the other sign, with polarity -1, give the same.
    void matchesTheFramesOwnPercentile()
    {
        const int samples = 60, frames = 2000;
        std::mt19937 rng(4242);
        std::normal_distribution<double> unit(0.0, 1.0);
        std::vector<double> texture(samples), first(samples);
        for (int i = 0; i < samples; ++i) {
            texture[std::size_t(i)] = 10.0 * unit(rng);
            first[std::size_t(i)] = texture[std::size_t(i)] + (i % 2 ? 2.0 : -2.0);
        }
        nb::video::StaticEdges edges(first, 1.0), flipped(first, 1.0);
        std::vector<std::vector<double>> columns(samples);
        for (int k = 0; k < frames; ++k) {
            std::vector<double> edge(samples);
            for (int i = 0; i < samples; ++i) {
                edge[std::size_t(i)] = texture[std::size_t(i)] + unit(rng);
                columns[std::size_t(i)].push_back(edge[std::size_t(i)]);
            }
            // A tip beyond the strip's end: every sample counts.
            edges.add(edge, 1, 1000.0, 10.0);
            for (double& e : edge)
                e = -e;
            flipped.add(edge, -1, 1000.0, 10.0);
        }
        const std::vector<double> found = edges.estimate(3);
        double worst = 0.0;
        for (int i = 0; i < samples; ++i)
            worst = std::max(worst, std::abs(found[std::size_t(i)] - lowPercentile(columns[std::size_t(i)])));
        QCOMPARE(flipped.estimate(3), found);
        qInfo("largest difference from the frames' own percentile: %.3f sigma", worst);
        QVERIFY2(worst < 0.05, qPrintable(QStringLiteral("%1 sigma off").arg(worst)));
    }

    // A tip 12 σ high resting at sample 30 in most frames: within the reach of it those frames
    // say nothing, and what is learnt there is the texture's percentile from the others. A frame
    // without a tip says nothing at all; where too few frames had the tip away, the first
    // estimate stands.
    void leavesTheTipOut()
    {
        const int samples = 60;
        std::mt19937 rng(7);
        std::normal_distribution<double> unit(0.0, 1.0);
        const std::vector<double> first(samples, 0.0);
        nb::video::StaticEdges edges(first, 1.0);
        std::vector<std::vector<double>> away(samples);
        auto frame = [&](double tip) {
            std::vector<double> edge(samples);
            for (int i = 0; i < samples; ++i)
                edge[std::size_t(i)] = unit(rng) + (std::abs(i - tip) < 4.0 ? 12.0 * (1.0 - std::abs(i - tip) / 4.0) : 0.0);
            edges.add(edge, 1, tip, 10.0);
            for (int i = 0; i < samples; ++i)
                if (std::abs(i - tip) > 10.0)
                    away[std::size_t(i)].push_back(edge[std::size_t(i)]);
        };
        for (int k = 0; k < 600; ++k)
            frame(30.0);
        for (int k = 0; k < 200; ++k)
            frame(50.0 + (k % 5));
        for (int k = 0; k < 100; ++k) {
            std::vector<double> edge(samples, 50.0);  // a frame whose tip was not read
            edges.add(edge, 1, std::numeric_limits<double>::quiet_NaN(), 10.0);
        }
        const std::vector<double> found = edges.estimate(3);
        for (int i = 0; i < samples; ++i) {
            const auto& column = away[std::size_t(i)];
            if (column.size() < 3) {
                QCOMPARE(found[std::size_t(i)], first[std::size_t(i)]);
                continue;
            }
            const double expected = lowPercentile(column);
            QVERIFY2(std::abs(found[std::size_t(i)] - expected) < 0.1,
                     qPrintable(QStringLiteral("sample %1: %2 against %3").arg(i).arg(found[std::size_t(i)]).arg(expected)));
            // Where the tip rests, the percentile is the noise's, about one σ below zero.
            if (std::abs(i - 30) <= 3)
                QVERIFY(found[std::size_t(i)] < 0.0);
        }
    }
};

QTEST_APPLESS_MAIN(TestStaticEdges)
#include "test_static_edges.moc"
