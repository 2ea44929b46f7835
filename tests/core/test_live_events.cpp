// Live contact and puncture: synthetic insertions with known events, fed in uneven chunks the
// way the window drains the live ring, are marked while the run goes on, close to where the
// whole-run detection puts them; a run in air, a slow relaxation and a start-up jolt are not.
#include "core/events.h"
#include "core/live_events.h"
#include "synthetic.h"

#include <QtTest>
#include <random>

using namespace nb;

namespace {
// Feeds `run` in chunks of 1-60 samples; returns the events with the sample count at which
// each came out.
std::vector<std::pair<LiveEvent, std::size_t>> feedInChunks(const Run& run, std::uint32_t seed)
{
    LiveEventDetector d;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> chunk(1, 60);
    std::vector<std::pair<LiveEvent, std::size_t>> out;
    for (std::size_t i = 0; i < run.size();) {
        const std::size_t n = std::min(chunk(rng), run.size() - i);
        for (LiveEvent& e : d.feed(std::span(run.time_s).subspan(i, n), std::span(run.position_mm).subspan(i, n),
                                   std::span(run.force_N).subspan(i, n)))
            out.emplace_back(std::move(e), i + n);
        i += n;
    }
    return out;
}
}  // namespace

class TestLiveEvents : public QObject {
    Q_OBJECT
private slots:
    void marksContactAndPunctureWhileTheRunGoesOn_data()
    {
        QTest::addColumn<double>("a1");
        QTest::addColumn<double>("a2");
        QTest::addColumn<double>("depth");
        QTest::addColumn<double>("contactTolerance");
        QTest::newRow("liver 1") << 0.0480 << 0.0052 << 16.57 << 0.15;
        QTest::newRow("liver 3") << 0.0371 << 0.0107 << 8.95 << 0.15;
        // A capsule that starts soft leaves the noise band late: live, up to a millimetre and a half.
        QTest::newRow("liver 2") << 0.0020 << 0.0023 << 22.38 << 1.6;
    }
    void marksContactAndPunctureWhileTheRunGoesOn()
    {
        QFETCH(double, a1);
        QFETCH(double, a2);
        QFETCH(double, depth);
        QFETCH(double, contactTolerance);
        for (std::uint32_t seed = 1; seed <= 5; ++seed) {
            synthetic::Insertion p;
            p.a1_N_per_mm = a1;
            p.a2_N_per_mm2 = a2;
            p.punctureDepth_mm = depth;
            p.end_mm = p.puncture_mm() + 10.0;
            p.seed = seed;
            const Run run = synthetic::makeInsertion(p);
            const auto events = feedInChunks(run, seed);
            const QString got = QStringLiteral("seed %1: %2 events").arg(seed).arg(events.size());
            QVERIFY2(events.size() == 2, qPrintable(got));
            QCOMPARE(events[0].first.name, QStringLiteral("contact"));
            QCOMPARE(events[1].first.name, QStringLiteral("puncture"));
            const double contactX = events[0].first.position_mm;
            QVERIFY2(contactX >= p.contact_mm - 0.2 && contactX <= p.contact_mm + contactTolerance,
                     qPrintable(QStringLiteral("%1: contact at %2 mm, true %3").arg(got).arg(contactX).arg(p.contact_mm)));
            const double punctureX = events[1].first.position_mm;
            if (seed == 1)
                qInfo("contact %.3f mm (true %.3f), puncture %.3f mm (true %.3f), marked %.3f s after the peak", contactX,
                      p.contact_mm, punctureX, p.puncture_mm(), run.time_s[events[1].second - 1] - events[1].first.time_s);
            QVERIFY2(std::fabs(punctureX - p.puncture_mm()) < 0.1,
                     qPrintable(QStringLiteral("%1: puncture at %2 mm, true %3").arg(got).arg(punctureX).arg(p.puncture_mm())));
            QVERIFY(std::fabs(events[1].first.force_N - p.force(p.puncture_mm())) < 0.05);
            // Live: marked within 0.15 s of the peak, long before the run ends.
            const double markedAt = run.time_s[events[1].second - 1];
            QVERIFY2(markedAt - events[1].first.time_s < 0.15 + 0.06 * 2, qPrintable(QString::number(markedAt - events[1].first.time_s)));
            // And where the whole-run detection puts them, give or take.
            const InsertionEvents whole = detectEvents(run);
            QVERIFY(std::fabs(punctureX - whole.puncture.position_mm) < 0.1);
        }
    }

    void nothingInAir()
    {
        synthetic::Insertion p;
        p.contact_mm = 500.0;  // never reached
        p.end_mm = 40.0;
        const Run run = synthetic::makeInsertion(p);
        QVERIFY(feedInChunks(run, 3).empty());
    }

    void aSlowRelaxationIsNoPuncture()
    {
        // The needle stops in the capsule: the force sags by 30 % over two seconds.
        Run run;
        for (int i = 0; i < 3000; ++i) {
            const double t = i * 0.002;
            double f = 0.0, x = 4.0 * std::min(t, 3.0);
            if (x > 5.0)
                f = 0.0480 * (x - 5.0) + 0.0052 * (x - 5.0) * (x - 5.0);
            if (t > 3.0)
                f *= 1.0 - 0.3 * std::min(1.0, (t - 3.0) / 2.0);
            run.time_s.push_back(t);
            run.position_mm.push_back(x);
            run.force_N.push_back(f + 0.003 * std::sin(i * 1.7));
        }
        const auto events = feedInChunks(run, 1);
        QCOMPARE(int(events.size()), 1);
        QCOMPARE(events[0].first.name, QStringLiteral("contact"));
    }

    void aStartUpJoltIsNotAContact()
    {
        // The needle holder's inertia as the axis accelerates: 40 mN for 10 ms at the start.
        synthetic::Insertion p;
        p.contact_mm = 500.0;
        p.end_mm = 20.0;
        Run run = synthetic::makeInsertion(p);
        for (std::size_t i = 0; i < 5; ++i)
            run.force_N[i] += 0.04;
        QVERIFY(feedInChunks(run, 5).empty());
    }
};

QTEST_GUILESS_MAIN(TestLiveEvents)
#include "test_live_events.moc"
