// The simulated rig reproduces the thesis's tables when its runs are analysed with the
// project's own fits: Table 2 (capsule stiffness and puncture, 5 seeds per liver, within
// 15 %) and Table 5 (friction per length on the platform, mass removed, phases from the truth, 20 %).
#include "engine_fixture.h"
#include "support/needlebench_cli.h"

#include "core/friction_fit.h"
#include "core/labels.h"
#include "core/run_file.h"

#include <QJsonArray>
#include <QJsonObject>
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
    if (!nbtest::waitFor(ended, 120000))
        qFatal("run did not end");
    return nb::readRunFile(path).run;
}

bool within(double value, double expected, double tolerance)
{
    return std::fabs(value - expected) <= tolerance * std::fabs(expected);
}

QString percent(double value, double expected)
{
    return QString::number(100.0 * (value - expected) / expected, 'f', 1);
}

}  // namespace

class TestSimReproduction : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void table2Stiffness_data()
    {
        QTest::addColumn<QString>("tissue");
        QTest::addColumn<QString>("tip");
        QTest::addColumn<double>("a1");
        QTest::addColumn<double>("a2");
        QTest::addColumn<double>("depth");
        QTest::addColumn<double>("force");
        QTest::newRow("liver1") << "liver1" << "beveled" << 0.0480 << 0.0052 << 16.5732 << 2.3888;
        QTest::newRow("liver2") << "liver2" << "beveled" << 0.0020 << 0.0023 << 22.3838 << 1.2597;
        QTest::newRow("liver3") << "liver3" << "beveled" << 0.0371 << 0.0107 << 8.9458 << 1.4370;
        QTest::newRow("liver5") << "liver5" << "diamond" << 0.0204 << 0.0008 << 10.4022 << 0.5352;
        QTest::newRow("liver7") << "liver7" << "diamond" << 0.0042 << 0.0133 << 8.0068 << 1.1283;
    }
    // Five insertions per liver through the real executables, as a user's script would run
    // them: `needlebench simulate`, then `needlebench fit stiffness --json`. Table 2's
    // positions are relative to the liver surface, which the thesis knew; here the operator's
    // contact label comes from the simulation's truth (the contact they would mark on the
    // video), and the fit must then give a1, a2, the mean puncture depth and force within 15 %.
    // The same runs fitted with the detected contact alone must land within 15 % too, except
    // a1 of liver 7 and liver 2, whose linear term carries 4 % of the force and is decided by
    // where the contact is put to a few hundredths of a millimetre.
    void table2Stiffness()
    {
        QFETCH(QString, tissue);
        QFETCH(QString, tip);
        QFETCH(double, a1);
        QFETCH(double, a2);
        QFETCH(double, depth);
        QFETCH(double, force);
        QStringList runs, labelArgs;
        for (int seed = 1; seed <= 5; ++seed) {
            const QString base = dir_.filePath(QStringLiteral("%1_%2").arg(tissue).arg(seed));
            const nbtest::CliResult sim = nbtest::runCli({QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                 QStringLiteral("--tissue"), tissue, QStringLiteral("--tip"), tip, QStringLiteral("--seed"),
                                 QString::number(seed), QStringLiteral("--truth"), base + QStringLiteral(".truth.json"),
                                 QStringLiteral("--out"), base + QStringLiteral(".csv")});
            QVERIFY2(sim.code == 0, qPrintable(sim.err));
            const QJsonObject truth = nbtest::readJsonFile(base + QStringLiteral(".truth.json"));
            QVERIFY(truth.value(QStringLiteral("contact_s")).isDouble());
            const double t = truth.value(QStringLiteral("contact_s")).toDouble();
            nb::writeLabelsFile(base + QStringLiteral(".labels.csv"),
                                {{QStringLiteral("events"), QStringLiteral("contact"), t, t, QString()}});
            runs << base + QStringLiteral(".csv");
            labelArgs << QStringLiteral("--labels") << base + QStringLiteral(".labels.csv");
        }
        for (const bool labelled : {true, false}) {
            const nbtest::CliResult fit = nbtest::runCli(QStringList{QStringLiteral("fit"), QStringLiteral("stiffness"), QStringLiteral("--json")} + runs +
                                (labelled ? labelArgs : QStringList()));
            QVERIFY2(fit.code == 0, qPrintable(fit.err));
            const QJsonObject o = fit.json();
            const QJsonObject pooled = o.value(QStringLiteral("pooled")).toObject();
            const double fa1 = pooled.value(QStringLiteral("a1_N_per_mm")).toDouble();
            const double fa2 = pooled.value(QStringLiteral("a2_N_per_mm2")).toDouble();
            double depthSum = 0.0, forceSum = 0.0;
            const QJsonArray perRun = o.value(QStringLiteral("runs")).toArray();
            QCOMPARE(perRun.size(), 5);
            for (const QJsonValue& r : perRun) {
                depthSum += r.toObject().value(QStringLiteral("puncture_depth_mm")).toDouble();
                forceSum += r.toObject().value(QStringLiteral("puncture_force_N")).toDouble();
            }
            const QString got = QStringLiteral("%1 contact: a1 %2 (%3 %) a2 %4 (%5 %) depth %6 (%7 %) force %8 (%9 %)")
                                    .arg(labelled ? QStringLiteral("labelled") : QStringLiteral("detected"))
                                    .arg(fa1).arg(percent(fa1, a1)).arg(fa2).arg(percent(fa2, a2))
                                    .arg(depthSum / 5).arg(percent(depthSum / 5, depth))
                                    .arg(forceSum / 5).arg(percent(forceSum / 5, force));
            qInfo("%s %s", qPrintable(tissue), qPrintable(got));
            if (labelled || a1 * depth >= 0.1 * (a1 * depth + a2 * depth * depth))
                QVERIFY2(within(fa1, a1, 0.15), qPrintable(got));
            QVERIFY2(within(fa2, a2, 0.15), qPrintable(got));
            QVERIFY2(within(depthSum / 5, depth, 0.15), qPrintable(got));
            QVERIFY2(within(forceSum / 5, force, 0.15), qPrintable(got));
        }
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
