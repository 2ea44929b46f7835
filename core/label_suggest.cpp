#include "label_suggest.h"
#include "phase_reading.h"

#include "events.h"
#include "models.h"
#include "tr.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

namespace nb {

using namespace phase_reading;

namespace {

// The needle settling back by more than this after its last stroke counts as a reversal
// (a few encoder counts: the thesis's stage resolves 1.5 µm).
constexpr double kSettleBack_mm = 0.01;

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

}  // namespace

Labels suggestPhaseLabels(const Run& run, const SuggestOptions& o)
{
    return suggestPhaseLabels(run, nullptr, o);
}

Labels suggestPhaseLabels(const Run& run, const TissueMotion* tissue, const SuggestOptions& o)
{
    Labels out;
    if (run.size() < 10)
        return out;
    const std::vector<double> v = velocity(run);
    double fastest = 0.0;
    for (double x : v)
        fastest = std::max(fastest, std::abs(x));
    const double videoNoise_mm_s = pictureNoise_mm_s(tissue);
    const PictureView picture{tissue, videoNoise_mm_s,
                              tissue && tissue->time_s.size() > 1
                                  ? 0.5 * (tissue->time_s.back() - tissue->time_s.front()) / double(tissue->time_s.size() - 1)
                                  : 0.0,
                              tissue && pictureTrusted(run, tissue, videoNoise_mm_s, o),
                              tissue ? QStringLiteral("suggested from the tissue's motion in %1 (timed by force and position)").arg(tissue->source)
                                     : QString()};
    const std::size_t n = run.size();
    const double rate = (n - 1) / std::max(1e-9, run.time_s.back() - run.time_s.front());
    const int half = std::max(1, int(0.01 * rate));
    const std::vector<double> force = forceLessHolder(run, v, half);
    const PhaseLines phaseLinesOfRun = phaseLines(run, force, v, fastest, rate, half);
    const std::optional<FrictionFit>& lines = phaseLinesOfRun.fit;
    const ForceReading reading{run, v, force, half, rate, phaseLinesOfRun};
    const QString forceSource = lines ? QStringLiteral("suggested from force and position")
                                      : QStringLiteral("suggested from position (velocity band)");
    // A stroke slower than the thesis's band (±1 mm at 0.4 Hz tops at 2.5 mm/s) still turns:
    // its turning points are found within half its top speed, not lost in one long label.
    const std::vector<HalfCycle> cycles = halfCycles(v, std::min(o.zeroBand_mm_s, 0.5 * fastest));
    // No sliding anywhere (the force the same going in and out at each depth): the slab was
    // carried by the needle all along, whatever lines the force's noise lets be drawn.
    const bool carried = carriedThroughout(run, v);
    const QString carriedSource = QStringLiteral("suggested from force and position (no friction between directions: the tissue moved with the needle)");
    // A stroke far shorter than the run's usual one is the stage settling (an overshoot when it
    // stops), not a stroke: the tissue cannot break away in it and stays carried (a).
    auto travel_mm = [&](const HalfCycle& h) { return std::abs(run.position_mm[h.end - 1] - run.position_mm[h.start]); };
    double usualTravel_mm = 0.0;
    {
        std::vector<double> travels;
        for (const HalfCycle& h : cycles)
            if (h.end > h.start + 4)
                travels.push_back(travel_mm(h));
        if (!travels.empty()) {
            std::nth_element(travels.begin(), travels.begin() + std::ptrdiff_t(travels.size() / 2), travels.end());
            usualTravel_mm = travels[travels.size() / 2];
        }
    }
    std::vector<const HalfCycle*> strokes;
    for (const HalfCycle& h : cycles)
        if (h.end > h.start + 4)
            strokes.push_back(&h);
    const bool firstCarried = lines && firstStrokeCarried(run, force, v, strokes, *lines);
    const HalfCycle* lastStroke = strokes.empty() ? nullptr : strokes.back();
    for (const HalfCycle* stroke : strokes) {
        const HalfCycle& h = *stroke;
        const QString track = h.direction > 0 ? QStringLiteral("insertion") : QStringLiteral("withdrawal");
        // Up to where the next half-cycle starts, so that the phases tile the run without gaps.
        const double t0 = run.time_s[h.start], t1 = h.end < run.size() ? run.time_s[h.end] : run.time_s.back();
        const bool neverReleased = firstCarried && stroke == strokes.front();
        if (travel_mm(h) < 0.1 * usualTravel_mm || carried || (neverReleased && !tissue)) {
            out.push_back({track, QStringLiteral("a"), t0, t1, carried ? carriedSource : forceSource});
            continue;
        }
        // The first stroke that never released the tissue, a stroke the tissue stayed stuck through
        // into the turning point (pressed on the plate and taken back), and a direction that never
        // slid are carried throughout as the force reads them; a trusted picture may still say
        // otherwise.
        const HalfCycle* next = &h + 1 < cycles.data() + cycles.size() ? &h + 1 : nullptr;
        const bool stuck = next && stuckThroughTurn(run, force, h, *next, phaseLinesOfRun.noise_N);
        StrokeBounds b = neverReleased || stuck || phaseLinesOfRun.neverSlid[h.direction > 0 ? 0 : 1] ? StrokeBounds{h.end, h.end, h.end, {}}
                                                                                                      : boundsFromForce(h, reading, o);
        const QString source = tissue ? placeByPicture(h, t0, t1, b, picture, reading, forceSource, o) : forceSource;
        if (b.aEnd >= h.end) {
            out.push_back({track, QStringLiteral("a"), t0, t1, source});
            continue;
        }
        b.cStart = std::min(std::max(b.cStart, b.aEnd), h.end - 1);
        b.b2Start = std::clamp(b.b2Start, b.aEnd, b.cStart);
        const double ta = run.time_s[std::min(b.aEnd, h.end - 1)], tb = run.time_s[b.b2Start], tc = run.time_s[b.cStart];
        if (ta > t0)
            out.push_back({track, QStringLiteral("a"), t0, ta, source});
        if (tb > ta)
            out.push_back({track, QStringLiteral("b1"), ta, tb, source});
        if (tb < tc)
            out.push_back({track, QStringLiteral("b2"), tb, tc, source});
        if (t1 > tc)
            out.push_back({track, QStringLiteral("c"), tc, t1, source});
    }
    // After the last stroke the needle comes to rest. When it settles back from its last
    // extreme, that is one more turning point and the tissue it holds is carried (a) to the
    // end; otherwise the tissue stays at rest (c).
    if (lastStroke && lastStroke->end < n) {
        const HalfCycle& h = *lastStroke;
        std::size_t extreme = h.start;
        for (std::size_t i = h.start; i < n; ++i)
            if (h.direction * run.position_mm[i] > h.direction * run.position_mm[extreme])
                extreme = i;
        const double back_mm = h.direction * (run.position_mm[extreme] - run.position_mm[n - 1]);
        Label& lastLabel = out.back();
        const double tx = run.time_s[extreme];
        if (back_mm > kSettleBack_mm && tx > lastLabel.start_s && lastLabel.label != QLatin1String("a")) {
            lastLabel.end_s = std::min(lastLabel.end_s, tx);
            const QString track = h.direction > 0 ? QStringLiteral("withdrawal") : QStringLiteral("insertion");
            out.push_back({track, QStringLiteral("a"), lastLabel.end_s, run.time_s.back(), lastLabel.comment});
        } else {
            lastLabel.end_s = run.time_s.back();
        }
    }
    return out;
}

Labels suggestEventLabels(const Run& run) { return suggestEventLabels(run, {}); }

Labels suggestEventLabels(const Run& run, const std::vector<SurfaceTrace>& surfaces, QString* relaxationProblem)
{
    Labels out;
    try {
        const InsertionEvents e = detectEvents(run);
        auto point = [&](const QString& name, double t, const QString& comment) {
            out.push_back({QStringLiteral("events"), name, t, t, comment});
        };
        const QString fromForce = QStringLiteral("suggested from force (event detection)");
        point(QStringLiteral("contact"), e.contact.time_s, fromForce);
        point(QStringLiteral("puncture"), e.puncture.time_s, fromForce);
        // Relaxation only from the picture: the tissue's surface springing back after the
        // puncture (to x_s3, models.md 4) takes a few tenths of a second, and the force does
        // not show when it is done (the end of its drop, a few milliseconds after the
        // puncture, is not it). Its duration comes from the video; it is counted from the
        // force's puncture, so that the clocks' residual offset does not enter.
        const SurfaceTrace* best = nullptr;
        std::optional<SpringBack> fit;
        QStringList problems;
        for (const SurfaceTrace& surface : surfaces) {
            QString problem;
            const std::optional<SpringBack> s = fitSpringBack(surface, e.puncture.time_s, e.contact.time_s, &problem);
            if (!s)
                problems << (surface.source.isEmpty() ? problem : surface.source + QStringLiteral(": ") + problem);
            // A trace that loses the surface reads its motion short: the larger spring-back wins.
            else if (!fit || s->amplitude_px > fit->amplitude_px)
                fit = s, best = &surface;
        }
        if (fit)
            point(QStringLiteral("relaxation"), fit->relaxed_s,
                  QStringLiteral("suggested from the surface's spring-back in %1 (4 tau after the puncture, tau %2 s, %3 px)")
                      .arg(best->source)
                      .arg(fit->tau_s, 0, 'f', 3)
                      .arg(fit->amplitude_px, 0, 'f', 1));
        else if (relaxationProblem && !surfaces.empty())
            *relaxationProblem = problems.join(QStringLiteral("; "));
        for (const RunEvent& p : e.internalPunctures)
            point(QStringLiteral("internal puncture"), p.time_s, fromForce);
        std::stable_sort(out.begin(), out.end(), [](const Label& a, const Label& b) { return a.start_s < b.start_s; });
    } catch (const std::exception&) {
        // No puncture found (or too few samples): nothing to suggest.
        if (!surfaces.empty() && relaxationProblem)
            *relaxationProblem = nb::TrCore::tr("no puncture found in the force");
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
