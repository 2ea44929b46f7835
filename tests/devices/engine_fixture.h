#pragma once
// Shared by the engine tests: an engine on an as-fast-as-possible simulated rig, brought to
// "ready" (enabled, biased, zeroed) the way an operator would.

#include "devices/acquisition_engine.h"
#include "devices/sim/simulated_rig.h"

#include <QSignalSpy>
#include <QtTest>
#include <memory>

namespace nbtest {

// An engine on the simulated rig, with the test's hand on the rig (truth, faults, clock).
struct SimEngine {
    std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
    std::unique_ptr<nb::devices::AcquisitionEngine> engine;
    nb::devices::AcquisitionEngine* operator->() const { return engine.get(); }
    nb::devices::AcquisitionEngine& operator*() const { return *engine; }
    nb::devices::AcquisitionEngine* get() const { return engine.get(); }
};

// `probe` (optional) runs on the engine thread for every sensor batch, on the device clock:
// the way to act at an exact simulated time.
inline SimEngine makeEngine(const nb::devices::sim::RigConfig& rig, double rateHz = 500.0, double forceLimit = 8.0,
                            std::function<void(double)> probe = {})
{
    nb::devices::EngineConfig c;
    c.rateHz = rateHz;
    c.forceLimit_N = forceLimit;
    c.realtimeScheduling = false;
    c.liveView = false;
    SimEngine e;
    e.rig = std::make_shared<nb::devices::sim::SimulatedRig>(rig);
    e.engine = std::make_unique<nb::devices::AcquisitionEngine>(nb::devices::sim::simulatedDeviceSet(e.rig), c);
    if (probe)
        e->setArrivalProbe([probe](double deviceTime, double) { probe(deviceTime); });
    e->start();
    return e;
}

// QSignalSpy::wait() counts only what arrives while it waits, and the engine thread may
// have emitted before the test gets there.
inline bool waitFor(QSignalSpy& spy, int timeout_ms = 5000)
{
    return !spy.isEmpty() || spy.wait(timeout_ms);
}

inline nb::devices::sim::RigConfig fastRig(const QString& tissue, nb::devices::sim::Tip tip)
{
    nb::devices::sim::RigConfig c;
    c.tissue = tissue;
    c.tip = tip;
    c.realtime = false;
    return c;
}

inline bool makeReady(nb::devices::AcquisitionEngine& e)
{
    e.enableStage(true);
    e.biasSensor();
    e.zeroStage();
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 20000) {
        const auto s = e.status();
        if (s.stageEnabled && s.biased && s.zeroed)
            return true;
        QTest::qWait(5);
    }
    return false;
}

}  // namespace nbtest
