// `needlebench acquire` end to end against both emulators: the U6 on umockdev (the child
// process inherits the preload and the testbed) and the Zaber controller on a pty.
#include <umockdev.h>  // before Qt: Qt's "signals" macro breaks gio's headers

#include "core/run_file.h"
#include "support/needlebench_cli.h"
#include "u6_emulator.h"
#include "umockdev_harness.h"
#include "zaber_emulator.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <memory>

using nb::test::U6Emulator;
using nb::test::ZaberEmulator;

class TestAcquireHw : public QObject {
    Q_OBJECT
    UMockdevTestbed* testbed_ = nullptr;
    std::unique_ptr<U6Emulator> u6_;
    std::unique_ptr<ZaberEmulator> zaber_;
    QTemporaryDir dir_;

    static nbtest::CliResult run(const QStringList& args) { return nbtest::runCli(args, 60000); }

private slots:
    void init()
    {
        testbed_ = umockdev_testbed_new();
        U6Emulator::Options o;
        o.calibration = nb::devices::u6::Calibration::nominal();
        // 0.2 V bias plus a slow ramp: 12.3 mV/N at x100 -> forces of a few tenths of a newton.
        o.volts = [](double t) { return 0.02 + 0.002 * t; };
        u6_ = std::make_unique<U6Emulator>(o);
        QString why;
        QVERIFY2(u6_->attach(testbed_, &why), qPrintable(why));
        zaber_ = std::make_unique<ZaberEmulator>();
        QVERIFY(zaber_->ok());
    }
    void cleanup()
    {
        zaber_.reset();
        u6_->unplug();
        g_object_unref(testbed_);
        u6_.reset();
    }

    void devicesListsTheU6()
    {
        const nbtest::CliResult r = run({QStringLiteral("devices"), QStringLiteral("--json")});
        QCOMPARE(r.code, 0);
        const QJsonObject o = r.json();
        QVERIFY2(r.out.contains("u6:360012345"), qPrintable(r.out));
        QVERIFY(o.value(QStringLiteral("stages")).isArray());
    }

    void acquiresARunFromBothDevices()
    {
        const QString out = dir_.filePath(QStringLiteral("run.csv"));
        const nbtest::CliResult r = run({QStringLiteral("acquire"), QStringLiteral("--daq"), QStringLiteral("u6:360012345"),
                              QStringLiteral("--stage"), QStringLiteral("zaber:") + zaber_->path(),
                              QStringLiteral("--zaber-microsteps-per-mm"), QStringLiteral("10000"),
                              QStringLiteral("--protocol"), QStringLiteral("stiffness"), QStringLiteral("--depth-mm"),
                              QStringLiteral("3"), QStringLiteral("--velocity-mm-s"), QStringLiteral("10"),
                              QStringLiteral("--rate-hz"), QStringLiteral("1000"), QStringLiteral("--out"), out});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(!r.out.isEmpty(), qPrintable(r.err));
        const QJsonObject o = r.json();
        QCOMPARE(o.value(QStringLiteral("end_reason")).toString(), QStringLiteral("completed"));
        QCOMPARE(o.value(QStringLiteral("dropped")).toDouble(), 0.0);
        QVERIFY(o.value(QStringLiteral("device")).toString().contains(QLatin1String("LabJack U6 #360012345")));
        const nb::Run run = nb::readRunFile(out).run;
        QVERIFY(run.size() > 200);
        QCOMPARE(run.meta(QStringLiteral("daq")).value_or(QString()), QStringLiteral("u6:360012345"));
        QVERIFY(run.meta(QStringLiteral("stage_position_source")).value_or(QString()).contains(QLatin1String("zaber polled")));
        for (std::size_t i = 1; i < run.size(); ++i)
            QVERIFY(std::abs(run.time_s[i] - run.time_s[i - 1] - 0.001) < 1e-9);  // the device clock
        const double maxPos = *std::max_element(run.position_mm.begin(), run.position_mm.end());
        QVERIFY2(std::abs(maxPos - 3.0) < 1e-3, qPrintable(QString::number(maxPos)));
        QCOMPARE(zaber_->position_mm(), 3.0);
        const auto* volts = run.numericColumn(QStringLiteral("voltage_V"));
        QVERIFY(volts);
        QVERIFY(std::abs(volts->back() - 0.02) < 0.01);
    }

    void aFailingDaqIsNamed()
    {
        u6_->setStalled(true);
        const nbtest::CliResult r = run({QStringLiteral("acquire"), QStringLiteral("--daq"), QStringLiteral("u6"), QStringLiteral("--stage"),
                              QStringLiteral("zaber:") + zaber_->path(), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                              QStringLiteral("--out"), dir_.filePath(QStringLiteral("never.csv"))});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains("LabJack U6"), qPrintable(r.err));
    }

    void badSpecsAreUsageErrors()
    {
        const nbtest::CliResult r = run({QStringLiteral("acquire"), QStringLiteral("--daq"), QStringLiteral("ni6009"), QStringLiteral("--protocol"),
                              QStringLiteral("stiffness"), QStringLiteral("--out"), dir_.filePath(QStringLiteral("x.csv"))});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains("unknown DAQ"));
    }
};

int main(int argc, char** argv)
{
    nb::test::reexecUnderUmockdev(argc, argv);
    QCoreApplication app(argc, argv);
    TestAcquireHw t;
    return QTest::qExec(&t, argc, argv);
}

#include "test_acquire_hw.moc"
