#include "tissue_tracker.h"
#include "core/tr.h"

#include "phase_correlation.h"
#include "video_error.h"

#include <QFileInfo>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>

namespace nb::video {

namespace {

constexpr int kWorkingSize_px = 480;  // longer side the picture is reduced to (speed; the texture survives)
constexpr int kBackgroundFrames = 41; // frames whose median is the static background
// The tissue's texture is coarser than the picture's noise (grain, compression): smoothed at
// this scale (in the working picture) before matching, heavy noise no longer decides the
// match, while the texture still does.
constexpr double kTextureBlur_px = 3.0;
constexpr double kScaleSpan_s = 0.2;  // stretch of video over which the scale is read

cv::Mat workingImage(const cv::Mat& grayFrame, const cv::Rect& roi, double scale)
{
    const cv::Mat gray = grayFrame(roi);
    cv::Mat small;
    if (scale < 1.0)
        cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
    else
        small = gray;
    cv::Mat f;
    small.convertTo(f, CV_32F);
    return f;
}

// The texture is also finer than about 8 px: coarser brightness (the tissue's bright body,
// the smeared copies of its outline that the mean background leaves where it rests longest)
// is taken away before the match. Under the match's window, which tapers the picture towards
// its edges and does not move, such brightness becomes a pattern that stays put and pulls the
// match towards zero shift; a thin slab has too little texture to outvote it (a 13 mm slab
// read at rest while it was carried at 10 mm/s). Found while the taper was applied again at
// every match (below); with each picture tapered once it still decided one case of the
// thickness matrix when last measured without it, at 16c725f (bench_accuracy --seed 191679
// --phase-thickness-mm 10:30, case 14: 88.2 % with it, 85.4 % without; the other 71 runs
// tried the same). This is that brightness:
// three box filters (17, 15, 17 px wide, a spread of 8.2 px) at a fixed cost per pixel, where
// a Gaussian kernel that wide took 12 ms a frame (bench_video). Not from a smaller copy: its
// grid would be a pattern that stays put.
cv::Mat coarseOf(const cv::Mat& image)
{
    cv::Mat coarse;
    cv::blur(image, coarse, cv::Size(17, 17), cv::Point(-1, -1), cv::BORDER_REFLECT);
    cv::blur(coarse, coarse, cv::Size(15, 15), cv::Point(-1, -1), cv::BORDER_REFLECT);
    cv::blur(coarse, coarse, cv::Size(17, 17), cv::Point(-1, -1), cv::BORDER_REFLECT);
    return coarse;
}

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x)
{
    if (t.empty())
        return 0.0;
    if (x <= t.front())
        return v.front();
    if (x >= t.back())
        return v.back();
    const std::size_t i = std::size_t(std::upper_bound(t.begin(), t.end(), x) - t.begin());
    const double w = (x - t[i - 1]) / std::max(1e-12, t[i] - t[i - 1]);
    return v[i - 1] + w * (v[i] - v[i - 1]);
}

double quantileOf(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

}  // namespace

TissueShifts trackTissueShifts(FrameReader& reader, QRect roi, const std::function<void(int, int)>& progress,
                               const std::atomic_bool* cancel)
{
    const FrameIndex& index = reader.index();
    TissueShifts out;
    const int n = index.size();
    if (n < 2)
        return out;
    const cv::Rect full(0, 0, index.width, index.height);
    cv::Rect r = roi.isEmpty() ? full : (cv::Rect(roi.x(), roi.y(), roi.width(), roi.height()) & full);
    if (r.width < 16 || r.height < 16)
        throw VideoError(index.path, nb::TrDevices::tr("the region for the tissue's motion is too small or outside the picture"));
    const double scale = std::min(1.0, double(kWorkingSize_px) / std::max(r.width, r.height));
    // What does not move (plates, the surround, burnt-in text) would pull the match to zero
    // shift: its per-pixel mean over frames spread through the video is taken away first. (The
    // mean, not the median: the tissue rests at two places, and a median keeps one of them
    // sharp, which would pull to zero in its turn; the mean smears it along the motion.)
    cv::Mat background;
    {
        const int count = std::min(n, kBackgroundFrames);
        int summed = 0;
        for (int j = 0; j < count; ++j) {
            const std::optional<cv::Mat> g = reader.grayUnlessDamaged(int((long long)j * (n - 1) / std::max(1, count - 1)));
            if (!g)
                continue;  // in a damaged stretch of the file
            const cv::Mat f = workingImage(*g, r, scale);
            if (background.empty())
                background = cv::Mat::zeros(f.size(), CV_32F);
            background += f;
            ++summed;
        }
        if (summed == 0)
            throw VideoError(index.path, nb::TrDevices::tr("no frame of the video could be decoded"));
        background /= double(summed);
    }
    // Each picture is matched against a reference picture, not only against the one before:
    // a slow tissue moves a fraction of a pixel a frame, and frame-to-frame shifts of that size
    // read short (pulled towards whole pixels) and add up their errors. Against a reference
    // the displacement grows to whole pixels and is measured once; the reference moves on when
    // the picture has moved well away from it (or the match weakens). The shift between two
    // frames is then the difference of their positions, so the shifts add up to the measured
    // displacement.
    constexpr double kRekey_px = 6.0;      // in the working picture
    constexpr double kWeakResponse = 0.05;
    // A thin slab has little texture to outvote what stays put under the match's window, and
    // against a reference a few frames old the match can jump between the tissue's peak and
    // the one at zero shift from one picture to the next (a 12 mm slab read 2-11 px apart from
    // the match with the picture before). That picture, one frame away, is the most alike: where
    // the two matches disagree by more than this, it becomes the reference. Elsewhere they agree
    // within a few tenths of a pixel (the median disagreement: 0.1-0.2 px on clear pictures,
    // 0.4 px under heavy noise), and the reference keeps the slow tissue's motion whole.
    constexpr double kDisagree_px = 1.5;
    // A repeated picture coded again by an inter-frame coder (a B-frame of the same camera
    // frame) is not the same picture: it differs from the one before by requantised noise, under
    // two fifths of what fresh noise and motion change between two pictures (H.264, seed 66063
    // phase case 16: 0.65 to 3.1 grey against 8 to 12). Read as a picture, it stops the
    // tissue for a frame and the next one doubles its step, which the phases read as the tissue
    // falling behind and catching up. Such a picture is left out too, one at a time: a run of
    // them is a picture at rest, not a camera that repeats itself.
    constexpr double kNearRepeat = 0.5;   // of the median change between successive pictures
    constexpr std::size_t kRecentChanges = 15;
    std::vector<double> recentChanges;    // the last kRecentChanges, oldest first
    bool skippedNearRepeat = false;
    cv::Mat window, lastShown;
    Spectrum previous, reference;
    double previousTime = 0.0, clip = 0.0;
    cv::Point2d referencePosition(0, 0), previousPosition(0, 0);
    for (int i = 0; i < n; ++i) {
        if (cancel && cancel->load())
            break;
        if (progress && i % 25 == 0)
            progress(i, n);
        // The same picture again: no motion to measure, and a false zero. Also where the index
        // does not say so (indexed from the file's packets, a long video).
        const std::optional<cv::Mat> g = reader.grayUnlessDamaged(i);
        if (!g)
            continue;  // in a damaged stretch of the file: left out, as a repeated picture is
        const cv::Mat shown = workingImage(*g, r, scale);
        const double change = pictureChange(lastShown, shown);
        const bool repeated = i > 0 && (index.frames[std::size_t(i)].duplicate || change < kSamePictureChange);
        bool nearRepeat = false;
        if (!repeated && std::isfinite(change)) {
            if (recentChanges.size() >= 3 && !skippedNearRepeat)
                nearRepeat = change < kNearRepeat * quantileOf(recentChanges, 0.5);
            recentChanges.push_back(change);
            if (recentChanges.size() > kRecentChanges)
                recentChanges.erase(recentChanges.begin());
        }
        skippedNearRepeat = nearRepeat;
        lastShown = shown;
        if (repeated || nearRepeat)
            continue;
        cv::Mat image = shown - background;
        // A few strong edges moving their own way (the needle's tip, bright against the
        // tissue) would outvote the tissue's faint texture: values are clipped to the
        // picture's typical contrast, so that every part counts by its area.
        if (clip <= 0.0) {
            const cv::Mat a = cv::abs(image);
            std::vector<float> v(a.begin<float>(), a.end<float>());
            std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
            clip = std::max(1.0, 2.5 * 1.4826 * double(v[v.size() / 2]));
        }
        cv::min(image, clip, image);
        cv::max(image, -clip, image);
        // The picture's own noise changes every frame; the tissue's texture does not.
        cv::GaussianBlur(image, image, cv::Size(0, 0), kTextureBlur_px);
        image -= coarseOf(image);
        const double t = index.frames[std::size_t(i)].time_s;
        // The match tapers each picture towards its edges, where texture enters and leaves the
        // picture with no counterpart in the other one: a Hanning window squared, applied here,
        // once. (cv::phaseCorrelate given a window multiplies it into its inputs in place when
        // their size needs no padding, as 480x360 does not: a reference matched against ten
        // pictures was tapered ten times over, and the shift right after the reference moved on
        // could read zero where the tissue had moved 4 px. One plain Hanning taper reads a slab
        // between plates worse than that: up to 1.25 px off a frame, test_tissue_tracker.)
        if (window.empty()) {
            cv::createHanningWindow(window, image.size(), CV_32F);
            window = window.mul(window);
        }
        cv::multiply(image, window, image);
        const Spectrum spectrum = spectrumOf(image);
        if (reference.empty()) {
            reference = spectrum;
        } else if (t > previousTime) {
            // Only for the first pair is the reference the picture before.
            const bool referenceIsPrevious = out.time_s.empty();
            // The match with the picture before runs beside the one with the reference: they
            // only read the same pictures, and on two cores the second costs no time.
            double previousResponse = 0.0;
            cv::Point2d fromPrevious;
            std::future<void> matchingPrevious;
            if (!referenceIsPrevious)
                matchingPrevious = std::async(std::launch::async, [&] {
                    fromPrevious = previousPosition + phaseShift(previous, spectrum, &previousResponse);
                });
            double response = 0.0;
            cv::Point2d position = referencePosition + phaseShift(reference, spectrum, &response);
            if (matchingPrevious.valid())
                matchingPrevious.get();
            const bool farOrWeak =
                std::hypot(position.x - referencePosition.x, position.y - referencePosition.y) > kRekey_px || response < kWeakResponse;
            // Too far from the reference (or no longer like it), or in disagreement with the
            // picture before: that picture, whose position is known, becomes the reference.
            // (Where it is the reference already, the match stands.)
            if (!referenceIsPrevious &&
                (farOrWeak || std::hypot(fromPrevious.x - position.x, fromPrevious.y - position.y) > kDisagree_px)) {
                reference = previous;
                referencePosition = previousPosition;
                position = fromPrevious;
                response = previousResponse;
            }
            const cv::Point2d shift = position - previousPosition;
            out.time_s.push_back(0.5 * (t + previousTime));
            out.dt_s.push_back(t - previousTime);
            out.dx_px.push_back(shift.x / scale);
            out.dy_px.push_back(shift.y / scale);
            out.response.push_back(response);
            previousPosition = position;
        } else {
            continue;  // no time between them: keep the earlier picture
        }
        previous = spectrum;
        previousTime = t;
    }
    if (progress)
        progress(n, n);
    return out;
}

std::pair<double, double> principalShiftAxis(const TissueShifts& s, std::size_t count)
{
    double sxx = 0, sxy = 0, syy = 0;
    for (std::size_t i = 0; i < count; ++i) {
        sxx += s.dx_px[i] * s.dx_px[i];
        sxy += s.dx_px[i] * s.dy_px[i];
        syy += s.dy_px[i] * s.dy_px[i];
    }
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    return {std::cos(angle), std::sin(angle)};
}

TissueMotion tissueMotionFromShifts(const TissueShifts& s, const Run& run, const TimelineMapping& mapping, QString* problem)
{
    TissueMotion m;
    auto fail = [&](const QString& why) {
        if (problem)
            *problem = why;
        return TissueMotion{};
    };
    if (s.time_s.size() < 8 || run.size() < 2)
        return fail(nb::TrDevices::tr("too few frames or samples to follow the tissue"));
    const std::size_t k = s.time_s.size();
    // The needle's displacement over each pair of frames, on the recording's clock.
    std::vector<double> dp(k), ta(k), tb(k);
    for (std::size_t i = 0; i < k; ++i) {
        ta[i] = mapping.toRecording(s.time_s[i] - 0.5 * s.dt_s[i]);
        tb[i] = mapping.toRecording(s.time_s[i] + 0.5 * s.dt_s[i]);
        const bool inside = ta[i] >= run.time_s.front() && tb[i] <= run.time_s.back();
        dp[i] = inside ? interpolate(run.time_s, run.position_mm, tb[i]) - interpolate(run.time_s, run.position_mm, ta[i])
                       : std::numeric_limits<double>::quiet_NaN();
    }
    // The direction the picture moves in.
    const auto [ux, uy] = principalShiftAxis(s, k);
    std::vector<double> along(k);
    for (std::size_t i = 0; i < k; ++i)
        along[i] = s.dx_px[i] * ux + s.dy_px[i] * uy;
    // Scale and sign against the needle, where the needle moves clearly. Over a few frames,
    // not frame by frame: the shifts are differences of positions measured against a
    // reference, so their sum over a stretch has the noise of two positions, not of as many
    // shifts; frame by frame the noise spreads the ratios, and the upper cluster taken for
    // the carried tissue reads the scale high (the tissue's motion short).
    const double frame_s = quantileOf(s.dt_s, 0.5);
    const std::size_t span = std::clamp<std::size_t>(std::size_t(std::lround(kScaleSpan_s / std::max(1e-3, frame_s))), 1, k / 4);
    std::vector<double> cumAlong(k + 1, 0.0), cumNeedle(k + 1, 0.0);
    std::vector<std::size_t> outside(k + 1, 0);  // pairs before i without the needle's motion (outside the run)
    for (std::size_t i = 0; i < k; ++i) {
        cumAlong[i + 1] = cumAlong[i] + along[i];
        cumNeedle[i + 1] = cumNeedle[i] + (std::isfinite(dp[i]) ? dp[i] : 0.0);
        outside[i + 1] = outside[i] + (std::isfinite(dp[i]) ? 0 : 1);
    }
    std::vector<double> spanAlong, spanNeedle;
    for (std::size_t i = 0; i + span <= k; ++i) {
        if (outside[i + span] != outside[i])
            continue;
        spanAlong.push_back(cumAlong[i + span] - cumAlong[i]);
        spanNeedle.push_back(cumNeedle[i + span] - cumNeedle[i]);
    }
    double fastest = 0.0;
    for (double d : spanNeedle)
        fastest = std::max(fastest, std::abs(d));
    if (fastest <= 0.0)
        return fail(nb::TrDevices::tr("the needle does not move while the video runs"));
    double agreement = 0.0;
    for (std::size_t i = 0; i < spanNeedle.size(); ++i)
        agreement += spanAlong[i] * spanNeedle[i];
    const double sign = agreement < 0 ? -1.0 : 1.0;
    std::vector<double> ratios;
    for (std::size_t i = 0; i < spanNeedle.size(); ++i)
        if (std::abs(spanNeedle[i]) > 0.15 * fastest)
            ratios.push_back(sign * spanAlong[i] / spanNeedle[i]);
    const double high = quantileOf(ratios, 0.9);
    if (!(high > 0.0))
        return fail(nb::TrDevices::tr("nothing in the picture moves with the needle"));
    // The cluster's middle, found from its upper side: a window of ±25 % moved onto the
    // median of what it holds until it settles (started at the upper side it would hold
    // the cluster's upper half and read the scale high).
    double pxPerMm = high;
    for (int pass = 0; pass < 8; ++pass) {
        std::vector<double> carried;
        for (double r : ratios)
            if (std::abs(r - pxPerMm) < 0.25 * pxPerMm)
                carried.push_back(r);
        const double middle = quantileOf(carried, 0.5);
        if (!(middle > 0.0) || std::abs(middle - pxPerMm) < 1e-3 * pxPerMm)
            break;
        pxPerMm = middle;
    }
    // A picture whose motion is mostly noise: the tissue never visibly follows the needle
    // (over the stretch the scale is read on, whose noise adds up at most as the root of its
    // frames).
    const double noise = quantileOf([&] {
        std::vector<double> a;
        for (double v : along)
            a.push_back(std::abs(v));
        return a;
    }(), 0.1);
    if (!(pxPerMm > 0.0) || pxPerMm * 0.15 * fastest < 2.0 * noise * std::sqrt(double(span)))
        return fail(nb::TrDevices::tr("the tissue's motion does not stand out of the picture's noise"));
    m.px_per_mm = pxPerMm;
    m.time_s.resize(k);
    m.velocity_mm_s.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
        m.time_s[i] = 0.5 * (ta[i] + tb[i]);
        m.velocity_mm_s[i] = sign * along[i] / pxPerMm / std::max(1e-9, tb[i] - ta[i]);
    }
    return m;
}

}  // namespace nb::video
