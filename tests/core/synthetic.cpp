#include "synthetic.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace nb::synthetic {

double Insertion::force(double x) const
{
    const double xs2 = puncture_mm();
    if (x < contact_mm)
        return 0.0;
    if (x <= xs2)
        return StiffnessModel{a1_N_per_mm, a2_N_per_mm2}(x - contact_mm);
    const double surface = xs2 - relaxation_mm;
    double after = cutting_N + friction_N_per_mm * (x - surface);
    for (const InternalPuncture& ip : internal) {
        const double peak = xs2 + ip.depth_mm;
        if (x > peak - 1.0 && x <= peak)
            after += ip.force_N * (x - (peak - 1.0));
    }
    const double peakForce = StiffnessModel{a1_N_per_mm, a2_N_per_mm2}(punctureDepth_mm);
    if (x < xs2 + dropTravel_mm) {
        const double u = (x - xs2) / dropTravel_mm;
        return peakForce + u * (after - peakForce);
    }
    return after;
}

Run makeInsertion(const Insertion& p)
{
    Run run;
    run.metadata.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
    run.metadata.set(QStringLiteral("rate_hz"), p.rate_hz);
    std::mt19937 rng(p.seed);
    std::normal_distribution<double> noise(0.0, p.noise_N);
    const double duration = (p.end_mm - p.start_mm) / p.speed_mm_s;
    const auto n = std::size_t(duration * p.rate_hz) + 1;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / p.rate_hz;
        const double x = p.start_mm + p.speed_mm_s * t;
        run.time_s.push_back(t);
        run.position_mm.push_back(x);
        run.force_N.push_back(p.force(x) + p.offset_N + noise(rng));
    }
    return run;
}

namespace {

struct FrictionSample {
    double t, x_mm, v_m_s, a_m_s2, force;
    bool sticking;
};

std::vector<FrictionSample> frictionSamples(const Friction& p)
{
    std::vector<FrictionSample> out;
    const double w = 2.0 * std::numbers::pi * p.frequency_hz;
    const auto n = std::size_t(p.cycles / p.frequency_hz * p.rate_hz) + 1;
    const double half = p.model.band_m_s / 2.0;
    double applied = 0.0;
    double lastX = 0.0;
    bool wasSticking = false;
    double lastFriction = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / p.rate_hz;
        const double x = p.amplitude_mm * std::sin(w * t);
        const double v = p.amplitude_mm * w * std::cos(w * t) / 1000.0;
        const double a = -p.amplitude_mm * w * w * std::sin(w * t) / 1000.0;
        const bool sticking = std::fabs(v) < half;
        double friction;
        if (sticking) {
            // The tissue moves with the needle and stores force like a stiff spring; the
            // friction can hold it only up to the static limits.
            if (!wasSticking)
                applied = lastFriction;
            applied = std::clamp(applied + p.stickStiffness_N_per_mm * (x - lastX), p.model.Dn_N, p.model.Dp_N);
            friction = p.model(v, applied);
        } else {
            friction = p.model(v, 0.0);
        }
        out.push_back({t, x, v, a, p.mass_kg * a + friction, sticking});
        lastFriction = friction;
        wasSticking = sticking;
        lastX = x;
    }
    return out;
}

}  // namespace

Run makeFriction(const Friction& p)
{
    Run run;
    run.metadata.set(QStringLiteral("protocol"), QStringLiteral("friction"));
    if (p.writeFrequency)
        run.metadata.set(QStringLiteral("frequency_hz"), p.frequency_hz);
    std::mt19937 rng(p.seed);
    std::normal_distribution<double> noise(0.0, p.noise_N);
    std::vector<QString>* phase = p.writePhases ? &run.addTextColumn(QStringLiteral("phase")) : nullptr;
    for (const FrictionSample& s : frictionSamples(p)) {
        run.time_s.push_back(s.t);
        const double x = p.encoderStep_mm > 0.0 ? std::round(s.x_mm / p.encoderStep_mm) * p.encoderStep_mm : s.x_mm;
        run.position_mm.push_back(x);
        run.force_N.push_back(s.force + noise(rng));
        if (phase)
            phase->push_back(s.sticking ? QStringLiteral("a") : QStringLiteral("c"));
    }
    return run;
}

Labels frictionLabels(const Friction& p)
{
    Labels labels;
    const auto samples = frictionSamples(p);
    const double dt = 1.0 / p.rate_hz;
    for (std::size_t i = 0; i < samples.size();) {
        std::size_t j = i;
        while (j + 1 < samples.size() && samples[j + 1].sticking == samples[i].sticking &&
               (samples[j + 1].v_m_s > 0) == (samples[i].v_m_s > 0))
            ++j;
        Label l;
        l.track = samples[i].v_m_s > 0 ? QStringLiteral("insertion") : QStringLiteral("withdrawal");
        l.label = samples[i].sticking ? QStringLiteral("a") : QStringLiteral("c");
        l.start_s = samples[i].t;
        l.end_s = samples[j].t + dt;
        labels.push_back(l);
        i = j + 1;
    }
    return labels;
}

CalibrationData makeCalibration(double slope_V_per_g, double intercept_V, double noise_V, std::uint32_t seed)
{
    CalibrationData d;
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, noise_V);
    for (int m = 0; m <= 850; m += 25) {
        d.mass_g.push_back(m);
        d.voltage_V.push_back(slope_V_per_g * m + intercept_V + noise(rng));
    }
    return d;
}

}  // namespace nb::synthetic
