// Calibration ▸ "Use the sensor's nominal calibration" in the real window on a LabJack U6
// (the umockdev emulator) with a bridge load cell: the slope comes from the devices, so the
// forces read are the emulated load's. It used to be the simulated amplified chain's, 100x off.
// umockdev (GLib) before any Qt header: Qt's "signals" macro breaks gio's headers.
#include <umockdev.h>

#include "main_window.h"

#include "core/models.h"
#include "devices/acquisition_engine.h"
#include "devices/device_spec.h"
#include "u6_emulator.h"
#include "umockdev_harness.h"
#include "widgets/control_panel.h"

#include <QAction>
#include <QApplication>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

namespace {

constexpr double kBridge_V_per_N = 0.0123;  // the thesis's load cell, straight into the U6
constexpr double kLoad_N = 2.0;
constexpr double kLoadFrom_s = 1.5;         // device time: no load before (for the bias)

double bridge(double t) { return 0.002 + (t >= kLoadFrom_s ? kLoad_N : 0.0) * kBridge_V_per_N; }

QAction* actionNamed(QWidget* w, const QString& text)
{
    for (QAction* a : w->findChildren<QAction*>())
        if (a->text().remove(QLatin1Char('&')) == text)
            return a;
    return nullptr;
}

}  // namespace

class TestU6Nominal : public QObject {
    Q_OBJECT
private slots:
    void nominalCalibrationReadsTheEmulatedLoad()
    {
        UMockdevTestbed* testbed = umockdev_testbed_new();
        nb::test::U6Emulator::Options o;
        o.calibration = nb::devices::u6::Calibration::nominal();
        o.volts = bridge;
        nb::test::U6Emulator emu(o);
        QString why;
        QVERIFY2(emu.attach(testbed, &why), qPrintable(why));
        {
            QTemporaryDir tmp;
            nb::WorkbenchOptions options;
            options.sessionDir = tmp.filePath(QStringLiteral("s"));
            options.persistSettings = false;
            options.deviceFactory = [] {
                nb::devices::DeviceSpec spec;
                spec.daq = QStringLiteral("u6");
                spec.stage = QStringLiteral("sim");
                try {
                    return nb::devices::openDevices(spec);
                } catch (const nb::Error& e) {
                    qFatal("the emulated U6 did not open: %s", qPrintable(e.message()));
                }
            };
            nb::MainWindow w(options);
            w.show();
            // The window, not only the engine, must know the devices run: it refuses a calibration before.
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().running && w.controlPanel()->interlockState().devicesRunning, 20000);
            QVERIFY2(w.engine()->deviceDescription().contains(QStringLiteral("U6")), qPrintable(w.engine()->deviceDescription()));

            QAction* nominal = actionNamed(&w, QStringLiteral("Use the sensor's nominal calibration"));
            QVERIFY(nominal);
            nominal->trigger();
            const double expected = kBridge_V_per_N * nb::kGravity_m_s2 / 1000.0;  // V/g
            QTRY_VERIFY_WITH_TIMEOUT(std::abs(w.engine()->status().slope_V_per_g - expected) < 1e-12 * expected, 10000);

            // Bias with nothing on the cell, then the load arrives.
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().deviceTime_s > 0.1, 10000);
            QVERIFY(w.engine()->status().deviceTime_s < kLoadFrom_s - 0.6);
            w.engine()->biasSensor();
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().biased, 10000);
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().deviceTime_s > kLoadFrom_s + 0.3, 20000);
            double sum = 0.0;
            int n = 0;
            for (int i = 0; i < 20; ++i) {
                sum += w.engine()->status().force_N;
                ++n;
                QTest::qWait(10);
            }
            const double force = sum / n;
            qInfo("nominal calibration on the emulated U6: read %.4f N for an emulated %.4f N", force, kLoad_N);
            QVERIFY2(std::abs(force - kLoad_N) < 0.01 * kLoad_N,
                     qPrintable(QStringLiteral("read %1 N for an emulated %2 N").arg(force).arg(kLoad_N)));
            w.engine()->shutdown();
        }
        emu.unplug();
        g_object_unref(testbed);
    }
};

int main(int argc, char** argv)
{
    nb::test::reexecUnderUmockdev(argc, argv);
    QApplication app(argc, argv);
    TestU6Nominal t;
    return QTest::qExec(&t, argc, argv);
}

#include "test_u6_nominal.moc"
