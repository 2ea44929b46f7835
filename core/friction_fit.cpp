#include "friction_fit.h"

#include "fit_error.h"
#include "signal.h"
#include "statistics.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {


// Samples after a sticking stretch still searched for its break-away force.
constexpr std::size_t kBreakAwaySamples = 2;

struct Extremes {
    double max = -INFINITY, min = INFINITY;
};

}  // namespace

double estimateFrequency(const Run& run)
{
    const std::size_t n = run.size();
    if (n < 4)
        return 0.0;
    const double m = mean(run.position_mm);
    const double s = sampleStdDev(run.position_mm);
    if (!(s > 0.0))
        return 0.0;
    // Hysteresis of a tenth of the spread keeps encoder noise from adding crossings.
    const double h = 0.1 * s;
    int state = 0;
    std::vector<double> crossings;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = run.position_mm[i] - m;
        const int next = x > h ? 1 : x < -h ? -1 : state;
        if (state != 0 && next != state)
            crossings.push_back(run.time_s[i]);
        state = next;
    }
    if (crossings.size() < 2)
        return 0.0;
    const double span = crossings.back() - crossings.front();
    return span > 0.0 ? double(crossings.size() - 1) / 2.0 / span : 0.0;
}

FrictionFit fitFriction(const Run& run, const FrictionOptions& options, const QStringList& givenPhases)
{
    const std::size_t n = run.size();
    if (!(options.thickness_mm > 0.0) || !std::isfinite(options.thickness_mm))
        throw FitError(QCoreApplication::translate("nb::fit", "the tissue thickness must be positive, got %1 mm").arg(options.thickness_mm));
    if (!(options.band_m_s >= 0.0))
        throw FitError(QCoreApplication::translate("nb::fit", "the zero-velocity band must not be negative"));
    const std::size_t trim = std::size_t(std::max(0, options.trimSamples));
    if (n < 2 * trim + 20)
        throw FitError(QCoreApplication::translate("nb::fit", "too few samples (%1) for a friction fit (%2 are trimmed at each end)").arg(n).arg(trim));
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(run.position_mm[i]) || !std::isfinite(run.force_N[i]) || !std::isfinite(run.time_s[i]))
            throw FitError(QCoreApplication::translate("nb::fit", "sample %1 is not a finite number").arg(i + 1));

    QStringList phases = givenPhases;
    if (phases.isEmpty())
        if (const auto* col = run.textColumn(QStringLiteral("phase")))
            phases = QStringList(col->begin(), col->end());
    const bool usePhases =
        qsizetype(n) == phases.size() && std::any_of(phases.begin(), phases.end(), [](const QString& p) { return !p.isEmpty(); });
    if (!phases.isEmpty() && phases.size() != qsizetype(n))
        throw FitError(QCoreApplication::translate("nb::fit", "%1 phase names for %2 samples").arg(phases.size()).arg(n));

    // The thesis's conditioning: smooth, differentiate, smooth again.
    const int w = windowForDuration(run.time_s, options.smoothing_s);
    const std::vector<double> x = movingAverage(run.position_mm, w);
    std::vector<double> v = movingAverage(derivative(run.time_s, x), w);
    for (double& e : v)
        e /= 1000.0;  // mm/s -> m/s
    const std::vector<double> a = movingAverage(derivative(run.time_s, v), w);
    const std::vector<double> f = movingAverage(run.force_N, w);

    const double half = options.band_m_s / 2.0;
    auto sliding = [&](std::size_t i) {
        return std::fabs(v[i]) >= half && v[i] != 0.0 && (!usePhases || phases[qsizetype(i)] == QLatin1String("c"));
    };
    // The smoothed signals mix samples across a stick/slip boundary (the force jumps there
    // from D to C), so only samples whose whole smoothing window slides are used.
    std::vector<std::size_t> notSliding(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        notSliding[i + 1] = notSliding[i] + (sliding(i) ? 0 : 1);
    const std::size_t reach = std::size_t(w / 2 + 1);
    std::vector<std::size_t> rows;
    std::size_t pos = 0, neg = 0;
    for (std::size_t i = trim; i < n - trim; ++i) {
        const std::size_t lo = i >= reach ? i - reach : 0, hi = std::min(n, i + reach + 1);
        if (notSliding[hi] - notSliding[lo] != 0)
            continue;
        rows.push_back(i);
        (v[i] > 0.0 ? pos : neg) += 1;
    }
    if (pos == 0 && neg == 0)
        throw FitError(usePhases ? QCoreApplication::translate("nb::fit", "no phase-c samples moving faster than the zero-velocity band")
                                 : QCoreApplication::translate("nb::fit", "no motion: no sample moves faster than the zero-velocity band (%1 m/s)")
                                       .arg(options.band_m_s));
    if (pos < 3 || neg < 3)
        throw FitError(QCoreApplication::translate("nb::fit", "motion in one direction only (%1 samples moving in, %2 moving out)").arg(pos).arg(neg));

    const int cols = options.estimateMass ? 5 : 4;
    const int off = options.estimateMass ? 1 : 0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(rows.size()), cols);
    Eigen::VectorXd y(Eigen::Index(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::size_t i = rows[r];
        const auto ri = Eigen::Index(r);
        if (options.estimateMass)
            A(ri, 0) = a[i];
        // Rows follow eq. 19/21: [s+, s+·v, s-, s-·v], s- = -1 for v < 0 (F = -Cn + bn·v).
        if (v[i] > 0.0) {
            A(ri, off + 0) = 1.0;
            A(ri, off + 1) = v[i];
        } else {
            A(ri, off + 2) = -1.0;
            A(ri, off + 3) = v[i];
        }
        y(ri) = f[i] - (options.estimateMass ? 0.0 : options.mass_kg * a[i]);
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if (qr.rank() < cols)
        throw FitError(QCoreApplication::translate("nb::fit", "the friction fit is singular (velocity does not vary within a direction)"));
    const Eigen::VectorXd p = qr.solve(y);
    const Eigen::VectorXd res = y - A * p;

    FrictionFit fit;
    const double mass = options.estimateMass ? p(0) : options.mass_kg;
    if (options.estimateMass)
        fit.massEstimate_kg = p(0);
    fit.model.Cp_N = p(off + 0);
    fit.model.bp_Ns_per_m = p(off + 1);
    fit.model.Cn_N = p(off + 2);
    fit.model.bn_Ns_per_m = p(off + 3);
    fit.model.band_m_s = options.band_m_s;
    fit.rms_N = std::sqrt(res.squaredNorm() / double(res.size()));
    fit.positiveSamples = pos;
    fit.negativeSamples = neg;

    // Static friction (models.md sec. 5): D_p is the force at which the tissue lets go when
    // motion starts in the + direction, D_n when it starts in the - direction. So each
    // sticking stretch (phase a, else the zero-velocity band around a turning point) gives
    // its extreme in the direction of the motion that follows it; the other extreme is the
    // force left over from the previous direction, not a static limit. A 3-sample average
    // only: the stretches are short and a wider window would flatten the peaks.
    const std::vector<double> f3 = movingAverage(run.force_N, 3);
    const std::size_t last = n - trim;
    auto sticking = [&](std::size_t i) {
        return usePhases ? phases[qsizetype(i)] == QLatin1String("a") : std::fabs(v[i]) < half;
    };
    std::vector<double> breakawayP, breakawayN;
    for (std::size_t i = trim; i < last;) {
        if (!sticking(i)) {
            ++i;
            continue;
        }
        Extremes e;
        for (; i < last && sticking(i); ++i) {
            const double g = f3[i] - mass * a[i];
            e.max = std::max(e.max, g);
            e.min = std::min(e.min, g);
        }
        // A stretch cut off by the end of the data never reached its break-away.
        if (i == last)
            break;
        // The break-away is the stretch's end: the force there, the extreme, lands on
        // either side of the label boundary (and the 3-sample average needs both sides).
        for (std::size_t j = i; j < std::min(last, i + kBreakAwaySamples); ++j) {
            const double g = f3[j] - mass * a[j];
            e.max = std::max(e.max, g);
            e.min = std::min(e.min, g);
        }
        // The direction that follows: the first sample after the stretch moving clearly.
        std::size_t k = i;
        while (k < last && (std::fabs(v[k]) < half || v[k] == 0.0))
            ++k;
        if (k == last)
            break;
        (v[k] > 0.0 ? breakawayP : breakawayN).push_back(v[k] > 0.0 ? e.max : e.min);
    }
    if (!breakawayP.empty() && !breakawayN.empty()) {
        fit.model.Dp_N = mean(breakawayP);
        fit.model.Dn_N = mean(breakawayN);
        fit.staticSource = usePhases ? QStringLiteral("phase a") : QStringLiteral("velocity band");
    } else {
        fit.staticSource = QStringLiteral("none");
    }

    const double L = options.thickness_mm / 1000.0;
    fit.perLength = {fit.model.Cp_N / L, fit.model.Cn_N / L, fit.model.bp_Ns_per_m / L,
                     fit.model.bn_Ns_per_m / L, fit.model.Dp_N / L,  fit.model.Dn_N / L};
    const auto metaF = run.meta(QStringLiteral("frequency_hz"));
    bool ok = false;
    const double mf = metaF ? metaF->trimmed().toDouble(&ok) : 0.0;
    fit.frequency_hz = ok && mf > 0.0 ? mf : estimateFrequency(run);
    return fit;
}

namespace {

FrictionGroup summarize(std::span<const FrictionFit> fits, std::span<const std::size_t> members)
{
    FrictionGroup g;
    g.runs = members.size();
    auto field = [&](auto get) {
        std::vector<double> vals;
        for (std::size_t k : members)
            vals.push_back(get(fits[k]));
        return std::pair{mean(vals), sampleStdDev(vals)};
    };
    auto set = [&](double KarnoppPerLength::*m) {
        const auto [mu, sd] = field([m](const FrictionFit& f) { return f.perLength.*m; });
        g.mean.*m = mu;
        g.stdDev.*m = sd;
    };
    set(&KarnoppPerLength::Cp_N_per_m);
    set(&KarnoppPerLength::Cn_N_per_m);
    set(&KarnoppPerLength::bp_Ns_per_m2);
    set(&KarnoppPerLength::bn_Ns_per_m2);
    set(&KarnoppPerLength::Dp_N_per_m);
    set(&KarnoppPerLength::Dn_N_per_m);
    g.frequency_hz = field([](const FrictionFit& f) { return f.frequency_hz; }).first;
    std::vector<double> masses;
    for (std::size_t k : members)
        if (fits[k].massEstimate_kg)
            masses.push_back(*fits[k].massEstimate_kg);
    if (!masses.empty()) {
        g.massEstimateMean_kg = mean(masses);
        g.massEstimateStdDev_kg = sampleStdDev(masses);
    }
    return g;
}

}  // namespace

std::vector<FrictionGroup> groupByFrequency(std::span<const FrictionFit> fits)
{
    std::vector<std::size_t> order(fits.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t l, std::size_t r) { return fits[l].frequency_hz < fits[r].frequency_hz; });
    std::vector<FrictionGroup> groups;
    std::vector<std::size_t> members;
    for (std::size_t k : order) {
        if (!members.empty() && fits[k].frequency_hz > 1.05 * fits[members.front()].frequency_hz) {
            groups.push_back(summarize(fits, members));
            members.clear();
        }
        members.push_back(k);
    }
    if (!members.empty())
        groups.push_back(summarize(fits, members));
    return groups;
}

FrictionGroup overall(std::span<const FrictionFit> fits)
{
    std::vector<std::size_t> all(fits.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        all[i] = i;
    FrictionGroup g = summarize(fits, all);
    g.frequency_hz = 0.0;
    return g;
}

}  // namespace nb
