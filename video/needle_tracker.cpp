#include "needle_tracker.h"

#include "needle_strip.h"
#include "picture_memory.h"
#include "static_edges.h"
#include "tip_path.h"
#include "video_error.h"

#include "core/tr.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>

namespace nb::video {

namespace {

using namespace strip;  // the strip reading this file is built on (needle_strip.h)

// Where a shaft of sign `sign` stands along a strip 2·kSettleHalfWidth_px + 1 rows wide
// (`sampled`): per segment of kSettleSegment_px, the peak of the mean across the strip
// (fractional row from the middle) where it stands more than `threshold_sigma` σ out of the
// picture beside it.
constexpr int kSettleSegment_px = 24, kSettleHalfWidth_px = 10;
std::vector<std::pair<double, double>> shaftCentres(const cv::Mat& sampled, double origin, double sign, double threshold_sigma)
{
    const int segments = sampled.cols / kSettleSegment_px;
    std::vector<std::vector<double>> across;
    std::vector<double> spread;
    for (int k = 0; k < segments; ++k) {
        cv::Mat column;
        cv::reduce(sampled.colRange(k * kSettleSegment_px, (k + 1) * kSettleSegment_px), column, 1, cv::REDUCE_AVG);
        std::vector<double> p(column.begin<float>(), column.end<float>());
        const double base = median(p);
        for (double& v : p) {
            v = sign * (v - base);
            spread.push_back(std::abs(v));
        }
        across.push_back(std::move(p));
    }
    std::vector<std::pair<double, double>> centres;  // (along the axis, across it)
    if (across.empty())
        return centres;
    const double noise = std::max(1e-3, 1.4826 * median(spread));
    for (int k = 0; k < segments; ++k) {
        const auto& p = across[std::size_t(k)];
        const auto peak = std::max_element(p.begin() + 1, p.end() - 1);
        if (!(*peak > threshold_sigma * noise))
            continue;
        const double across = double(peak - p.begin()) + peakOffset(*(peak - 1), *peak, *(peak + 1)) - kSettleHalfWidth_px;
        centres.emplace_back(origin + (k + 0.5) * kSettleSegment_px, across);
    }
    return centres;
}

// `axis` moved onto the shaft the frames' mean shows, when it shows one clearly over a good
// stretch; as it is otherwise. A line found from the tip's path is a few degrees off where the
// path is short (±34 px of travel: 1.7° off, 9 px from the shaft at the picture's edge, and the
// sync 17 s off at confidence 0), and so is one drawn by hand. The shaft's centres across the line
// (shaftCentres beyond `threshold_sigma`, of the sign that shows more of them) are fitted with a
// line (Theil-Sen: the digits of a clock on the line, grain that happens to stand out, are
// outliers); that line is the shaft if most centres lie on it, and it lies within 3° and 4 px of
// `axis`.
NeedleAxis settleOnShaft(const cv::Mat& mean, const NeedleAxis& axis, double threshold_sigma = 4.0)
{
    const Strip wide(axis, mean.cols, mean.rows, kSettleHalfWidth_px);
    if (wide.length < 5 * kSettleSegment_px)
        return axis;
    cv::Mat sampled;
    cv::remap(mean, sampled, wide.mapX, wide.mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    std::vector<std::pair<double, double>> centres = shaftCentres(sampled, wide.origin, 1.0, threshold_sigma);
    if (auto dark = shaftCentres(sampled, wide.origin, -1.0, threshold_sigma); dark.size() > centres.size())
        centres = std::move(dark);
    if (centres.size() < 5)
        return axis;
    std::vector<double> slopes;
    for (std::size_t i = 0; i < centres.size(); ++i)
        for (std::size_t j = i + 1; j < centres.size(); ++j)
            slopes.push_back((centres[j].second - centres[i].second) / (centres[j].first - centres[i].first));
    const double slope = median(slopes);
    std::vector<double> offsets;
    for (const auto& [t, o] : centres)
        offsets.push_back(o - slope * t);
    const double offset = median(offsets);  // across the axis at its first point
    // Most centres must lie on that line: a shaft, not grain that stands out here and there.
    const auto onLine = std::count_if(centres.begin(), centres.end(), [&](const auto& c) { return std::abs(c.second - offset - slope * c.first) < 1.5; });
    const double len = axis.length();
    if (onLine < 5 || 3 * onLine < 2 * std::ptrdiff_t(centres.size()) || std::abs(slope) > std::tan(3.0 * M_PI / 180.0)
        || std::abs(offset + slope * 0.5 * len) > 4.0)
        return axis;
    // The centres are read to a few tenths of a pixel: a line that close is left as it is.
    const double from = offset + slope * wide.origin, to = offset + slope * (wide.origin + wide.length);
    if (std::max(std::abs(from), std::abs(to)) < 0.5)
        return axis;
    const QPointF u = (axis.p2() - axis.p1()) / len, n(-u.y(), u.x());
    return NeedleAxis(axis.p1() + n * offset, axis.p2() + n * (offset + slope * len));
}

// What each sample of a needle strip shows behind the tip and ahead of it (the shaft or what
// it covers, and the picture it has not reached), learnt from sampled frames in which the tip
// was clearly on either side of it; NaN where no side is known.
struct TipSides {
    std::vector<double> behind, ahead;
    double noise = 1.0;  // of the strip's middle, per sample and frame
};

constexpr int kSideClear = 4, kSideFrames = 3;
constexpr std::size_t kSideReach = 32;

// `middles`: the strip's middle in sampled frames; `tips`: the tip found in each.
TipSides learnTipSides(const std::vector<std::vector<double>>& middles, const std::vector<double>& tips)
{
    TipSides s;
    if (middles.empty())
        return s;
    s.noise = robustSigma(middles);
    const std::size_t n = middles.front().size();
    s.behind.assign(n, kNaN);
    s.ahead.assign(n, kNaN);
    std::vector<double> b, a;
    for (std::size_t i = 0; i < n; ++i) {
        b.clear();
        a.clear();
        for (std::size_t k = 0; k < middles.size(); ++k) {
            if (tips[k] > double(i) + kSideClear)
                b.push_back(middles[k][i]);
            else if (tips[k] < double(i) - kSideClear)
                a.push_back(middles[k][i]);
        }
        if (int(b.size()) >= kSideFrames)
            s.behind[i] = median(b);
        if (int(a.size()) >= kSideFrames)
            s.ahead[i] = median(a);
    }
    // Beyond the tip's furthest reach in the sampled frames the shaft was never seen, and
    // short of its nearest the picture without it: there the needle is taken to stand out
    // of what it covers as it does at the nearest sample where both were seen.
    std::vector<double> contrast(n, kNaN);
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(s.behind[i]) && std::isfinite(s.ahead[i]))
            contrast[i] = s.behind[i] - s.ahead[i];
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isfinite(s.behind[i]) == std::isfinite(s.ahead[i]))
            continue;
        double nearest = kNaN;
        for (std::size_t d = 1; d <= kSideReach && !std::isfinite(nearest); ++d) {
            if (i >= d && std::isfinite(contrast[i - d]))
                nearest = contrast[i - d];
            else if (i + d < n && std::isfinite(contrast[i + d]))
                nearest = contrast[i + d];
        }
        if (!std::isfinite(nearest))
            continue;
        if (std::isfinite(s.ahead[i]))
            s.behind[i] = s.ahead[i] + nearest;
        else
            s.ahead[i] = s.behind[i] - nearest;
    }
    return s;
}

// The tip in a window of samples around `centre`, where the shares of the way from ahead to
// behind that its samples have come put it; nullopt where a sample barely changes with the
// tip or is not known on either side. `framed`: the window begins behind the tip and ends
// ahead of it.
constexpr int kRefineWindow = 8;
struct Shares {
    double at = kNaN;
    bool framed = false;
};

std::optional<Shares> sharesAround(const TipSides& sides, const std::vector<double>& middle, double centre)
{
    const int n = int(middle.size());
    const int lo = int(std::lround(centre)) - kRefineWindow, hi = int(std::lround(centre)) + kRefineWindow;
    if (lo < 0 || hi >= n)
        return std::nullopt;
    constexpr int quarter = kRefineWindow / 2;
    double sum = 0.0, first = 0.0, last = 0.0;
    for (int i = lo; i <= hi; ++i) {
        const double b = sides.behind[std::size_t(i)], a = sides.ahead[std::size_t(i)];
        if (!std::isfinite(b) || !std::isfinite(a) || std::abs(b - a) < 4.0 * sides.noise)
            return std::nullopt;
        const double share = std::clamp((middle[std::size_t(i)] - a) / (b - a), -0.5, 1.5);
        sum += share;
        if (i < lo + quarter)
            first += share / quarter;
        else if (i > hi - quarter)
            last += share / quarter;
    }
    return Shares{double(lo) - 0.5 + sum, first > 0.7 && last < 0.3};
}

// The tip found at `rough` in `middle`, measured again against what the strip shows on either
// side of a tip: the share of the way from ahead to behind that each sample has come, summed
// over a window, is how far into the window the tip stands. The edge detector's own peak is
// pulled by a textured background to the nearest of its edges (grain of 4 px, 12 grey levels,
// under a needle 35 bright: up to 6 px off, by position, the same at every pass); the shares
// are not, since the background is in both references. The window is moved onto what it
// measured until it reads as behind, then ahead; `rough` where it cannot be.
double tipAgainstSides(const TipSides& sides, const std::vector<double>& middle, double rough)
{
    if (sides.behind.size() != middle.size())
        return rough;
    double at = rough;
    for (int pass = 0; pass < 4; ++pass) {
        const std::optional<Shares> next = sharesAround(sides, middle, at);
        if (!next)
            return rough;
        const double moved = std::abs(next->at - at);
        at = next->at;
        if (std::abs(at - rough) > kRefineWindow)
            return rough;
        // Two windows a sample apart may read a tenth of a pixel apart, by turns.
        if (next->framed && moved < 0.5)
            return at;
    }
    return rough;
}

// The samples of a strip not to read, asked for as the stretch `stretch` (in samples): that
// stretch, widened over the samples either side whose edge response changes from one sampled
// frame to the next (`g`) more than twice as much as the strip's usually does, and then by a
// tip's reach. What held a track there may reach further: a counter's other digits, whose
// edges held it again just past a stretch of one digit (probe seed 577215 case 14).
std::vector<char> unreadAbout(const AxisStretch& stretch, const std::vector<std::vector<double>>& g)
{
    const int n = g.empty() ? 0 : int(g.front().size());
    std::vector<double> spread(std::size_t(n), 0.0), column;
    for (int i = kStep; i < n - kStep; ++i) {
        column.clear();
        for (const std::vector<double>& frame : g)
            column.push_back(frame[std::size_t(i)]);
        const double middle = median(column);
        for (double& v : column)
            v = std::abs(v - middle);
        spread[std::size_t(i)] = median(column);
    }
    const double usual = median(std::vector<double>(spread.begin() + std::min(n, kStep), spread.end() - std::min(n, kStep)));
    auto changing = [&](int i) { return i >= 0 && i < n && spread[std::size_t(i)] > 2.0 * usual; };
    int from = std::clamp(int(std::floor(stretch.from_px)), 0, n), to = std::clamp(int(std::ceil(stretch.to_px)), -1, n - 1);
    while (changing(from - 1))
        --from;
    while (changing(to + 1))
        ++to;
    std::vector<char> out(std::size_t(n), 0);
    for (int i = std::max(0, from - int(kAwayFromTip)); i <= std::min(n - 1, to + int(kAwayFromTip)); ++i)
        out[std::size_t(i)] = 1;
    return out;
}

// Per sample, how far the edge response (of sign `polarity`) usually stands above what is always
// there (`still`), in the sampled frames whose tip was found away from it: the median, never below
// zero; zero where fewer than kFramesAway frames tell. What is always there is a low percentile, so
// that a tip resting through most of the video is not taken for it: over noise alone the response
// stands 1 σ above it at the median, and where few frames had their tip away the percentile fell
// lower still (probe seed 97101 case 12, a faint needle resting 13 s before its stroke: 2-2.6 σ
// at two places 10 and 50 px behind it).
std::vector<double> usualAboveStill(const std::vector<std::vector<double>>& g, int polarity, const std::vector<double>& still,
                                    const std::vector<double>& tipAt)
{
    std::vector<double> out(still.size(), 0.0), column;
    for (std::size_t i = 0; i < still.size(); ++i) {
        column.clear();
        for (std::size_t k = 0; k < g.size() && k < tipAt.size(); ++k)
            if (std::isfinite(tipAt[k]) && std::abs(tipAt[k] - double(i)) > kAwayFromTip && i < g[k].size())
                column.push_back(polarity * g[k][i] - still[i]);
        if (column.size() >= kFramesAway)
            out[i] = std::max(0.0, median(column));
    }
    return out;
}

// One axis being tracked: its strip, what is always there, the noise and the tip's sign.
struct AxisTracker {
    NeedleStrip strip;
    std::vector<double> still;
    std::vector<double> background;  // of the strip's shaft profile (shaftBackground)
    UsualAtEnd usualAtEnd;           // what the strip's end shows as shaft in nearly every frame
    double sigma = 1.0;
    int polarity = 1;
    bool gated = false;  // the tip is where a shaft ends (TipModel)
    double frame_s = 1.0 / 30.0;  // the video's usual frame interval
    double last = kNaN;  // last tip position (profile samples)
    double lastTime_s = kNaN;
    double velocity = 0.0;  // profile samples per second, over the last few sightings
    int lost = 0;        // frames since it was last seen
    std::vector<double> strengths;
    std::vector<double> slopes;  // grey levels per sample along the middle at each decided tip
    std::vector<std::pair<double, double>> recent;  // (time, position) of the last sightings in a row
    TipSides sides;
    std::vector<double> usualAbove;  // usualAboveStill: where noise alone stands out of what is always there

    NeedleAxis axis;  // as given, or turned to point from the shaft to the tip

    bool shaftSeen = false;  // the tip model's (NeedleTrack::shaftSeen)

    AxisTracker(const NeedleAxis& given, const FrameSamples& s, double frameDuration_s, const std::optional<AxisStretch>& notRead,
                QRect within, const AxisReading& reading)
        : strip(given, s.width, s.height, within), frame_s(frameDuration_s > 0 ? frameDuration_s : 1.0 / 30.0), axis(given)
    {
        if (strip.length < 20)
            return;
        std::vector<StripProfile> profiles = sampleStrip(strip, s);
        std::optional<AxisStretch> blind = notRead;
        // A line drawn by the operator may point either way (found ones are turned already).
        if (!reading.asPointed && shaftFromFarEnd(profiles)) {
            axis = NeedleAxis(given.p2(), given.p1());
            strip = NeedleStrip(axis, s.width, s.height, within);
            profiles = sampleStrip(strip, s);
            if (blind)
                blind = AxisStretch{given.length() - blind->to_px, given.length() - blind->from_px};
        }
        std::vector<std::vector<double>> g;
        for (const StripProfile& p : profiles)
            g.push_back(gradient(p.middle));
        withoutNoisierFrames(profiles, g);
        if (blind)
            unread = unreadAbout({blind->from_px - strip.origin, blind->to_px - strip.origin}, g);
        sigma = robustSigma(g);
        TipModel model = tipModel(profiles, g, sigma, reading.shaftSign);
        polarity = model.polarity;
        shaftSeen = model.shaftSeen;
        gated = model.gated;
        // Frames whose shaft runs on to the strip's end show no tip (asked before the shaft's
        // background is taken off: where the tip is often beyond the end, that is the shaft).
        std::vector<ShaftAtEnds> ends;
        for (const StripProfile& p : profiles)
            ends.push_back(shaftAtEnds(p, -polarity));
        usualAtEnd = usualShaftAtEnd(ends);
        std::vector<char> beyond(profiles.size(), 0);
        for (std::size_t k = 0; gated && k < profiles.size(); ++k)
            beyond[k] = shaftReachesEnd(ends[k], usualAtEnd);
        still = unreadWhereAsked(std::move(model.still));
        auto tipsSeen = [&] {
            std::vector<double> at(profiles.size(), kNaN);
            for (std::size_t k = 0; k < profiles.size(); ++k) {
                if (beyond[k])
                    continue;
                const Peak p = findTip(g[k], profiles[k].shaft, still, polarity, gated, sigma);
                if (std::isfinite(p.position) && p.strength > 5.0 * sigma)
                    at[k] = p.position;
            }
            return at;
        };
        const std::vector<double> firstSeenAt = tipsSeen();
        still = unreadWhereAsked(staticPartAwayFromTips(g, polarity, firstSeenAt, std::move(still)));
        background = shaftBackground(profiles, firstSeenAt);
        for (StripProfile& p : profiles)
            withoutBackground(p);
        std::vector<std::vector<double>> middles;
        std::vector<double> tips;
        const std::vector<double> seenAt = tipsSeen();
        usualAbove = usualAboveStill(g, polarity, still, seenAt);
        for (std::size_t k = 0; k < profiles.size(); ++k)
            if (std::isfinite(seenAt[k])) {
                tips.push_back(seenAt[k]);
                middles.push_back(profiles[k].middle);
            }
        sides = learnTipSides(middles, tips);
        // The edge detector's tips are pulled by a textured background (probe seed 246810
        // case 6: 2.9 px behind the truth at rest, 0.6 px ahead while moving), and sides
        // learnt from them take some of the shaft for the picture ahead of it where the tip
        // rests: measured against them, the tip read 0.9 px behind at rest and 0.1 px ahead
        // while moving, and the sync was 1.2 frames off. Learnt again from the tips measured
        // against them, they are not (one pass; a second moves the tips by hundredths).
        for (std::size_t k = 0; k < tips.size(); ++k)
            tips[k] = tipAgainstSides(sides, middles[k], tips[k]);
        sides = learnTipSides(middles, tips);
        course = TipPath(strip.length, 48, frame_s);
        everyFrame.emplace(still, sigma);
    }

    // FrameSamples where the caller asked for no tip to be read: nothing there stands above what is
    // always there (+inf), so no tip is found and the course gains nothing there.
    std::vector<char> unread;
    std::vector<double> unreadWhereAsked(std::vector<double> stillEdges) const
    {
        for (std::size_t i = 0; i < unread.size() && i < stillEdges.size(); ++i)
            if (unread[i])
                stillEdges[i] = std::numeric_limits<double>::infinity();
        return stillEdges;
    }

    void withoutBackground(StripProfile& p) const
    {
        if (p.shaft.size() == background.size())
            for (std::size_t i = 0; i < background.size(); ++i)
                p.shaft[i] -= background[i];
    }

    // How strong the tip's edge has been lately. In a clean picture the noise is a fraction
    // of a grey level and coding artefacts along the shaft (block edges, ringing) stand
    // many σ out of it; the tip stands out far more. A tip hidden for long may come back
    // fainter (other background), so the memory fades while it is lost.
    double typicalStrength() const
    {
        const double m = lastSeenStrength();
        return lost > 8 ? m * std::pow(0.9, lost - 8) : m;
    }

    // The tip's edge as strong as the last frames that showed it on their own (median of 25),
    // 0 before five did.
    double lastSeenStrength() const
    {
        if (strengths.size() < 5)
            return 0.0;
        const std::size_t k = std::min<std::size_t>(strengths.size(), 25);
        return median(std::vector<double>(strengths.end() - std::ptrdiff_t(k), strengths.end()));
    }

    // The tip in this frame: searched near where it should be by now (a faint tip in heavy
    // noise beats the noise nearby more easily than the noise of the whole line), everywhere
    // when it has been lost for a while. A fast needle moves further between two frames than
    // the search reaches around its last place, so the search follows its velocity.
    // NaN when no edge stands clearly out of the noise and like the tip seen so far.
    // `repeated`: the index calls the picture a repeat of the one before; taken only when
    // the tip has not moved either (the index judges the whole picture, in which a thin
    // needle is a few hundred pixels: a clean, smoothly coded video of a fast needle gets
    // most frames flagged).
    // The tip as the edge detector found it, and measured against the strip's sides.
    struct Sighting {
        double found = kNaN, measured = kNaN;
        double strength = 0.0;  // of the edge found, in grey levels
    };

    // One frame, kept until the tip's course decides where the tip was in it.
    struct Seen {
        StripProfile profile;
        bool beyond = false;  // the shaft runs on to the strip's end (shaftReachesEnd)
        std::vector<double> g;
        Sighting sighting;
    };
    TipPath course{1};
    std::deque<Seen> undecided;

    // What is always there, learnt again over every frame as it is decided (static_edges.h says
    // why), and each decided frame's edge response about its tip, to read the tip there again
    // against it at the end.
    struct AboutTip {
        int peak = -1;  // the sample the tip was read at; -1 when none was
        std::array<float, 5> edge{};  // in the tip's sign, samples peak-2 ... peak+2
    };
    std::optional<StaticEdges> everyFrame;
    std::vector<AboutTip> aboutTips;

    Sighting decideAndLearn(const Seen& seen, int at)
    {
        const Sighting tip = decide(seen, at);
        double slope = kNaN;
        if (std::isfinite(tip.found)) {
            const std::size_t p = std::size_t(std::lround(std::max(0.0, tip.found)));
            const std::vector<double>& m = seen.profile.middle;
            if (p >= 1 && p + 1 < m.size())
                slope = 0.5 * std::abs(m[p + 1] - m[p - 1]);
        }
        slopes.push_back(slope);
        AboutTip about;
        if (everyFrame && std::isfinite(tip.found)) {
            everyFrame->add(seen.g, polarity, tip.found, kAwayFromTip);
            const int peak = int(std::lround(tip.found));
            if (peak >= 2 && peak + 2 < int(seen.g.size())) {
                about.peak = peak;
                for (int j = -2; j <= 2; ++j)
                    about.edge[std::size_t(j + 2)] = float(polarity * seen.g[std::size_t(peak + j)]);
            }
        }
        aboutTips.push_back(about);
        return tip;
    }

    // The tips decided, `found` (one per decided frame, in order, along the axis: the strip's
    // samples plus `origin`), read again at the end against what is always there as every frame
    // shows it: the peak within a sample of where it was read, to a fraction of a sample as before.
    void readAgain(std::vector<double>& found, double origin) const
    {
        if (!everyFrame || found.size() != aboutTips.size())
            return;
        const std::vector<double> floor = everyFrame->estimate(int(kFramesAway));
        const int n = int(floor.size());
        for (std::size_t k = 0; k < found.size(); ++k) {
            const AboutTip& about = aboutTips[k];
            if (about.peak < 0 || !std::isfinite(found[k]))
                continue;
            auto v = [&](int j) { return double(about.edge[std::size_t(j + 2)]) - floor[std::size_t(about.peak + j)]; };
            int best = 0;
            for (int j : {-1, 1})
                if (v(j) > v(best))
                    best = j;
            const int b = about.peak + best;
            if (cutOffAtEnd(b, n))
                continue;
            found[k] = origin + double(b) + peakOffset(v(best - 1), v(best), v(best + 1));
        }
    }

    // Each frame is looked at on its own (locate), and the tip's course through the frames
    // (TipPath) says where it was a few dozen frames later (decide). Returns the frame decided
    // by this one, the frames in order.
    std::optional<Sighting> next(const cv::Mat& gray, double time_s, bool repeated)
    {
        Seen seen;
        seen.profile = strip.sample(gray);
        seen.beyond = gated && shaftReachesEnd(shaftAtEnds(seen.profile, -polarity), usualAtEnd);
        withoutBackground(seen.profile);
        seen.g = gradient(seen.profile.middle);
        seen.sighting = locate(seen.profile, seen.g, time_s, repeated, seen.beyond);
        const std::optional<int> at = course.push(edgeScores(seen));
        undecided.push_back(std::move(seen));
        if (!at)
            return std::nullopt;
        const Sighting decided = decideAndLearn(undecided.front(), *at);
        undecided.pop_front();
        return decided;
    }

    // The frames still undecided at the end of the video.
    std::vector<Sighting> rest()
    {
        std::vector<Sighting> out;
        for (int at : course.finish()) {
            out.push_back(decideAndLearn(undecided.front(), at));
            undecided.pop_front();
        }
        return out;
    }

    // How much each sample of one frame looks like the tip, in units of the noise: an edge
    // above what is always there, and where a shaft is seen, as far as the shaft ends there.
    // Where the frame alone shows the tip clearly, its course passes near it (within what a
    // textured background pulls the edge detector, 8 samples): the course counts no frame for
    // more than TipPath::kScoreCap, and the changing digits of a frame counter on the line
    // score as high in every frame (probe seed 531911 case 6: the course sat on them in 337 of
    // 584 frames, the tip 6 σ and more in 534). Away from it a sample scores the least a frame
    // can, however strong its edge; not a hard bound: on a line with no needle, what stands
    // out in single frames jumps about faster than any course.
    std::vector<double> edgeScores(const Seen& seen) const
    {
        std::vector<double> out(seen.g.size(), 0.0);
        const bool clear = clearlySeen(seen.sighting);
        for (std::size_t i = 2; i + 3 < seen.g.size(); ++i) {
            if (clear && std::abs(double(i) - seen.sighting.found) > 8.0)
                continue;  // set below; the gate's medians were a tenth of a sync's time
            const double v = polarity * seen.g[i] - still[i];
            // The gate only lowers a score, and below 1 σ it changes little.
            out[i] = (gated && v > sigma ? gatedStrength(seen.profile.shaft, polarity, sigma, int(i), v) : v) / sigma;
        }
        if (clear)
            for (std::size_t i = 0; i < out.size(); ++i)
                if (std::abs(double(i) - seen.sighting.found) > 8.0)
                    out[i] = -TipPath::kScoreCap;
        return out;
    }

    // An edge no noise along the strip makes (its strongest is about 3 σ).
    bool clearlySeen(const Sighting& s) const { return std::isfinite(s.found) && s.strength >= 6.0 * sigma; }

    // A clear edge that tells whether the course keeps to the tip: 6 σ above where the edge
    // response usually stands at its sample, not above what is always there. 6 σ above that was
    // 3.4-4 σ of noise at two places where the usual stood 2-2.6 σ above it, and three of the ten
    // frames that cleared it while a faint tip rested (probe seed 97101 case 12) were taken as the
    // course losing the tip: it was no longer trusted, each frame's strongest edge anywhere on the
    // strip was kept instead of the course that followed the tip all along, and the sync was 68
    // frames off with the needle's line given. Only the trust is judged so; what a clear edge does
    // otherwise (kept for its own frame, pulling the course to it) stays as it was: judged so as
    // well, a tip that leaves the picture through a clock (seed 27053 case 11) read 1.8 frames
    // off where it read 1.0, and case 12 came out the same either way.
    bool tellsOfTheCourse(const Sighting& s) const
    {
        if (!clearlySeen(s))
            return false;
        const long at = std::lround(s.found);
        const double usual = at >= 0 && std::size_t(at) < usualAbove.size() ? usualAbove[std::size_t(at)] : 0.0;
        return s.strength >= 6.0 * sigma + usual;
    }

    // Whether the course passed within 3 samples of the tip, in the last frames that showed
    // the tip clearly on their own (at most 50).
    std::deque<bool> courseAgreed;

    // The tip in a frame, given where its course through the frames puts it (`at`, in whole
    // samples). A faint tip in heavy noise (2-3 σ, an edge of noise elsewhere on the strip as
    // high) is lost or mistaken in many frames looked at alone, and its course finds it (probe
    // seed 4711 case 8: 93 of 283 frames masked along the true line, the sync off). An edge
    // found alone is kept where it is clear or where the course agrees; else the edge on the
    // course, where it stands 2 σ out of the noise, as long as the course has kept to the
    // tip where it was clear. A tip may move faster than the course's velocities (16 samples
    // a frame at 30 frames/s), and there the course is noise.
    Sighting decide(const Seen& seen, int at)
    {
        if (seen.beyond)
            return {};
        const Sighting& alone = seen.sighting;
        const Peak onCourse = findTip(seen.g, seen.profile.shaft, still, polarity, gated, sigma, at - 2, at + 2);
        const bool agree = std::isfinite(alone.found) && std::abs(alone.found - onCourse.position) <= 3.0;
        if (clearlySeen(alone)) {
            if (tellsOfTheCourse(alone)) {
                courseAgreed.push_back(agree);
                if (courseAgreed.size() > 50)
                    courseAgreed.pop_front();
            }
            return alone;
        }
        // Not clear on its own, an edge a quarter as strong as the tip was when last seen: a tip
        // that runs out of the picture leaves its course at the strip's end, where the grain's
        // edges of 1-4 σ were read as a tip 15-20 px short of the edge while a tip of 21 σ was
        // out of sight (test_needle_axis leavesNoTipReadWhereItIsOutOfThePicture). A faint tip
        // in heavy noise, seen alone at 3.5-5 σ, still takes edges of 2 σ on its course.
        const double likeTheTip = std::max(2.0, 0.25 * lastSeenStrength()) * sigma;
        const auto agreed = std::count(courseAgreed.begin(), courseAgreed.end(), true);
        const bool trusted = courseAgreed.size() < 5 || double(agreed) >= 0.8 * double(courseAgreed.size());
        if (agree || !trusted)
            return alone.strength >= likeTheTip ? alone : Sighting{};
        if (!std::isfinite(onCourse.position) || !(onCourse.strength >= likeTheTip))
            return {};
        return {onCourse.position, tipAgainstSides(sides, seen.profile.middle, onCourse.position), onCourse.strength};
    }

    Sighting locate(const StripProfile& profile, const std::vector<double>& g, double time_s, bool repeated, bool beyond)
    {
        const int n = int(g.size());
        int lo = 2, hi = n - 3;
        const bool near = std::isfinite(last) && lost < 8;
        if (near) {
            const double ahead = std::isfinite(lastTime_s) ? velocity * (time_s - lastTime_s) : 0.0;
            const double expected = last + ahead;
            const double w = 24 + 8 * lost + 0.5 * std::abs(ahead);
            lo = std::clamp(int(expected - w), 2, n - 3);
            hi = std::clamp(int(expected + w), 2, n - 3);
        }
        const Peak tip = beyond ? Peak{} : findTip(g, profile.shaft, still, polarity, gated, sigma, lo, hi);
        const double bestV = tip.strength;
        const double needed = std::max((near ? 3.5 : 5.0) * sigma, 0.25 * typicalStrength() * sigma);
        if (!std::isfinite(tip.position) || !(bestV > needed)) {
            ++lost;
            if (lost >= 8) {
                velocity = 0.0;
                recent.clear();
            }
            return {};
        }
        strengths.push_back(bestV / sigma);
        const double found = tip.position;
        const bool repeat = repeated && std::isfinite(last) && std::abs(found - last) < 0.5;
        if (!repeat)
            updateVelocity(time_s, found);
        last = found;
        lastTime_s = time_s;
        lost = 0;
        return {found, tipAgainstSides(sides, profile.middle, found), bestV};
    }

    // The velocity as the straight line through the last few sightings, not from the last
    // two alone: a variable-rate file's timestamps may sit a millisecond apart for frames a
    // frame apart (a writer's rounding), and two such points make any velocity.
    void updateVelocity(double time_s, double found)
    {
        recent.emplace_back(time_s, found);
        while (recent.size() > 4 || (recent.size() > 1 && time_s - recent.front().first > 0.3))
            recent.erase(recent.begin());
        const double span = recent.back().first - recent.front().first;
        if (recent.size() < 2 || span < 0.5 * frame_s) {
            velocity = 0.0;
            return;
        }
        double mt = 0, mx = 0;
        for (const auto& [t, x] : recent) {
            mt += t;
            mx += x;
        }
        mt /= double(recent.size());
        mx /= double(recent.size());
        double stt = 0, stx = 0;
        for (const auto& [t, x] : recent) {
            stt += (t - mt) * (t - mt);
            stx += (t - mt) * (x - mx);
        }
        // The line lags a needle that speeds up; the newest step says where it is going.
        const double fitted = stt > 0 ? stx / stt : 0.0;
        const auto& p = recent[recent.size() - 2];
        const double dt = time_s - p.first;
        velocity = dt >= 0.5 * frame_s ? 0.5 * (fitted + (found - p.second) / dt) : fitted;
    }
};

// How much a track `d` scatters about its own smooth course while the tip moves (by more than
// 3 px over the 7 frames around, by `course`): the median distance of each such point from the
// quadratic through it and its three neighbours on either side (Savitzky-Golay, 7 points).
// Infinite when there is no such point. At rest a texture pulls the edge detector the same way
// in every frame, so only the moving frames tell a steady track from one the texture bends.
double jitterWhileMoving(const std::vector<double>& d, const std::vector<double>& course)
{
    static constexpr std::array<double, 7> kSmooth{-2.0 / 21, 3.0 / 21, 6.0 / 21, 7.0 / 21, 6.0 / 21, 3.0 / 21, -2.0 / 21};
    std::vector<double> off;
    for (std::size_t k = 3; k + 3 < d.size(); ++k) {
        if (!(std::abs(course[k + 3] - course[k - 3]) > 3.0))
            continue;
        double smooth = 0.0;
        for (std::size_t j = 0; j < kSmooth.size(); ++j)
            smooth += kSmooth[j] * d[k + j - 3];
        if (std::isfinite(smooth))
            off.push_back(std::abs(d[k] - smooth));
    }
    return off.empty() ? std::numeric_limits<double>::infinity() : median(off);
}

// Isolated jumps (a noise peak elsewhere on the strip) against their neighbours: masked.
// What the neighbours say a point should be is the median of three guesses in time (the
// line through the nearest point on each side, and each side's two nearest extended), so
// that a needle moving many pixels a frame is no jump and one bad neighbour does not decide.
void maskJumps(const std::vector<double>& t, std::vector<double>& d)
{
    std::vector<std::size_t> finite;
    for (std::size_t i = 0; i < d.size(); ++i)
        if (std::isfinite(d[i]))
            finite.push_back(i);
    std::vector<double> cleaned = d;
    auto line = [&](std::size_t a, std::size_t b, double at) {
        const double dt = t[b] - t[a];
        return std::abs(dt) > 1e-9 ? d[a] + (d[b] - d[a]) * (at - t[a]) / dt : 0.5 * (d[a] + d[b]);
    };
    for (std::size_t k = 2; k + 2 < finite.size(); ++k) {
        const std::size_t i = finite[k];
        const std::size_t p1 = finite[k - 1], p2 = finite[k - 2], n1 = finite[k + 1], n2 = finite[k + 2];
        // Neighbours far away in time say little about this frame.
        if (t[n1] - t[p1] > 0.5)
            continue;
        const double guess = median({line(p1, n1, t[i]), line(p2, p1, t[i]), line(n1, n2, t[i])});
        const double step = std::max(std::abs(d[n1] - d[i]), std::abs(d[i] - d[p1]));
        const double sideSteps = std::min(std::abs(d[p1] - d[p2]), std::abs(d[n2] - d[n1]));
        // A jump leaves both neighbours far behind while they move little themselves.
        if (std::abs(d[i] - guess) > 10.0 + sideSteps && step > 10.0 + sideSteps)
            cleaned[i] = kNaN;
    }
    d = cleaned;
}

// A tip that runs on past the end of its strip (out of the picture, or of the operator's region)
// is no longer in it, but something on the line behind it is still found, and kept to: a clock's
// digits the shaft runs through (probe seed 27053 case 11: the tip left the picture at the end of
// a 40 mm stroke and was read 40 px back on the clock for the last 1.6 s; the sync was 17 frames
// off at confidence 0.01, 7 frames with the needle's line given). Once the tip has been read within
// kEndReach samples of the strip's far end `end` and is next read farther back than it can have
// moved since, the readings are masked for as long as they keep to that place, a thing that does
// not move: a tip coming back into the picture is read at its end first, and a tip drawn back
// does not stay in one place. Not after more than kEndGap frames unread: a tip may have been
// drawn back unseen and rest where it is read next.
constexpr double kEndReach = 3.0 * kStep, kStillFoil_px = 6.0;
constexpr std::size_t kEndGap = 10;
void maskBeyondEnd(std::vector<double>& d, double end)
{
    double step = 0.0;  // the tip's last step between two frames read in a row
    std::size_t last = d.size();  // the last frame read, while it is within reach of the end
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (!std::isfinite(d[k]))
            continue;
        if (last < d.size() && k - last <= kEndGap && end - d[k] > end - d[last] + std::max(8.0, 3.0 * std::abs(step) * double(k - last))) {
            const double foil = d[k];
            std::size_t j = k;
            for (; j < d.size() && (!std::isfinite(d[j]) || (std::abs(d[j] - foil) <= kStillFoil_px && end - d[j] > kEndReach)); ++j)
                d[j] = kNaN;
            last = d.size();
            k = j - 1;
            continue;
        }
        if (k > 0 && std::isfinite(d[k - 1]))
            step = d[k] - d[k - 1];
        last = end - d[k] <= kEndReach ? k : d.size();
    }
}

}  // namespace

std::vector<std::optional<NeedleAxis>> settledOnFaintShafts(const FrameSamples& s, const std::vector<NeedleAxis>& axes)
{
    const cv::Mat mean = framesMean(s);
    std::vector<std::optional<NeedleAxis>> out;
    for (const NeedleAxis& axis : axes) {
        const NeedleAxis loose = settleOnShaft(mean, axis, 3.0);
        if (settleOnShaft(mean, axis) == axis && loose != axis)
            out.emplace_back(loose);
        else
            out.emplace_back();
    }
    return out;
}

std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress, const std::atomic_bool* cancel,
                                      const std::vector<std::optional<AxisStretch>>& notRead, QRect within)
{
    return trackNeedles(reader, sampleFrames(reader, 40), axes, progress, cancel, notRead, within);
}

std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const FrameSamples& s, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress, const std::atomic_bool* cancel,
                                      const std::vector<std::optional<AxisStretch>>& notRead, QRect within,
                                      const std::vector<AxisReading>& readings)
{
    const FrameIndex& index = reader.index();
    const cv::Mat mean = framesMean(s);
    std::vector<AxisTracker> trackers;
    std::vector<NeedleTrack> out(axes.size());
    std::vector<std::vector<double>> measured(axes.size());
    // A line that the region leaves too little of to read a tip on is not read at all (every
    // frame masked): among found lines, one that only clips the region's corner.
    std::vector<char> readable(axes.size(), 1);
    for (std::size_t a = 0; a < axes.size(); ++a) {
        trackers.emplace_back(settleOnShaft(mean, axes[a]), s, index.frameDuration(),
                              a < notRead.size() ? notRead[a] : std::nullopt, within,
                              a < readings.size() ? readings[a] : AxisReading{});
        readable[a] = trackers.back().strip.length >= 20;
        out[a].tipPolarity = readable[a] ? trackers.back().polarity : 0;
        out[a].shaftSeen = trackers.back().shaftSeen;
        if (!readable[a] && within.isEmpty())
            throw VideoError(index.path, nb::TrDevices::tr("the needle line lies outside the picture"));
        out[a].axis = trackers.back().axis;
    }
    if (!axes.empty() && std::none_of(readable.begin(), readable.end(), [](char r) { return r; }))
        throw VideoError(index.path, nb::TrDevices::tr("the needle line does not cross the region %1,%2 %3x%4 (at least 20 pixels of it)")
                                         .arg(within.x()).arg(within.y()).arg(within.width()).arg(within.height()));
    // A frame's tip, once decided, along the axis from its p1.
    auto record = [&](std::size_t a, const AxisTracker::Sighting& tip) {
        out[a].displacement_px.push_back(tip.found + trackers[a].strip.origin);
        measured[a].push_back(tip.measured + trackers[a].strip.origin);
    };
    const int first = s.span.first, n = s.span.last + 1;
    PictureMemoryMeter memory;
    for (int i = first; i < n && !(cancel && cancel->load()); ++i) {
        // Frames the index calls duplicates are tracked too, at their own time: a slow
        // needle in a clean, smoothly coded picture changes too little between frames to
        // tell from a repeat (whole runs of frames get flagged), and a real repeat only shows
        // its tip one frame late, which the fit over all frames absorbs.
        const FrameInfo& info = index.frames[std::size_t(i)];
        const std::optional<cv::Mat> shown = reader.grayUnlessDamaged(i);
        if (!shown) {
            for (NeedleTrack& t : out)
                ++t.damaged;
            continue;  // in a damaged stretch of the file: left out, as a dropped frame
        }
        const cv::Mat& gray = *shown;
        memory.add(gray);
        for (std::size_t a = 0; a < axes.size(); ++a) {
            out[a].time_s.push_back(info.time_s);
            if (!readable[a])
                out[a].displacement_px.push_back(kNaN);
            else if (const std::optional<AxisTracker::Sighting> tip = trackers[a].next(gray, info.time_s, info.duplicate))
                record(a, *tip);
        }
        if (progress && (i - first) % 50 == 0)
            progress(i - first, n - first);
    }
    for (std::size_t a = 0; a < axes.size(); ++a) {
        if (!readable[a]) {
            out[a].masked = int(out[a].displacement_px.size());
            continue;
        }
        for (const AxisTracker::Sighting& tip : trackers[a].rest())
            record(a, tip);
        trackers[a].readAgain(out[a].displacement_px, trackers[a].strip.origin);
        maskJumps(out[a].time_s, out[a].displacement_px);
        maskJumps(out[a].time_s, measured[a]);
        const double end = trackers[a].strip.origin + trackers[a].strip.length - 1;
        maskBeyondEnd(out[a].displacement_px, end);
        maskBeyondEnd(measured[a], end);
        // Measured against the strip's sides, the tip is freed of a still texture's pull (probe
        // seed 4711, two linear strokes on grain: 0.36 and 0.38 px of scatter against 0.47 and
        // 0.43), but where the picture ahead of it moves (the simulator's imaging view, tissue
        // the needle pushes along) the sides do not hold and the measure scatters (0.29
        // against 0.23; 1.1 px from the truth against 0.29): the clearly steadier is kept.
        const std::vector<double>& found = out[a].displacement_px;
        if (jitterWhileMoving(measured[a], found) < 0.9 * jitterWhileMoving(found, found))
            out[a].displacement_px = std::move(measured[a]);
        const auto& d = out[a].displacement_px;
        out[a].masked = int(std::count_if(d.begin(), d.end(), [](double v) { return !std::isfinite(v); }));
        out[a].edgeSnr = median(trackers[a].strengths);
        out[a].coding = memory.coding();
        std::vector<double> moving;
        const auto& sl = trackers[a].slopes;
        for (std::size_t k = 2; k + 2 < d.size() && k < sl.size(); ++k)
            if (std::isfinite(sl[k]) && std::isfinite(d[k - 2]) && std::isfinite(d[k + 2]) && std::abs(d[k + 2] - d[k - 2]) >= 1.0)
                moving.push_back(sl[k]);
        if (moving.size() >= 10)
            out[a].coding.edgeSlope_grey_per_px = median(moving);
    }
    return out;
}

NeedleTrack trackNeedle(FrameReader& reader, const NeedleAxis& axis, const std::function<void(int, int)>& progress,
                        const std::atomic_bool* cancel)
{
    return trackNeedles(reader, {axis}, progress, cancel).front();
}

}  // namespace nb::video
