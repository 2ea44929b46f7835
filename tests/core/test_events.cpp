// Event detection on synthetic constant-velocity insertions with known contact, puncture,
// relaxation and internal punctures (Table 2 parameters, 6 mN noise, 500 Hz, 4 mm/s).
#include "core/events.h"
#include "core/fit_error.h"
#include "core/labels.h"
#include "synthetic.h"

#include <Eigen/Dense>
#include <QtTest>
#include <cmath>

using namespace nb;

class TestEvents : public QObject {
    Q_OBJECT

    static synthetic::Insertion liver(int row)
    {
        synthetic::Insertion p;
        switch (row) {
        case 1: p.a1_N_per_mm = 0.0480; p.a2_N_per_mm2 = 0.0052; p.punctureDepth_mm = 16.5732; break;
        case 3: p.a1_N_per_mm = 0.0371; p.a2_N_per_mm2 = 0.0107; p.punctureDepth_mm = 8.9458; break;
        case 5: p.a1_N_per_mm = 0.0204; p.a2_N_per_mm2 = 0.0008; p.punctureDepth_mm = 10.4022; break;
        }
        return p;
    }

private slots:
    void contactFitMeetsTargets_data()
    {
        QTest::addColumn<int>("liver");
        QTest::addColumn<int>("seed");
        for (int l : {1, 3})
            for (int s = 1; s <= 5; ++s)
                QTest::addRow("liver%d seed%d", l, s) << l << s;
    }
    void contactFitMeetsTargets()
    {
        QFETCH(int, liver);
        QFETCH(int, seed);
        auto p = this->liver(liver);
        p.seed = std::uint32_t(seed);
        const auto ev = detectEvents(synthetic::makeInsertion(p));
        const QString got = QStringLiteral("contact %1 a1 %2 a2 %3")
                                .arg(ev.contact.position_mm)
                                .arg(ev.stiffness.a1_N_per_mm)
                                .arg(ev.stiffness.a2_N_per_mm2);
        QVERIFY2(std::fabs(ev.contact.position_mm - p.contact_mm) < 0.3, qPrintable(got));
        QVERIFY2(std::fabs(ev.stiffness.a1_N_per_mm / p.a1_N_per_mm - 1.0) < 0.10, qPrintable(got));
        QVERIFY2(std::fabs(ev.stiffness.a2_N_per_mm2 / p.a2_N_per_mm2 - 1.0) < 0.05, qPrintable(got));
        QVERIFY(std::fabs(ev.zeroOffset_N - p.offset_N) < 0.003);
        QVERIFY(std::fabs(ev.noise_N - p.noise_N) < 0.001);
        QVERIFY(std::fabs(ev.contact.time_s - p.contact_mm / p.speed_mm_s) < 0.3 / p.speed_mm_s);
    }
    void contactSearchMatchesDirectLeastSquares()
    {
        // The search works on precomputed moments of samples sorted by position: check it
        // against a plain least-squares solve over the samples, on positions that go back
        // and forth (backlash) and repeat (a coarse encoder), far from the origin.
        auto p = liver(3);
        p.start_mm = 100.0;
        p.contact_mm = 104.0;
        p.end_mm = 125.0;
        const Run run = synthetic::makeInsertion(p);
        std::vector<double> pos, force;
        for (std::size_t i = 0; i < run.size() && run.position_mm[i] < p.puncture_mm() - 0.5; ++i) {
            pos.push_back(std::round((run.position_mm[i] + (i % 7 == 3 ? -0.02 : 0.0)) / 0.01) * 0.01);
            force.push_back(run.force_N[i]);
        }
        const ContactFit fit = fitContact(pos, force);
        auto direct = [&](double xc) {
            Eigen::MatrixXd A(Eigen::Index(pos.size()), 3);
            Eigen::VectorXd y(Eigen::Index(pos.size()));
            for (std::size_t i = 0; i < pos.size(); ++i) {
                const double d = std::max(0.0, pos[i] - xc);
                A.row(Eigen::Index(i)) << 1.0, d, d * d;
                y(Eigen::Index(i)) = force[i];
            }
            const Eigen::Vector3d x = A.colPivHouseholderQr().solve(y);
            return std::pair{x, (y - A * x).squaredNorm()};
        };
        const auto [x, sse] = direct(fit.contact_mm);
        const QString got = QStringLiteral("contact %1 offset %2/%3 a1 %4/%5 a2 %6/%7")
                                .arg(fit.contact_mm).arg(fit.offset_N).arg(x(0)).arg(fit.stiffness.a1_N_per_mm).arg(x(1))
                                .arg(fit.stiffness.a2_N_per_mm2).arg(x(2));
        QVERIFY2(std::fabs(fit.offset_N - x(0)) < 1e-9 && std::fabs(fit.stiffness.a1_N_per_mm - x(1)) < 1e-9 &&
                     std::fabs(fit.stiffness.a2_N_per_mm2 - x(2)) < 1e-9,
                 qPrintable(got));
        QVERIFY(std::fabs(fit.rms_N - std::sqrt(sse / double(pos.size()))) < 1e-12);
        // A minimum of the direct error too: no neighbour does better.
        for (double dx : {-0.2, -0.05, -0.01, 0.01, 0.05, 0.2})
            QVERIFY2(direct(fit.contact_mm + dx).second >= sse * (1.0 - 1e-9), qPrintable(got + QStringLiteral(" dx %1").arg(dx)));
        QVERIFY2(std::fabs(fit.contact_mm - p.contact_mm) < 0.3, qPrintable(got));
    }
    void mostlyQuadraticCapsuleKeepsContact()
    {
        // Liver 2: a1 carries ~7 % of the puncture force, so the first ~0.2 mm past contact
        // are below the noise; the contact must not slide early with a negative a1.
        for (std::uint32_t seed = 1; seed <= 8; ++seed) {
            synthetic::Insertion p;
            p.a1_N_per_mm = 0.0020;
            p.a2_N_per_mm2 = 0.0023;
            p.punctureDepth_mm = 22.3838;
            p.end_mm = 40.0;
            p.seed = seed;
            const auto ev = detectEvents(synthetic::makeInsertion(p));
            const QString got = QStringLiteral("seed %1 contact %2 a1 %3 a2 %4").arg(seed).arg(ev.contact.position_mm)
                                    .arg(ev.stiffness.a1_N_per_mm).arg(ev.stiffness.a2_N_per_mm2);
            QVERIFY2(ev.stiffness.a1_N_per_mm >= 0.0, qPrintable(got));
            QVERIFY2(std::fabs(ev.contact.position_mm - p.contact_mm) < 0.4, qPrintable(got));
            QVERIFY2(std::fabs(ev.stiffness.a2_N_per_mm2 / p.a2_N_per_mm2 - 1.0) < 0.05, qPrintable(got));
        }
    }
    void punctureAndRelaxation()
    {
        for (std::uint32_t seed = 1; seed <= 3; ++seed) {
            auto p = liver(1);
            p.seed = seed;
            const auto ev = detectEvents(synthetic::makeInsertion(p));
            const double peak = StiffnessModel{p.a1_N_per_mm, p.a2_N_per_mm2}(p.punctureDepth_mm);
            QVERIFY2(std::fabs(ev.puncture.position_mm - p.puncture_mm()) < 0.1,
                     qPrintable(QString::number(ev.puncture.position_mm)));
            QVERIFY(std::fabs(ev.puncture.force_N - peak) < 0.03);
            QVERIFY(std::fabs(ev.punctureDepth_mm() - p.punctureDepth_mm) < 0.35);
            QVERIFY(ev.relaxation.has_value());
            // The drop ends dropTravel_mm past the peak.
            QVERIFY2(std::fabs(ev.relaxation->position_mm - (p.puncture_mm() + p.dropTravel_mm)) < 0.15,
                     qPrintable(QString::number(ev.relaxation->position_mm)));
            QVERIFY(ev.relaxation->force_N < 0.3 * peak);
            QVERIFY(ev.internalPunctures.empty());
        }
    }
    void internalPuncturesFound()
    {
        auto p = liver(1);
        p.internal = {{4.0, 0.1}, {9.0, 0.06}};
        const auto ev = detectEvents(synthetic::makeInsertion(p));
        QCOMPARE(ev.internalPunctures.size(), std::size_t(2));
        QVERIFY(std::fabs(ev.internalPunctures[0].position_mm - (p.puncture_mm() + 4.0)) < 0.15);
        QVERIFY(std::fabs(ev.internalPunctures[1].position_mm - (p.puncture_mm() + 9.0)) < 0.15);
        QVERIFY(ev.internalPunctures[0].time_s > ev.puncture.time_s);
    }
    void lowStiffnessLiverStillPunctures()
    {
        auto p = liver(5);
        const auto ev = detectEvents(synthetic::makeInsertion(p));
        QVERIFY(std::fabs(ev.puncture.position_mm - p.puncture_mm()) < 0.15);
        QVERIFY(std::fabs(ev.contact.position_mm - p.contact_mm) < 0.5);
    }
    void onlyForwardStrokeCounts()
    {
        // The stage stops and backs out after the stroke; the samples after the deepest
        // point must not produce events.
        auto p = liver(1);
        Run run = synthetic::makeInsertion(p);
        const std::size_t n = run.size();
        for (std::size_t i = 1; i < 500; ++i) {
            run.time_s.push_back(run.time_s[n - 1] + double(i) / p.rate_hz);
            run.position_mm.push_back(run.position_mm[n - 1] - 4.0 * double(i) / p.rate_hz);
            run.force_N.push_back(run.force_N[n - 1] - 1.0);
        }
        const auto ev = detectEvents(run);
        QVERIFY(ev.internalPunctures.empty());
        QVERIFY(std::fabs(ev.puncture.position_mm - p.puncture_mm()) < 0.1);
    }
    void noPunctureThrows()
    {
        auto p = liver(1);
        p.punctureDepth_mm = 100.0;  // never reached
        QVERIFY_THROWS_EXCEPTION(FitError, detectEvents(synthetic::makeInsertion(p)));
    }
    // A puncture detection misses (here the run stops before the one the model has) but the
    // operator marked, with the contact: the labels' events, as Analysis and fit stiffness
    // --labels use them (they said 'no puncture' whatever was marked). Without a contact label
    // detection's own error stands.
    void labelsStandWhereDetectionFindsNoPuncture()
    {
        auto p = liver(1);
        p.punctureDepth_mm = 100.0;
        const Run run = synthetic::makeInsertion(p);
        const auto timeAt = [&](double x) {
            std::size_t i = 0;
            while (i + 1 < run.size() && run.position_mm[i] < x)
                ++i;
            return run.time_s[i];
        };
        Labels marks{{QStringLiteral("events"), QStringLiteral("contact"), timeAt(p.contact_mm), timeAt(p.contact_mm), {}},
                     {QStringLiteral("events"), QStringLiteral("puncture"), timeAt(20.0), timeAt(20.0), {}}};
        const InsertionEvents ev = eventsWithLabels(run, marks);
        QVERIFY2(std::fabs(ev.contact.position_mm - p.contact_mm) < 0.05, qPrintable(QString::number(ev.contact.position_mm)));
        QVERIFY2(std::fabs(ev.puncture.position_mm - 20.0) < 0.3, qPrintable(QString::number(ev.puncture.position_mm)));
        QVERIFY(std::fabs(ev.zeroOffset_N - p.offset_N) < 0.01);
        marks.erase(marks.begin());
        QVERIFY_THROWS_EXCEPTION(FitError, eventsWithLabels(run, marks));
        // Where detection works, the labels still override it.
        const Run punctured = synthetic::makeInsertion(liver(1));
        const InsertionEvents detected = detectEvents(punctured);
        const InsertionEvents labelled = eventsWithLabels(punctured, {});
        QCOMPARE(labelled.puncture.index, detected.puncture.index);
    }
    void noMotionOrTooFewSamplesThrow()
    {
        Run still;
        for (int i = 0; i < 1000; ++i) {
            still.time_s.push_back(i * 0.002);
            still.position_mm.push_back(3.0);
            still.force_N.push_back(0.01 * (i % 7));
        }
        QVERIFY_THROWS_EXCEPTION(FitError, detectEvents(still));
        Run tiny;
        for (int i = 0; i < 5; ++i) {
            tiny.time_s.push_back(i);
            tiny.position_mm.push_back(i);
            tiny.force_N.push_back(0);
        }
        QVERIFY_THROWS_EXCEPTION(FitError, detectEvents(tiny));
        Run nan = synthetic::makeInsertion(liver(1));
        nan.force_N[100] = std::nan("");
        QVERIFY_THROWS_EXCEPTION(FitError, detectEvents(nan));
    }
};

QTEST_GUILESS_MAIN(TestEvents)
#include "test_events.moc"
