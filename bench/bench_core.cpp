// Times the core's file reader and fits on realistic sizes and prints the figures. Each
// fit on a 1e5-sample run is also given as a multiple of reading that run from its CSV
// file in the same process, which says more than milliseconds on a shared machine.
#include "core/calibration.h"
#include "core/events.h"
#include "core/friction_fit.h"
#include "core/insertion_model.h"
#include "core/run_file.h"
#include "core/stiffness_fit.h"
#include "tests/core/synthetic.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>
#include <random>

using namespace nb;

namespace {

// Best of `repeats` (the least disturbed by other processes), in ms.
template <typename F>
double timeMs(F&& f, int repeats = 3)
{
    double best = INFINITY;
    for (int i = 0; i < repeats; ++i) {
        QElapsedTimer t;
        t.start();
        f();
        best = std::min(best, t.nsecsElapsed() / 1e6);
    }
    return best;
}

void readerOnMillionRows(const QTemporaryDir& dir)
{
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
    const double writeMs = timeMs([&] { writeRunFile(path, run); }, 1);
    std::size_t rows = 0;
    const double readMs = timeMs([&] { rows = readRunFile(path).run.size(); }, 1);
    std::printf("run file write, %d rows: %.1f ms\n", n, writeMs);
    std::printf("run file read,  %d rows: %.1f ms (%.2f Mrows/s), %zu rows back\n", n, readMs, n / readMs / 1e3, rows);
}

// Issue 15: metadata lines parse in linear time (60 000 distinct keys once took 11 s, 100 000
// took 47 s). Both sizes are printed: linear time shows as the same time per line.
void metadataLines()
{
    for (const int n : {10'000, 100'000}) {
        QByteArray text;
        for (int i = 0; i < n; ++i)
            text += "# key_" + QByteArray::number(i) + ": value " + QByteArray::number(i) + '\n';
        text += "time_s,position_mm,force_N\n0,0,0\n";
        std::size_t keys = 0;
        const double ms = timeMs([&] { keys = parseRunText(text, QStringLiteral("meta.csv")).run.metadata.entries().size(); }, 1);
        std::printf("metadata, %d distinct '# key: value' lines: %.1f ms (%.2f us/line), %zu keys back\n", n, ms, ms * 1e3 / n, keys);
    }
}

}  // namespace

int main()
{
    QTemporaryDir dir;
    metadataLines();
    readerOnMillionRows(dir);

    constexpr int n = 100'000;
    // Insertion: liver 1 over 35 mm at 4 mm/s, sampled fast enough for 1e5 samples.
    synthetic::Insertion ins;
    ins.rate_hz = n / ((ins.end_mm - ins.start_mm) / ins.speed_mm_s);
    ins.internal = {{4.0, 0.1}};
    const Run insertion = synthetic::makeInsertion(ins);
    const QString insPath = dir.filePath(QStringLiteral("insertion.csv"));
    writeRunFile(insPath, insertion);
    const double readIns = timeMs([&] { readRunFile(insPath); });

    InsertionEvents ev;
    const double eventsMs = timeMs([&] { ev = detectEvents(insertion); });
    const StiffnessSegment seg = stiffnessSegment(insertion, ev);
    StiffnessFit stiff;
    const double stiffMs = timeMs([&] { stiff = fitStiffness(seg); });

    InsertionModel model;
    model.stiffness = ev.stiffness;
    model.contact_mm = ev.contact.position_mm;
    model.punctureDepth_mm = ev.punctureDepth_mm();
    model.friction.Cp_N_per_m = 10.0;
    double distance = 0.0;
    const double simMs = timeMs([&] {
        distance = rmsDistance(simulateInsertion(model, insertion.time_s, insertion.position_mm), insertion);
    });

    // Friction: 8 cycles at 0.5 Hz sampled for 1e5 samples.
    synthetic::Friction fr;
    fr.rate_hz = n / (fr.cycles / fr.frequency_hz);
    const Run friction = synthetic::makeFriction(fr);
    const QString frPath = dir.filePath(QStringLiteral("friction.csv"));
    writeRunFile(frPath, friction);
    const double readFr = timeMs([&] { readRunFile(frPath); });
    FrictionOptions fo;
    fo.thickness_mm = 20.0;
    FrictionFit ff;
    const double frictionMs = timeMs([&] { ff = fitFriction(friction, fo); });
    fo.estimateMass = true;
    const double frictionMassMs = timeMs([&] { ff = fitFriction(friction, fo); });

    const auto cal = synthetic::makeCalibration(1.2e-4, 0.015, 1e-4, 1);
    std::vector<CalibrationPoint> points;
    while (points.size() < std::size_t(n))
        for (std::size_t i = 0; i < cal.mass_g.size() && points.size() < std::size_t(n); ++i)
            points.push_back({cal.mass_g[i], cal.voltage_V[i]});
    const double calMs = timeMs([&] { fitCalibration(points); });

    std::printf("\nfits on %d-sample runs (best of 3; x = multiple of reading that run's CSV)\n", n);
    std::printf("read insertion run:                %8.1f ms\n", readIns);
    std::printf("events (contact search + peaks):   %8.1f ms  %5.2fx  (contact %.3f mm, a1 %.4f, a2 %.5f)\n", eventsMs,
                eventsMs / readIns, ev.contact.position_mm, ev.stiffness.a1_N_per_mm, ev.stiffness.a2_N_per_mm2);
    std::printf("stiffness fit (quad+cubic+spring): %8.1f ms  %5.2fx  (%zu samples)\n", stiffMs, stiffMs / readIns, seg.depth_mm.size());
    std::printf("simulate + rms distance:           %8.1f ms  %5.2fx  (rms %.4f N)\n", simMs, simMs / readIns, distance);
    std::printf("read friction run:                 %8.1f ms\n", readFr);
    std::printf("friction fit, known mass:          %8.1f ms  %5.2fx\n", frictionMs, frictionMs / readFr);
    std::printf("friction fit, mass estimated:      %8.1f ms  %5.2fx  (m_est %.4f kg)\n", frictionMassMs,
                frictionMassMs / readFr, ff.massEstimate_kg.value_or(0.0));
    std::printf("calibration fit, %d points:    %8.1f ms\n", n, calMs);
    return 0;
}
