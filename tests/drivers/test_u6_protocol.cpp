// The U6 wire format: checksums, command/reply packets, calibration constants, stream data.
#include "devices/labjack_u6/u6_calibration.h"
#include "devices/labjack_u6/u6_protocol.h"

#include <QTest>

using namespace nb::devices::u6;

class TestU6Protocol : public QObject {
    Q_OBJECT
private slots:
    void checksum8FoldsTwice()
    {
        // 0xFF * 3 = 0x2FD -> 0xFD + 0x02 = 0xFF; a second fold is needed for 0x1FF-type sums.
        const std::uint8_t a[] = {0xFF, 0xFF, 0xFF};
        QCOMPARE(checksum8(a), std::uint8_t(0xFF));
        const std::uint8_t b[] = {0xFF, 0x01};  // 0x100 -> 0x00 + 0x01
        QCOMPARE(checksum8(b), std::uint8_t(0x01));
        const std::uint8_t c[] = {0xFF, 0xFF};  // 0x1FE -> 0xFE + 1 = 0xFF
        QCOMPARE(checksum8(c), std::uint8_t(0xFF));
    }
    void streamStartAndStopAreTheDocumentedBytes()
    {
        QCOMPARE(streamStartCommand(), (Bytes{0xA8, 0xA8}));
        QCOMPARE(streamStopCommand(), (Bytes{0xB0, 0xB0}));
    }
    void configU6CommandLayout()
    {
        const Bytes p = configU6Command();
        QCOMPARE(p.size(), std::size_t(26));
        QCOMPARE(p[1], std::uint8_t(0xF8));
        QCOMPARE(p[2], std::uint8_t(0x0A));
        QCOMPARE(p[3], std::uint8_t(0x08));
        // All-zero data: chk16 0, chk8 = fold(0xF8 + 0x0A + 0x08) = 0x10A -> 0x0B
        QCOMPARE(p[4], std::uint8_t(0));
        QCOMPARE(p[0], std::uint8_t(0x0B));
        QVERIFY(extendedChecksumOk(p));
    }
    void corruptedPacketFailsChecksum()
    {
        Bytes p = readCalCommand(3);
        QVERIFY(extendedChecksumOk(p));
        p[7] ^= 0x01;
        QVERIFY(!extendedChecksumOk(p));
    }
    void configReplyRoundTrip()
    {
        DeviceInfo info{360012345u, 6, 1.43, 2.00};
        QString why;
        const auto parsed = parseConfigU6Reply(configU6Reply(info), &why);
        QVERIFY2(parsed, qPrintable(why));
        QCOMPARE(parsed->serial, 360012345u);
        QCOMPARE(parsed->productId, 6);
        QCOMPARE(parsed->firmware, 1.43);
        Bytes bad = configU6Reply(info);
        bad[20] ^= 0x40;
        QVERIFY(!parseConfigU6Reply(bad, &why));
        QVERIFY(why.contains(QLatin1String("checksum")));
        QVERIFY(!parseConfigU6Reply(Bytes(10, 0), &why));
        QVERIFY(why.contains(QLatin1String("short")));
    }
    void streamConfigRoundTrip()
    {
        StreamSettings s = settingsForRate(10000.0);
        s.channels = {{2, true, 2}};
        s.resolutionIndex = 3;
        const Bytes p = streamConfigCommand(s);
        QCOMPARE(p.size(), std::size_t(16));
        QCOMPARE(p[2], std::uint8_t(5));
        QCOMPARE(p[15], std::uint8_t(0x80 | 0x20));
        const auto back = parseStreamConfigCommand(p);
        QVERIFY(back);
        QCOMPARE(back->scanInterval, std::uint16_t(400));
        QCOMPARE(back->scanRateHz(), 10000.0);
        QCOMPARE(back->samplesPerPacket, 25);
        QCOMPARE(back->channels.at(0).gainIndex, 2);
        QCOMPARE(back->channels.at(0).channel, 2);
    }
    void slowRatesUseTheDividedClock()
    {
        const StreamSettings s = settingsForRate(20.0);
        QVERIFY(s.divideBy256);
        QCOMPARE(s.scanRateHz(), 4e6 / 256 / s.scanInterval);
        QVERIFY(std::abs(s.scanRateHz() - 20.0) < 0.01);
        QCOMPARE(s.samplesPerPacket, 1);
        QCOMPARE(settingsForRate(500).samplesPerPacket, 10);
    }
    void fixedPointDecodesKnownBytes()
    {
        // 1.5 = integer 1, fraction 0x80000000
        const std::uint8_t onePointFive[8] = {0, 0, 0, 0x80, 1, 0, 0, 0};
        QCOMPARE(fixed3232ToDouble(std::span<const std::uint8_t, 8>(onePointFive)), 1.5);
        // -0.25 = integer -1, fraction 0xC0000000
        const std::uint8_t minusQuarter[8] = {0, 0, 0, 0xC0, 0xFF, 0xFF, 0xFF, 0xFF};
        QCOMPARE(fixed3232ToDouble(std::span<const std::uint8_t, 8>(minusQuarter)), -0.25);
        const auto bytes = doubleToFixed3232(3.158e-4);
        QVERIFY(std::abs(fixed3232ToDouble(bytes) - 3.158e-4) < 1e-9);
    }
    void calibrationUsesTwoSlopesAroundTheCentre()
    {
        Calibration c = Calibration::nominal();
        c.gains[0] = {3.0e-4, 3.2e-4, 33000.0};
        const auto blocks = c.toBlocks();
        const Calibration d = Calibration::fromBlocks(blocks);
        QVERIFY(std::abs(d.gains[0].positiveSlope - 3.0e-4) < 1e-9);
        QVERIFY(std::abs(d.gains[0].negativeSlope - 3.2e-4) < 1e-9);
        QVERIFY(std::abs(d.gains[0].centre - 33000.0) < 1e-6);
        QVERIFY(std::abs(d.volts(34000, 0) - 0.3) < 1e-6);
        QVERIFY(std::abs(d.volts(32000, 0) + 0.32) < 1e-6);
        QVERIFY(std::abs(d.gains[3].positiveSlope - 3.158e-7) < 1e-9);  // 32.32 resolves 2.3e-10
        QCOMPARE(d.counts(0.3, 0), std::uint16_t(34000));
        QCOMPARE(d.counts(100.0, 0), std::uint16_t(65535));
    }
    void streamPacketRoundTripAndChecks()
    {
        StreamPacket s;
        s.counter = 200;
        s.errorCode = kErrStreamRecovered;
        s.scansLost = 77;
        s.backlog = 3;
        for (int i = 0; i < 25; ++i)
            s.samples.push_back(std::uint16_t(30000 + i));
        const Bytes p = streamPacket(s);
        QCOMPARE(p.size(), std::size_t(64));
        QString why;
        auto back = parseStreamPacket(p, 25, &why);
        QVERIFY2(back, qPrintable(why));
        QCOMPARE(back->counter, std::uint8_t(200));
        QCOMPARE(back->scansLost, 77u);
        QCOMPARE(back->backlog, std::uint8_t(3));
        QCOMPARE(back->samples, s.samples);
        Bytes bad = p;
        bad[30] ^= 0x10;
        QVERIFY(!parseStreamPacket(bad, 25, &why));
        QVERIFY(why.contains(QLatin1String("checksum")));
        QVERIFY(!parseStreamPacket(p, 10, &why));  // wrong samples per packet
    }
    void normalReplyChecks()
    {
        QVERIFY(checkNormalReply(normalReply(kStreamStop, 52), kStreamStop).ok);
        QCOMPARE(checkNormalReply(normalReply(kStreamStop, 52), kStreamStop).errorCode, std::uint8_t(52));
        QVERIFY(!checkNormalReply(normalReply(kStreamStart, 0), kStreamStop).ok);
    }
};

QTEST_GUILESS_MAIN(TestU6Protocol)
#include "test_u6_protocol.moc"
