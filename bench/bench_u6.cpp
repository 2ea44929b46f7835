// The U6 driver streaming through the umockdev emulator: lost packets at 10 kHz and the
// CPU the driver's thread takes. Usage: bench_u6 [seconds=60] [rate_hz=10000]
#include <umockdev.h>  // before Qt: Qt's "signals" macro breaks gio's headers

#include "devices/labjack_u6/u6_force_sensor.h"
#include "../tests/drivers/u6_emulator.h"
#include "../tests/drivers/umockdev_harness.h"

#include <QCoreApplication>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sys/resource.h>

namespace {
double threadCpu()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + t.tv_nsec * 1e-9;
}
double processCpu()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + t.tv_nsec * 1e-9;
}
}  // namespace

int main(int argc, char** argv)
{
    nb::test::reexecUnderUmockdev(argc, argv);
    QCoreApplication app(argc, argv);
    const double seconds = argc > 1 ? std::atof(argv[1]) : 60.0;
    const double rate = argc > 2 ? std::atof(argv[2]) : 10000.0;
    UMockdevTestbed* testbed = umockdev_testbed_new();
    nb::test::U6Emulator::Options o;
    o.calibration = nb::devices::u6::Calibration::nominal();
    o.volts = [](double t) { return 0.05 * std::sin(6.283 * t); };
    nb::test::U6Emulator emu(o);
    QString why;
    if (!emu.attach(testbed, &why)) {
        std::fprintf(stderr, "emulator: %s\n", qPrintable(why));
        return 1;
    }
    try {
        nb::devices::U6ForceSensor sensor;
        const double actual = sensor.start(rate);
        std::vector<nb::devices::VoltageSample> out;
        out.reserve(std::size_t(actual * seconds * 1.1));
        const auto t0 = std::chrono::steady_clock::now();
        const double cpu0 = threadCpu(), proc0 = processCpu();
        while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < seconds)
            sensor.read(out, std::chrono::milliseconds(20));
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = threadCpu() - cpu0, proc = processCpu() - proc0;
        sensor.stop();
        std::printf("u6 stream through umockdev: rate %.0f Hz, %.1f s\n", actual, wall);
        std::printf("  samples %zu (expected ~%.0f), packets %llu, lost packets %llu, bad packets %llu, lost samples %llu\n",
                    out.size(), actual * wall, (unsigned long long)sensor.packets(), (unsigned long long)sensor.lostPackets(),
                    (unsigned long long)sensor.badPackets(), (unsigned long long)sensor.deviceLostSamples());
        std::printf("  driver thread CPU %.1f %% of one core (libusb busy-polls the emulated node)\n", 100.0 * cpu / wall);
        std::printf("  whole process CPU (driver + emulator) %.1f %%\n", 100.0 * proc / wall);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    emu.unplug();
    g_object_unref(testbed);
    return 0;
}
