// The live-run model between the engine's ring and the views, pushed through synchronously:
// samples go into a real ring, pull() drains it on the test's own thread, and every answer
// (times, marks, signals) is known from the samples made here. No thread, no timer, no sleep.
#include "core/run_file.h"
#include "devices/live_run.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <random>

using namespace nb::devices;

namespace {

constexpr double kRate_Hz = 1000.0;
constexpr double kSpeed_mm_s = 2.0;
constexpr double kContact_mm = 5.0;
constexpr double kPuncture_mm = 15.0;

// A linear insertion from x = 0 at 2 mm/s: air (noise only) until the capsule at 5 mm, a
// quadratic rise to 1.5 N at 15 mm, then the force collapses to friction (0.3 N).
double insertionForce_N(double x_mm)
{
    if (x_mm < kContact_mm)
        return 0.0;
    if (x_mm < kPuncture_mm) {
        const double u = (x_mm - kContact_mm) / (kPuncture_mm - kContact_mm);
        return 1.5 * u * u;
    }
    return 0.3;
}

struct Rig {
    SpscRing<Sample> ring{1 << 16};
    std::mt19937 noise{20261123};
    std::uint64_t seq = 0;
    double deviceStart_s = 100.0;  // the device clock does not start at zero

    // `n` samples of the insertion, from the sample index `seq` on (time since the move began
    // is (seq - moveStart) / rate).
    void push(int n, std::uint64_t moveStart)
    {
        std::normal_distribution<double> sigma(0.0, 0.002);
        for (int i = 0; i < n; ++i, ++seq) {
            Sample s;
            s.seq = seq;
            s.time_s = deviceStart_s + double(seq) / kRate_Hz;
            const double moving_s = seq >= moveStart ? double(seq - moveStart) / kRate_Hz : 0.0;
            s.position_mm = kSpeed_mm_s * moving_s;
            s.force_N = insertionForce_N(s.position_mm) + sigma(noise);
            s.volts = 0.4 + 0.1 * s.force_N;
            QVERIFY(ring.push(s));
        }
    }
};

int count(const std::vector<LiveMark>& marks, LiveMarkKind kind)
{
    return int(std::count_if(marks.begin(), marks.end(), [&](const LiveMark& m) { return m.kind == kind; }));
}

double timeOf(const std::vector<LiveMark>& marks, LiveMarkKind kind)
{
    for (const LiveMark& m : marks)
        if (m.kind == kind)
            return m.time_s;
    return -1.0;
}

}  // namespace

class TestLiveRun : public QObject {
    Q_OBJECT
private slots:
    // Devices switched (another simulated rig, a real stage): the new engine's clock starts at
    // zero, and the series starts over on it. Timed on the old clock's origin, its samples fell
    // 70 s before it and the live plots stayed empty at rest.
    void anotherEngineStartsTheSeriesOver()
    {
        SpscRing<Sample> first(1 << 12), second(1 << 12);
        LiveRun live;
        live.setSource(&first);
        for (int i = 0; i < 1000; ++i) {
            Sample s;
            s.time_s = 70.0 + i / kRate_Hz;
            QVERIFY(first.push(s));
        }
        live.pull();
        QCOMPARE(live.series().size(), std::size_t(1000));
        QSignalSpy reset(&live, &LiveRun::reset);
        live.setSource(&second);
        QCOMPARE(reset.count(), 1);
        QCOMPARE(live.series().size(), std::size_t(0));
        for (int i = 0; i < 500; ++i) {
            Sample s;
            s.time_s = i / kRate_Hz;
            QVERIFY(second.push(s));
        }
        live.pull();
        QCOMPARE(live.series().size(), std::size_t(500));
        QCOMPARE(live.series().time_s.front(), 0.0);
        QVERIFY(live.series().time_s.back() > 0.49);
    }

    void pullDrainsTheRingInOrder()
    {
        Rig rig;
        LiveRun live;
        live.setSource(&rig.ring);
        QSignalSpy appended(&live, &LiveRun::samplesAppended);
        QSignalSpy pulled(&live, &LiveRun::pulled);
        rig.push(250, 0);
        live.pull();
        QCOMPARE(rig.ring.size(), std::size_t(0));
        QCOMPARE(live.series().size(), std::size_t(250));
        QCOMPARE(appended.count(), 1);
        QCOMPARE(appended.at(0).at(0).value<std::size_t>(), std::size_t(0));
        rig.push(100, 0);
        live.pull();
        QCOMPARE(appended.at(1).at(0).value<std::size_t>(), std::size_t(250));
        QCOMPARE(pulled.count(), 2);
        // On the model's clock: the first sample is zero, then one sample period apart.
        QCOMPARE(live.series().time_s.front(), 0.0);
        QVERIFY(std::abs(live.series().time_s.back() - 349.0 / kRate_Hz) < 1e-9);
        QVERIFY(std::abs(live.clockOrigin_s() - rig.deviceStart_s) < 1e-9);
        // An empty pull says so (views redraw) but appends nothing.
        live.pull();
        QCOMPARE(appended.count(), 2);
        QCOMPARE(pulled.count(), 3);
    }

    void aRunStartsTheClockAtItsFirstSample()
    {
        Rig rig;
        LiveRun live;
        live.setSource(&rig.ring);
        rig.push(500, 1u << 30);
        live.pull();
        QSignalSpy reset(&live, &LiveRun::reset);
        live.beginRun(false);
        QCOMPARE(reset.count(), 1);
        QVERIFY(live.recording());
        QCOMPARE(live.series().size(), std::size_t(0));
        rig.push(10, 1u << 30);
        live.pull();
        QVERIFY(std::abs(live.series().time_s.front() - 1.0 / kRate_Hz) < 1e-9);
        QVERIFY(live.marks().empty());
    }

    void betweenRunsOnlyTheLastMinuteIsKept()
    {
        Rig rig;
        LiveRun live(60.0);
        live.setSource(&rig.ring);
        QSignalSpy reset(&live, &LiveRun::reset);
        for (int chunk = 0; chunk < 70; ++chunk) {  // 70 s in 1 s pulls
            rig.push(1000, 1u << 30);
            live.pull();
        }
        QCOMPARE(reset.count(), 1);
        QVERIFY(live.series().size() <= std::size_t(60 * kRate_Hz));
        QVERIFY(live.series().time_s.back() < 60.0);
        // A run keeps every sample, however long.
        live.beginRun(false);
        for (int chunk = 0; chunk < 70; ++chunk) {
            rig.push(1000, 1u << 30);
            live.pull();
        }
        QCOMPARE(live.series().size(), std::size_t(70 * 1000));
        QCOMPARE(reset.count(), 2);
    }

    void aLinearRunIsMarkedLiveThenFromItsFile()
    {
        Rig rig;
        LiveRun live;
        live.setSource(&rig.ring);
        rig.push(300, 1u << 30);
        live.pull();
        live.beginRun(true);
        const std::uint64_t moveStart = rig.seq;
        QSignalSpy marksChanged(&live, &LiveRun::marksChanged);
        for (int chunk = 0; chunk < 100; ++chunk) {  // 10 s in 0.1 s pulls: 20 mm
            rig.push(100, moveStart);
            live.pull();
        }
        const double contactTrue_s = kContact_mm / kSpeed_mm_s, punctureTrue_s = kPuncture_mm / kSpeed_mm_s;
        QCOMPARE(count(live.marks(), LiveMarkKind::Contact), 1);
        QCOMPARE(count(live.marks(), LiveMarkKind::Puncture), 1);
        QVERIFY2(std::abs(timeOf(live.marks(), LiveMarkKind::Contact) - contactTrue_s) < 1.0,
                 qPrintable(QString::number(timeOf(live.marks(), LiveMarkKind::Contact))));
        QVERIFY2(std::abs(timeOf(live.marks(), LiveMarkKind::Puncture) - punctureTrue_s) < 0.2,
                 qPrintable(QString::number(timeOf(live.marks(), LiveMarkKind::Puncture))));
        QVERIFY(marksChanged.count() >= 2);

        // The operator's stop is marked at the latest sample.
        live.mark(LiveMarkKind::Stop);
        QCOMPARE(live.marks().back().time_s, live.series().time_s.back());

        // The run as the recorder wrote it: the same samples, on the run's clock.
        QTemporaryDir dir;
        nb::Run run;
        run.time_s = live.series().time_s;
        run.position_mm = live.series().position_mm;
        run.force_N = live.series().force_N;
        const QString path = dir.filePath(QStringLiteral("run_001_linear.csv"));
        nb::writeRunFile(path, run);
        QVERIFY(live.endRun(path).isEmpty());
        QVERIFY(!live.recording());
        QCOMPARE(count(live.marks(), LiveMarkKind::Contact), 1);
        QCOMPARE(count(live.marks(), LiveMarkKind::Puncture), 1);
        QCOMPARE(count(live.marks(), LiveMarkKind::Stop), 1);  // the operator's marks stay
        QVERIFY(std::abs(timeOf(live.marks(), LiveMarkKind::Puncture) - punctureTrue_s) < 0.05);
    }

    void aRunThatCannotBeReadBackIsNamed()
    {
        Rig rig;
        LiveRun live;
        live.setSource(&rig.ring);
        live.beginRun(true);
        rig.push(50, 0);
        live.pull();
        const QString missing = QStringLiteral("/nonexistent/run_009_linear.csv");
        const QString problem = live.endRun(missing);
        QVERIFY2(problem.contains(QStringLiteral("run_009_linear.csv")), qPrintable(problem));
        QCOMPARE(live.series().size(), std::size_t(50));  // nothing shown is lost
    }

    void aSineRunIsNotMarked()
    {
        Rig rig;
        LiveRun live;
        live.setSource(&rig.ring);
        live.beginRun(false);
        for (int chunk = 0; chunk < 100; ++chunk) {
            rig.push(100, 0);
            live.pull();
        }
        QVERIFY(live.marks().empty());
        QVERIFY(live.endRun(QStringLiteral("/nonexistent/run.csv")).isEmpty());  // not read at all
    }
};

QTEST_GUILESS_MAIN(TestLiveRun)
#include "test_live_run.moc"
