#include "frame_reader.h"
#include "capture.h"
#include "orientation.h"
#include "core/tr.h"

#include "video_error.h"

#include <QCoreApplication>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace nb::video {

FrameReader::FrameReader(FrameIndex index, int cacheFrames) : index_(std::move(index)), cache_(cacheFrames)
{
    if (index_.frames.empty())
        throw VideoError(index_.path, nb::TrDevices::tr("the video has no indexed frames"));
    if (index_.medianInterval_s <= 0)
        index_.updateStats();
    firstFrameNumber_ = int(std::llround(index_.timeOrigin_s * index_.fpsNominal));
    // OpenCV seeks to a frame number as time × nominal rate, then counts one per frame it
    // decodes. When the nominal rate is a time base rather than the picture rate (a
    // variable-rate MKV says 1000 frames/s for 30 pictures a second) it decodes on some 30
    // times too far, often to the end of the file, and every read after a seek decodes from
    // the start again: 6 minutes to sync a 25 s video. Such a file is read forward only.
    const double picturesPerNominal = index_.fpsNominal * index_.frameDuration();
    seekable_ = index_.timestampsMonotonic && !(index_.fpsNominal > 0 && (picturesPerNominal > 2.0 || picturesPerNominal < 0.5));
    for (const DamagedSpan& d : index_.damaged)
        damagedPackets_ += d.packets;
    damaged_.assign(index_.frames.size(), false);
    reopen();
    stats_.sequentialResets = 0;
}

void FrameReader::reopen()
{
    cap_.release();
    if (!openCapture(cap_, index_.path))
        throw VideoError(index_.path, nb::TrDevices::tr("cannot reopen the video (moved or deleted?)"));
    rotation_deg_ = takeRotation(cap_);
    current_ = -1;
    fresh_ = true;
    ++stats_.sequentialResets;
}

int FrameReader::grabNext()
{
    // Past a damaged stretch (packets the decoder refuses) grabbing on reads the frames after
    // it, as the index did; only their timestamps then say which. A file indexed from its
    // packets has its damage unknown, hence the tries beyond what the index found; at the end
    // of the file each refusal is immediate.
    int refused = 0;
    for (;;) {
        while (!cap_.grab())
            if (!index_.timestampsMonotonic || ++refused > damagedPackets_ + kRefusedPacketsTried)
                return -1;
        refused_ = refused_ || refused > 0;
        ++stats_.grabbed;
        // Counting is exact while decoding on from a known frame; after a seek, or packets
        // skipped, only the timestamp tells where we are.
        const int counted = refused == 0 && (current_ >= 0 || fresh_) ? current_ + 1 : -2;
        fresh_ = false;
        if (index_.timestampsMonotonic) {
            const double t = cap_.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
            // A zero time past the start is OpenCV's "no timestamp" (drained frames).
            if (t > 0.0 || counted == 0) {
                const auto j = index_.frameWithTime(t - index_.timeOrigin_s);
                // A picture the decoder made up after damage, with a lost packet's time, that
                // the index left out (isStrayAfterDamage): not a frame; the count goes on past it.
                if (damagedPackets_ > 0 && t > 0.0 && (!j || (current_ >= 0 && *j <= current_))) {
                    refused_ = true;
                    continue;
                }
                if (j) {
                    current_ = *j;
                    return current_;
                }
            }
        }
        current_ = counted < 0 ? -1 : counted;
        return counted;
    }
}

bool FrameReader::forwardIsCheaper(int from, int to) const
{
    // Decoding on keeps every frame on the way, which the next pass then need not decode; a
    // seek would skip them, to decode them later. Frames outside the kept span are not kept.
    if (!gray_.empty() && from + 1 >= grayKept_.first && to <= grayKept_.last)
        return true;
    // Without a usable seek the alternative is decoding from the start.
    if (!seekable_ || to - from <= 12)
        return true;
    if (!index_.keyframesKnown)
        return to - from <= 30;
    // A seek decodes from the keyframe before the target anyway; without a keyframe in
    // between, decoding on from here costs no more.
    return index_.keyframeAtOrBefore(to) <= from;
}

void FrameReader::seekTo(int n)
{
    if (!seekable_ || n == 0) {
        reopen();
        return;
    }
    const double fps = index_.fpsNominal > 0 ? index_.fpsNominal : 1.0 / index_.frameDuration();
    // OpenCV numbers frames by timestamp × nominal rate; on a constant-rate file this is n.
    long long target = std::llround((index_.frames[std::size_t(n)].time_s + index_.timeOrigin_s) * fps) - firstFrameNumber_;
    for (int attempt = 0; attempt < 5; ++attempt) {
        if (target <= 0)
            break;
        current_ = -1;
        fresh_ = false;
        cap_.set(cv::CAP_PROP_POS_FRAMES, double(target));
        ++stats_.seeks;
        const int j = grabNext();
        if (j >= 0 && j <= n)
            return;
        ++stats_.retries;
        target -= (j > n ? (j - n) : 0) + 1 + 8 * attempt;
    }
    reopen();
}

DecodedFrame FrameReader::read(int n)
{
    if (n < 0 || n >= index_.size())
        throw VideoError(index_.path, nb::TrDevices::tr("frame %1 does not exist (the video has %2 frames)").arg(n).arg(index_.size()));
    const double time = index_.frames[std::size_t(n)].time_s;
    if (auto img = cache_.get(n)) {
        ++stats_.cacheHits;
        return {n, time, *img};
    }
    // A frame found damaged once is damaged again: passes over the video and playback's
    // prefetch ask for it again and again, and each asking cost a seek and a decode.
    auto damaged = [&] {
        damaged_[std::size_t(n)] = true;
        return DamagedFrame(index_.path, nb::TrDevices::tr("frame %1 lies in a damaged stretch of the file and cannot be decoded").arg(n));
    };
    if (damaged_[std::size_t(n)])
        throw damaged();
    refused_ = false;
    if (current_ < 0 || current_ > n || !forwardIsCheaper(current_, n))
        seekTo(n);
    auto decodeForward = [&] {
        while (current_ < n) {
            const int j = grabNext();
            if (j < 0 || j > n)
                return false;
            if (j < n)
                keepGrabbedGray(j);
        }
        return true;
    };
    // After a seek the decoder may not give back the last frames of a file (B-frames
    // drained at the end); decoding from the start always does. But a frame passed over after
    // a refused packet lies in a damaged stretch: from the start it would be refused again,
    // after decoding the whole file before it.
    if (!decodeForward()) {
        if (refused_ && current_ > n)
            throw damaged();
        reopen();
        if (!decodeForward()) {
            if (refused_)
                throw damaged();
            throw VideoError(index_.path, nb::TrDevices::tr("frame %1 could not be decoded (truncated or changed file?)").arg(n));
        }
    }
    cv::Mat image;
    if (!cap_.retrieve(image) || image.empty())
        throw VideoError(index_.path, nb::TrDevices::tr("frame %1 could not be decoded").arg(n));
    turnUpright(image, rotation_deg_);
    cache_.put(n, image);
    return {n, time, image};
}

namespace {
cv::Mat grayOf(const cv::Mat& image)
{
    if (image.channels() == 1)
        return image;
    cv::Mat g;
    cv::cvtColor(image, g, cv::COLOR_BGR2GRAY);
    return g;
}
}  // namespace

bool FrameReader::keepGrayFrames(std::size_t budget_bytes, FrameSpan span)
{
    grayKept_ = span.within(index_.size());
    const std::size_t bytes = std::size_t(std::max(0, index_.width)) * std::size_t(std::max(0, index_.height))
                              * std::size_t(grayKept_.size());
    gray_.clear();
    if (bytes > 0 && bytes <= budget_bytes)
        gray_.resize(index_.frames.size());
    return !gray_.empty();
}

void FrameReader::keepGrabbedGray(int j)
{
    if (j < grayKept_.first || j > grayKept_.last || std::size_t(j) >= gray_.size() || !gray_[std::size_t(j)].empty())
        return;
    cv::Mat image;
    if (cap_.retrieve(image) && !image.empty()) {
        turnUpright(image, rotation_deg_);
        gray_[std::size_t(j)] = grayOf(image);
    }
}

cv::Mat FrameReader::gray(int n)
{
    const bool keeping = n >= grayKept_.first && n <= grayKept_.last && std::size_t(n) < gray_.size();
    if (keeping && !gray_[std::size_t(n)].empty())
        return gray_[std::size_t(n)];
    const cv::Mat g = grayOf(read(n).image);
    if (keeping)
        gray_[std::size_t(n)] = g;
    return g;
}

std::optional<cv::Mat> FrameReader::grayUnlessDamaged(int n)
{
    if (leaveOutAcross_ && index_.decodedAcrossDamage(n))
        return std::nullopt;
    try {
        return gray(n);
    } catch (const DamagedFrame&) {
        return std::nullopt;
    }
}

int FrameReader::fillCache(int from, int to, int budget)
{
    from = std::max(0, from);
    to = std::min(to, index_.size() - 1);
    int decoded = 0;
    for (int i = from; i <= to && (budget < 0 || decoded < budget); ++i) {
        if (cache_.contains(i))
            continue;
        try {
            read(i);
            ++decoded;
        } catch (const DamagedFrame&) {
        }
    }
    return decoded;
}

}  // namespace nb::video
