// Zaber command round trip (`get pos`) over a pty to the emulator, as the driver sees it.
// Usage: bench_zaber [requests=2000]
#include "devices/zaber/zaber_stage.h"
#include "../tests/drivers/zaber_emulator.h"

#include <QCoreApplication>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int n = argc > 1 ? std::atoi(argv[1]) : 2000;
    nb::test::ZaberEmulator emu;
    nb::devices::ZaberConfig c;
    c.port = emu.path();
    c.units = {10000.0, 1.6384};
    try {
        nb::devices::ZaberStage stage(c);
        std::vector<double> us;
        us.reserve(std::size_t(n));
        for (int i = 0; i < n; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            stage.state();
            us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        }
        std::sort(us.begin(), us.end());
        auto pct = [&](double p) { return us[std::min(us.size() - 1, std::size_t(p * double(us.size())))]; };
        std::printf("zaber 'get pos' round trip over a pty, %d requests: p50 %.0f us, p99 %.0f us, max %.0f us\n", n,
                    pct(0.50), pct(0.99), us.back());
        std::printf("  (a real controller at 115200 baud adds ~2 ms of line time per request/reply pair)\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
