// Zaber ASCII messages, units and the position interpolation onto the force clock.
#include "devices/zaber/position_track.h"
#include "devices/zaber/zaber_protocol.h"

#include <QTest>

using namespace nb::devices::zaber;

class TestZaberProtocol : public QObject {
    Q_OBJECT
private slots:
    void commandLine() { QCOMPARE(command(1, 1, "move abs 2000"), QByteArray("/1 1 move abs 2000\n")); }
    void parsesReply()
    {
        const auto m = parse("@01 1 OK BUSY -- 12345\r\n");
        QVERIFY(m);
        QCOMPARE(m->type, '@');
        QCOMPARE(m->device, 1);
        QCOMPARE(m->axis, 1);
        QVERIFY(!m->rejected);
        QVERIFY(m->busy);
        QCOMPARE(m->warning, QByteArray("--"));
        QCOMPARE(m->data, QByteArray("12345"));
    }
    void parsesRejectionAndAlert()
    {
        const auto rj = parse("@01 1 RJ IDLE -- DRIVERDISABLED");
        QVERIFY(rj && rj->rejected);
        QVERIFY(rejectionText(rj->data).contains(QLatin1String("disabled")));
        const auto alert = parse("!01 1 IDLE FS");
        QVERIFY(alert);
        QCOMPARE(alert->type, '!');
        QCOMPARE(alert->warning, QByteArray("FS"));
        QVERIFY(!faultText(alert->warning).isEmpty());
        QVERIFY(rejectionText("WHATEVER").contains(QLatin1String("WHATEVER")));
    }
    void rejectsGarbage()
    {
        QVERIFY(!parse(""));
        QVERIFY(!parse("hello"));
        QVERIFY(!parse("@01 1 MAYBE IDLE -- 0"));
        QVERIFY(!parse("@xx 1 OK IDLE -- 0"));
    }
    void checksumIsVerified()
    {
        // LRC over "01 1 OK IDLE -- 0"
        QByteArray body = "01 1 OK IDLE -- 0";
        unsigned s = 0;
        for (char c : body)
            s += std::uint8_t(c);
        const QByteArray sum = QByteArray::number((~s + 1) & 0xff, 16).rightJustified(2, '0').toUpper();
        QVERIFY(parse('@' + body + ':' + sum));
        QVERIFY(!parse('@' + body + ":00"));
    }
    void formatRoundTrip()
    {
        Message m{'@', 1, 1, true, false, "--", "BADDATA"};
        QCOMPARE(format(m), QByteArray("@01 1 RJ IDLE -- BADDATA"));
        const auto back = parse(format(m));
        QVERIFY(back && back->rejected && back->data == "BADDATA");
    }
    void units()
    {
        Units u{1000.0, 1.6384};
        QCOMPARE(u.steps(12.5), std::int64_t(12500));
        QCOMPARE(u.mm(2500), 2.5);
        QCOMPARE(u.speedData(4.0), std::int64_t(6554));
        QVERIFY(std::abs(u.mmPerSecond(6553.6) - 4.0) < 1e-12);
    }
    void interpolatesOntoSampleTimes()
    {
        PositionTrack track;
        QVERIFY(!track.at(0.0));
        track.add(0.00, 0.0);
        track.add(0.02, 0.08);
        track.add(0.04, 0.16);
        track.add(0.03, 99.0);  // out of order: ignored
        QCOMPARE(track.size(), std::size_t(3));
        QVERIFY(std::abs(*track.at(0.01) - 0.04) < 1e-12);
        QVERIFY(std::abs(*track.at(0.035) - 0.14) < 1e-12);
        QVERIFY(!track.at(-0.001));
        QCOMPARE(*track.at(0.05), 0.16);
        QVERIFY(!track.at(0.5));  // stale: polling stopped
        QVERIFY(std::abs(track.rateHz() - 50.0) < 1e-9);
        track.dropBefore(0.03);
        QCOMPARE(track.size(), std::size_t(2));
        QVERIFY(std::abs(*track.at(0.03) - 0.12) < 1e-12);
        QCOMPARE(positionSourceText(50.2), QStringLiteral("zaber polled 50 Hz, interpolated"));
    }
};

QTEST_GUILESS_MAIN(TestZaberProtocol)
#include "test_zaber_protocol.moc"
