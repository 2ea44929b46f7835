#include "surface_trace.h"

#include "needle_axis_finder.h"
#include "needle_tracker.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace nb::video {

SurfaceTrace surfaceTraceFromShifts(const TissueShifts& s, const TimelineMapping& mapping)
{
    SurfaceTrace out;
    const std::size_t k = std::min({s.time_s.size(), s.dt_s.size(), s.dx_px.size(), s.dy_px.size()});
    if (k == 0)
        return out;
    // The principal axis of the shifts: the spring-back's few large steps and the carried
    // motion before it both lie along the needle.
    const auto [ux, uy] = principalShiftAxis(s, k);
    // Positions at the frames' own times: the first frame's, then each later frame's.
    double position = 0.0;
    out.time_s.push_back(mapping.toRecording(s.time_s[0] - 0.5 * s.dt_s[0]));
    out.displacement_px.push_back(position);
    for (std::size_t i = 0; i < k; ++i) {
        position += s.dx_px[i] * ux + s.dy_px[i] * uy;
        out.time_s.push_back(mapping.toRecording(s.time_s[i] + 0.5 * s.dt_s[i]));
        out.displacement_px.push_back(position);
    }
    return out;
}

}  // namespace nb::video

namespace nb::video {

namespace {

constexpr int kSurfaceWorkingSize_px = 480;  // longer side the picture is reduced to
constexpr double kRekey_bins = 6.0;   // the reference moves on beyond this (as in tissue_tracker)
constexpr double kSmooth_bins = 1.5;  // profile smoothing before the gradient
constexpr int kBackgroundRounds = 3;  // the background taken again, the surface tracked again

cv::Mat workingGray(const cv::Mat& gray, double scale)
{
    cv::Mat small;
    if (scale < 1.0)
        cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
    else
        small = gray;
    return small;
}

// Shift (bins) of `current` against `reference` that matches best within ±range, sub-bin by a
// parabola through the peak; `score` gets the normalised correlation there.
double matchShift(const std::vector<double>& reference, const std::vector<double>& current, int range, double* score)
{
    const int n = int(reference.size());
    std::vector<double> c(std::size_t(2 * range + 1), -2.0);
    for (int k = -range; k <= range; ++k) {
        double sab = 0, saa = 0, sbb = 0;
        for (int s = std::max(0, -k); s < std::min(n, n - k); ++s) {
            const double a = reference[std::size_t(s)], b = current[std::size_t(s + k)];
            sab += a * b, saa += a * a, sbb += b * b;
        }
        if (saa > 0 && sbb > 0)
            c[std::size_t(k + range)] = sab / std::sqrt(saa * sbb);
    }
    const int best = int(std::max_element(c.begin(), c.end()) - c.begin());
    double offset = 0.0;
    if (best > 0 && best < 2 * range) {
        const double l = c[std::size_t(best - 1)], m = c[std::size_t(best)], r = c[std::size_t(best + 1)];
        const double den = l - 2 * m + r;
        if (den < 0)
            offset = std::clamp(0.5 * (l - r) / den, -0.5, 0.5);
    }
    if (score)
        *score = c[std::size_t(best)];
    return best - range + offset;
}

// `p` moved by `by` bins (what was at x − by is at x), linearly between bins, its ends held.
std::vector<double> moved(const std::vector<double>& p, double by)
{
    const int n = int(p.size());
    std::vector<double> out(p.size());
    for (int x = 0; x < n; ++x) {
        const double from = std::clamp(x - by, 0.0, double(n - 1));
        const int i = std::min(int(from), n - 2);
        const double f = from - i;
        out[std::size_t(x)] = (1.0 - f) * p[std::size_t(i)] + f * p[std::size_t(i) + 1];
    }
    return out;
}

// What stays put behind the surface, given where the surface's layer is in each profile
// (`positions`, bins): each profile is the background and the layer moved into place. In turn,
// the layer is the mean of the profiles less the background, moved back into line, and the
// background the mean of the profiles less the layer moved into place; from `background`.
std::vector<double> stillBackground(const std::vector<std::vector<double>>& profiles, const std::vector<double>& positions,
                                    std::vector<double> background)
{
    const std::size_t length = background.size();
    const double n = double(profiles.size());
    for (int round = 0; round < 3; ++round) {
        std::vector<double> layer(length, 0.0), next(length, 0.0);
        for (std::size_t k = 0; k < profiles.size(); ++k) {
            std::vector<double> d(length);
            for (std::size_t b = 0; b < length; ++b)
                d[b] = profiles[k][b] - background[b];
            const std::vector<double> back = moved(d, -positions[k]);
            for (std::size_t b = 0; b < length; ++b)
                layer[b] += back[b] / n;
        }
        for (std::size_t k = 0; k < profiles.size(); ++k) {
            const std::vector<double> there = moved(layer, positions[k]);
            for (std::size_t b = 0; b < length; ++b)
                next[b] += (profiles[k][b] - there[b]) / n;
        }
        background = std::move(next);
    }
    return background;
}

}  // namespace

SurfaceTrace trackSurfaceEdges(FrameReader& reader, const QLineF& axis, const TimelineMapping& mapping)
{
    SurfaceTrace out;
    const FrameIndex& index = reader.index();
    const int n = index.size();
    if (n < 2 || axis.length() <= 0.0)
        return out;
    const double scale = std::min(1.0, double(kSurfaceWorkingSize_px) / std::max(index.width, index.height));
    const double ux = (axis.p2().x() - axis.p1().x()) / axis.length(), uy = (axis.p2().y() - axis.p1().y()) / axis.length();
    // Each working pixel's place along the axis, shared between two bins.
    const int w = std::max(1, int(std::lround(index.width * scale))), h = std::max(1, int(std::lround(index.height * scale)));
    const double half = 0.5 * std::hypot(w, h);
    const int bins = int(std::ceil(2 * half)) + 2;
    std::vector<int> bin(std::size_t(w) * std::size_t(h));
    std::vector<float> frac(bin.size());
    std::vector<double> count(std::size_t(bins), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double s = (x - 0.5 * w) * ux + (y - 0.5 * h) * uy + half;
            const int b = std::clamp(int(std::floor(s)), 0, bins - 2);
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            bin[i] = b;
            frac[i] = float(s - b);
            count[std::size_t(b)] += 1.0 - frac[i];
            count[std::size_t(b) + 1] += frac[i];
        }
    // Bins across a corner of the picture hold few pixels and much noise: only where the
    // picture is at least a third as wide across the axis as at its widest.
    const double widest = *std::max_element(count.begin(), count.end());
    int first = 0, last = bins - 1;
    while (first < bins && count[std::size_t(first)] < widest / 3)
        ++first;
    while (last > first && count[std::size_t(last)] < widest / 3)
        --last;
    const int length = last - first + 1;
    if (length < 16)
        return out;
    std::vector<std::vector<double>> profiles;
    std::vector<double> times;
    cv::Mat lastShown;
    for (int k = 0; k < n; ++k) {
        // The same picture again: no motion to measure (also where the index does not say so:
        // indexed from the file's packets, a long video).
        const std::optional<cv::Mat> decoded = reader.grayUnlessDamaged(k);
        if (!decoded)
            continue;  // in a damaged stretch of the file: left out, as a repeated picture is
        const cv::Mat g = workingGray(*decoded, scale);
        const bool repeated = k > 0 && (index.frames[std::size_t(k)].duplicate || samePicture(lastShown, g));
        lastShown = g;
        if (repeated)
            continue;
        if (g.cols != w || g.rows != h)
            continue;
        std::vector<double> sum(std::size_t(bins), 0.0);
        for (int y = 0; y < h; ++y) {
            const unsigned char* row = g.ptr<unsigned char>(y);
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                sum[std::size_t(bin[i])] += (1.0 - frac[i]) * row[x];
                sum[std::size_t(bin[i]) + 1] += frac[i] * row[x];
            }
        }
        std::vector<double> p(static_cast<std::size_t>(length));
        for (int b = 0; b < length; ++b)
            p[std::size_t(b)] = sum[std::size_t(first + b)] / count[std::size_t(first + b)];
        const double t = index.frames[std::size_t(k)].time_s;
        if (!times.empty() && t <= times.back())
            continue;
        profiles.push_back(std::move(p));
        times.push_back(t);
    }
    if (profiles.size() < 2)
        return out;
    // What stays put over the video (plates, overlays, the surround) is taken away; the
    // gradient of what is left carries the moving edges. At first that is the profiles' mean;
    // but where the surface rests for long, its edge is in the mean too, stays put, and holds
    // the match back: a spring-back of τ 0.080 s read as 0.117 (bench_accuracy --seed 1205
    // relaxation case 5: a blurred picture with little texture, relaxation 6.6 frames late).
    // So the background is taken again as what the profiles hold besides the surface's layer
    // moved as tracked, and the surface tracked again on it: τ 0.092, 0.088, 0.087.
    std::vector<double> background(std::size_t(length), 0.0);
    for (const auto& p : profiles)
        for (int b = 0; b < length; ++b)
            background[std::size_t(b)] += p[std::size_t(b)] / double(profiles.size());
    const int radius = int(std::ceil(3 * kSmooth_bins));
    std::vector<double> kernel(std::size_t(2 * radius + 1));
    for (int j = -radius; j <= radius; ++j)
        kernel[std::size_t(j + radius)] = std::exp(-0.5 * j * j / (kSmooth_bins * kSmooth_bins));
    auto gradient = [&](const std::vector<double>& p) {
        std::vector<double> s(std::size_t(length), 0.0), g(std::size_t(length), 0.0);
        for (int b = 0; b < length; ++b) {
            double acc = 0, wsum = 0;
            for (int j = -radius; j <= radius; ++j)
                if (b + j >= 0 && b + j < length) {
                    acc += kernel[std::size_t(j + radius)] * (p[std::size_t(b + j)] - background[std::size_t(b + j)]);
                    wsum += kernel[std::size_t(j + radius)];
                }
            s[std::size_t(b)] = acc / wsum;
        }
        for (int b = 1; b + 1 < length; ++b)
            g[std::size_t(b)] = 0.5 * (s[std::size_t(b + 1)] - s[std::size_t(b - 1)]);
        return g;
    };
    // Matched against a reference profile, which moves on when the picture has moved well
    // away from it (as in tissue_tracker: sub-bin motion does not add up its errors).
    const int range = std::max(8, length / 6);
    auto track = [&] {
        std::vector<double> reference = gradient(profiles.front()), previous = reference;
        double referencePosition = 0.0, previousPosition = 0.0;
        std::vector<double> positions{0.0};
        for (std::size_t k = 1; k < profiles.size(); ++k) {
            const std::vector<double> g = gradient(profiles[k]);
            double score = 0.0;
            double position = referencePosition + matchShift(reference, g, range, &score);
            if (std::abs(position - referencePosition) > kRekey_bins || score < 0.5) {
                reference = previous;
                referencePosition = previousPosition;
                position = referencePosition + matchShift(reference, g, range, &score);
            }
            positions.push_back(position);
            previous = g;
            previousPosition = position;
        }
        return positions;
    };
    std::vector<double> positions = track();
    for (int round = 0; round < kBackgroundRounds; ++round) {
        background = stillBackground(profiles, positions, background);
        positions = track();
    }
    for (std::size_t k = 0; k < profiles.size(); ++k) {
        out.time_s.push_back(mapping.toRecording(times[k]));
        out.displacement_px.push_back(positions[k] / scale);
    }
    return out;
}

}  // namespace nb::video

namespace nb::video {

std::vector<SurfaceTrace> surfaceTraces(FrameReader& reader, const TissueShifts& shifts, const TimelineMapping& mapping,
                                        const QString& name)
{
    std::vector<SurfaceTrace> out;
    // The edges along the direction the picture moves in most (the texture's shifts), and
    // along the needle where it is found at another angle: a found "needle" may be some other
    // straight line (a plate's edge), and a texture too faint to follow may give a wrong
    // direction; the fit decides between them.
    std::vector<QLineF> axes;
    const FrameIndex& index = reader.index();
    const QPointF centre(0.5 * index.width, 0.5 * index.height);
    double sxx = 0, sxy = 0, syy = 0;
    for (std::size_t i = 0; i < std::min({shifts.dx_px.size(), shifts.dy_px.size()}); ++i) {
        sxx += shifts.dx_px[i] * shifts.dx_px[i];
        sxy += shifts.dx_px[i] * shifts.dy_px[i];
        syy += shifts.dy_px[i] * shifts.dy_px[i];
    }
    if (sxx + syy > 0.0) {
        const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
        axes.push_back(QLineF(centre, centre + QPointF(std::cos(angle), std::sin(angle))));
    }
    if (const std::optional<QLineF> needle = detectNeedleAxis(reader)) {
        const double apart = axes.empty() ? 90.0 : std::fmod(std::abs(axes.front().angleTo(*needle)), 180.0);
        if (std::min(apart, 180.0 - apart) > 10.0)
            axes.push_back(*needle);
    }
    for (std::size_t k = 0; k < axes.size(); ++k) {
        SurfaceTrace edges = trackSurfaceEdges(reader, axes[k], mapping);
        if (edges.time_s.size() >= 2) {
            edges.source = name + (k == 0 ? QStringLiteral(" (edges along the motion)") : QStringLiteral(" (edges along the needle)"));
            out.push_back(std::move(edges));
        }
    }
    SurfaceTrace texture = surfaceTraceFromShifts(shifts, mapping);
    if (texture.time_s.size() >= 2) {
        texture.source = name + QStringLiteral(" (texture)");
        out.push_back(std::move(texture));
    }
    return out;
}

}  // namespace nb::video
