// Capsule stiffness fits (eq. 11, Table 2): quadratic per run and pooled, cubic and
// nonlinear spring alternatives.
#include "core/events.h"
#include "core/fit_error.h"
#include "core/stiffness_fit.h"
#include "synthetic.h"

#include <QtTest>
#include <cmath>

using namespace nb;

class TestStiffnessFit : public QObject {
    Q_OBJECT

    static StiffnessSegment curve(double (*f)(double), double to, int n)
    {
        StiffnessSegment s;
        for (int i = 0; i < n; ++i) {
            const double x = to * i / (n - 1);
            s.depth_mm.push_back(x);
            s.force_N.push_back(f(x));
        }
        return s;
    }

private slots:
    void exactQuadratic()
    {
        const auto fit = fitStiffness(curve([](double x) { return 0.048 * x + 0.0052 * x * x; }, 16.57, 400));
        QVERIFY(std::fabs(fit.quadratic.model.a1_N_per_mm - 0.048) < 1e-10);
        QVERIFY(std::fabs(fit.quadratic.model.a2_N_per_mm2 - 0.0052) < 1e-10);
        QVERIFY(std::fabs(fit.quadratic.r2 - 1.0) < 1e-12);
        QVERIFY(fit.quadratic.rms_N < 1e-10);
        QVERIFY(std::fabs(fit.cubic.a3_N_per_mm3) < 1e-10);
        QCOMPARE(fit.samples, std::size_t(400));
        // The spring cannot bend upwards like this curve does everywhere: worse than quadratic.
        QVERIFY(fit.spring.rms_N > fit.quadratic.rms_N);
    }
    void exactSpringIsRecovered()
    {
        // f = x / (a x + b) with a = 0.2 /N, b = 10 mm/N: saturating toward 5 N.
        const auto fit = fitStiffness(curve([](double x) { return x / (0.2 * x + 10.0); }, 20.0, 300));
        QVERIFY(fit.spring.converged);
        QVERIFY2(std::fabs(fit.spring.a_per_N - 0.2) < 1e-6, qPrintable(QString::number(fit.spring.a_per_N)));
        QVERIFY(std::fabs(fit.spring.b_mm_per_N - 10.0) < 1e-5);
        QVERIFY(fit.spring.rms_N < 1e-8);
        QVERIFY(fit.spring.rms_N < fit.quadratic.rms_N);
    }
    void cubicTermOfCubicData()
    {
        const auto fit = fitStiffness(curve([](double x) { return 0.01 * x + 0.002 * x * x + 0.0003 * x * x * x; }, 10.0, 200));
        QVERIFY(std::fabs(fit.cubic.a3_N_per_mm3 - 0.0003) < 1e-10);
        QVERIFY(fit.cubic.rms_N < fit.quadratic.rms_N);
    }
    void perRunAndPooledOnSyntheticRuns()
    {
        // Runs of one liver vary a little; the pooled fit and the mean of runs both land
        // near the generating parameters.
        std::vector<StiffnessSegment> segs;
        for (std::uint32_t seed = 1; seed <= 6; ++seed) {
            synthetic::Insertion p;
            p.seed = seed;
            p.punctureDepth_mm = 15.0 + seed * 0.5;
            const Run run = synthetic::makeInsertion(p);
            const auto ev = detectEvents(run);
            segs.push_back(stiffnessSegment(run, ev));
            QVERIFY(segs.back().depth_mm.front() >= 0.0);
            QVERIFY(std::fabs(segs.back().depth_mm.back() - p.punctureDepth_mm) < 0.35);
        }
        const auto sum = fitStiffnessRuns(segs);
        QCOMPARE(sum.runs.size(), std::size_t(6));
        QVERIFY(std::fabs(sum.pooled.quadratic.model.a1_N_per_mm / 0.048 - 1.0) < 0.10);
        QVERIFY(std::fabs(sum.pooled.quadratic.model.a2_N_per_mm2 / 0.0052 - 1.0) < 0.05);
        QVERIFY(std::fabs(sum.meanOfRuns.a1_N_per_mm / 0.048 - 1.0) < 0.10);
        QVERIFY(std::fabs(sum.meanOfRuns.a2_N_per_mm2 / 0.0052 - 1.0) < 0.05);
        QVERIFY(sum.stdDevOfRuns.a1_N_per_mm > 0.0 && sum.stdDevOfRuns.a1_N_per_mm < 0.005);
        QVERIFY(sum.pooled.quadratic.r2 > 0.99);
        QVERIFY(std::fabs(sum.pooled.quadratic.rms_N - 0.006) < 0.001);
        // The thesis's finding holds on its own model: the cubic term is about zero.
        QVERIFY(std::fabs(sum.pooled.cubic.a3_N_per_mm3) < 1e-4);
        QCOMPARE(sum.pooled.samples, std::size_t(0) + [&] {
            std::size_t n = 0;
            for (const auto& s : segs)
                n += s.depth_mm.size();
            return n;
        }());
    }
    void badInputThrows()
    {
        StiffnessSegment few;
        few.depth_mm = {0.0, 1.0, 2.0};
        few.force_N = {0.0, 0.1, 0.2};
        QVERIFY_THROWS_EXCEPTION(FitError, fitStiffness(few));
        StiffnessSegment flat;
        flat.depth_mm = {0.0, 0.0, 0.0, 0.0, 0.0};
        flat.force_N = {0.0, 0.1, 0.2, 0.1, 0.0};
        QVERIFY_THROWS_EXCEPTION(FitError, fitStiffness(flat));
        StiffnessSegment mismatch;
        mismatch.depth_mm = {0.0, 1.0, 2.0, 3.0, 4.0};
        mismatch.force_N = {0.0, 0.1};
        QVERIFY_THROWS_EXCEPTION(FitError, fitStiffness(mismatch));
        QVERIFY_THROWS_EXCEPTION(FitError, fitStiffnessRuns({}));
    }
};

QTEST_GUILESS_MAIN(TestStiffnessFit)
#include "test_stiffness_fit.moc"
