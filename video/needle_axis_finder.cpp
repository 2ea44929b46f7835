#include "needle_axis_finder.h"

#include "needle_strip.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace nb::video {

namespace {

using namespace strip;  // the strip reading this file is built on (needle_strip.h)

struct AxisScore {
    NeedleAxis axis;
    double ridge = 0.0;
    double snr = 0.0;
};

// How many of `positions` lie more than a pixel from their median.
int movedFrames(const std::vector<double>& positions)
{
    std::vector<double> finite;
    for (double p : positions)
        if (std::isfinite(p))
            finite.push_back(p);
    if (finite.empty())
        return 0;
    const double usual = median(finite);
    return int(std::count_if(finite.begin(), finite.end(), [&](double p) { return std::abs(p - usual) > 1.0; }));
}

// The step detector's noise from rounding to whole grey levels alone (σ 1/√12 a pixel), over
// the middle's rows and kStep samples each side.
const double kRoundingSigma = std::sqrt(1.0 / 12.0) * std::sqrt(2.0 / kStep) / std::sqrt(2.0 * kMiddleHalfWidth_px + 1.0);

// How clearly an edge moves along `axis` in the sampled frames.
double movingEdgeSnr(const FrameSamples& s, const NeedleAxis& axis)
{
    const NeedleStrip strip(axis, s.width, s.height);
    if (strip.length < 20)
        return 0.0;
    std::vector<StripProfile> profiles;
    std::vector<std::vector<double>> g;
    for (const cv::Mat& f : s.gray) {
        profiles.push_back(strip.sample(f));
        g.push_back(gradient(profiles.back().middle));
    }
    const double sigma = robustSigma(g);
    const TipModel model = tipModel(profiles, g, sigma);
    double best = 0.0;
    for (int polarity : {1, -1}) {
        // The sign the tracker would not take does not count when a shaft ends at its tip.
        if (model.gated && polarity != model.polarity)
            continue;
        const std::vector<double> still = polarity == model.polarity ? model.still : staticPart(g, polarity);
        std::vector<double> strength, position, alone;
        for (std::size_t k = 0; k < g.size(); ++k) {
            const Peak p = findTip(g[k], profiles[k].shaft, still, polarity, model.gated, sigma);
            strength.push_back(p.strength);
            position.push_back(p.position);
            alone.push_back(p.strength > 0 ? 1.0 - p.second / p.strength : 0.0);
        }
        // An edge that moves: more than a pixel from its usual place in a few of the frames.
        // A few, not a share: a video begun long before the run shows the needle at rest in
        // most of them (17.3 s of rest before 4.7 s of a 1.4 Hz sine: 8 frames of 40 moved,
        // and the needle's 10th to 90th percentile spread was 0.13 px).
        if (movedFrames(position) < 2)
            continue;
        // One tip stands alone on its line; changing text has many edges alike. Against no
        // less noise than the 8-bit picture's rounding: a coder that holds a still picture's
        // pixels from frame to frame leaves no other, and a ratio to nothing outranked every
        // other line (the simulator's view as H.264 at -crf 30: a line 5° off the needle scored
        // 10⁷, the needle 608, and was never tried).
        best = std::max(best, median(strength) / std::max(sigma, kRoundingSigma) * median(alone));
    }
    return best;
}

// Refines a candidate line: the small turn and shift (±`turn_deg`, ±3 px) that puts the most
// ridge under it, at full resolution. With `plateau` > 0, the middle of the turns and shifts
// within that fraction of the most: on a picture clipped flat (PictureChange::counted) many
// lines sum alike, and the first of them tried lies at an edge of the band, not along it.
NeedleAxis refineAxis(const cv::Mat& ridge, const NeedleAxis& rough, double turn_deg = 1.5, double plateau = 0.0)
{
    const double len = rough.length();
    if (len < 2)
        return rough;
    const QPointF mid = 0.5 * (rough.p1() + rough.p2());
    const double base = std::atan2(rough.y2() - rough.y1(), rough.x2() - rough.x1());
    auto sumAlong = [&](double angle, double shift) {
        const double ux = std::cos(angle), uy = std::sin(angle), nx = -uy, ny = ux;
        double sum = 0.0;
        for (double s = -len / 2; s <= len / 2; s += 1.0) {
            const double x = mid.x() + s * ux + shift * nx, y = mid.y() + s * uy + shift * ny;
            const int xi = int(x), yi = int(y);
            if (xi < 0 || yi < 0 || xi + 1 >= ridge.cols || yi + 1 >= ridge.rows)
                continue;
            const double fx = x - xi, fy = y - yi;
            sum += (1 - fx) * (1 - fy) * ridge.at<float>(yi, xi) + fx * (1 - fy) * ridge.at<float>(yi, xi + 1)
                   + (1 - fx) * fy * ridge.at<float>(yi + 1, xi) + fx * fy * ridge.at<float>(yi + 1, xi + 1);
        }
        return sum;
    };
    double bestA = base, bestS = 0.0, bestV = -1.0;
    std::vector<std::array<double, 3>> tried;  // (sum, angle, shift)
    for (double da = -turn_deg; da <= turn_deg + 1e-9; da += 0.1)
        for (double sh = -3.0; sh <= 3.0 + 1e-9; sh += 0.25) {
            const double v = sumAlong(base + da * M_PI / 180.0, sh);
            if (plateau > 0.0)
                tried.push_back({v, base + da * M_PI / 180.0, sh});
            if (v > bestV) {
                bestV = v;
                bestA = base + da * M_PI / 180.0;
                bestS = sh;
            }
        }
    if (plateau > 0.0) {
        double angles = 0.0, shifts = 0.0;
        int alike = 0;
        for (const auto& [v, angle, shift] : tried)
            if (v >= (1.0 - plateau) * bestV) {
                angles += angle;
                shifts += shift;
                ++alike;
            }
        bestA = angles / alike;
        bestS = shifts / alike;
    }
    const double ux = std::cos(bestA), uy = std::sin(bestA);
    const QPointF c = mid + QPointF(-uy, ux) * bestS;
    return NeedleAxis(c - QPointF(ux, uy) * (len / 2), c + QPointF(ux, uy) * (len / 2));
}

// Straight-line sums of a picture at every whole degree (a Radon transform by rotation), on
// a copy at most 360 pixels wide: one row of sums per angle, one sum per line across it.
struct LineSums {
    std::vector<cv::Mat> rows;  // [angle in degrees], CV_32F column of diag sums
    int diag = 0;
    cv::Point2f centre;
    double scale = 1.0;  // of the copy against the picture
};

struct LineCandidate {
    int angle_deg = 0;
    int row = 0;  // index into LineSums::rows[angle_deg]
    double score = 0.0;
};

// The sums of `image` along horizontal lines of copies turned by every whole degree (a Radon
// transform by rotation): one column per angle. Sets `geometry`'s diag and centre.
std::vector<cv::Mat> sumAlongLines(const cv::Mat& image, LineSums& geometry)
{
    geometry.diag = int(std::ceil(std::hypot(image.cols, image.rows))) + 2;
    geometry.centre = cv::Point2f(image.cols / 2.0f, image.rows / 2.0f);
    std::vector<cv::Mat> out;
    for (int a = 0; a < 180; ++a) {
        cv::Mat m = cv::getRotationMatrix2D(geometry.centre, a, 1.0);
        m.at<double>(0, 2) += geometry.diag / 2.0 - geometry.centre.x;
        m.at<double>(1, 2) += geometry.diag / 2.0 - geometry.centre.y;
        cv::Mat rotated, rows;
        cv::warpAffine(image, rotated, m, cv::Size(geometry.diag, geometry.diag), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
        cv::reduce(rotated, rows, 1, cv::REDUCE_SUM);  // one sum per horizontal line
        out.push_back(rows);
    }
    return out;
}

// The median of a float picture's values, and their spread around it (1.4826 times their
// median distance from it: σ for Gaussian noise).
std::pair<float, float> middleAndSpread(const cv::Mat& image)
{
    std::vector<float> values(image.begin<float>(), image.end<float>());
    auto medianOf = [](std::vector<float>& v) {
        const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
        std::nth_element(v.begin(), mid, v.end());
        return *mid;
    };
    const float middle = medianOf(values);
    for (float& v : values)
        v = std::abs(v - middle);
    return {middle, 1.4826f * medianOf(values)};
}

LineSums lineSums(const cv::Mat& image)
{
    LineSums out;
    out.scale = std::min(1.0, 360.0 / std::max(image.cols, image.rows));
    cv::Mat small;
    cv::resize(image, small, cv::Size(), out.scale, out.scale, cv::INTER_AREA);
    // What noise leaves in the picture everywhere is taken off first: in a noisy picture it
    // adds up along a line with its length, and the picture's long diagonals outweighed a
    // needle reaching half across it (seed 586261: 16 candidates, all diagonals).
    const auto [floor, noise] = middleAndSpread(small);
    small -= floor;
    cv::max(small, 0.0f, small);
    // Capped so that a wide bright bar does not outweigh a long thin needle, but well above
    // the noise: a thin needle is less than a hundredth of the picture, and a cap at the
    // noise's own tail made it no more than noise.
    std::vector<float> values(small.begin<float>(), small.end<float>());
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() * 99 / 100), values.end());
    const float cap = std::max({1e-3f, values[values.size() * 99 / 100], 6.0f * noise});
    cv::min(small, cap, small);
    out.rows = sumAlongLines(small, out);
    return out;
}

// How long the line of sumAlongLines at `angle_deg` and `rho` (from the picture's centre,
// along the line's normal) runs inside a `width` × `height` picture: what the sums of a
// picture of ones would be (within 0.7 % on a 640x480 picture, lines of 40 px and more),
// without turning one 180 times.
double lengthInside(int width, int height, int angle_deg, double rho)
{
    const double th = angle_deg * M_PI / 180.0, dx = std::cos(th), dy = std::sin(th);
    const double px = width / 2.0 - rho * dy, py = height / 2.0 + rho * dx;
    double from = -1e9, to = 1e9;
    // Pixel k covers k ± 0.5.
    auto clip = [&](double p, double d, double size) {
        if (std::abs(d) < 1e-9) {
            if (p < -0.5 || p > size - 0.5)
                to = from;
            return;
        }
        const double a = (-0.5 - p) / d, b = (size - 0.5 - p) / d;
        from = std::max(from, std::min(a, b));
        to = std::min(to, std::max(a, b));
    };
    clip(px, dx, width);
    clip(py, dy, height);
    return std::max(0.0, to - from);
}

// Where a shaft of one sign stands along a straight line of the sampled frames' mean: per
// line, the signed sum of the picture's departure from its surroundings, in units of what a
// picture without lines sums to along as long a line (its spread grows with the root of the
// length). At full resolution, up to 1024 px: a faint needle (26 grey levels) on a grain as
// strong and as fine (4 px) stands out along its length, but not of the absolute departure,
// which the grain fills everywhere, nor on a copy 360 px wide, where the grain outweighs the
// shaft (probe seed 246810 case 10: the needle's line was none of the 14 lines of ridge or
// change; in a numpy copy of these sums it stands 9.9 spreads of all lines' sums out of their
// median, the next line 7.3, and on the copy 360 px wide it is second).
constexpr int kShaftLineMin_px = 40;
constexpr std::size_t kShaftLines = 3;
constexpr std::size_t kSpareShaftLines = 5;  // after them: spare lines (needleAxisCandidates)
LineSums shaftLineSums(const cv::Mat& mean, cv::Mat& departure)
{
    LineSums out;
    out.scale = std::min(1.0, 1024.0 / std::max(mean.cols, mean.rows));
    cv::Mat small, local;
    cv::resize(mean, small, cv::Size(), out.scale, out.scale, cv::INTER_AREA);
    cv::blur(small, local, cv::Size(15, 15));
    departure = small - local;
    // Text and bright bars count no more than a strong shaft.
    const auto [middle, spread] = middleAndSpread(departure);
    const float noise = std::max(1e-3f, spread);
    departure -= middle;
    cv::min(departure, 3.0f * noise, departure);
    cv::max(departure, -3.0f * noise, departure);
    const std::vector<cv::Mat> sums = sumAlongLines(departure, out);
    for (std::size_t a = 0; a < sums.size(); ++a) {
        cv::Mat row(sums[a].size(), CV_32F, cv::Scalar(0));
        for (int y = 0; y < row.rows; ++y) {
            const double length = lengthInside(departure.cols, departure.rows, int(a), y - out.diag / 2.0);
            if (length >= kShaftLineMin_px)
                row.at<float>(y) = float(std::abs(sums[a].at<float>(y)) / std::sqrt(length));
        }
        out.rows.push_back(row);
    }
    return out;
}

// The strongest lines of `sums` (local maxima across the lines of one angle), at most
// `maxCount`, lines alike (within 8 degrees and 8 pixels of the copy) counted once.
std::vector<LineCandidate> strongestLines(const LineSums& sums, std::size_t maxCount)
{
    std::vector<LineCandidate> candidates;
    for (int a = 0; a < int(sums.rows.size()); ++a) {
        const cv::Mat& rows = sums.rows[std::size_t(a)];
        for (int y = 1; y + 1 < rows.rows; ++y) {
            const float v = rows.at<float>(y);
            if (v > rows.at<float>(y - 1) && v >= rows.at<float>(y + 1))
                candidates.push_back({a, y, double(v)});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const LineCandidate& x, const LineCandidate& y) { return x.score > y.score; });
    std::vector<LineCandidate> kept;
    const double half = sums.diag / 2.0;
    for (const LineCandidate& c : candidates) {
        bool near = false;
        for (const LineCandidate& k : kept) {
            // (angle, rho) and (angle ± 180, −rho) are the same line.
            const int raw = std::abs(c.angle_deg - k.angle_deg);
            const bool wrapped = raw > 90;
            const int da = wrapped ? 180 - raw : raw;
            const double rho = c.row - half, krho = k.row - half;
            if (da < 8 && std::abs(rho - (wrapped ? -krho : krho)) < 8.0)
                near = true;
        }
        if (!near)
            kept.push_back(c);
        if (kept.size() >= maxCount)
            break;
    }
    return kept;
}

// The line of `c` across the whole picture (`width` × `height`).
NeedleAxis lineAcross(const LineSums& sums, const LineCandidate& c)
{
    // A horizontal line at height rho (from the centre) in the rotated copy: with
    // getRotationMatrix2D's y' = −sin·x + cos·y it runs along (cos, sin) in the picture, rho
    // along the normal (−sin, cos).
    const double th = c.angle_deg * M_PI / 180.0, rho = c.row - sums.diag / 2.0;
    const double dx = std::cos(th), dy = std::sin(th);
    const double nx = -std::sin(th), ny = std::cos(th);
    const double cx = (sums.centre.x + rho * nx) / sums.scale, cy = (sums.centre.y + rho * ny) / sums.scale;
    return NeedleAxis(QPointF(cx - dx * sums.diag, cy - dy * sums.diag), QPointF(cx + dx * sums.diag, cy + dy * sums.diag));
}

// The largest of `sums` along `axis` and the lines either side of it at its nearest whole degree.
double sumAlong(const LineSums& sums, const NeedleAxis& axis)
{
    const double angle = std::fmod(std::fmod(axis.angle(), 180.0) + 180.0, 180.0);
    const int a = int(std::lround(angle)) % 180;
    const double th = a * M_PI / 180.0;
    const QPointF mid = 0.5 * (axis.p1() + axis.p2()) * sums.scale;
    const double rho = (mid.x() - sums.centre.x) * -std::sin(th) + (mid.y() - sums.centre.y) * std::cos(th);
    const cv::Mat& rows = sums.rows[std::size_t(a)];
    const int row = int(std::lround(rho + sums.diag / 2.0));
    double best = 0.0;
    for (int y = std::max(0, row - 1); y <= std::min(rows.rows - 1, row + 1); ++y)
        best = std::max(best, double(rows.at<float>(y)));
    return best;
}

// Two lines that are one: within `angle_deg` and the middle of `b` within `distance_px` of `a`.
bool alike(const NeedleAxis& a, const NeedleAxis& b, double angle_deg = 5.0, double distance_px = 6.0)
{
    const double angle = std::abs(std::remainder(b.angle() - a.angle(), 180.0));
    const QPointF mid = 0.5 * (b.p1() + b.p2());
    const double dist = std::abs((a.x2() - a.x1()) * (a.y1() - mid.y()) - (a.x1() - mid.x()) * (a.y2() - a.y1())) / a.length();
    return angle < angle_deg && dist < distance_px;
}

// The stretch of `line` along which the picture changes at least half as much as at the most,
// the best of a few pixels either side (smoothed over 9 px); nothing when under 10 px.
std::optional<NeedleAxis> stretchOfChange(const cv::Mat& change, const NeedleAxis& line)
{
    const double len = line.length();
    if (len < 20)
        return std::nullopt;
    const QPointF u((line.x2() - line.x1()) / len, (line.y2() - line.y1()) / len), n(-u.y(), u.x());
    std::vector<double> along(std::size_t(len), 0.0);
    for (std::size_t i = 0; i < along.size(); ++i)
        for (int side = -3; side <= 3; ++side) {
            const QPointF p = line.p1() + u * double(i) + n * double(side);
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (x >= 0 && y >= 0 && x < change.cols && y < change.rows)
                along[i] = std::max(along[i], double(change.at<float>(y, x)));
        }
    cv::Mat smooth(along, true);
    cv::blur(smooth, smooth, cv::Size(1, 9));
    const std::vector<double> level(smooth.begin<double>(), smooth.end<double>());
    const auto peak = std::max_element(level.begin(), level.end());
    std::size_t from = std::size_t(peak - level.begin()), to = from;
    while (from > 0 && level[from - 1] >= 0.5 * *peak)
        --from;
    while (to + 1 < level.size() && level[to + 1] >= 0.5 * *peak)
        ++to;
    if (to < from + 10)
        return std::nullopt;
    return NeedleAxis(line.p1() + u * double(from), line.p1() + u * double(to));
}

// `segment`'s line across the whole picture; nothing when under 20 px of it is inside.
std::optional<NeedleAxis> acrossPicture(const NeedleAxis& segment, int width, int height)
{
    const double len = segment.length(), across = std::hypot(width, height);
    const QPointF v((segment.x2() - segment.x1()) / len, (segment.y2() - segment.y1()) / len);
    const NeedleAxis whole(segment.p1() - v * across, segment.p1() + v * across);
    const Strip clipper(whole, width, height, 0);
    if (clipper.length < 20)
        return std::nullopt;
    return NeedleAxis(whole.p1() + v * clipper.origin, whole.p1() + v * (clipper.origin + clipper.length));
}

// How much each pixel changes over the sampled frames (its standard deviation): the path
// of a moving tip stands out here even where the still picture around it (tissue texture,
// speckle) hides the shaft in the mean. `counted` says whether a pixel changes, not how much
// (clipped at three noise widths): a burnt-in clock's digits change far more than a faint
// needle's path, and its lines would outweigh the needle's. `measured` is how much (above the
// usual change), for where across a path it changes most.
struct PictureChange {
    cv::Mat counted, measured;
};

constexpr int kMaxPathWidth_px = 20;
constexpr std::size_t kStreaks = 8;
constexpr double kStreakLengthPerWidth = 2.0;
constexpr double kFlatPlateau = 0.005;  // lines within half a percent of the most sum alike
constexpr std::size_t kMostChangePaths = 2;  // tracked whatever their rank
constexpr std::size_t kMostApartPaths = 3;   // the same, with the changing digits set aside
constexpr double kPathLengthPerWidth = 4.0;

// A line along which a tip's path was seen, and the change summed along that path (a line a
// little across the path crosses it over a shorter stretch; the change there is as strong).
struct PathLine {
    NeedleAxis axis;
    double changeOnPath = 0.0;
    double ridge = 0.0;  // the ridge's line sum where it was found (LineSums units)
};

// Refines a line along which the picture changes to the tip's path on it: the stretch of
// change on the line, turned (±4°) and shifted (±3 px) to put the most change under it, then
// carried across the picture, again until it turns no more. The line sums find the path's
// angle only to a few degrees (lines within 8° count once), and a line a few degrees off
// crosses only part of the path (refined once, one path came out as lines 3.5° apart). Summed
// along the stretch, not the whole line: along the whole line a compressed picture's block
// pattern (rows of slightly more noise every 8 pixels) outweighed the path. Nothing when the
// change is a patch, not a line (the digits of a clock or counter), or shorter than
// `lengthPerWidth` times its width.
// The stretch and the width are read on `change` (PictureChange::counted), the turn and shift on
// `centredOn`: counted where digits change in the picture (they would pull the line), taking the
// middle of the lines that sum alike (`plateau`, as refineAxis takes it), and the change measured
// where the digits are set aside. Counted, a faint tip's path is a flat-topped band as wide as
// the blur, and the first line tried that sums the most lay 2-6 px and up to 2.3° off the needle
// (slow-small probe seed 5 case 9, seed 6 case 13: the needle's line not found).
std::optional<PathLine> refinePath(const cv::Mat& change, const cv::Mat& centredOn, double plateau, const NeedleAxis& rough,
                                   int width, int height, double lengthPerWidth = kPathLengthPerWidth)
{
    NeedleAxis line = rough, path = rough;
    for (int pass = 0; pass < 4; ++pass) {
        const std::optional<NeedleAxis> stretch = stretchOfChange(change, line);
        if (!stretch)
            return std::nullopt;
        path = refineAxis(centredOn, *stretch, 4.0, plateau);
        const std::optional<NeedleAxis> whole = acrossPicture(path, width, height);
        if (!whole)
            return std::nullopt;
        const double turned = std::abs(std::remainder(whole->angle() - line.angle(), 180.0));
        line = *whole;
        if (turned < 0.5)
            break;
    }
    const double pathLen = path.length();
    const QPointF v((path.x2() - path.x1()) / pathLen, (path.y2() - path.y1()) / pathLen), w(-v.y(), v.x());
    // A tip's path is a line of change, far longer than it is wide; a patch of changing digits
    // changes as much well beside the line as on it.
    auto meanAlong = [&](double side) {
        double sum = 0.0;
        int count = 0;
        for (double t = 0.0; t <= pathLen; t += 1.0) {
            const QPointF p = path.p1() + v * t + w * side;
            const int x = int(std::lround(p.x())), y = int(std::lround(p.y()));
            if (x >= 0 && y >= 0 && x < change.cols && y < change.rows) {
                sum += change.at<float>(y, x);
                ++count;
            }
        }
        return count > 0 ? sum / count : 0.0;
    };
    const double onLine = meanAlong(0.0);
    if (!(onLine > 0.0))
        return std::nullopt;
    int wide = 1;
    for (int side = 1; side <= kMaxPathWidth_px && meanAlong(side) >= 0.5 * onLine; ++side)
        ++wide;
    for (int side = 1; side <= kMaxPathWidth_px && meanAlong(-side) >= 0.5 * onLine; ++side)
        ++wide;
    if (wide > kMaxPathWidth_px || pathLen < lengthPerWidth * wide)
        return std::nullopt;
    return PathLine{line, onLine * pathLen, 0.0};
}

PictureChange changeOverFrames(const FrameSamples& s, const cv::Mat& mean)
{
    cv::Mat squares = cv::Mat::zeros(s.height, s.width, CV_32F);
    for (const cv::Mat& f : s.gray)
        cv::accumulateSquare(f, squares);
    cv::Mat variance = squares / double(s.gray.size()) - mean.mul(mean), deviation;
    cv::max(variance, 0.0, variance);
    cv::sqrt(variance, deviation);
    cv::GaussianBlur(deviation, deviation, cv::Size(0, 0), 1.0);
    std::vector<float> values(deviation.begin<float>(), deviation.end<float>());
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    const float usual = values[values.size() / 2];
    for (float& v : values)
        v = std::abs(v - usual);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    const float noise = std::max(1e-3f, 1.4826f * values[values.size() / 2]);
    PictureChange out;
    deviation -= usual;
    cv::max(deviation, 0.0f, out.measured);
    cv::min(out.measured, 3.0f * noise, out.counted);
    return out;
}

// Where burnt-in text changes (a clock's or a counter's digits): patches of change wider every
// way than a tip's path (a square of 11 px fits inside them, where a tip's path is a few pixels
// wide), and a few pixels round them.
cv::Mat changingPatches(const cv::Mat& change)
{
    double top = 0.0;
    cv::minMaxLoc(change, nullptr, &top);
    cv::Mat patches = change >= 0.5 * top;
    cv::morphologyEx(patches, patches, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(11, 11)));
    cv::dilate(patches, patches, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(9, 9)));
    return patches;
}

// The short streaks of change (blobs of half the strongest change or more, kSpareStreakMin_px
// long or more (twice the blob's major semi-axis) and twice as long as wide), each as a rough
// line along it across the picture, the largest first: a tip that moves a few millimetres draws
// a path too short to stand out of the line sums, where the rows of a coder's blocks, summed over
// the whole picture, do (slow-small probe seed 5 case 9: a path of 19 px by 10 at -94.6°, the 32
// strongest lines of change all within 11° of the rows).
constexpr double kStreakMin_px = 20.0;       // taken as candidates
constexpr double kSpareStreakMin_px = 14.0;  // spare: a tip's path of 12 px (a stroke of ±6 px)
struct Streak {
    double length_px = 0.0;
    NeedleAxis line;
};
std::vector<Streak> streaksOfChange(const cv::Mat& counted, int width, int height)
{
    double top = 0.0;
    cv::minMaxLoc(counted, nullptr, &top);
    if (!(top > 0.0))
        return {};
    const cv::Mat mask = counted >= 0.5 * top;
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    std::vector<std::pair<int, Streak>> streaks;  // (area, streak)
    for (int i = 1; i < n; ++i) {
        const int area = stats.at<int>(i, cv::CC_STAT_AREA);
        if (area < 20)
            continue;
        const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP), stats.at<int>(i, cv::CC_STAT_WIDTH),
                           stats.at<int>(i, cv::CC_STAT_HEIGHT));
        const cv::Moments m = cv::moments(labels(box) == i, true);
        const double mu20 = m.mu20 / m.m00, mu02 = m.mu02 / m.m00, mu11 = m.mu11 / m.m00;
        const double common = std::sqrt(4.0 * mu11 * mu11 + (mu20 - mu02) * (mu20 - mu02));
        const double major = std::sqrt(std::max(0.0, 2.0 * (mu20 + mu02 + common)));
        const double minor = std::sqrt(std::max(0.0, 2.0 * (mu20 + mu02 - common)));
        if (2.0 * major < kSpareStreakMin_px || major < 2.0 * std::max(minor, 1.0))
            continue;
        const double angle = 0.5 * std::atan2(2.0 * mu11, mu20 - mu02);
        const QPointF c(box.x + m.m10 / m.m00, box.y + m.m01 / m.m00), u(std::cos(angle), std::sin(angle));
        if (const std::optional<NeedleAxis> line = acrossPicture(NeedleAxis(c - u * major, c + u * major), width, height))
            streaks.emplace_back(area, Streak{2.0 * major, *line});
    }
    std::stable_sort(streaks.begin(), streaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<Streak> out;
    for (const auto& [area, streak] : streaks)
        out.push_back(streak);
    return out;
}

// The first kStreaks of `streaks` at least `minLength_px` long.
std::vector<NeedleAxis> longestFirst(const std::vector<Streak>& streaks, double minLength_px)
{
    std::vector<NeedleAxis> out;
    for (const Streak& st : streaks)
        if (st.length_px >= minLength_px && out.size() < kStreaks)
            out.push_back(st.line);
    return out;
}

}  // namespace

std::vector<NeedleAxis> needleAxisCandidates(FrameReader& reader, QRect roi, int maxCount, int sampleFrames_,
                                             std::vector<double>* scores)
{
    return needleAxisCandidates(sampleFrames(reader, sampleFrames_), roi, maxCount, scores);
}

std::vector<NeedleAxis> needleAxisCandidates(const FrameSamples& s, QRect roi, int maxCount, std::vector<double>* scores,
                                             std::vector<std::pair<double, NeedleAxis>>* spares)
{
    if (s.gray.size() < 3)
        return {};
    const cv::Mat mean = framesMean(s);
    // Thin structures of either polarity: the picture minus its local mean.
    cv::Mat local, ridge;
    cv::blur(mean, local, cv::Size(15, 15));
    ridge = cv::abs(mean - local);
    cv::GaussianBlur(ridge, ridge, cv::Size(0, 0), 1.0);

    // The strongest straight lines of the ridge are the candidates, and the strongest lines
    // along which the picture changes: a thin needle on textured tissue (speckle as strong as
    // the shaft) ranks below the texture's lines in the ridge, but its tip's path is the only
    // line that changes (a look not made by our renderer, 1024x768 MJPEG, a needle 26 grey
    // levels bright on texture of 25: no needle found and the sync was off by 7 s).
    const LineSums ridgeSums = lineSums(ridge);
    const PictureChange picture = changeOverFrames(s, mean);
    const cv::Mat& change = picture.counted;
    const LineSums changeSums = lineSums(change);
    // Line `c` of `sums`, as far as it runs inside the picture.
    auto clipped = [&](const LineSums& sums, const LineCandidate& c) -> std::optional<NeedleAxis> {
        const NeedleAxis rough = lineAcross(sums, c);
        const Strip clipper(rough, s.width, s.height, 0);
        if (clipper.length < 20)
            return std::nullopt;
        const double len = rough.length();
        const QPointF u((rough.x2() - rough.x1()) / len, (rough.y2() - rough.y1()) / len);
        return NeedleAxis(rough.p1() + u * clipper.origin, rough.p1() + u * (clipper.origin + clipper.length));
    };
    // The ridge's line sum under line `c` of a picture's sums (all share the ridge's geometry),
    // by which a line of the ridge is ranked.
    auto ridgeUnder = [&](const LineCandidate& c) {
        double most = 0.0;
        const cv::Mat& rows = ridgeSums.rows[std::size_t(c.angle_deg)];
        for (int y = std::max(0, c.row - 1); y <= std::min(rows.rows - 1, c.row + 1); ++y)
            most = std::max(most, double(rows.at<float>(y)));
        return most;
    };
    std::vector<std::pair<double, NeedleAxis>> scored;
    for (const LineCandidate& c : strongestLines(ridgeSums, 16)) {
        const std::optional<NeedleAxis> rough = clipped(ridgeSums, c);
        if (!rough)
            continue;
        const NeedleAxis axis = shaftBehindTip(s, refineAxis(ridge, *rough));
        // Noise alone gives a strongest edge about 3 σ above the noise; but under heavy noise a
        // tip's edge in single frames is no more, while its shaft is the strongest line of the
        // picture (probe seed 531911 case 11: 2.8 σ, the line 25 % above the next, and the sync
        // 24 frames off without it). Such lines are tracked too, ranked by what they show;
        // which line is the needle, the fit to the recording decides.
        const double snr = movingEdgeSnr(s, axis);
        if (snr >= 2.0)
            scored.emplace_back(snr * std::sqrt(c.score), axis);
    }
    // One path is crossed by several of the strongest lines of change, each refined onto it a
    // little differently: the one with the most change under it is the path (kept the first
    // found, a line 0.6° and 5 px off it lost the tip in 261 frames of 512).
    std::vector<PathLine> paths;
    for (LineCandidate c : strongestLines(changeSums, 32)) {
        const std::optional<NeedleAxis> rough = clipped(ridgeSums, c);
        std::optional<PathLine> path = rough ? refinePath(change, change, kFlatPlateau, *rough, s.width, s.height) : std::nullopt;
        if (!path)
            continue;
        // Ranked by the ridge under the line it was found from, as the ridge's own lines are.
        path->ridge = ridgeUnder(c);
        const auto same = std::find_if(paths.begin(), paths.end(), [&](const PathLine& p) { return alike(p.axis, path->axis); });
        if (same == paths.end())
            paths.push_back(*path);
        else if (path->changeOnPath > same->changeOnPath)
            *same = {path->axis, path->changeOnPath, std::max(path->ridge, same->ridge)};
    }
    // The lines along which a shaft stands out of the mean most (a faint needle on a grain as
    // fine as it: the ridge's lines are the grain's), refined onto the shaft's own sign.
    std::vector<std::pair<double, NeedleAxis>> shafts, spareShafts;
    cv::Mat departure;
    const LineSums shaftSums = shaftLineSums(mean, departure);
    cv::resize(departure, departure, mean.size(), 0, 0, cv::INTER_LINEAR);
    const std::vector<LineCandidate> shaftLines = strongestLines(shaftSums, kShaftLines + (spares ? kSpareShaftLines : 0));
    for (std::size_t k = 0; k < shaftLines.size(); ++k) {
        const LineCandidate& c = shaftLines[k];
        const std::optional<NeedleAxis> rough = clipped(shaftSums, c);
        if (!rough)
            continue;
        const Strip line(*rough, s.width, s.height, 0);
        cv::Mat along;
        cv::remap(departure, along, line.mapX, line.mapY, cv::INTER_LINEAR);
        const cv::Mat shaft = cv::sum(along)[0] < 0 ? cv::Mat(-departure) : departure;
        const NeedleAxis axis = shaftBehindTip(s, refineAxis(shaft, *rough));
        // Ranked as a line of change is (what it shows moving, and the ridge under it), and
        // tracked even when that ranks it below the lines kept: a faint needle's ridge is low
        // and its tip's edge barely moves in single frames (246810 case 10: 17th of 17).
        const double score = std::max(movingEdgeSnr(s, axis), 2.0) * std::sqrt(sumAlong(ridgeSums, axis));
        if (k >= kShaftLines) {
            spareShafts.emplace_back(score, axis);
            continue;
        }
        shafts.emplace_back(score, axis);
        scored.push_back(shafts.back());
    }
    std::vector<std::pair<double, std::pair<double, NeedleAxis>>> pathsByChange;  // (change on the path, (score, axis))
    for (const PathLine& p : paths) {
        // A path of change is evidence of a tip of its own, where single frames are too noisy
        // to show its edge (15 frames/s MJPEG, needle 32 grey levels under noise of 21: 0.9 σ
        // on its path, which the sync then followed to within a frame).
        const NeedleAxis axis = shaftBehindTip(s, p.axis);
        scored.emplace_back(std::max(movingEdgeSnr(s, axis), 3.0) * std::sqrt(p.ridge), axis);
        pathsByChange.emplace_back(p.changeOnPath, scored.back());
    }
    std::sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // The region the operator drew (if any) says where the needle is: lines found in the
    // whole picture (a part of a line is too short to find it reliably) that cross it.
    auto crosses = [&](const NeedleAxis& axis) {
        for (double t = 0; t <= 1.0; t += 0.01)
            if (roi.contains(axis.pointAt(t).toPoint()))
                return true;
        return false;
    };
    if (!roi.isEmpty() && std::any_of(scored.begin(), scored.end(), [&](const auto& c) { return crosses(c.second); })) {
        auto outside = [&](const auto& c) { return !crosses(c.second); };
        scored.erase(std::remove_if(scored.begin(), scored.end(), outside), scored.end());
        shafts.erase(std::remove_if(shafts.begin(), shafts.end(), outside), shafts.end());
    }
    // Refined lines that ended up alike count once.
    std::vector<NeedleAxis> out;
    auto keep = [&](double score, const NeedleAxis& axis, double angle_deg, double distance_px) {
        if (std::any_of(out.begin(), out.end(), [&](const NeedleAxis& o) { return alike(o, axis, angle_deg, distance_px); }))
            return;
        out.push_back(axis);
        if (scores)
            scores->push_back(score);
    };
    for (const auto& [score, axis] : scored)
        if (int(out.size()) < maxCount)
            keep(score, axis, 5.0, 6.0);
    // A line of the ridge, found on a copy a third as wide, may cross a faint shaft at a few
    // degrees, where the line the shaft itself gives lies along it (probe seed 187716 case 15:
    // 3.0° and 0.1° off the needle); both are tracked.
    for (const auto& [score, axis] : shafts)
        keep(score, axis, 1.0, 3.0);
    // The paths with the most change under them are tracked too, when they ranked lower: a
    // faint needle's ridge is low, and the lines across a clock's row of digits rank above it
    // (probe seed 161803 case 0: the needle's path, 192 units of change against about 100 along
    // the clock's row, ranked below 16 lines through the clock and the counter).
    std::sort(pathsByChange.begin(), pathsByChange.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; k < pathsByChange.size() && k < kMostChangePaths; ++k) {
        const auto& [score, axis] = pathsByChange[k].second;
        if (roi.isEmpty() || crosses(axis))
            keep(score, axis, 5.0, 6.0);
    }
    // Burnt-in digits that change outweigh a short path in the sums of change (probe seed 820417
    // case 5: a tip moving ±11 px, the 32 strongest lines of change all through a clock and a
    // counter or along the rows of an MJPEG's blocks, none on the needle). With the patches of
    // change set aside, the three lines of change with a moving edge and the most change on their
    // path that no line kept is alike are tracked too, and so are the short streaks of change
    // (streaksOfChange). Not two: a needle at −92° in a 320x240 MPEG-4 picture with a counter
    // and a clock left a path with 21.5 units of change on it and an edge 7 times its noise,
    // third of the four such lines; no line tracked was the needle, and the sync was 245 frames
    // off (slow-small probe seed 287761 case 14). With the digits set aside, how much a pixel
    // changes says where the path's middle is (refinePath): such a path lies on the needle, and
    // is alike another line only within 1° and 3 px, as the shafts' lines are (slow-small probe
    // seed 5 case 9: a line from the ridge 2.3° off the needle, its track lost; the path's line,
    // 0.2° off, had been dropped as alike it).
    const cv::Mat patches = changingPatches(change);
    PictureChange apart{change.clone(), picture.measured.clone()};
    apart.counted.setTo(0.0f, patches);
    apart.measured.setTo(0.0f, patches);
    // A rough line refined onto the path of change on it: (change on the path, the line behind
    // the tip, how clearly an edge moves along it).
    struct ApartPath {
        double changeOnPath = 0.0;
        NeedleAxis axis;
        double snr = 0.0;
    };
    auto pathApart = [&](const NeedleAxis& rough, double lengthPerWidth) -> std::optional<ApartPath> {
        const std::optional<PathLine> path = refinePath(apart.counted, apart.measured, 0.0, rough, s.width, s.height, lengthPerWidth);
        if (!path)
            return std::nullopt;
        const NeedleAxis axis = shaftBehindTip(s, path->axis);
        return ApartPath{path->changeOnPath, axis, movingEdgeSnr(s, axis)};
    };
    std::vector<std::pair<double, std::pair<double, NeedleAxis>>> apartByChange;
    auto addApart = [&](const NeedleAxis& rough, double ridgeThere, double lengthPerWidth) {
        if (const std::optional<ApartPath> p = pathApart(rough, lengthPerWidth); p && p->snr >= 2.0)
            apartByChange.emplace_back(p->changeOnPath, std::pair{p->snr * std::sqrt(ridgeThere), p->axis});
    };
    for (const LineCandidate& c : strongestLines(lineSums(apart.counted), 32))
        if (const std::optional<NeedleAxis> rough = clipped(ridgeSums, c))
            addApart(*rough, ridgeUnder(c), kPathLengthPerWidth);
    const std::vector<Streak> streaks = streaksOfChange(apart.counted, s.width, s.height);
    for (const NeedleAxis& rough : longestFirst(streaks, kStreakMin_px))
        addApart(rough, sumAlong(ridgeSums, rough), kStreakLengthPerWidth);
    std::sort(apartByChange.begin(), apartByChange.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::size_t added = 0;
    for (const auto& [onPath, scoredAxis] : apartByChange) {
        if (added == kMostApartPaths)
            break;
        const std::size_t before = out.size();
        if (roi.isEmpty() || crosses(scoredAxis.second))
            keep(scoredAxis.first, scoredAxis.second, 1.0, 3.0);
        added += out.size() - before;
    }
    // Spare: the shafts of the frames' mean that ranked after those kept, when no line kept is
    // alike them. Burnt-in text's rows outrank a faint shaft there (slow-small 112358 #17: the
    // needle's line the fourth to eighth of them, 35 grey levels over grain of 25, the text
    // rows first).
    // And the short streaks of change, down to a tip's path of 12 px, whatever edge single frames
    // show moving along them: a faint tip's path of 17 px by 8 at the top of a 320x240 MJPEG picture
    // was the largest blob of change by twice, and the shaft behind it too faint to find in the
    // mean; tracked, the sync was 0.4 frames off, where it had been 76 frames off (slow-small
    // 112358 #5). A needle 26 grey levels over noise of 20.5 left a path of 23 px whose edge moves
    // 0.95 times its noise in single frames (60613 #5, 47 frames off).
    auto spare = [&](double score, const NeedleAxis& axis) {
        if ((roi.isEmpty() || crosses(axis))
            && std::none_of(out.begin(), out.end(), [&](const NeedleAxis& o) { return alike(o, axis, 1.0, 3.0); })
            && std::none_of(spares->begin(), spares->end(), [&](const auto& o) { return alike(o.second, axis, 1.0, 3.0); }))
            spares->emplace_back(score, axis);
    };
    if (spares) {
        for (const auto& [score, axis] : spareShafts)
            spare(score, axis);
        for (const NeedleAxis& rough : longestFirst(streaks, kSpareStreakMin_px))
            if (const std::optional<ApartPath> p = pathApart(rough, kStreakLengthPerWidth))
                spare(std::max(p->snr, 2.0) * std::sqrt(sumAlong(ridgeSums, rough)), p->axis);
    }
    return out;
}

std::optional<NeedleAxis> detectNeedleAxis(FrameReader& reader, QRect roi, int sampleFrames)
{
    const std::vector<NeedleAxis> c = needleAxisCandidates(reader, roi, 1, sampleFrames);
    if (c.empty())
        return std::nullopt;
    return c.front();
}

}  // namespace nb::video
