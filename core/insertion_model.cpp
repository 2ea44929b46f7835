#include "insertion_model.h"
#include "core/tr.h"

#include "fit_error.h"
#include "signal.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace nb {

Run simulateInsertion(const InsertionModel& model, std::span<const double> time_s, std::span<const double> position_mm)
{
    if (time_s.size() != position_mm.size())
        throw FitError(nb::TrCore::tr("%1 time stamps for %2 positions")
                           .arg(time_s.size())
                           .arg(position_mm.size()));
    Run run;
    run.metadata.set(QStringLiteral("source"), QStringLiteral("insertion model"));
    run.time_s.assign(time_s.begin(), time_s.end());
    run.position_mm.assign(position_mm.begin(), position_mm.end());
    run.force_N.resize(time_s.size());
    const std::vector<double> v_mm_s = derivative(time_s, position_mm);
    const double puncture = model.puncture_mm();
    const double surface = model.surfaceAfterPuncture_mm();
    bool punctured = false;
    for (std::size_t i = 0; i < time_s.size(); ++i) {
        const double x = position_mm[i];
        const double v = v_mm_s[i] / 1000.0;
        // Eq. 7: stiffness alone until the capsule gives way, then cutting plus friction
        // over the needle length in tissue; once punctured it stays punctured (t >= t_p).
        if (!punctured && x > puncture)
            punctured = true;
        double f = 0.0;
        if (!punctured) {
            f = model.stiffness(x - model.contact_mm);
        } else {
            const double inTissue_m = std::max(0.0, x - surface) / 1000.0;
            const KarnoppModel friction = model.friction.forLength(inTissue_m, model.band_m_s);
            // Inside the band the needle sticks: with no other modelled force, stiction holds 0.
            f = model.cutting(true, x, surface, v) + friction(v, 0.0);
        }
        run.force_N[i] = f;
    }
    return run;
}

double rmsDistance(const Run& simulated, const Run& recorded)
{
    if (simulated.size() < 2 || recorded.size() < 1)
        throw FitError(nb::TrCore::tr("the runs to compare are empty"));
    const auto& ts = simulated.time_s;
    double sum = 0.0;
    std::size_t count = 0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < recorded.size(); ++i) {
        const double t = recorded.time_s[i];
        if (t < ts.front() || t > ts.back())
            continue;
        while (j + 2 < ts.size() && ts[j + 1] < t)
            ++j;
        const double dt = ts[j + 1] - ts[j];
        const double u = dt > 0.0 ? std::clamp((t - ts[j]) / dt, 0.0, 1.0) : 0.0;
        const double model = simulated.force_N[j] + u * (simulated.force_N[j + 1] - simulated.force_N[j]);
        const double r = recorded.force_N[i] - model;
        sum += r * r;
        ++count;
    }
    if (count == 0)
        throw FitError(nb::TrCore::tr("the simulated and recorded runs do not overlap in time"));
    return std::sqrt(sum / double(count));
}

}  // namespace nb
