#include "label_suggest.h"

#include "events.h"
#include "friction_fit.h"
#include "models.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

namespace nb {

namespace {

std::vector<double> velocity(const Run& run)
{
    const std::size_t n = run.size();
    std::vector<double> v(n, 0.0);
    if (const auto* col = run.numericColumn(QStringLiteral("velocity_mm_s"))) {
        v = *col;
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
            v[i] = (run.position_mm[b] - run.position_mm[a]) / std::max(1e-9, run.time_s[b] - run.time_s[a]);
        }
    }
    // Light smoothing (about 20 ms) so noise does not make false turning points.
    const double rate = n > 1 ? (n - 1) / std::max(1e-9, run.time_s.back() - run.time_s.front()) : 1.0;
    const int half = std::max(1, int(0.01 * rate));
    std::vector<double> s(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i >= std::size_t(half) ? i - half : 0, b = std::min(n - 1, i + half);
        double sum = 0;
        for (std::size_t k = a; k <= b; ++k)
            sum += v[k];
        s[i] = sum / double(b - a + 1);
    }
    return s;
}

// Half-cycles [start, end) between turning points, with their direction.
struct HalfCycle {
    std::size_t start, end;
    int direction;
};

std::vector<HalfCycle> halfCycles(const std::vector<double>& v, double band)
{
    std::vector<HalfCycle> out;
    int dir = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const int d = v[i] > band / 2 ? 1 : (v[i] < -band / 2 ? -1 : 0);
        if (d == 0 || d == dir)
            continue;
        // The turning point is where the velocity crossed zero before this sample.
        std::size_t turn = i;
        while (turn > start && v[turn - 1] * d > 0)
            --turn;
        if (dir != 0)
            out.push_back({start, turn, dir});
        start = turn;
        dir = d;
    }
    if (dir != 0) {
        std::size_t end = v.size();
        while (end > start + 1 && std::abs(v[end - 1]) < band / 2)
            --end;  // the needle at rest after the last stroke belongs to no phase
        out.push_back({start, end, dir});
    }
    return out;
}

}  // namespace

namespace {

// The sliding lines F = C + b·v of the run (friction_fit.h, its band found in the data, no
// phases used); nullopt when the fit fails.
std::optional<FrictionFit> slidingLines(const Run& run)
{
    try {
        FrictionOptions o;
        o.thickness_mm = run.metadata.number(QStringLiteral("thickness_mm")).value_or(30.0);
        o.estimateBand = true;
        return fitFriction(run, o, QStringList(qsizetype(run.size()), QString()));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace

Labels suggestPhaseLabels(const Run& run, const SuggestOptions& o)
{
    Labels out;
    if (run.size() < 10)
        return out;
    const std::vector<double> v = velocity(run);
    const std::optional<FrictionFit> lines = slidingLines(run);
    const QString source = lines ? QStringLiteral("suggested from force and position")
                                 : QStringLiteral("suggested from position (velocity band)");
    // Force less the needle holder's inertia, lightly smoothed.
    const std::size_t n = run.size();
    std::vector<double> force(n);
    {
        const double rate = n > 1 ? (n - 1) / std::max(1e-9, run.time_s.back() - run.time_s.front()) : 1.0;
        const int half = std::max(1, int(0.01 * rate));
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t a = i >= std::size_t(half) ? i - half : 0, b = std::min(n - 1, i + half);
            double sum = 0;
            for (std::size_t k = a; k <= b; ++k)
                sum += run.force_N[k];
            const double acc = (v[b] - v[a]) / 1000.0 / std::max(1e-9, run.time_s[b] - run.time_s[a]);
            force[i] = sum / double(b - a + 1) - kNeedleHolderMass_kg * acc;
        }
    }
    for (const HalfCycle& h : halfCycles(v, o.zeroBand_mm_s)) {
        if (h.end <= h.start + 4)
            continue;
        const QString track = h.direction > 0 ? QStringLiteral("insertion") : QStringLiteral("withdrawal");
        // Up to where the next half-cycle starts, so that the phases tile the run without gaps.
        const double t0 = run.time_s[h.start], t1 = h.end < run.size() ? run.time_s[h.end] : run.time_s.back();
        std::size_t aEnd = h.start, cStart = h.start, b2Start = h.start;
        if (lines) {
            // c: the force follows the sliding line (relative velocity = needle velocity)
            // from here to the turning point; a: the tissue is carried until it lets go, at
            // the force's peak in the direction of motion; b1/b2: in between, b2 once the gap
            // to the line has closed to a quarter of its largest.
            const KarnoppModel& m = lines->model;
            auto line = [&](std::size_t i) {
                const double vi = v[i] / 1000.0;
                return h.direction > 0 ? m.Cp_N + m.bp_Ns_per_m * vi : -m.Cn_N + m.bn_Ns_per_m * vi;
            };
            const double tolerance = std::max(3.0 * lines->rms_N, 0.05 * std::max(std::abs(m.Cp_N), std::abs(m.Cn_N)));
            // Just before the turning point the needle is slower than the band and the force
            // leaves the line although the tissue still rests: scanned from before that.
            std::size_t last = h.end;
            const double slowest = 1000.0 * lines->bandSlowingDown_m_s / 2.0;
            while (last > h.start + 1 && std::abs(v[last - 1]) < slowest)
                --last;
            // Backwards while the force follows the line; a few stray samples (noise) do not
            // end c, a run of them does.
            // The samples nearest the turning point may still be off the line (a slow needle
            // inside the band): they do not end the search before it has begun.
            cStart = last;
            int off = 0;
            bool onLine = false;
            for (std::size_t i = last; i > h.start; --i) {
                if (std::abs(force[i - 1] - line(i - 1)) <= tolerance) {
                    off = 0;
                    onLine = true;
                    cStart = i - 1;
                } else if (onLine && ++off >= 5) {
                    break;
                }
            }
            if (cStart == last)
                cStart = h.end;
            std::size_t peak = h.start;
            for (std::size_t i = h.start; i < cStart; ++i)
                if (h.direction * force[i] > h.direction * force[peak])
                    peak = i;
            aEnd = cStart > h.start ? peak : h.start;
            double widest = 0.0;
            for (std::size_t i = aEnd; i < cStart; ++i)
                widest = std::max(widest, std::abs(force[i] - line(i)));
            b2Start = cStart;
            while (b2Start > aEnd && std::abs(force[b2Start - 1] - line(b2Start - 1)) <= 0.25 * widest)
                --b2Start;
        } else {
            while (aEnd < h.end && std::abs(v[aEnd]) < o.zeroBand_mm_s / 2)
                ++aEnd;
            const std::size_t len = h.end - h.start;
            std::vector<double> mid(run.force_N.begin() + std::ptrdiff_t(h.start + len * 3 / 10),
                                    run.force_N.begin() + std::ptrdiff_t(h.start + len * 7 / 10));
            std::nth_element(mid.begin(), mid.begin() + std::ptrdiff_t(mid.size() / 2), mid.end());
            const double plateau = mid.empty() ? run.force_N[h.start] : mid[mid.size() / 2];
            const double step = std::abs(run.force_N[h.start] - plateau);
            cStart = aEnd;
            while (cStart < h.end && std::abs(run.force_N[cStart] - plateau) > o.settledFraction * step)
                ++cStart;
            b2Start = aEnd + (cStart - std::min(cStart, aEnd)) / 2;
        }
        cStart = std::min(std::max(cStart, aEnd), h.end - 1);
        b2Start = std::clamp(b2Start, aEnd, cStart);
        const double ta = run.time_s[std::min(aEnd, h.end - 1)], tb = run.time_s[b2Start], tc = run.time_s[cStart];
        if (ta > t0)
            out.push_back({track, QStringLiteral("a"), t0, ta, source});
        if (tb > ta)
            out.push_back({track, QStringLiteral("b1"), ta, tb, source});
        if (tc > tb)
            out.push_back({track, QStringLiteral("b2"), tb, tc, source});
        if (t1 > tc)
            out.push_back({track, QStringLiteral("c"), tc, t1, source});
    }
    return out;
}

Labels suggestEventLabels(const Run& run)
{
    Labels out;
    try {
        const InsertionEvents e = detectEvents(run);
        auto point = [&](const QString& name, double t) {
            out.push_back({QStringLiteral("events"), name, t, t, QStringLiteral("suggested from force (event detection)")});
        };
        point(QStringLiteral("contact"), e.contact.time_s);
        point(QStringLiteral("puncture"), e.puncture.time_s);
        if (e.relaxation)
            point(QStringLiteral("relaxation"), e.relaxation->time_s);
        for (const RunEvent& p : e.internalPunctures)
            point(QStringLiteral("internal puncture"), p.time_s);
    } catch (const std::exception&) {
        // No puncture found (or too few samples): nothing to suggest.
    }
    return out;
}

Labels suggestLabels(const Run& run, const SuggestOptions& options)
{
    const QString protocol = run.metadata.value(QStringLiteral("protocol"), QString());
    if (protocol == QLatin1String("friction"))
        return suggestPhaseLabels(run, options);
    if (!protocol.isEmpty())
        return suggestEventLabels(run);
    // No protocol named: several turning points mean a sinusoid.
    const Labels phases = suggestPhaseLabels(run, options);
    const auto turns = std::count_if(phases.begin(), phases.end(), [](const Label& l) { return l.label == QLatin1String("c"); });
    return turns >= 3 ? phases : suggestEventLabels(run);
}

}  // namespace nb
