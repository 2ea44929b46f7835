#include "run_once.h"

#include "core/tr.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <atomic>

namespace nb::devices {

RunOnceResult runOnce(AcquisitionEngine& engine, const RunPlan& plan, const RunOnceOptions& options)
{
    RunOnceResult result;
    QEventLoop loop;
    std::atomic<bool> started{false};
    QObject guard;  // owns the connections, so they end with this call
    QObject::connect(&engine, &AcquisitionEngine::runEnded, &guard, [&](const RunSummary& r) {
        result.summary = r;
        loop.quit();
    });
    QObject::connect(&engine, &AcquisitionEngine::runRefused, &guard, [&](const QString& why) {
        result.error = why;
        loop.quit();
    });
    QObject::connect(&engine, &AcquisitionEngine::faultOccurred, &guard,
                     [&](const QString& device, const QString& reason) { result.error = device + QStringLiteral(": ") + reason; });
    QObject::connect(&engine, &AcquisitionEngine::runStarted, &guard, [&](const QString& path) {
        if (options.onStarted)
            options.onStarted(path);
    });
    // Started from the engine thread the moment the interlocks are met.
    QObject::connect(
        &engine, &AcquisitionEngine::statusChanged, &guard,
        [&](const EngineStatus& st) {
            if (st.biased && st.zeroed && st.stageEnabled && !started.exchange(true))
                engine.startRun(plan);
        },
        Qt::DirectConnection);
    engine.enableStage(true);
    engine.biasSensor();
    engine.zeroStage();
    engine.start();

    QElapsedTimer wall;
    wall.start();
    QTimer tick;
    tick.setInterval(5);
    bool interrupting = false;
    int interrupted = 0;
    QObject::connect(&tick, &QTimer::timeout, &guard, [&] {
        const EngineStatus st = engine.status();
        if (!started.load()) {
            if (!st.fault.isEmpty()) {
                result.error = st.fault;
                loop.quit();
            } else if (wall.elapsed() > options.readyTimeout_ms) {
                result.error = nb::TrDevices::tr("the devices did not get ready within %1 s").arg(options.readyTimeout_ms / 1000);
                loop.quit();
            }
        }
        if (options.onTick)
            options.onTick(st);
        if (options.interruption) {
            const RunOnceOptions::Interruption i = options.interruption();
            if (i.count > 0 && (!started.load() || i.count > 1)) {
                if (result.error.isEmpty())
                    result.error = nb::TrDevices::tr("interrupted before the run ended");
                loop.quit();
            } else if (i.count > 0 && interrupted == 0) {
                interrupted = i.count;
                interrupting = true;
                engine.interrupt(i.footer);
            }
        }
        if (wall.elapsed() > options.runTimeout_ms && !interrupting) {
            interrupting = true;
            result.error = nb::TrDevices::tr("the run did not finish within %1 minutes").arg(options.runTimeout_ms / 60000);
            engine.endRun();
        }
    });
    tick.start();
    loop.exec();
    tick.stop();
    result.last = engine.status();
    engine.shutdown();
    return result;
}

}  // namespace nb::devices
