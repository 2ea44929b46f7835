// Sustained acquisition with recording on the real-time simulated rig (1 kHz and 10 kHz by
// default): samples vs expected, drops, arrival jitter, CPU of the acquisition and recorder
// threads; the simulated rig's as-fast-as-possible speed, and what an idle engine on it
// costs. Prints figures, asserts nothing.
//
//   bench_acquisition [--duration-s 60] [--rates 1000,10000] [--out-dir DIR]

#include "devices/acquisition_engine.h"
#include "devices/device_set.h"
#include "devices/sim/simulated_rig.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QStringList>
#include <QTemporaryDir>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace nb::devices;
using Clock = std::chrono::steady_clock;

namespace {

// utime + stime of one thread of this process, in seconds.
double threadCpu_s(int tid)
{
    if (tid <= 0)
        return 0.0;
    QFile f(QStringLiteral("/proc/self/task/%1/stat").arg(tid));
    if (!f.open(QIODevice::ReadOnly))
        return 0.0;
    const QByteArray s = f.readAll();
    // Fields after the ")" of the command name: state is field 3, utime 14, stime 15.
    const QList<QByteArray> fields = s.mid(s.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return 0.0;
    return (fields[11].toDouble() + fields[12].toDouble()) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

void sustained(double rateHz, double duration_s, const QString& dir)
{
    sim::RigConfig rig;
    rig.tissue = QStringLiteral("liver7");
    rig.tip = sim::Tip::Diamond;
    rig.setup = sim::Setup::Platform;
    rig.realtime = true;
    EngineConfig cfg;
    cfg.rateHz = rateHz;
    cfg.realtimeScheduling = true;
    AcquisitionEngine engine(sim::makeSimulatedDevices(rig), cfg);

    std::mutex m;
    std::vector<double> arrivals, deviceTimes;
    arrivals.reserve(static_cast<std::size_t>(rateHz * (duration_s + 5)));
    deviceTimes.reserve(arrivals.capacity());
    bool measuring = false;
    engine.setArrivalProbe([&](double dev, double host) {
        std::lock_guard lock(m);  // uncontended except at the window's edges
        if (measuring) {
            deviceTimes.push_back(dev);
            arrivals.push_back(host);
        }
    });
    engine.start();
    engine.enableStage(true);
    engine.biasSensor();
    engine.zeroStage();
    std::vector<Sample> drained;
    auto drainLive = [&] {
        drained.clear();
        engine.liveRing().popAll(drained);
    };
    while (!(engine.status().biased && engine.status().zeroed)) {
        drainLive();
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    RunPlan plan;
    plan.motion = RunPlan::Motion::Sine;
    plan.sine = {10.0, 0.5, static_cast<int>(duration_s * 0.5) + 2};
    plan.outPath = QDir(dir).filePath(QStringLiteral("bench_%1.csv").arg(rateHz));
    plan.endWhenMotionDone = false;
    RunSummary summary;
    bool ended = false;
    QObject::connect(&engine, &AcquisitionEngine::runEnded, [&](const RunSummary& s) {
        summary = s;
        ended = true;
    });
    engine.startRun(plan);
    while (!engine.status().recording) {
        drainLive();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const EngineStatus s0 = engine.status();
    const double cpuA0 = threadCpu_s(engine.acquisitionThreadId()), cpuR0 = threadCpu_s(engine.recorderThreadId());
    {
        std::lock_guard lock(m);
        measuring = true;
    }
    const auto t0 = Clock::now();
    // The GUI's part: drain the live ring at ~30 Hz.
    while (Clock::now() - t0 < std::chrono::duration<double>(duration_s)) {
        drainLive();
        std::this_thread::sleep_for(std::chrono::milliseconds(33));
    }
    {
        std::lock_guard lock(m);
        measuring = false;
    }
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    const double cpuA = threadCpu_s(engine.acquisitionThreadId()) - cpuA0;
    const double cpuR = threadCpu_s(engine.recorderThreadId()) - cpuR0;
    const EngineStatus s1 = engine.status();
    engine.endRun();
    while (!ended) {
        QCoreApplication::processEvents();
        drainLive();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    engine.shutdown();

    // Arrival latency: host arrival minus device time, relative to the best seen.
    std::vector<double> latency, interval;
    double best = 1e300;
    for (std::size_t i = 0; i < arrivals.size(); ++i)
        best = std::min(best, arrivals[i] - deviceTimes[i]);
    for (std::size_t i = 0; i < arrivals.size(); ++i) {
        latency.push_back((arrivals[i] - deviceTimes[i] - best) * 1e3);
        if (i)
            interval.push_back((arrivals[i] - arrivals[i - 1]) * 1e3);
    }
    const double received = static_cast<double>(s1.samples - s0.samples);
    std::printf("rate %.0f Hz, %.1f s wall, recording on, live ring drained at 30 Hz\n", rateHz, wall);
    const double span = s1.deviceTime_s - s0.deviceTime_s;
    std::printf("  samples received %.0f; expected %.0f by the device clock (%.5f), %.0f by the wall clock (%.4f)\n",
                received, rateHz * span, received / (rateHz * span), rateHz * wall, received / (rateHz * wall));
    std::printf("  sensor gaps %llu, ring overruns %llu, late periods %llu\n",
                static_cast<unsigned long long>(s1.dropped - s0.dropped),
                static_cast<unsigned long long>(s1.overruns - s0.overruns),
                static_cast<unsigned long long>(s1.latePeriods - s0.latePeriods));
    std::printf("  run file: %llu samples written, %llu dropped (%s)\n", static_cast<unsigned long long>(summary.samples),
                static_cast<unsigned long long>(summary.dropped), qPrintable(summary.path));
    std::printf("  period jitter (arrival after the device clock) ms: p50 %.3f  p99 %.3f  max %.3f   (batch interval ms: p50 %.3f p99 %.3f max %.3f)\n",
                percentile(latency, 0.5), percentile(latency, 0.99), percentile(latency, 1.0), percentile(interval, 0.5),
                percentile(interval, 0.99), percentile(interval, 1.0));
    std::printf("  CPU: acquisition thread %.1f %%, recorder thread %.1f %% of one core\n", 100.0 * cpuA / wall,
                100.0 * cpuR / wall);
    std::printf("  real-time: %s\n", s1.realtimeWarning.isEmpty() ? "SCHED_FIFO + mlockall" : qPrintable(s1.realtimeWarning));
    std::fflush(stdout);
}

void asFastAsPossible(double simSeconds)
{
    // The rig alone: samples per wall second on the simulated clock.
    sim::RigConfig rig;
    rig.realtime = false;
    for (double rate : {500.0, 10000.0}) {
        DeviceSet d = sim::makeSimulatedDevices(rig);
        d.sensor->start(rate);
        d.stage->enable(true);
        d.stage->moveLinear({4.0, 100.0});
        std::vector<VoltageSample> buf;
        const auto t0 = Clock::now();
        std::size_t n = 0;
        const std::size_t target = static_cast<std::size_t>(simSeconds * rate);
        while (n < target) {
            buf.clear();
            d.sensor->read(buf, std::chrono::milliseconds(10));
            n += buf.size();
            d.stage->state();
        }
        const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
        std::printf("simulated rig as fast as possible at %.0f Hz: %.0f samples/s (%.0fx real time)\n", rate, n / wall,
                    simSeconds / wall);
    }
    std::fflush(stdout);
}

void idleAsFastAsPossible(double wall_s)
{
    // An engine on the as-fast-as-possible rig, ready but with nothing to do (as between the
    // runs of a script): what it costs while it waits for the next command.
    sim::RigConfig rig;
    rig.realtime = false;
    EngineConfig cfg;
    cfg.rateHz = 500.0;
    cfg.realtimeScheduling = false;
    cfg.liveView = false;
    AcquisitionEngine engine(sim::makeSimulatedDevices(rig), cfg);
    engine.start();
    engine.enableStage(true);
    engine.biasSensor();
    engine.zeroStage();
    while (!(engine.status().biased && engine.status().zeroed))
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const double sim0 = engine.status().deviceTime_s;
    const double cpu0 = threadCpu_s(engine.acquisitionThreadId());
    const auto t0 = Clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(wall_s));
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    const double cpu = threadCpu_s(engine.acquisitionThreadId()) - cpu0;
    std::printf("as-fast-as-possible engine, idle for %.1f s: acquisition thread %.1f %% of one core, simulated clock "
                "advanced %.2f s\n",
                wall, 100.0 * cpu / wall, engine.status().deviceTime_s - sim0);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    double duration = 60.0;
    QList<double> rates{1000.0, 10000.0};
    QTemporaryDir tmp;
    QString dir = tmp.path();
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--duration-s") && i + 1 < args.size())
            duration = args[++i].toDouble();
        else if (args[i] == QLatin1String("--rates") && i + 1 < args.size()) {
            rates.clear();
            for (const QString& r : args[++i].split(QLatin1Char(',')))
                rates << r.toDouble();
        } else if (args[i] == QLatin1String("--out-dir") && i + 1 < args.size())
            dir = args[++i];
        else {
            std::fprintf(stderr, "usage: bench_acquisition [--duration-s 60] [--rates 1000,10000] [--out-dir DIR]\n");
            return 2;
        }
    }
    for (double r : rates)
        sustained(r, duration, dir);
    asFastAsPossible(std::min(duration, 60.0));
    idleAsFastAsPossible(std::min(duration, 5.0));
    return 0;
}
