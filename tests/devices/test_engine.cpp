// The acquisition engine on the simulated rig: interlocks, recording, the force limit and
// device faults (injected in the rig), checked against the rig's ground truth and the run file.
#include "engine_fixture.h"

#include "core/run_file.h"

#include <QTemporaryDir>
#include <atomic>
#include <cmath>

using namespace nb::devices;
using namespace nb::devices::sim;
using nb::EndReason;
using nbtest::fastRig;
using nbtest::makeEngine;
using nbtest::makeReady;

namespace {

RunPlan linearPlan(const QString& path, double depth = 40.0, double v = 4.0)
{
    RunPlan p;
    p.motion = RunPlan::Motion::Linear;
    p.linear = {v, depth};
    p.outPath = path;
    p.metadata.set(QStringLiteral("protocol"), QStringLiteral("test"));
    return p;
}

RunSummary waitForEnd(QSignalSpy& spy)
{
    if (spy.isEmpty() && !spy.wait(60000))
        qFatal("run did not end");
    return spy.takeFirst().at(0).value<RunSummary>();
}

const TruthEvent* findEvent(const GroundTruth& g, const QString& name)
{
    for (const auto& e : g.events)
        if (e.name == name)
            return &e;
    return nullptr;
}

// Every sample the sensor delivered while recording is in the file, in order, no gaps.
void verifyContiguous(const nb::Run& run)
{
    const auto* seq = run.numericColumn(QStringLiteral("seq"));
    QVERIFY(seq && !seq->empty());
    for (std::size_t i = 1; i < seq->size(); ++i)
        QCOMPARE((*seq)[i], (*seq)[i - 1] + 1.0);
    QCOMPARE(run.meta(QStringLiteral("samples")).value_or(QString()).toULongLong(), static_cast<qulonglong>(run.size()));
}

}  // namespace

class TestEngine : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.filePath(name); }

private slots:
    // As fast as possible means as fast as there is something to simulate: a ready engine with
    // nothing to do waits for the operator instead of racing the simulated clock (and a core)
    // ahead, and still answers the next command at once.
    void idleFastEngineWaitsForCommands()
    {
        auto e = makeEngine(fastRig(QStringLiteral("liver1"), Tip::Beveled));
        QVERIFY(nbtest::makeReady(*e));
        const double t0 = e->status().deviceTime_s;
        QTest::qWait(500);
        const double idle = e->status().deviceTime_s - t0;
        // Racing, the rig simulates ~1000 s per wall second; waiting, about 0.05 s.
        QVERIFY2(idle < 25.0, qPrintable(QStringLiteral("simulated %1 s while idle").arg(idle)));
        QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
        e->startRun(linearPlan(path(QStringLiteral("after_idle.csv"))));
        const RunSummary s = waitForEnd(ended);
        QCOMPARE(s.endReason, EndReason::Completed);
    }

    void startRunRefusedUntilEnabledBiasedZeroed()
    {
        auto e = makeEngine(fastRig(QStringLiteral("liver1"), Tip::Beveled));
        QSignalSpy refused(e.get(), &AcquisitionEngine::runRefused);
        QSignalSpy started(e.get(), &AcquisitionEngine::runStarted);
        const RunPlan plan = linearPlan(path(QStringLiteral("refused.csv")));

        e->startRun(plan);
        QVERIFY(nbtest::waitFor(refused, 5000));
        QVERIFY(refused.takeFirst().at(0).toString().contains(QStringLiteral("Enable the stage")));
        e->enableStage(true);
        e->startRun(plan);
        QVERIFY(nbtest::waitFor(refused, 5000));
        QVERIFY(refused.takeFirst().at(0).toString().contains(QStringLiteral("bias"), Qt::CaseInsensitive));
        e->biasSensor();
        QTRY_VERIFY_WITH_TIMEOUT(e->status().biased, 10000);
        e->startRun(plan);
        QVERIFY(nbtest::waitFor(refused, 5000));
        QVERIFY(refused.takeFirst().at(0).toString().contains(QStringLiteral("zero"), Qt::CaseInsensitive));
        QCOMPARE(started.count(), 0);
        QVERIFY(!QFile::exists(plan.outPath));

        e->zeroStage();
        QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
        e->startRun(plan);
        QVERIFY(nbtest::waitFor(started, 5000));
        const RunSummary s = waitForEnd(ended);
        QCOMPARE(s.endReason, EndReason::Completed);
        QCOMPARE(s.dropped, std::uint64_t{0});

        const auto r = nb::readRunFile(plan.outPath);
        QCOMPARE(r.run.meta(QStringLiteral("end_reason")).value(), QStringLiteral("completed"));
        QCOMPARE(r.run.meta(QStringLiteral("protocol")).value(), QStringLiteral("test"));
        QCOMPARE(r.run.meta(QStringLiteral("rate_hz")).value(), QStringLiteral("500"));
        QCOMPARE(static_cast<std::uint64_t>(r.run.size()), s.samples);
        verifyContiguous(r.run);
        // 40 mm at 4 mm/s: about 10 s of samples at 500 Hz, first at t = 0.
        QVERIFY(r.run.size() > 4900 && r.run.size() < 5300);
        QCOMPARE(r.run.time_s.front(), 0.0);
        QVERIFY(std::fabs(r.run.position_mm.back() - 40.0) < 0.01);
        // The engine's force (bias + calibration) matches the rig's true force at puncture.
        const GroundTruth g = e.rig->truth();
        const double origin = r.run.meta(QStringLiteral("run_start_device_time_s"))->toDouble();
        double peak = 0.0;
        for (double f : r.run.force_N)
            peak = std::max(peak, f);
        QVERIFY2(std::fabs(peak - g.punctureForce_N) < 0.1, qPrintable(QStringLiteral("%1 %2").arg(peak).arg(g.punctureForce_N)));
        QVERIFY(g.puncture_s - origin > 0.0);
        // Truth columns ride along in simulated runs.
        QVERIFY(r.run.numericColumn(QStringLiteral("tissue_position_mm")) != nullptr);
    }

    void refusesAWhileRunIsOpenAndStopMotionKeepsRecording()
    {
        // "Stop motion only" at an exact simulated time: 3 s after the start (12 mm in).
        AcquisitionEngine* engine = nullptr;
        std::atomic<double> stopAt{1e9};
        auto e = makeEngine(fastRig(QStringLiteral("liver1"), Tip::Beveled), 500.0, 8.0, [&](double t) {
            if (t >= stopAt.load()) {
                stopAt = 1e9;
                engine->stopMotion();
            }
        });
        engine = e.get();
        QVERIFY(makeReady(*e));
        QSignalSpy refused(e.get(), &AcquisitionEngine::runRefused);
        QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
        RunPlan plan = linearPlan(path(QStringLiteral("open.csv")), 60.0);
        plan.endWhenMotionDone = false;
        connect(e.get(), &AcquisitionEngine::runStarted, this, [&] { stopAt = e.rig->simTime_s() + 3.0; },
                Qt::DirectConnection);
        e->startRun(plan);
        e->startRun(linearPlan(path(QStringLiteral("second.csv"))));
        QVERIFY(nbtest::waitFor(refused, 5000));
        QVERIFY(refused.takeFirst().at(0).toString().contains(QStringLiteral("already recording")));
        QTRY_VERIFY_WITH_TIMEOUT(stopAt.load() > 1e8 && e->status().position_mm > 10.0, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!e->status().moving, 10000);
        QVERIFY(e->status().recording);
        const double stoppedAt = e->status().position_mm;
        e->withdraw(10.0);
        QTRY_VERIFY_WITH_TIMEOUT(e->status().position_mm < 0.01 && !e->status().moving, 20000);
        e->endRun();
        const RunSummary s = waitForEnd(ended);
        QCOMPARE(s.endReason, EndReason::Stopped);
        const auto r = nb::readRunFile(plan.outPath);
        verifyContiguous(r.run);
        // The withdrawal is in the file: it went in, stopped short of 60 mm and came back out.
        double maxPos = 0;
        for (double p : r.run.position_mm)
            maxPos = std::max(maxPos, p);
        QVERIFY(maxPos < 59.0 && maxPos >= stoppedAt - 0.01);
        QVERIFY(std::fabs(r.run.position_mm.back()) < 0.01);
        QVERIFY(!QFile::exists(path(QStringLiteral("second.csv"))));
    }

    void forceLimitStopsTheNeedleAtBone()
    {
        RigConfig rig = fastRig(QStringLiteral("liver1"), Tip::Beveled);
        rig.boneDepth_mm = 25.0;
        const double limit = 5.0;
        auto e = makeEngine(rig, 500.0, limit);
        QVERIFY(makeReady(*e));
        QSignalSpy tripped(e.get(), &AcquisitionEngine::forceLimitTripped);
        QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
        e->startRun(linearPlan(path(QStringLiteral("bone.csv")), 60.0));
        const RunSummary s = waitForEnd(ended);
        QCOMPARE(s.endReason, EndReason::ForceLimit);
        QCOMPARE(tripped.count(), 1);
        const double trippedForce = tripped.at(0).at(0).toDouble();
        QVERIFY(trippedForce > limit);

        const GroundTruth g = e.rig->truth();
        const TruthEvent* bone = findEvent(g, QStringLiteral("bone_contact"));
        const TruthEvent* stop = findEvent(g, QStringLiteral("emergency_stop"));
        QVERIFY(bone && stop);
        const auto r = nb::readRunFile(path(QStringLiteral("bone.csv")));
        verifyContiguous(r.run);
        const double origin = r.run.meta(QStringLiteral("run_start_device_time_s"))->toDouble();
        // The first sample over the limit, and the stop command within one sample period of it.
        std::size_t first = 0;
        while (first < r.run.size() && r.run.force_N[first] <= limit)
            ++first;
        QVERIFY(first < r.run.size());
        const double overAt = r.run.time_s[first] + origin;
        QVERIFY2(stop->time_s - overAt >= -1e-9 && stop->time_s - overAt <= 1.0 / 500 + 1e-9,
                 qPrintable(QStringLiteral("over %1 stop %2").arg(overAt).arg(stop->time_s)));
        QCOMPARE(r.run.meta(QStringLiteral("force_limit_force_N"))->toDouble(), std::round(trippedForce * 1e4) / 1e4);
        // The needle stops: the force settles instead of climbing on into the bone.
        double peak = 0;
        for (double f : r.run.force_N)
            peak = std::max(peak, f);
        QVERIFY2(peak < limit + 2.0, qPrintable(QString::number(peak)));
        QVERIFY(std::fabs(r.run.position_mm.back() - r.run.position_mm[first]) < 0.05);
        QTRY_VERIFY_WITH_TIMEOUT(!e->status().moving && e->status().forceLimitTripped, 5000);
    }

    void faultsStopMotionAndEndTheRun_data()
    {
        QTest::addColumn<int>("fault");
        QTest::addColumn<QString>("device");
        QTest::addColumn<QString>("reason");
        QTest::newRow("sensor silent") << int(Fault::SensorSilent) << "load cell" << "no samples";
        QTest::newRow("sensor error") << int(Fault::SensorError) << "load cell" << "LIBUSB_ERROR_IO";
        QTest::newRow("stage silent") << int(Fault::StageSilent) << "stage" << "no reply";
        QTest::newRow("stage rejects") << int(Fault::StageRejects) << "stage" << "rejected";
    }
    void faultsStopMotionAndEndTheRun()
    {
        QFETCH(int, fault);
        QFETCH(QString, device);
        QFETCH(QString, reason);
        const bool rejects = static_cast<Fault>(fault) == Fault::StageRejects;
        // The rejection needs a command mid-run: that case runs on the wall clock so the
        // move is still going when the command comes.
        RigConfig rig = fastRig(QStringLiteral("liver1"), Tip::Beveled);
        rig.realtime = rejects;
        auto e = makeEngine(rig);
        QVERIFY(makeReady(*e));
        QSignalSpy faults(e.get(), &AcquisitionEngine::faultOccurred);
        QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
        const QString file = path(QStringLiteral("fault%1.csv").arg(fault));
        if (!rejects)
            e.rig->injectFault(static_cast<Fault>(fault), e.rig->simTime_s() + 3.0);  // mid-insertion
        e->startRun(linearPlan(file, 60.0));
        if (rejects) {
            QTRY_VERIFY_WITH_TIMEOUT(e->status().position_mm > 0.5, 20000);
            // A controller that rejects commands is found out by the next command; the
            // engine's reaction is timed from that rejection.
            e.rig->injectFault(Fault::StageRejects);
            e->stopMotion();
        }
        const RunSummary s = waitForEnd(ended);
        QCOMPARE(s.endReason, EndReason::Fault);
        QVERIFY2(s.fault.contains(device) && s.fault.contains(reason), qPrintable(s.fault));
        QVERIFY(faults.count() >= 1);
        QVERIFY(faults.at(0).at(0).toString().contains(device));
        QTRY_VERIFY_WITH_TIMEOUT(e->status().fault.contains(reason), 5000);

        // Motion stopped within 200 ms of the fault (sim clock). A silent stage is stopped by
        // its controller's watchdog, which the world may not have reached yet: wait for it.
        auto stopped = [&] {
            const GroundTruth t = e.rig->truth();
            return findEvent(t, QStringLiteral("emergency_stop")) || findEvent(t, QStringLiteral("controller_watchdog_stop"));
        };
        QTRY_VERIFY_WITH_TIMEOUT(stopped(), 10000);
        const GroundTruth g = e.rig->truth();
        const TruthEvent* f = findEvent(g, rejects ? QStringLiteral("command_rejected") : QStringLiteral("fault"));
        QVERIFY(f);
        const TruthEvent* stop = findEvent(g, QStringLiteral("emergency_stop"));
        if (!stop || static_cast<Fault>(fault) == Fault::StageSilent)
            stop = findEvent(g, QStringLiteral("controller_watchdog_stop"));
        QVERIFY(stop);
        QVERIFY2(stop->time_s - f->time_s < 0.2, qPrintable(QString::number(stop->time_s - f->time_s)));

        // Every sample up to the fault is in the file, with the reason in its footer.
        const auto r = nb::readRunFile(file);
        verifyContiguous(r.run);
        QCOMPARE(r.run.meta(QStringLiteral("end_reason")).value(), QStringLiteral("fault"));
        QVERIFY(r.run.meta(QStringLiteral("fault"))->contains(reason));
        const double origin = r.run.meta(QStringLiteral("run_start_device_time_s"))->toDouble();
        QVERIFY(r.run.time_s.back() + origin >= f->time_s - 0.11);

        // A new run is refused while the fault stands.
        QSignalSpy refused(e.get(), &AcquisitionEngine::runRefused);
        e->startRun(linearPlan(path(QStringLiteral("after.csv"))));
        QVERIFY(nbtest::waitFor(refused, 5000));
        QVERIFY(refused.takeFirst().at(0).toString().contains(QStringLiteral("Device fault")));
    }
};

QTEST_GUILESS_MAIN(TestEngine)
#include "test_engine.moc"
