// The unmodified U6 driver through real libusb against the umockdev U6 emulator: discovery,
// calibration, a clock-paced stream, and the faults (lost/corrupt packets, overflow, stall,
// unplug).
// umockdev (GLib) before any Qt header: Qt's "signals" macro breaks gio's headers.
#include <umockdev.h>

#include "devices/device_error.h"
#include "devices/labjack_u6/u6_force_sensor.h"
#include "u6_emulator.h"
#include "umockdev_harness.h"

#include <QCoreApplication>
#include <QTest>
#include <cmath>
#include <memory>
#include <numbers>

using namespace nb::devices;
using nb::test::U6Emulator;

namespace {

u6::Calibration unusualCalibration()
{
    // Not the nominal values: proves the driver reads the device's own constants.
    u6::Calibration c = u6::Calibration::nominal();
    for (int g = 0; g < 4; ++g) {
        const double scale = std::pow(10.0, -g);
        c.gains[std::size_t(g)] = {3.21e-4 * scale, 3.27e-4 * scale, 32900.0 + g};
    }
    return c;
}

double loadCell(double t)
{
    return 0.040 + 0.030 * std::sin(2 * std::numbers::pi * 3.0 * t);  // within +-100 mV at x100
}

}  // namespace

class TestU6Driver : public QObject {
    Q_OBJECT
    UMockdevTestbed* testbed_ = nullptr;
    std::unique_ptr<U6Emulator> emu_;

    U6Config config()
    {
        U6Config c;
        c.stallTimeout = std::chrono::milliseconds(300);
        c.commandTimeout = std::chrono::milliseconds(300);
        return c;
    }
    // Reads until `n` samples arrived (or 5 s passed).
    static void readAtLeast(U6ForceSensor& s, std::vector<VoltageSample>& out, std::size_t n)
    {
        QElapsedTimer t;
        t.start();
        while (out.size() < n && t.elapsed() < 5000)
            s.read(out, std::chrono::milliseconds(20));
    }

private slots:
    void init()
    {
        testbed_ = umockdev_testbed_new();
        U6Emulator::Options o;
        o.calibration = unusualCalibration();
        o.volts = loadCell;
        emu_ = std::make_unique<U6Emulator>(o);
        QString why;
        QVERIFY2(emu_->attach(testbed_, &why), qPrintable(why));
    }
    void cleanup()
    {
        emu_->unplug();  // makes any leftover client calls fail fast
        g_object_unref(testbed_);
        testbed_ = nullptr;
        emu_.reset();
    }

    void listsTheDeviceWithItsSerial()
    {
        const auto found = findU6Devices();
        QCOMPARE(found.size(), std::size_t(1));
        QCOMPARE(found[0].serial, QStringLiteral("360012345"));
        QCOMPARE(found[0].bus, 1);
        QCOMPARE(found[0].address, 7);
    }

    void readsConfigurationAndCalibration()
    {
        U6Config c = config();
        c.serial = QStringLiteral("360012345");
        U6ForceSensor s(c);
        QCOMPARE(s.name(), QStringLiteral("LabJack U6 #360012345"));
        QCOMPARE(s.info().productId, 6);
        const auto expected = unusualCalibration();
        for (int g = 0; g < 4; ++g) {
            QVERIFY(std::abs(s.calibration().gains[std::size_t(g)].positiveSlope - expected.gains[std::size_t(g)].positiveSlope) < 1e-9);
            QVERIFY(std::abs(s.calibration().gains[std::size_t(g)].negativeSlope - expected.gains[std::size_t(g)].negativeSlope) < 1e-9);
            QVERIFY(std::abs(s.calibration().gains[std::size_t(g)].centre - expected.gains[std::size_t(g)].centre) < 1e-6);
        }
    }

    void aWrongSerialIsAClearError()
    {
        U6Config c = config();
        c.serial = QStringLiteral("999");
        try {
            U6ForceSensor s(c);
            QFAIL("opened a device with another serial number");
        } catch (const DeviceError& e) {
            QCOMPARE(e.device(), QStringLiteral("LabJack U6 #999"));
            QVERIFY2(e.reason().contains(QLatin1String("not found")), qPrintable(e.message()));
        }
    }

    void streamsOnTheDeviceClock()
    {
        U6ForceSensor s(config());
        QCOMPARE(s.start(1000.0), 1000.0);
        QVERIFY(emu_->streaming());
        QCOMPARE(emu_->stopsWhileIdle(), 1);  // the start-up StreamStop got error 52, tolerated
        QCOMPARE(emu_->settings().channels.at(0).gainIndex, 2);
        QVERIFY(emu_->settings().channels.at(0).differential);
        std::vector<VoltageSample> out;
        readAtLeast(s, out, 300);
        QVERIFY(out.size() >= 300);
        const double lsb = 3.27e-6;  // x100 counts
        for (std::size_t i = 0; i < out.size(); ++i) {
            QCOMPARE(out[i].index, std::uint64_t(i));
            QCOMPARE(out[i].deviceTime_s, double(i) / 1000.0);
            if (std::abs(out[i].volts - loadCell(out[i].deviceTime_s)) > lsb)
                QFAIL(qPrintable(QStringLiteral("sample %1: %2 V, expected %3 V").arg(i).arg(out[i].volts).arg(loadCell(out[i].deviceTime_s))));
        }
        QCOMPARE(s.deviceLostSamples(), std::uint64_t(0));
        s.stop();
        QVERIFY(!emu_->streaming());
        // A second stream starts cleanly from index 0.
        s.start(500.0);
        out.clear();
        readAtLeast(s, out, 20);
        QCOMPARE(out.front().index, std::uint64_t(0));
        s.stop();
    }

    void lostAndCorruptPacketsAreCounted()
    {
        U6ForceSensor s(config());
        s.start(10000.0);  // 25 samples per packet
        std::vector<VoltageSample> out;
        readAtLeast(s, out, 500);
        emu_->dropNextPackets(2);
        readAtLeast(s, out, out.size() + 500);
        emu_->corruptNextPackets(1);
        readAtLeast(s, out, out.size() + 500);
        QCOMPARE(s.lostPackets(), std::uint64_t(3));
        QCOMPARE(s.badPackets(), std::uint64_t(1));
        QCOMPARE(s.deviceLostSamples(), std::uint64_t(75));
        // The gaps are in the indices, and times still follow the device clock.
        std::uint64_t gaps = 0;
        for (std::size_t i = 1; i < out.size(); ++i) {
            gaps += out[i].index - out[i - 1].index - 1;
            QCOMPARE(out[i].deviceTime_s, double(out[i].index) / 10000.0);
        }
        QCOMPARE(gaps, std::uint64_t(75));
        QVERIFY(!s.takeWarnings().isEmpty());
    }

    void overflowRecoveryReportsScansLost()
    {
        U6ForceSensor s(config());
        s.start(2000.0);
        std::vector<VoltageSample> out;
        readAtLeast(s, out, 200);
        emu_->injectOverflow(130);
        readAtLeast(s, out, out.size() + 400);
        QCOMPARE(s.overflows(), std::uint64_t(1));
        QCOMPARE(s.deviceLostSamples(), std::uint64_t(130));
        std::uint64_t gaps = 0;
        for (std::size_t i = 1; i < out.size(); ++i)
            gaps += out[i].index - out[i - 1].index - 1;
        QCOMPARE(gaps, std::uint64_t(130));
        // Samples after the gap still carry the signal at their device time.
        const VoltageSample& last = out.back();
        QVERIFY(std::abs(last.volts - loadCell(last.deviceTime_s)) < 3.27e-6);
    }

    void aStalledDeviceIsNamedAndKeepsTheSamples()
    {
        U6ForceSensor s(config());
        s.start(1000.0);
        std::vector<VoltageSample> out;
        readAtLeast(s, out, 100);
        const std::size_t before = out.size();
        emu_->setStalled(true);
        QElapsedTimer t;
        t.start();
        try {
            while (t.elapsed() < 5000)
                s.read(out, std::chrono::milliseconds(20));
            QFAIL("a silent device was not reported");
        } catch (const DeviceError& e) {
            QCOMPARE(e.device(), QStringLiteral("LabJack U6 #360012345"));
            QVERIFY2(e.reason().contains(QLatin1String("no stream data")), qPrintable(e.message()));
        }
        QVERIFY(out.size() >= before);
        for (std::size_t i = 0; i < out.size(); ++i)
            QCOMPARE(out[i].index, std::uint64_t(i));
    }

    void unplugIsReported()
    {
        U6ForceSensor s(config());
        s.start(1000.0);
        std::vector<VoltageSample> out;
        readAtLeast(s, out, 50);
        emu_->unplug();
        try {
            for (int i = 0; i < 100; ++i)
                s.read(out, std::chrono::milliseconds(20));
            QFAIL("an unplugged device was not reported");
        } catch (const DeviceError& e) {
            QCOMPARE(e.device(), QStringLiteral("LabJack U6 #360012345"));
            QVERIFY2(e.reason().contains(QLatin1String("unplugged")), qPrintable(e.message()));
        }
        QVERIFY(out.size() >= 50);
    }

    void noDeviceIsAClearError()
    {
        emu_->unplug();
        umockdev_testbed_remove_device(testbed_, "/sys/devices/pci0000:00/0000:00:14.0/usb1/1-7");
        try {
            U6ForceSensor s(config());
            QFAIL("opened a device that is not there");
        } catch (const DeviceError& e) {
            QVERIFY2(e.reason().contains(QLatin1String("not found")), qPrintable(e.message()));
        }
    }
};

int main(int argc, char** argv)
{
    nb::test::reexecUnderUmockdev(argc, argv);
    QCoreApplication app(argc, argv);
    TestU6Driver t;
    return QTest::qExec(&t, argc, argv);
}

#include "test_u6_driver.moc"
