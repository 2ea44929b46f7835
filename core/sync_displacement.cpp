// Synchronisation on the needle's tracked displacement (sync.h).
#include "sync.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace nb {

namespace {

struct Points {
    std::vector<double> t, d;
};

// Linear in between; outside the recording the rig rests at its first and last position.
double positionAt(const TimeSignal& p, double t)
{
    const auto& ts = p.time_s;
    if (t <= ts.front())
        return p.value.front();
    if (t >= ts.back())
        return p.value.back();
    // The first sample after t. A recording is sampled at a steady rate, so its place is
    // nearly where the rate puts it: a few steps from there, and a search only when it is not
    // (the sync asks this some millions of times; a search from the ends was a tenth of its time).
    const std::size_t last = ts.size() - 1;
    const double guess = (t - ts.front()) / (ts.back() - ts.front()) * double(last);
    std::size_t i = guess >= double(last) ? last : guess >= 1.0 ? std::size_t(guess) : 1;
    for (int step = 0; step < 8 && ts[i] <= t; ++step)
        ++i;
    for (int step = 0; step < 8 && ts[i - 1] > t; ++step)
        --i;
    if (ts[i] <= t || ts[i - 1] > t)
        i = std::size_t(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
    const double w = (t - ts[i - 1]) / std::max(1e-12, ts[i] - ts[i - 1]);
    return p.value[i - 1] + w * (p.value[i] - p.value[i - 1]);
}

struct Fit {
    double r2 = 0.0, slope = 0.0, intercept = 0.0, residual = 0.0;
    int n = 0;
};

// The sums a straight line y ≈ intercept + slope · x is fitted from.
struct LineSums {
    double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    void add(double x, double y)
    {
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
    }
    // About the means: Σ(x − x̄)(y − ȳ), Σ(x − x̄)², Σ(y − ȳ)².
    double cov() const { return n > 0 ? sxy - sx * sy / n : 0.0; }
    double vx() const { return n > 0 ? sxx - sx * sx / n : 0.0; }
    double vy() const { return n > 0 ? syy - sy * sy / n : 0.0; }
};

// d ≈ intercept + slope · position(recording time of each video point).
Fit fitAt(const Points& v, const TimeSignal& pos, double offset, double drift, std::size_t from, std::size_t to,
          std::size_t stride = 1)
{
    LineSums s;
    for (std::size_t i = from; i < to; i += stride)
        s.add(positionAt(pos, (v.t[i] - offset) / (1.0 + drift)), v.d[i]);
    Fit f;
    f.n = int(s.n);
    if (f.n < 3)
        return f;
    const double cov = s.cov(), vx = s.vx(), vy = s.vy();
    if (vx <= 0 || vy <= 0)
        return f;
    f.r2 = cov * cov / (vx * vy);
    f.slope = cov / vx;
    f.intercept = (s.sy - f.slope * s.sx) / s.n;
    f.residual = std::sqrt(std::max(0.0, (vy - f.slope * cov) / std::max(1, f.n - 2)));
    return f;
}

// The drift's standard error as the motion's own events can give it. Along a steady stroke a
// drift only tilts the line the scale fit takes up; it is seen at the events (onset, stop,
// turning points), each timed to about what one reading is off (the fit's residual over the
// tip's speed in pixels a second: a tracker reads the tip up to a pixel ahead along one
// stretch of the picture and behind along another, whatever the frame rate), and k events
// over a span T time the clock's rate to √2·σ/(T·√(k/2)).
double driftStandardError(const Points& v, const TimeSignal& pos, double offset, double drift, double slope_px_per_mm,
                          double residual_px)
{
    double sum2 = 0.0, first = 0.0, last = 0.0;
    int moving = 0, turns = 0, sign = 0;
    for (std::size_t i = 1; i < v.t.size(); ++i) {
        const double t0 = (v.t[i - 1] - offset) / (1.0 + drift), t1 = (v.t[i] - offset) / (1.0 + drift);
        if (!(t1 > t0))
            continue;
        const double speed_mm_s = (positionAt(pos, t1) - positionAt(pos, t0)) / (t1 - t0);
        if (std::abs(speed_mm_s) < 0.05)
            continue;
        const int now = speed_mm_s > 0 ? 1 : -1;
        turns += sign != 0 && now != sign;
        sign = now;
        if (moving++ == 0)
            first = t0;
        last = t1;
        sum2 += speed_mm_s * speed_mm_s;
    }
    const double speed_px_s = moving > 0 ? std::abs(slope_px_per_mm) * std::sqrt(sum2 / moving) : 0.0;
    if (!(speed_px_s > 0.0) || !(last > first))
        return 1.0;
    const double events = 2.0 + turns, eventSigma_s = residual_px / speed_px_s;
    return std::sqrt(2.0) * eventSigma_s / ((last - first) * std::sqrt(events / 2.0));
}

// The offset in [centre − half, centre + half] with the best fit, to `step` and then to a
// fraction of it (parabola through the best three).
std::pair<double, double> bestOffset(const Points& v, const TimeSignal& pos, double drift, double centre, double half,
                                     double step, std::size_t from, std::size_t to, std::size_t stride = 1)
{
    std::vector<double> offs, r2s;
    for (double o = centre - half; o <= centre + half + 1e-12; o += step) {
        offs.push_back(o);
        r2s.push_back(fitAt(v, pos, o, drift, from, to, stride).r2);
    }
    const std::size_t k = std::size_t(std::max_element(r2s.begin(), r2s.end()) - r2s.begin());
    double o = offs[k];
    if (k > 0 && k + 1 < offs.size()) {
        const double a = r2s[k - 1], b = r2s[k], c = r2s[k + 1], den = a - 2 * b + c;
        if (std::abs(den) > 1e-15)
            o += std::clamp(0.5 * (a - c) / den, -0.5, 0.5) * step;
    }
    return {o, r2s[k]};
}

// Like bestOffset, but with the scale and intercept of the whole fit held: a stretch of
// steady motion then still pins the offset (with both free it fits any shift).
double bestOffsetHeld(const Points& v, const TimeSignal& pos, double drift, double centre, double half, double step,
                      std::size_t from, std::size_t to, double slope, double intercept)
{
    std::vector<double> offs, rss;
    for (double o = centre - half; o <= centre + half + 1e-12; o += step) {
        double sum = 0.0;
        for (std::size_t i = from; i < to; ++i) {
            const double e = v.d[i] - intercept - slope * positionAt(pos, (v.t[i] - o) / (1.0 + drift));
            sum += e * e;
        }
        offs.push_back(o);
        rss.push_back(sum);
    }
    const std::size_t k = std::size_t(std::min_element(rss.begin(), rss.end()) - rss.begin());
    double o = offs[k];
    if (k > 0 && k + 1 < offs.size()) {
        const double a = rss[k - 1], b = rss[k], c = rss[k + 1], den = a - 2 * b + c;
        if (std::abs(den) > 1e-15)
            o += std::clamp(0.5 * (a - c) / den, -0.5, 0.5) * step;
    }
    return o;
}

// Which way the rig moves at each video point's recording time: +1, -1, or 0 where it rests
// or turns (slower than a twentieth of its fastest, over a tenth of a second either side).
std::vector<int> directions(const Points& v, const TimeSignal& pos, double offset, double drift)
{
    auto speed = [&](double t) { return (positionAt(pos, t + 0.1) - positionAt(pos, t - 0.1)) / 0.2; };
    std::vector<double> at(v.t.size());
    double fastest = 0.0;
    for (std::size_t i = 0; i < v.t.size(); ++i) {
        at[i] = speed((v.t[i] - offset) / (1.0 + drift));
        fastest = std::max(fastest, std::abs(at[i]));
    }
    std::vector<int> out(v.t.size(), 0);
    for (std::size_t i = 0; i < v.t.size(); ++i)
        if (std::abs(at[i]) > 0.05 * fastest)
            out[i] = at[i] > 0 ? 1 : -1;
    return out;
}

// The sum of squares left by d ≈ intercept(way) + slope · position, with an intercept of its
// own for each way the rig moves and for rest (directions() at this offset), over every
// `stride`th video point.
double residualByDirection(const Points& v, const TimeSignal& pos, double offset, double drift, std::size_t stride = 1)
{
    const std::vector<int> ways = directions(v, pos, offset, drift);
    LineSums by[3];
    for (std::size_t i = 0; i < v.t.size(); i += stride)
        by[ways[i] + 1].add(positionAt(pos, (v.t[i] - offset) / (1.0 + drift)), v.d[i]);
    double cov = 0.0, vx = 0.0, vy = 0.0;
    for (const LineSums& s : by) {
        cov += s.cov();
        vx += s.vx();
        vy += s.vy();
    }
    return vx > 0 ? vy - cov * cov / vx : vy;
}

// The offset within ±`half` of `centre` at which the fit by way leaves least, and what it
// leaves there over every point: in steps of 5·`step` over a stride of the points (about 800)
// first, then in steps of `step` over all of them, within 5·`step` of the best (as the offset's
// own search goes from coarse to fine: every point at every step is an hour's video times 300).
std::pair<double, double> bestOffsetByDirection(const Points& v, const TimeSignal& pos, double drift, double centre,
                                                double half, double step)
{
    const std::size_t stride = std::max<std::size_t>(1, v.t.size() / 800);
    auto search = [&](double from, double to, double by, std::size_t every) {
        std::pair<double, double> best{centre, residualByDirection(v, pos, centre, drift, every)};
        for (double off = from; off <= to + 1e-12; off += by)
            if (const double left = residualByDirection(v, pos, off, drift, every); left < best.second)
                best = {off, left};
        return best;
    };
    const double coarse = 5 * step;
    const double near = search(centre - half, centre + half, coarse, stride).first;
    return search(near - coarse, near + coarse, step, 1);
}

// When the signal first leaves its resting value `base` by a tenth of its range; nullopt
// when it does not rest at the start (its first `rest_s` already span a twentieth of it).
std::optional<double> onsetFrom(const std::vector<double>& t, const std::vector<double>& x, double base, double rest_s)
{
    if (t.size() < 5)
        return std::nullopt;
    std::vector<double> sorted = x;
    std::sort(sorted.begin(), sorted.end());
    const double range = sorted[sorted.size() * 98 / 100] - sorted[sorted.size() * 2 / 100];
    if (!(range > 0))
        return std::nullopt;
    double restLo = base, restHi = base;
    for (std::size_t i = 0; i < t.size() && t[i] - t.front() <= rest_s; ++i) {
        restLo = std::min(restLo, x[i]);
        restHi = std::max(restHi, x[i]);
    }
    if (rest_s > 0 && restHi - restLo > 0.05 * range)
        return std::nullopt;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (std::abs(x[i] - base) > 0.1 * range)
            return t[i];
    return std::nullopt;
}

double medianOf(std::vector<double> v)
{
    if (v.empty())
        return 0.0;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

TimeSignal needlePosition(const Run& run) { return {run.time_s, run.position_mm}; }

TimeSignal trackedPosition(const TimeSignal& video, const SyncResult& fit, const TimelineMapping& mapping)
{
    TimeSignal out;
    if (fit.scale_px_per_mm == 0.0 || !std::isfinite(fit.scale_px_per_mm))
        return out;
    const std::size_t n = std::min(video.time_s.size(), video.value.size());
    out.time_s.reserve(n);
    out.value.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        out.time_s.push_back(mapping.toRecording(video.time_s[i]));
        out.value.push_back((video.value[i] - fit.intercept_px) / fit.scale_px_per_mm);
    }
    return out;
}

SyncResult synchroniseDisplacement(const TimeSignal& video, const TimeSignal& position, double frame_s,
                                   const SyncOptions& o)
{
    Points v;
    for (std::size_t i = 0; i < video.time_s.size() && i < video.value.size(); ++i)
        if (std::isfinite(video.value[i]) && std::isfinite(video.time_s[i])) {
            v.t.push_back(video.time_s[i]);
            v.d.push_back(video.value[i]);
        }
    TimeSignal pos;
    for (std::size_t i = 0; i < position.time_s.size() && i < position.value.size(); ++i)
        if (std::isfinite(position.value[i]) && std::isfinite(position.time_s[i])) {
            pos.time_s.push_back(position.time_s[i]);
            pos.value.push_back(position.value[i]);
        }
    if (v.t.size() < 20 || pos.time_s.size() < 10)
        throw std::invalid_argument("too few samples to synchronise");
    const auto [pmin, pmax] = std::minmax_element(pos.value.begin(), pos.value.end());
    if (!(*pmax - *pmin > 0))
        throw std::invalid_argument("the recorded position does not change");
    frame_s = std::clamp(frame_s > 0 ? frame_s : 1.0 / 30.0, 1e-3, 1.0);
    const std::size_t n = v.t.size();

    SyncResult r;
    r.method = QStringLiteral("needle displacement along its axis vs recorded position");
    // Onsets: the rig rests at its first position before the recording.
    double videoRest = 0.0;
    {
        std::vector<double> restD;
        for (std::size_t i = 0; i < n && v.t[i] - v.t.front() <= 0.5; ++i)
            restD.push_back(v.d[i]);
        videoRest = medianOf(restD);
        const auto a = onsetFrom(v.t, v.d, videoRest, 0.5);
        const auto b = onsetFrom(pos.time_s, pos.value, pos.value.front(), 0.0);
        if (a && b)
            r.onsetOffset_s = *a - *b;
    }

    // Coarse: every half frame (at most 20 ms), drift 0, on at most ~800 points.
    const double coarse = std::min(0.02, frame_s / 2);
    const std::size_t stride = std::max<std::size_t>(1, n / 800);
    std::vector<double> offs, r2s;
    for (double off = -o.maxOffset_s; off <= o.maxOffset_s + 1e-9; off += coarse) {
        offs.push_back(off);
        r2s.push_back(fitAt(v, pos, off, 0.0, 0, n, stride).r2);
    }
    for (std::size_t i = 0; i < offs.size(); i += std::max<std::size_t>(1, offs.size() / 600))
        r.curve.emplace_back(offs[i], std::sqrt(r2s[i]));
    // Local maxima, best first.
    std::vector<std::size_t> peaks;
    const int w = std::max(1, int(0.1 / coarse));
    for (std::size_t i = 0; i < offs.size(); ++i) {
        bool isMax = true;
        for (int j = -w; j <= w && isMax; ++j) {
            const long k = long(i) + j;
            if (j != 0 && k >= 0 && k < long(offs.size()) && r2s[std::size_t(k)] > r2s[i])
                isMax = false;
        }
        if (isMax)
            peaks.push_back(i);
    }
    std::sort(peaks.begin(), peaks.end(), [&](std::size_t a, std::size_t b) { return r2s[a] > r2s[b]; });
    if (peaks.empty() || r2s[peaks.front()] <= 0)
        throw std::invalid_argument("the video's displacement does not follow the recorded position");

    // Refine the best few peaks: drift and offset together. The offset is searched around
    // the coarse peak moved by the drift at the middle of the video, where the coarse scan
    // (drift 0) matched best.
    const double videoMid = 0.5 * (v.t.front() + v.t.back());
    struct Refined {
        double offset, drift, r2;
    };
    std::vector<Refined> refined;
    for (std::size_t p = 0; p < peaks.size() && p < 4; ++p) {
        if (r2s[peaks[p]] < r2s[peaks.front()] - 0.1)
            break;
        const double o0 = offs[peaks[p]];
        const double recMid = videoMid - o0;
        Refined best{o0, 0.0, -1.0};
        auto tryDrift = [&](double drift) {
            const double centre = o0 - drift * recMid;
            const auto [off, r2] = bestOffset(v, pos, drift, centre, 2 * coarse, frame_s / 20, 0, n, std::max<std::size_t>(1, stride / 2));
            if (r2 > best.r2)
                best = {off, drift, r2};
        };
        const double dStep = std::max(o.maxDrift / 10, 1e-5);
        for (double d = -o.maxDrift; d <= o.maxDrift + 1e-12; d += dStep)
            tryDrift(d);
        const double d0 = best.drift;
        for (double d = d0 - dStep; d <= d0 + dStep + 1e-12; d += dStep / 10)
            tryDrift(d);
        // Last: every point, offset to a fiftieth of a frame.
        const auto [off, r2] = bestOffset(v, pos, best.drift, best.offset, frame_s / 10, frame_s / 50, 0, n);
        // The clocks agree unless the picture shows otherwise. A drift is seen only between
        // two moments the motion marks (an onset and a stop, turning points); over a single
        // steady stroke, stretching time only tilts the line the scale fit takes up, and the
        // search would keep whichever drift the noise favours. So the drift found stands only
        // where it explains the picture better than none by more than its noise allows (a
        // likelihood ratio above 3 standard deviations, one independent reading per frame)
        // and where the motion's events time it (3 standard errors from none: counting every
        // frame as independent, a single 4.7 s stroke read with a bias gave +0.55 % for a true
        // −0.13 %, 1.1 frames off at its end at confidence 0.85).
        if (best.drift != 0.0) {
            const auto [offZero, r2Zero] = bestOffset(v, pos, 0.0, o0, 2 * coarse, frame_s / 50, 0, n);
            const Fit f = fitAt(v, pos, off, best.drift, 0, n);
            if (double(n) * (r2 - r2Zero) / std::max(1e-12, 1.0 - r2) < 9.0
                || std::abs(best.drift) < 3.0 * driftStandardError(v, pos, off, best.drift, f.slope, f.residual)) {
                refined.push_back({offZero, 0.0, r2Zero});
                continue;
            }
        }
        refined.push_back({off, best.drift, r2});
    }
    std::sort(refined.begin(), refined.end(), [](const Refined& a, const Refined& b) { return a.r2 > b.r2; });
    // Near-equal peaks (a repeating motion): the one the onsets point to.
    Refined chosen = refined.front();
    if (o.anchorOnOnset && r.onsetOffset_s && std::abs(*r.onsetOffset_s) <= o.maxOffset_s + 1.0) {
        double bestDist = std::abs(chosen.offset - *r.onsetOffset_s);
        for (const Refined& c : refined)
            if (c.r2 >= refined.front().r2 - 0.01 && std::abs(c.offset - *r.onsetOffset_s) < bestDist) {
                bestDist = std::abs(c.offset - *r.onsetOffset_s);
                chosen = c;
            }
    }
    // A video that starts while the needle moves slowly (near a turning point) looks at
    // rest at first: its "onset" is no onset. It is one only when the picture's resting
    // place is where the fit puts the rig's resting position.
    if (r.onsetOffset_s) {
        const Fit f = fitAt(v, pos, chosen.offset, chosen.drift, 0, n);
        const auto [dmin, dmax] = std::minmax_element(v.d.begin(), v.d.end());
        if (std::abs(videoRest - (f.intercept + f.slope * pos.value.front())) > 0.05 * (*dmax - *dmin)) {
            r.onsetOffset_s.reset();
            chosen = refined.front();
        }
    }
    const Fit fit = fitAt(v, pos, chosen.offset, chosen.drift, 0, n);
    r.offset_s = chosen.offset;
    r.drift = chosen.drift;
    r.correlation = fit.slope >= 0 ? std::sqrt(fit.r2) : -std::sqrt(fit.r2);
    r.scale_px_per_mm = fit.slope;
    r.intercept_px = fit.intercept;
    r.pairs = fit.n;

    // How precise: the fit's noise against what a shift in time changes in the picture, and
    // the two halves of the motion (split where half of the travel is done) fitted apart.
    // What a shift changes is the signal's slope at each frame, less what the fit's free scale
    // and intercept take up: a steady stroke shifted in time is the same stroke at another
    // intercept, and only its ends (onset, stop, turns) time it. Counted whole, every frame of
    // a slow stroke timed the offset (probe seed 314159 case 1: a stroke whose start the video
    // missed, timed by its stop alone, claimed 0.29 frames and was 1.8 off at confidence 0.71;
    // what the free intercept and scale leave is a seventh of it).
    double travel = 0.0, sa = 0.0, saa = 0.0, sax = 0.0, sx = 0.0, sxx = 0.0, speeds = 0.0;
    std::vector<double> cumulative(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double tr = (v.t[i] - chosen.offset) / (1 + chosen.drift);
        const double h = 0.5 * frame_s;
        const double dxdt = fit.slope * (positionAt(pos, tr + h) - positionAt(pos, tr - h)) / (2 * h);
        const double x = positionAt(pos, tr);
        speeds += std::abs(dxdt);
        sa += dxdt;
        saa += dxdt * dxdt;
        sax += dxdt * x;
        sx += x;
        sxx += x * x;
        if (i > 0)
            travel += std::abs(x - positionAt(pos, (v.t[i - 1] - chosen.offset) / (1 + chosen.drift)));
        cumulative[i] = travel;
    }
    // The slopes' sum of squares less their projection on (1, position).
    const double det = double(n) * sxx - sx * sx;
    const double taken = det > 0 ? (sxx * sa * sa - 2.0 * sx * sa * sax + double(n) * sax * sax) / det : 0.0;
    const double shiftSeen = saa - taken;
    const double fitSigma_s = shiftSeen > 1e-12 * saa && saa > 0 ? fit.residual / std::sqrt(shiftSeen) : 1e9;
    std::size_t split = 0;
    while (split < n && cumulative[split] < 0.5 * travel)
        ++split;
    double halves_s = 1e9;
    if (split >= 10 && n - split >= 10) {
        const double a = bestOffsetHeld(v, pos, chosen.drift, chosen.offset, 3 * frame_s, frame_s / 20, 0, split, fit.slope, fit.intercept);
        const double b = bestOffsetHeld(v, pos, chosen.drift, chosen.offset, 3 * frame_s, frame_s / 20, split, n, fit.slope, fit.intercept);
        halves_s = std::abs(a - b);
    }
    r.uncertainty_s = std::max(3.0 * fitSigma_s, 0.5 * halves_s);
    // A tracker may read a moving tip a fraction of a pixel off along its motion, ahead of it
    // one way and behind it the other; over a slow motion back and forth that reads as a shift
    // in time that neither the fit's noise nor its halves show (a sine of 0.12 Hz and ±10 px
    // read 0.27 px off each way: 1.15 frames late, claimed 0.46 frames, confidence 0.54). A fit
    // with an intercept of its own for each way the rig moves (and for rest) would place the
    // offset elsewhere; which of the two is right, the picture does not say (over nineteen
    // slow sines of a faint needle the fit by way was the nearer in 7 and the farther in 12).
    // Where the rig moves both ways for a good part of the video and the fit by way explains the
    // picture better than its noise allows (as a drift must: a likelihood ratio above 3 standard
    // deviations), the offset is known no better than half the distance between them; under
    // heavy noise the fit by way only scatters (probe seed 314159 case 10: 1.3 frames from a
    // sync 0.56 frames off).
    {
        const std::vector<int> ways = directions(v, pos, chosen.offset, chosen.drift);
        const auto forward = std::count(ways.begin(), ways.end(), 1), backward = std::count(ways.begin(), ways.end(), -1);
        if (5 * std::min(forward, backward) >= long(n)) {
            const auto [byWay, least] = bestOffsetByDirection(v, pos, chosen.drift, chosen.offset, 3 * frame_s, frame_s / 50);
            const double oneIntercept = fit.residual * fit.residual * double(std::max(1, fit.n - 2));
            if (least > 0 && double(n) * (oneIntercept - least) / least >= 9.0)
                r.uncertainty_s = std::max(r.uncertainty_s, 0.5 * std::abs(byWay - chosen.offset));
        }
    }

    // The coded pictures show the tip a trail behind it (core/picture_lag.h): late by the trail
    // over its speed. Each frame times the offset as much as its slope squared, and so weighs its
    // own lag: trail · Σ|v| / Σv². The trail is known within a range (what the coder is and
    // whether it was the first); the offset is taken at its middle and known no better than
    // half of it and what the model leaves unexplained.
    const double pictureUncertainty_s = r.uncertainty_s;
    r.pictureTrail = pictureTrail(o.coding);
    if (saa > 0) {
        r.pictureLag_s = r.pictureTrail.likely_px() * speeds / saa;
        r.offset_s -= r.pictureLag_s;
        r.pictureLagUncertainty_s = r.pictureTrail.uncertainty_px() * speeds / saa;
        r.uncertainty_s = std::max(r.uncertainty_s, r.pictureLagUncertainty_s);
    }

    // Confidence: each factor is 1 when that part is convincing.
    const double qFit = std::clamp((fit.r2 - 0.8) / 0.15, 0.0, 1.0);
    double second = 0.0;
    for (std::size_t p : peaks)
        if (std::abs(offs[p] - chosen.offset) > 0.15) {
            second = std::max(second, r2s[p]);
        }
    const double qUnique = std::clamp((fit.r2 - second) / 0.05, 0.0, 1.0);
    auto precise = [&](double uncertainty_s) {
        const double u = uncertainty_s / frame_s;
        return 1.0 / (1.0 + (u / 0.5) * (u / 0.5));
    };
    double qOnset = 1.0;
    if (r.onsetOffset_s) {
        const double d = (chosen.offset - *r.onsetOffset_s) / 0.25;
        qOnset = std::exp(-d * d);
    }
    const double seen = qFit * qUnique * qOnset;
    r.confidence = std::clamp(seen * precise(r.uncertainty_s), 0.0, 1.0);
    r.trackConfidence = std::clamp(seen * precise(pictureUncertainty_s), 0.0, 1.0);
    // Where nothing times the offset (no onset, stop or turn seen, or no halves to compare),
    // its uncertainty is unknown, not the placeholder above: `sync` printed it as 15000000000
    // frames (video probe, a noise video).
    if (!(r.uncertainty_s < 1e8))
        r.uncertainty_s = std::numeric_limits<double>::infinity();
    return r;
}

}  // namespace nb
