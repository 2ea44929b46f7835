// The simulated rig reproduces the thesis's tables when its runs are analysed with the
// project's own fits: Table 2 (capsule stiffness, 5 seeds per liver, within 15 %) and
// Table 5 (friction per length on the platform, mass removed, phases from the truth, 20 %).
#include "engine_fixture.h"

#include "core/events.h"
#include "core/friction_fit.h"
#include "core/run_file.h"
#include "core/stiffness_fit.h"

#include <QTemporaryDir>
#include <cmath>

using namespace nb::devices;
using namespace nb::devices::sim;

namespace {

nb::Run record(const RigConfig& rig, const RunPlan& planIn, const QString& path)
{
    auto e = nbtest::makeEngine(rig);
    if (!nbtest::makeReady(*e))
        qFatal("engine not ready");
    QSignalSpy ended(e.get(), &AcquisitionEngine::runEnded);
    RunPlan plan = planIn;
    plan.outPath = path;
    e->startRun(plan);
    if (!ended.wait(120000))
        qFatal("run did not end");
    return nb::readRunFile(path).run;
}

bool within(double value, double expected, double tolerance)
{
    return std::fabs(value - expected) <= tolerance * std::fabs(expected);
}

}  // namespace

class TestSimReproduction : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void table2Stiffness_data()
    {
        QTest::addColumn<QString>("tissue");
        QTest::addColumn<int>("tip");
        QTest::addColumn<double>("a1");
        QTest::addColumn<double>("a2");
        QTest::addColumn<double>("depth");
        QTest::newRow("liver1") << "liver1" << int(Tip::Beveled) << 0.0480 << 0.0052 << 16.5732;
        QTest::newRow("liver2") << "liver2" << int(Tip::Beveled) << 0.0020 << 0.0023 << 22.3838;
        QTest::newRow("liver3") << "liver3" << int(Tip::Beveled) << 0.0371 << 0.0107 << 8.9458;
        QTest::newRow("liver5") << "liver5" << int(Tip::Diamond) << 0.0204 << 0.0008 << 10.4022;
        QTest::newRow("liver7") << "liver7" << int(Tip::Diamond) << 0.0042 << 0.0133 << 8.0068;
    }
    void table2Stiffness()
    {
        QFETCH(QString, tissue);
        QFETCH(int, tip);
        QFETCH(double, a1);
        QFETCH(double, a2);
        QFETCH(double, depth);
        std::vector<nb::StiffnessSegment> segments;
        double depthSum = 0.0;
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            RigConfig rig = nbtest::fastRig(tissue, static_cast<Tip>(tip));
            rig.seed = seed;
            RunPlan plan;
            plan.linear = {4.0, 45.0};
            const nb::Run run = record(rig, plan, dir_.filePath(QStringLiteral("%1_%2.csv").arg(tissue).arg(seed)));
            const nb::InsertionEvents ev = nb::detectEvents(run);
            depthSum += ev.punctureDepth_mm();
            segments.push_back(nb::stiffnessSegment(run, ev));
        }
        const nb::StiffnessSummary s = nb::fitStiffnessRuns(segments);
        const nb::StiffnessModel& m = s.pooled.quadratic.model;
        const QString got = QStringLiteral("a1 %1 a2 %2 depth %3").arg(m.a1_N_per_mm).arg(m.a2_N_per_mm2).arg(depthSum / 5);
        qInfo("%s: %s", qPrintable(tissue), qPrintable(got));
        // The fitted force over the loaded half of the range matches Table 2's within 15 %,
        // and each coefficient does where its term carries at least a third of the force at
        // puncture (a term that carries little is poorly determined by any fit: a1 of
        // livers 2 and 7, a2 of liver 5).
        for (double x : {0.5 * depth, 0.75 * depth, depth})
            QVERIFY2(within(m(x), a1 * x + a2 * x * x, 0.15), qPrintable(got));
        const double total = a1 * depth + a2 * depth * depth;
        if (a1 * depth >= total / 3)
            QVERIFY2(within(m.a1_N_per_mm, a1, 0.15), qPrintable(got));
        if (a2 * depth * depth >= total / 3)
            QVERIFY2(within(m.a2_N_per_mm2, a2, 0.15), qPrintable(got));
        QVERIFY2(within(depthSum / 5, depth, 0.15), qPrintable(got));
    }

    void table5Friction()
    {
        // Liver 7 slab on the platform, 0.2 / 0.5 / 0.8 Hz, several locations (seeds).
        std::vector<nb::FrictionFit> fits;
        for (double f : {0.2, 0.5, 0.8}) {
            for (std::uint64_t seed = 1; seed <= 2; ++seed) {
                RigConfig rig = nbtest::fastRig(QStringLiteral("liver7"), Tip::Diamond);
                rig.setup = Setup::Platform;
                rig.seed = seed;
                RunPlan plan;
                plan.motion = RunPlan::Motion::Sine;
                plan.sine = {10.0, f, 7};
                plan.metadata.set(QStringLiteral("frequency_hz"), f);
                plan.metadata.set(QStringLiteral("thickness_mm"), rig.thickness_mm);
                const nb::Run run = record(rig, plan, dir_.filePath(QStringLiteral("fric_%1_%2.csv").arg(f).arg(seed)));
                QVERIFY(run.textColumn(QStringLiteral("phase")));
                nb::FrictionOptions o;
                o.thickness_mm = rig.thickness_mm;
                fits.push_back(nb::fitFriction(run, o));  // phases from the run's truth column
            }
        }
        const nb::FrictionGroup all = nb::overall(fits);
        const nb::KarnoppPerLength& m = all.mean;
        const nb::KarnoppPerLength t = sim::table5Friction();
        const QString got = QStringLiteral("Cp %1 bp %2 Cn %3 bn %4 Dp %5 Dn %6")
                                .arg(m.Cp_N_per_m).arg(m.bp_Ns_per_m2).arg(m.Cn_N_per_m).arg(m.bn_Ns_per_m2)
                                .arg(m.Dp_N_per_m).arg(m.Dn_N_per_m);
        qInfo("table 5 overall: %s", qPrintable(got));
        QVERIFY2(within(m.Cp_N_per_m, t.Cp_N_per_m, 0.2), qPrintable(got));
        QVERIFY2(within(m.Cn_N_per_m, t.Cn_N_per_m, 0.2), qPrintable(got));
        QVERIFY2(within(m.bp_Ns_per_m2, t.bp_Ns_per_m2, 0.2), qPrintable(got));
        QVERIFY2(within(m.bn_Ns_per_m2, t.bn_Ns_per_m2, 0.2), qPrintable(got));
        // Static friction from fitFriction itself: the break-away force of each phase-a
        // stretch in the direction of the motion that follows it.
        QVERIFY2(within(m.Dp_N_per_m, t.Dp_N_per_m, 0.2), qPrintable(got));
        QVERIFY2(within(m.Dn_N_per_m, t.Dn_N_per_m, 0.2), qPrintable(got));
        for (const nb::FrictionFit& fit : fits)
            QCOMPARE(fit.staticSource, QStringLiteral("phase a"));
    }
};

QTEST_GUILESS_MAIN(TestSimReproduction)
#include "test_sim_reproduction.moc"
