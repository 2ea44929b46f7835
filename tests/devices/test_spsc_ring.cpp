// The lock-free ring between the acquisition thread and its consumers.
#include "devices/spsc_ring.h"

#include <QtTest>
#include <thread>

using nb::devices::SpscRing;

class TestSpscRing : public QObject {
    Q_OBJECT
private slots:
    void capacityRoundsUpToPowerOfTwo()
    {
        SpscRing<int> r(100);
        QCOMPARE(r.capacity(), std::size_t{128});
    }
    void wrapsAroundInOrder()
    {
        SpscRing<int> r(8);
        int next = 0, expect = 0;
        // Many laps of the ring with the fill level changing, so indices wrap repeatedly.
        for (int lap = 0; lap < 100; ++lap) {
            for (int i = 0; i < 5 + lap % 3; ++i)
                QVERIFY(r.push(next++));
            int v;
            while (r.pop(v))
                QCOMPARE(v, expect++);
        }
        QCOMPARE(expect, next);
        QCOMPARE(r.overruns(), std::uint64_t{0});
    }
    void countsOverrunsAndKeepsOldData()
    {
        SpscRing<int> r(4);
        for (int i = 0; i < 10; ++i)
            r.push(i);
        QCOMPARE(r.overruns(), std::uint64_t{6});
        std::vector<int> out;
        QCOMPARE(r.popAll(out), std::size_t{4});
        QCOMPARE(out, (std::vector<int>{0, 1, 2, 3}));
        QVERIFY(r.push(42));
        int v = 0;
        QVERIFY(r.pop(v));
        QCOMPARE(v, 42);
        QVERIFY(!r.pop(v));
    }
    void twoThreadStress()
    {
        // A producer racing a consumer: every value arrives once, in order, or is counted.
        SpscRing<std::uint64_t> r(1024);
        constexpr std::uint64_t n = 2'000'000;
        std::uint64_t received = 0, lastSeen = 0;
        bool ordered = true;
        std::thread consumer([&] {
            std::vector<std::uint64_t> batch;
            while (received + r.overruns() < n || r.size() > 0) {
                batch.clear();
                r.popAll(batch, 300);
                for (std::uint64_t v : batch) {
                    if (received > 0 && v <= lastSeen)
                        ordered = false;
                    lastSeen = v;
                    ++received;
                }
            }
        });
        std::uint64_t accepted = 0;
        for (std::uint64_t i = 1; i <= n; ++i)
            if (r.push(i))
                ++accepted;
        consumer.join();
        QVERIFY(ordered);
        QCOMPARE(received, accepted);
        QCOMPARE(accepted + r.overruns(), n);
    }
};

QTEST_GUILESS_MAIN(TestSpscRing)
#include "test_spsc_ring.moc"
