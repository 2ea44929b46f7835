// The settling fit (core/settling_fit.h) shared by the surface's spring-back and the tissue
// slowing on the plate: on samples drawn at random (printed seed) at a video's frame rate
// with pixel noise, it finds the onset, τ and the rest it was drawn with; it says when there
// is nothing to fit.
#include "core/settling_fit.h"
#include "support/accuracy_seed.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

class TestSettlingFit : public QObject {
    Q_OBJECT

private slots:
    void findsOnsetTauAndRest()
    {
        std::mt19937 rng(nb::test::accuracySeed(771203u));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        double worstOnset_frames = 0.0, worstTau = 0.0, sumTau = 0.0;
        const int cases = 30;
        for (int i = 0; i < cases; ++i) {
            const double fps = u(rng) < 0.5 ? 25.0 : 29.97, frame_s = 1.0 / fps;
            const double t0 = 1.0 + u(rng) * frame_s, tau = 0.05 + 0.25 * u(rng), v = (u(rng) < 0.5 ? -1 : 1) * (20.0 + 40.0 * u(rng));
            const double d0 = 10.0 * u(rng), rest = d0 - std::copysign(8.0 + 20.0 * u(rng), v), noise_px = 0.1 + 0.3 * u(rng);
            std::normal_distribution<double> noise(0.0, noise_px);
            std::vector<double> t, d;
            for (double time = 0.5 + u(rng) * frame_s; time < t0 + 8.0 * tau; time += frame_s) {
                t.push_back(time);
                d.push_back((time < t0 ? d0 + v * (time - t0) : rest + (d0 - rest) * std::exp(-(time - t0) / tau)) + noise(rng));
            }
            const std::vector<double> w(t.size(), 1.0);
            const nb::SettlingFit f = nb::fitSettling(t, d, w, 0.8, 1.2, 0.001, 0.01, 1.0, 1.01, t.front(), t.back());
            QVERIFY(std::isfinite(f.sse));
            worstOnset_frames = std::max(worstOnset_frames, std::abs(f.t0_s - t0) / frame_s);
            worstTau = std::max(worstTau, std::abs(f.tau_s / tau - 1.0));
            sumTau += std::abs(f.tau_s / tau - 1.0);
            QVERIFY2(std::abs(f.rest - rest) < 4.0 * noise_px, qPrintable(QStringLiteral("case %1: rest %2, drawn %3").arg(i).arg(f.rest).arg(rest)));
            QVERIFY2(std::abs(f.v / v - 1.0) < 0.2, qPrintable(QStringLiteral("case %1: v %2, drawn %3").arg(i).arg(f.v).arg(v)));
            // The fitted curve is what the fit's parameters say, and its speed is its slope.
            const double probe = t0 + 0.5 * tau, h = 1e-6;
            QCOMPARE(f.at(t.back()), f.rest + (f.d0 - f.rest) * std::exp(-(t.back() - f.t0_s) / f.tau_s));
            QVERIFY(std::abs(f.speedAt(probe) - (f.at(probe + h) - f.at(probe - h)) / (2 * h)) < 1e-3 * std::abs(f.speedAt(probe)));
            QCOMPARE(f.speedAt(f.t0_s - 0.1), f.v);
        }
        qInfo("worst onset error %.2f frames; tau error mean %.1f %%, worst %.1f %%", worstOnset_frames, 100.0 * sumTau / cases,
              100.0 * worstTau);
        // A settling over a frame or two, 0.4 px noise: τ rests on two or three samples.
        QVERIFY(worstOnset_frames < 0.5);
        QVERIFY(sumTau / cases < 0.08);
        QVERIFY(worstTau < 0.4);
    }

    void knownOnsetFitsTauAndRest()
    {
        std::mt19937 rng(nb::test::accuracySeed(409117u));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < 30; ++i) {
            const double frame_s = 1.0 / 29.97, t0 = 2.0, tau = frame_s * (0.7 + 6.0 * u(rng)), travel = 1.0 + 4.0 * u(rng);
            std::normal_distribution<double> noise(0.0, 0.02);
            std::vector<double> t{t0 - 0.5 * frame_s}, d{0.0};
            for (double time = t0 + 0.5 * frame_s; time < t0 + 12.0 * tau + 3 * frame_s; time += frame_s) {
                t.push_back(time);
                d.push_back(travel * (1.0 - std::exp(-(time - t0) / tau)) + noise(rng));
            }
            const nb::SettlingFit f = nb::fitSettlingFrom(t, d, t0, frame_s / 3.0, 10.0 * frame_s, 60);
            QVERIFY(std::isfinite(f.sse));
            QCOMPARE(f.t0_s, t0);
            QCOMPARE(f.v, 0.0);
            // The τ grid's steps are 6 % apart.
            QVERIFY2(std::abs(f.tau_s / tau - 1.0) < 0.12, qPrintable(QStringLiteral("case %1: tau %2, drawn %3").arg(i).arg(f.tau_s).arg(tau)));
            QVERIFY2(std::abs(f.rest - f.d0 - travel) < 0.05 * travel + 0.05,
                     qPrintable(QStringLiteral("case %1: travel %2, drawn %3").arg(i).arg(f.rest - f.d0).arg(travel)));
        }
    }

    // A tissue slowing on a soft support meets a stiff one and stops at once, short of where
    // it was settling to: the fit that may stop finds where, and the τ it was slowing with;
    // one that did not stop is fitted as not stopping.
    void settlingThatStopsShort()
    {
        std::mt19937 rng(nb::test::accuracySeed(620417u));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < 30; ++i) {
            const double frame_s = 1.0 / 29.97, t0 = 2.0, tau = frame_s * (1.0 + 2.0 * u(rng)), travel = 1.0 + 3.0 * u(rng);
            // Stopped between one and two and a half τ after the onset, while still plainly
            // moving (later, the stop hardly shows), or never.
            const bool stops = i % 3 != 0;
            const double stop = stops ? t0 + tau * (1.0 + 1.5 * u(rng)) : std::numeric_limits<double>::infinity();
            std::normal_distribution<double> noise(0.0, 0.01);
            std::vector<double> t{t0 - 0.5 * frame_s}, d{0.0}, stops_s;
            for (double time = t0 + 0.5 * frame_s; time < t0 + 8.0 * tau + 4 * frame_s; time += frame_s) {
                t.push_back(time);
                d.push_back(travel * (1.0 - std::exp(-(std::min(time, stop) - t0) / tau)) + noise(rng));
            }
            for (double s = t0 + 0.25 * frame_s; s < t.back(); s += 0.25 * frame_s)
                stops_s.push_back(s);
            const nb::SettlingFit f = nb::fitSettlingFromOrStop(t, d, t0, frame_s / 3.0, 10.0 * frame_s, 60, stops_s);
            const QString what = QStringLiteral("case %1: tau %2 (drawn %3), stop %4 (drawn %5)")
                                     .arg(i)
                                     .arg(f.tau_s)
                                     .arg(tau)
                                     .arg(f.stop_s - t0)
                                     .arg(stop - t0);
            // τ, where four frames or more show the slowing (two or three fit a range of curves).
            if (stop - t0 >= 4.0 * frame_s)
                QVERIFY2(std::abs(f.tau_s / tau - 1.0) < 0.4, qPrintable(what));
            // Where it ends, and how fast it moves before then.
            QVERIFY2(std::abs(f.at(t.back()) - d.front() - travel * (1.0 - std::exp(-(std::min(stop, t.back()) - t0) / tau))) < 0.05,
                     qPrintable(what));
            if (stops) {
                QVERIFY2(std::abs(f.stop_s - stop) < frame_s, qPrintable(what));
                QCOMPARE(f.speedAt(f.stop_s + 1e-6), 0.0);
                QVERIFY(f.speedAt(f.stop_s - 1e-3) > 0.0);
            } else {
                // Not stopping, or stopping where it has all but settled (the noise in its tail).
                QVERIFY2(!std::isfinite(f.stop_s) || std::abs(f.rest - f.at(f.stop_s)) < 0.05 * travel, qPrintable(what));
            }
            // The fit that may not stop reads the same settling with a shorter τ (it must bend
            // sooner to stay flat after the stop): the stop is what makes τ true.
            if (stops && stop - t0 < 1.5 * tau) {
                const nb::SettlingFit plain = nb::fitSettlingFrom(t, d, t0, frame_s / 3.0, 10.0 * frame_s, 60);
                QVERIFY2(plain.sse > f.sse, qPrintable(what));
            }
        }
    }

    // The grid's search sums each onset's terms from running sums; it must pick what fitting
    // every point of the grid on its own picks, windows and weights as they come.
    void gridPicksWhatEveryPointPicks()
    {
        std::mt19937 rng(nb::test::accuracySeed(552871u));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < 12; ++i) {
            const double frame_s = 1.0 / (u(rng) < 0.5 ? 25.0 : 29.97), t0 = 1.0 + u(rng), tau = 0.02 + 0.3 * u(rng);
            const double v = 30.0 * (u(rng) - 0.5), rest = 20.0 * (u(rng) - 0.5);
            std::normal_distribution<double> noise(0.0, 0.05 + 0.5 * u(rng));
            std::vector<double> t, d, w;
            for (double time = 20.0 + u(rng) * frame_s; time < 20.0 + t0 + 10.0 * tau; time += frame_s) {
                t.push_back(time);
                const double r = time - 20.0;
                d.push_back((r < t0 ? v * (r - t0) : rest * (1.0 - std::exp(-(r - t0) / tau))) + noise(rng));
                w.push_back(u(rng) < 0.1 ? 0.2 * u(rng) : 1.0);
            }
            const double lo = 20.0 + 0.3 * u(rng), hi = t.back() - 0.2 * u(rng) * tau;
            const double from = 20.0 + t0 - 0.1, to = 20.0 + t0 + 0.1, step = 0.004, tauFrom = 0.005, tauTo = 1.0, factor = 1.03;
            const nb::SettlingFit grid = nb::fitSettling(t, d, w, from, to, step, tauFrom, tauTo, factor, lo, hi);
            nb::SettlingFit each;
            for (double o = from; o <= to + 1e-12; o += step)
                for (double k = tauFrom; k <= tauTo * (1 + 1e-9); k *= factor)
                    if (const nb::SettlingFit f = nb::fitSettlingAt(t, d, w, o, k, lo, hi); f.sse < each.sse)
                        each = f;
            QVERIFY(std::isfinite(each.sse));
            QVERIFY2(grid.sse <= each.sse * (1.0 + 1e-9) + 1e-12,
                     qPrintable(QStringLiteral("case %1: sse %2 at t0 %3, tau %4; point by point %5 at t0 %6, tau %7")
                                    .arg(i).arg(grid.sse, 0, 'g', 12).arg(grid.t0_s, 0, 'f', 4).arg(grid.tau_s, 0, 'f', 4)
                                    .arg(each.sse, 0, 'g', 12).arg(each.t0_s, 0, 'f', 4).arg(each.tau_s, 0, 'f', 4)));
            QCOMPARE(grid.t0_s, each.t0_s);
            QCOMPARE(grid.tau_s, each.tau_s);
        }
        // An onset before every sample in the window, or after all of them: one side is empty,
        // nothing is determined, as point by point.
        const std::vector<double> t{1.0, 1.1, 1.2, 1.3}, d{0.0, 1.0, 2.0, 3.0}, w(4, 1.0);
        QVERIFY(!std::isfinite(nb::fitSettling(t, d, w, 2.0, 2.5, 0.1, 0.01, 1.0, 1.1, 0.0, 3.0).sse));
        QVERIFY(!std::isfinite(nb::fitSettling(t, d, w, 0.0, 0.9, 0.1, 0.01, 1.0, 1.1, 0.0, 3.0).sse));
    }

    void nothingToFit()
    {
        const std::vector<double> none;
        QVERIFY(!std::isfinite(nb::fitSettling(none, none, none, 0.0, 1.0, 0.1, 0.01, 1.0, 1.1, 0.0, 1.0).sse));
        QVERIFY(!std::isfinite(nb::fitSettlingFrom(none, none, 0.0, 0.01, 1.0, 10).sse));
        // Every sample at one time: no line and no settling can be told apart.
        const std::vector<double> t(5, 1.0), d{1, 2, 3, 4, 5}, w(5, 1.0);
        QVERIFY(!std::isfinite(nb::fitSettlingFrom(t, d, 0.5, 0.01, 1.0, 10).sse));
        QVERIFY(!std::isfinite(nb::fitSettling(t, d, w, 0.0, 0.5, 0.1, 0.01, 1.0, 1.1, 0.0, 2.0).sse));
    }
};

QTEST_GUILESS_MAIN(TestSettlingFit)
#include "test_settling_fit.moc"
