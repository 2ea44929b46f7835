// The engine's per-sample work, pushed through synchronously as Open Ephys tests push a block
// through a processor: no thread, no sleep, no timed wait. Every batch is made here, so each
// assertion knows the exact answer.
#include "core/models.h"
#include "devices/sample_processor.h"

#include <QtTest>
#include <cmath>

using namespace nb::devices;

namespace {

constexpr double kRate = 1000.0;
constexpr double kSlope = 0.0123 * 100.0 * 9.81 / 1000.0;  // V/g: the simulated chain
constexpr double kOffset_V = 0.42;

// Eq. 6 inverted: F = (V - V0) g / (1000 d).
double voltsFor(double force_N) { return kOffset_V + force_N * 1000.0 * kSlope / nb::kGravity_m_s2; }

// `n` samples from sensor index `first`, force from `force(t)`.
std::vector<VoltageSample> batch(std::uint64_t first, int n, const std::function<double(double)>& force)
{
    std::vector<VoltageSample> b;
    for (int i = 0; i < n; ++i) {
        const std::uint64_t k = first + std::uint64_t(i);
        const double t = double(k) / kRate;
        b.push_back({k, t, voltsFor(force(t))});
    }
    return b;
}

struct Pushed {
    std::vector<Sample> samples;
    std::vector<ProcessorEvent> events;
};

Pushed push(SampleProcessor& p, const std::vector<VoltageSample>& b, const StageState& stage)
{
    Pushed out;
    p.process(b, stage, b.empty() ? 0.0 : b.back().deviceTime_s, out.samples, out.events);
    return out;
}

// A processor already biased at zero force (0.5 s of air).
SampleProcessor biased(std::uint64_t* next)
{
    SampleProcessor p(kRate, false);
    p.setSlope(kSlope);
    p.startBias(0.5);
    const Pushed r = push(p, batch(0, 600, [](double) { return 0.0; }), {});
    Q_ASSERT(p.biased() && !r.events.empty());
    *next = 600;
    return p;
}

class FakeTruth : public GroundTruthSource {
public:
    SampleTruth sampleTruth(std::uint64_t index) const override
    {
        return {0.0, double(index) * 0.01, index % 2 ? TruePhase::B1 : TruePhase::C};
    }
    QJsonObject truthJson() const override { return {}; }
};

}  // namespace

class TestSampleProcessor : public QObject {
    Q_OBJECT
private slots:
    void voltsBecomeForceAfterTheBias()
    {
        SampleProcessor p(kRate, false);
        p.setSlope(kSlope);
        p.startBias(0.5);
        const Pushed r = push(p, batch(0, 600, [](double) { return 0.0; }), {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].kind, ProcessorEvent::Kind::BiasDone);
        QCOMPARE(r.events[0].count, std::uint64_t(501));  // 0.5 s at 1 kHz, both ends included
        QVERIFY(std::abs(p.bias_V() - kOffset_V) < 1e-12);
        // The sample that completed the bias already reads zero: nothing sees it as loaded.
        QVERIFY(std::abs(p.last().force_N) < 1e-9);
        const Pushed after = push(p, batch(600, 10, [](double) { return 0.25; }), {});
        for (const Sample& s : after.samples)
            QVERIFY2(std::abs(s.force_N - 0.25) < 1e-9, qPrintable(QString::number(s.force_N)));
    }

    void gapsAreCounted()
    {
        SampleProcessor p(kRate, false);
        std::vector<VoltageSample> b = batch(0, 10, [](double) { return 0.0; });
        b.erase(b.begin() + 3, b.begin() + 6);  // three lost
        push(p, b, {});
        push(p, batch(20, 5, [](double) { return 0.0; }), {});  // ten more lost between batches
        QCOMPARE(p.counters().dropped, std::uint64_t(13));
        QCOMPARE(p.counters().samples, std::uint64_t(12));
    }

    void positionIsInterpolatedOnTheSampleClock()
    {
        SampleProcessor p(kRate, false);
        StageState st;
        st.position_mm = 0.0;
        push(p, batch(0, 100, [](double) { return 0.0; }), st);  // read-back 0 mm at t = 0.099 s
        st.position_mm = 1.0;
        const Pushed r = push(p, batch(100, 100, [](double) { return 0.0; }), st);  // 1 mm at 0.199 s
        // Half way between the read-backs' times, half way between their positions.
        const Sample& mid = r.samples[49];  // t = 0.149 s
        QVERIFY2(std::abs(mid.position_mm - 0.5) < 1e-9, qPrintable(QString::number(mid.position_mm)));
        QVERIFY(std::abs(r.samples.back().position_mm - 1.0) < 1e-12);
    }

    void insertionLimitGuardsInsertionOnly()
    {
        std::uint64_t next = 0;
        SampleProcessor p = biased(&next);
        p.setLimits(0.1, 0.5);
        p.setGuard(ForceGuard::Insertion);
        Pushed r = push(p, batch(next, 50, [](double) { return 0.2; }), {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].kind, ProcessorEvent::Kind::ForceLimit);
        QCOMPARE(r.events[0].limit_N, 0.1);
        QVERIFY(p.tripped());
        // Tripped once; quiet until re-armed (the stop itself is over the limit).
        r = push(p, batch(next + 50, 50, [](double) { return 0.3; }), {});
        QVERIFY(r.events.empty());

        // Coming out, the same 0.2 N (or friction pulling the other way) is allowed: only the
        // larger withdrawal limit on |F| applies, so the needle can always be taken out.
        p.rearm();
        p.setGuard(ForceGuard::Withdrawal);
        const double switch_s = double(next + 125) / kRate;
        r = push(p, batch(next + 100, 50, [switch_s](double t) { return t < switch_s ? 0.2 : -0.4; }), {});
        QVERIFY(r.events.empty());
        r = push(p, batch(next + 150, 10, [](double) { return -0.6; }), {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].limit_N, 0.5);
    }

    void sineGuardsBothDirections()
    {
        std::uint64_t next = 0;
        SampleProcessor p = biased(&next);
        p.setLimits(0.3, 1.0);
        p.setGuard(ForceGuard::Both);
        const Pushed r = push(p, batch(next, 20, [](double) { return -0.35; }), {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].force_N < 0, true);
        // Off: nothing moves and nothing records, so nothing is guarded.
        SampleProcessor q = biased(&next);
        q.setLimits(0.3, 1.0);
        QVERIFY(push(q, batch(next, 20, [](double) { return 5.0; }), {}).events.empty());
    }

    // A reading at the end of the sensor's input range trips the limit, said so: the force is at
    // least that and may be any higher. With the nominal chain +10 V read 7.79 N, under the
    // default 8 N limit, and a needle driven 20 mm into bone was saved as completed (probe).
    void aReadingAtTheEndOfTheRangeTrips()
    {
        std::uint64_t next = 0;
        SampleProcessor p = biased(&next);
        p.setInputRange(10.0);
        p.setLimits(100.0, 100.0);  // far beyond what the load cell reads
        const double top = p.readableForce_N(+1);
        QVERIFY2(top > 7.0 && top < 8.0, qPrintable(QString::number(top)));
        p.setGuard(ForceGuard::Insertion);
        // The margin shown is to where the stage stops: the reading's end, not the 100 N limit.
        QVERIFY(std::abs(p.margin_N(1.0) - (top - 1.0)) < 1e-9);
        // Up to just short of the end: no trip; at the ADC's last code (one step short of +10 V): a trip.
        const double lsb = 20.0 / 65536.0;
        std::vector<VoltageSample> b = batch(next, 20, [](double) { return 1.0; });
        for (std::size_t i = 0; i < b.size(); ++i)
            b[i].volts = i < 10 ? 9.95 : 10.0 - lsb;
        Pushed r = push(p, b, {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QCOMPARE(r.events[0].kind, ProcessorEvent::Kind::ForceLimit);
        QVERIFY(r.events[0].overRange);
        QCOMPARE(r.events[0].time_s, b[10].deviceTime_s);
        QVERIFY(std::abs(r.events[0].force_N - top) < 0.01);

        // Coming out, a reading stuck at the other end does not stop the withdrawal again.
        p.rearm();
        p.setGuard(ForceGuard::Withdrawal);
        b = batch(next + 20, 20, [](double) { return 1.0; });
        for (VoltageSample& v : b)
            v.volts = -10.0;
        QVERIFY(push(p, b, {}).events.empty());
        // In a sine either end trips.
        p.setGuard(ForceGuard::Both);
        b = batch(next + 40, 5, [](double) { return 1.0; });
        for (VoltageSample& v : b)
            v.volts = -10.0;
        r = push(p, b, {});
        QCOMPARE(r.events.size(), std::size_t(1));
        QVERIFY(r.events[0].overRange);

        // A range not known (0): nothing is read into the end of it.
        SampleProcessor q = biased(&next);
        q.setLimits(100.0, 100.0);
        q.setGuard(ForceGuard::Insertion);
        b = batch(next, 5, [](double) { return 1.0; });
        for (VoltageSample& v : b)
            v.volts = 10.0;
        QVERIFY(push(q, b, {}).events.empty());
        QVERIFY(std::isinf(q.readableForce_N(+1)));
    }

    // The margin the panel shows is against the guard in force: a pull on the needle (negative
    // force) read as more margin than the limit itself while a sine or a withdrawal runs.
    void marginIsAgainstTheGuardInForce()
    {
        SampleProcessor p(kRate, false);
        p.setLimits(8.0, 9.5);
        p.setGuard(ForceGuard::Insertion);
        QCOMPARE(p.margin_N(3.0), 5.0);
        QCOMPARE(p.margin_N(-3.0), 11.0);  // going in, a pull is far from the push limit
        p.setGuard(ForceGuard::Both);
        QCOMPARE(p.margin_N(-3.0), 5.0);
        p.setGuard(ForceGuard::Withdrawal);
        QCOMPARE(p.margin_N(-3.0), 6.5);
        p.setGuard(ForceGuard::Off);
        QCOMPARE(p.margin_N(-3.0), 5.0);  // the next move's
    }

    void withdrawalLimitIsNeverBelowTheInsertionLimit()
    {
        SampleProcessor p(kRate, false);
        p.setLimits(2.0, 1.0);
        QCOMPARE(p.withdrawalLimit(), 2.0);
    }

    void punctureIsReportedFromTheLiveForce()
    {
        std::uint64_t next = 0;
        SampleProcessor p = biased(&next);
        p.watchPunctures(true);
        // A needle at 4 mm/s: air for 0.5 s, then a capsule loading to 0.6 N over 2 s, then a
        // sharp drop to 0.15 N (the puncture at t0 + 2.5 s), then cutting.
        const double t0 = double(next) / kRate;
        auto force = [t0](double t) {
            // A little deterministic noise, as a real load cell has (±1 mN).
            const double noise = 0.001 * std::sin(t * 12345.678);
            const double u = t - t0 - 0.5;
            if (u < 0)
                return noise;
            if (u < 2.0)
                return 0.6 * (u / 2.0) * (u / 2.0) + noise;
            return 0.15 + noise;
        };
        std::vector<ProcessorEvent> events;
        for (int k = 0; k < 40; ++k) {
            StageState st;
            st.position_mm = 4.0 * (double(next) / kRate - t0);
            st.velocity_mm_s = 4.0;
            st.moving = true;
            Pushed r = push(p, batch(next, 100, force), st);
            events.insert(events.end(), r.events.begin(), r.events.end());
            next += 100;
        }
        int contacts = 0, punctures = 0;
        for (const ProcessorEvent& e : events) {
            if (e.kind == ProcessorEvent::Kind::Contact) {
                ++contacts;
                QVERIFY2(std::abs(e.time_s - (t0 + 0.5)) < 0.3, qPrintable(QString::number(e.time_s - t0)));
            }
            if (e.kind == ProcessorEvent::Kind::Puncture) {
                ++punctures;
                QCOMPARE(e.count, std::uint64_t(1));
                QVERIFY2(std::abs(e.time_s - (t0 + 2.5)) < 0.02, qPrintable(QString::number(e.time_s - t0)));
                QVERIFY(e.force_N > 0.5);
            }
        }
        QCOMPARE(contacts, 1);
        QCOMPARE(punctures, 1);
        QCOMPARE(p.punctures(), 1);
    }

    void truthComesFromTheDeviceSetsSource()
    {
        SampleProcessor p(kRate, false, std::make_shared<FakeTruth>());
        const Pushed r = push(p, batch(7, 2, [](double) { return 0.0; }), {});
        QCOMPARE(r.samples[0].phase, TruePhase::B1);
        QCOMPARE(r.samples[1].phase, TruePhase::C);
        QVERIFY(std::abs(r.samples[1].tissue_position_mm - 0.08) < 1e-12);
        // Without a source the truth stays unknown.
        SampleProcessor q(kRate, false);
        const Pushed s = push(q, batch(0, 1, [](double) { return 0.0; }), {});
        QVERIFY(std::isnan(s.samples[0].tissue_position_mm));
        QCOMPARE(s.samples[0].phase, TruePhase::None);
    }
};

QTEST_GUILESS_MAIN(TestSampleProcessor)
#include "test_sample_processor.moc"
