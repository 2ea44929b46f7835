// The slab's give against its plate (core/plate_give.h): on carried stretches drawn at random
// (printed seed) from a contact with a spring, its losses and a stiff part behind a knee, at
// the rig's 500 samples/s with force noise, it reads the stiffness, the losses and how far the
// contact held; it reads nothing from a stretch that only leaves the other plate, or whose force
// never falls from its top; and the tissue it drives at rest moves as the contact's law says.
#include "core/plate_give.h"
#include "support/accuracy_seed.h"

#include <QtTest>

#include <cmath>
#include <random>

namespace {

std::vector<double> averaged(const std::vector<double>& x, int window)
{
    std::vector<double> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const std::size_t lo = i >= std::size_t(window / 2) ? i - std::size_t(window / 2) : 0;
        const std::size_t hi = std::min(x.size(), lo + std::size_t(window));
        double sum = 0.0;
        for (std::size_t j = lo; j < hi; ++j)
            sum += x[j];
        out[i] = sum / double(hi - lo);
    }
    return out;
}

// A needle moving + at constant speed carries the tissue across a gap into the plate: no force
// in the gap, then k·depth + c·v (the soft part, up to `soft_m`), stiffer beyond; it lets go at
// `breakAway_N` and slides on at `sliding_N`. One stroke of `samples`, noise added.
struct Stroke {
    std::vector<double> x_m, v_m_s, force_N;
};
Stroke carriedStroke(double k, double c, double speed_m_s, double gap_m, double soft_m, double breakAway_N, double sliding_N,
                     double noise_N, std::mt19937& rng)
{
    std::normal_distribution<double> noise(0.0, noise_N);
    Stroke s;
    const double dt = 0.002;
    bool slipped = false;
    for (int i = 0; i < 1500; ++i) {
        const double x = speed_m_s * dt * i;
        const double depth = x - gap_m;
        double f = 0.0;
        if (depth > 0.0)
            f = depth < soft_m ? k * depth + c * speed_m_s : k * soft_m + 25.0 * k * (depth - soft_m) + 5.0 * c * speed_m_s;
        slipped = slipped || f > breakAway_N;
        s.x_m.push_back(x);
        s.v_m_s.push_back(speed_m_s);
        s.force_N.push_back((slipped ? sliding_N : f) + noise(rng));
    }
    return s;
}

}  // namespace

class TestPlateGive : public QObject {
    Q_OBJECT

private slots:
    void readsTheContactFromCarriedStrokes()
    {
        std::mt19937 rng(nb::test::accuracySeed(52871u));
        auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
        for (int draw = 0; draw < 30; ++draw) {
            const double k = uniform(100.0, 400.0), c = uniform(10.0, 25.0), speed = uniform(0.002, 0.008), soft = uniform(0.0006, 0.0015);
            const double gap = uniform(0.0005, 0.002), noise = 0.0004;
            // Half the draws let go on the soft part, half only at the knee.
            const bool atKnee = draw % 2 == 1;
            const double held = atKnee ? k * soft : uniform(0.5, 0.85) * k * soft;
            const double breakAway = atKnee ? k * soft + c * speed + 0.05 : held + c * speed;
            const double sliding = 0.5 * held;
            // Four strokes end to end, each its own carried stretch.
            Stroke all;
            std::vector<std::pair<std::size_t, std::size_t>> carried;
            for (int stroke = 0; stroke < 4; ++stroke) {
                const Stroke s = carriedStroke(k, c, speed, gap, soft, breakAway, sliding, noise, rng);
                const std::size_t from = all.force_N.size();
                all.x_m.insert(all.x_m.end(), s.x_m.begin(), s.x_m.end());
                all.v_m_s.insert(all.v_m_s.end(), s.v_m_s.begin(), s.v_m_s.end());
                all.force_N.insert(all.force_N.end(), s.force_N.begin(), s.force_N.end());
                carried.emplace_back(from, all.force_N.size());
            }
            const std::vector<double> sharp = averaged(all.force_N, 3), smooth = averaged(all.force_N, 10);
            const auto give = nb::plateGive(all.x_m, all.v_m_s, smooth, sharp, carried, 1, noise / std::sqrt(3.0), 10);
            const QString what = QStringLiteral("draw %1: k %2 N/m, c %3 N·s/m, %4 mm/s, soft %5 mm, held %6 N%7")
                                     .arg(draw)
                                     .arg(k, 0, 'f', 0)
                                     .arg(c, 0, 'f', 1)
                                     .arg(1000 * speed, 0, 'f', 1)
                                     .arg(1000 * soft, 0, 'f', 2)
                                     .arg(held, 0, 'f', 3)
                                     .arg(atKnee ? QStringLiteral(", lets go at the knee") : QString());
            QVERIFY2(give, qPrintable(what));
            QVERIFY2(std::fabs(give->stiffness_N_per_m / k - 1.0) < 0.05, qPrintable(what + QStringLiteral(": read %1 N/m").arg(give->stiffness_N_per_m)));
            QVERIFY2(std::fabs(give->losses_Ns_per_m / c - 1.0) < 0.2, qPrintable(what + QStringLiteral(": read %1 N·s/m").arg(give->losses_Ns_per_m)));
            QVERIFY2(std::fabs(give->upTo_N / held - 1.0) < 0.1, qPrintable(what + QStringLiteral(": held up to %1 N").arg(give->upTo_N)));
            QCOMPARE(give->rises, std::size_t(4));
            QCOMPARE(give->breakAways.size(), std::size_t(4));
            // Where each let go, within 20 %: the averaged force's top spans a few samples of
            // travel, and the losses taken out are those read from the step at contact (a step
            // of 20 mN or more here, 50 times the noise).
            for (const nb::PlateGive::BreakAway& b : give->breakAways)
                QVERIFY2(std::fabs(b.depth_m * k / held - 1.0) < 0.2, qPrintable(what + QStringLiteral(": let go %1 mm in").arg(1000 * b.depth_m)));
        }
    }

    // A stretch that only leaves the other plate (the force pulling back, easing to nothing) and
    // one whose force rises and levels off (the sliding force growing with speed) hold no rise.
    void readsNothingWhereTheTissueNeverMetThePlate()
    {
        std::mt19937 rng(7u);
        std::normal_distribution<double> noise(0.0, 0.0004);
        std::vector<double> x, v, f;
        std::vector<std::pair<std::size_t, std::size_t>> carried;
        for (int stroke = 0; stroke < 4; ++stroke) {
            const std::size_t from = f.size();
            for (int i = 0; i < 600; ++i) {
                x.push_back(0.004 * 0.002 * i);
                v.push_back(0.004);
                const double t = 0.002 * i;
                // Leaving: -0.3 N easing to 0 over 0.4 s; then, in the odd strokes, a sliding
                // force rising with the speed to 0.2 N and staying there.
                double force = t < 0.4 ? -0.3 * (1.0 - t / 0.4) : 0.0;
                if (stroke % 2 == 1 && t > 0.6)
                    force = std::min(0.2, 0.2 * (t - 0.6) / 0.3);
                f.push_back(force + noise(rng));
            }
            carried.emplace_back(from, f.size());
        }
        QVERIFY(!nb::plateGive(x, v, averaged(f, 10), averaged(f, 3), carried, 1, 0.0004 / std::sqrt(3.0), 10));
    }

    // At rest on the soft part under a force falling at a steady rate, from a depth off the law's
    // own: k·s + c·ṡ = F has s' = -r/k - (k/c)·(s0 - F0/k - r·c/k²)·exp(-k·t/c).
    void tissueFollowsTheContactsLaw()
    {
        nb::PlateGive g;
        g.stiffness_N_per_m = 200.0;
        g.losses_Ns_per_m = 14.4;
        g.upTo_N = 0.2;
        const double s0 = 0.00098, F0 = 0.18, r = 0.2;  // m, N, N/s
        g.breakAways.push_back({0, 0, s0});
        std::vector<double> t, v, f;
        for (int i = 0; i < 200; ++i) {
            t.push_back(0.002 * i);
            v.push_back(0.005);
            f.push_back(F0 - r * t.back());
        }
        const std::vector<double> tissue = nb::restingTissueVelocity(g, t, v, f, 1);
        QVERIFY(std::isnan(tissue[0]));
        const double k = g.stiffness_N_per_m, c = g.losses_Ns_per_m;
        for (std::size_t i = 10; i < t.size(); i += 10) {
            // The step's mean velocity, against the law's at its middle.
            const double mid = t[i] - 0.001;
            const double want = -r / k - (k / c) * (s0 - F0 / k - r * c / (k * k)) * std::exp(-k * mid / c);
            QVERIFY2(std::fabs(tissue[i] - want) < 0.02 * std::fabs(want) + 2e-6,
                     qPrintable(QStringLiteral("t %1 s: %2 mm/s, the law %3 mm/s").arg(t[i]).arg(1000 * tissue[i]).arg(1000 * want)));
        }
        // Pressed harder than the soft part holds, it goes in to the knee and stays there.
        std::vector<double> hard(f.size(), 0.3);
        const std::vector<double> held = nb::restingTissueVelocity(g, t, v, hard, 1);
        double depth = s0;
        for (std::size_t i = 1; i < held.size(); ++i) {
            QVERIFY(held[i] >= 0.0);
            depth += held[i] * (t[i] - t[i - 1]);
        }
        QVERIFY2(std::fabs(depth - g.upTo_N / k) < 1e-7, qPrintable(QString::number(1000 * depth)));
        QVERIFY(held.back() < 1e-5);
    }
};

QTEST_GUILESS_MAIN(TestPlateGive)
#include "test_plate_give.moc"
