// Times the core's file reader and fits on realistic sizes and prints the figures.
#include "core/run_file.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>
#include <random>

using namespace nb;

int main()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.csv"));
    Run run;
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0.0, 0.006);
    const int n = 1'000'000;
    for (int i = 0; i < n; ++i) {
        run.time_s.push_back(i * 0.001);
        run.position_mm.push_back(i * 0.004);
        run.force_N.push_back(0.05 * i * 0.004 + noise(rng));
    }
    QElapsedTimer t;
    t.start();
    writeRunFile(path, run);
    const double writeMs = t.nsecsElapsed() / 1e6;
    t.restart();
    const auto back = readRunFile(path);
    const double readMs = t.nsecsElapsed() / 1e6;
    std::printf("run file write, %d rows: %.1f ms\n", n, writeMs);
    std::printf("run file read,  %d rows: %.1f ms (%.2f Mrows/s), %zu rows back\n", n, readMs,
                n / readMs / 1e3, back.run.size());
    return 0;
}
