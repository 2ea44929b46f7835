// The summed insertion model (eq. 7, eq. 27, Fig. 38): simulate along a trajectory and
// compare with a recording.
#include "core/fit_error.h"
#include "core/insertion_model.h"
#include "core/run_file.h"
#include "synthetic.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace nb;

class TestInsertionModel : public QObject {
    Q_OBJECT

    // The model that generated synthetic::Insertion's defaults (up to its finite drop).
    static InsertionModel matching(const synthetic::Insertion& p)
    {
        InsertionModel m;
        m.stiffness = {p.a1_N_per_mm, p.a2_N_per_mm2};
        m.contact_mm = p.contact_mm;
        m.punctureDepth_mm = p.punctureDepth_mm;
        m.relaxation_mm = p.relaxation_mm;
        m.cutting.force_N = p.cutting_N;
        m.friction.Cp_N_per_m = p.friction_N_per_mm * 1000.0;
        return m;
    }

private slots:
    void cuttingFollowsEquation27()
    {
        const CuttingModel c{0.1};
        QCOMPARE(c(false, 30.0, 10.0, 0.004), 0.0);
        QCOMPARE(c(true, 30.0, 10.0, 0.004), 0.1);
        QCOMPARE(c(true, 5.0, 10.0, 0.004), 0.0);   // tip not yet past the surface
        QCOMPARE(c(true, 30.0, 10.0, -0.004), 0.0);  // withdrawing cuts nothing
    }
    void piecesOfTheSummedModel()
    {
        InsertionModel m;
        m.stiffness = {0.05, 0.005};
        m.contact_mm = 2.0;
        m.punctureDepth_mm = 10.0;
        m.relaxation_mm = 2.0;
        m.cutting.force_N = 0.1;
        m.friction.Cp_N_per_m = 10.0;
        m.friction.bp_Ns_per_m2 = 200.0;
        std::vector<double> t, x;
        for (int i = 0; i <= 5000; ++i) {
            t.push_back(i * 0.002);
            x.push_back(i * 0.002 * 4.0);  // 4 mm/s to 40 mm
        }
        const Run r = simulateInsertion(m, t, x);
        QCOMPARE(r.size(), t.size());
        QCOMPARE(r.force_N[100], 0.0);  // 0.8 mm: before contact
        QVERIFY(std::fabs(r.force_N[1000] - m.stiffness(8.0 - 2.0)) < 1e-12);
        // At 30 mm: cutting + (Cp + bp·v)·L, L = 30 - (12 - 2) = 20 mm, v = 0.004 m/s.
        const double L = 0.020;
        QVERIFY(std::fabs(r.force_N[3750] - (0.1 + (10.0 + 200.0 * 0.004) * L)) < 1e-9);
        // Withdrawing after puncture: friction reverses and cutting stops.
        m.friction.Cn_N_per_m = 12.0;
        const Run w = simulateInsertion(m, std::vector<double>{0.0, 0.002, 0.004}, std::vector<double>{13.0, 30.0, 29.992});
        QVERIFY(std::fabs(w.force_N[2] - (-12.0 * (0.029992 - 0.010))) < 1e-9);
    }
    void simulationMatchesItsSyntheticRecording()
    {
        synthetic::Insertion p;
        p.dropTravel_mm = 1e-6;  // the model drops at once
        const Run recorded = synthetic::makeInsertion(p);
        Run zeroed = recorded;
        for (double& f : zeroed.force_N)
            f -= p.offset_N;
        const InsertionModel m = matching(p);
        const Run sim = simulateInsertion(m, recorded.time_s, recorded.position_mm);
        const double d = rmsDistance(sim, zeroed);
        // Only the noise (6 mN) is left.
        QVERIFY2(std::fabs(d - p.noise_N) < 0.002, qPrintable(QString::number(d)));
        InsertionModel stiffer = m;
        stiffer.stiffness.a1_N_per_mm *= 1.5;
        QVERIFY(rmsDistance(simulateInsertion(stiffer, recorded.time_s, recorded.position_mm), zeroed) > 2.0 * d);
        InsertionModel noFriction = m;
        noFriction.friction = {};
        QVERIFY(rmsDistance(simulateInsertion(noFriction, recorded.time_s, recorded.position_mm), zeroed) > 2.0 * d);
    }
    void survivesRunFileRoundTrip()
    {
        synthetic::Insertion p;
        p.noise_N = 0.0;
        p.offset_N = 0.0;
        const Run recorded = synthetic::makeInsertion(p);
        const Run sim = simulateInsertion(matching(p), recorded.time_s, recorded.position_mm);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sim.csv"));
        writeRunFile(path, sim);
        const Run back = readRunFile(path).run;
        QVERIFY(rmsDistance(back, sim) < 1e-4);
        QCOMPARE(rmsDistance(sim, sim), 0.0);
    }
    void badInputThrows()
    {
        const InsertionModel m;
        QVERIFY_THROWS_EXCEPTION(FitError, simulateInsertion(m, std::vector<double>{0.0, 1.0}, std::vector<double>{0.0}));
        Run a, b;
        a.time_s = {0.0, 1.0};
        a.position_mm = {0.0, 1.0};
        a.force_N = {0.0, 0.0};
        b.time_s = {5.0, 6.0};
        b.position_mm = {0.0, 1.0};
        b.force_N = {0.0, 0.0};
        QVERIFY_THROWS_EXCEPTION(FitError, rmsDistance(a, b));
        QVERIFY_THROWS_EXCEPTION(FitError, rmsDistance(Run{}, b));
    }
};

QTEST_GUILESS_MAIN(TestInsertionModel)
#include "test_insertion_model.moc"
