#pragma once
// Frame-exact random access: frame N is the N-th frame in presentation order (as in the
// FrameIndex), whatever the container's frame rate claims. Seeks with OpenCV, then checks
// the decoded timestamp against the index and decodes forward (or retries earlier) until
// it holds exactly frame N. Not thread-safe: one owner thread (VideoDecoder).

#include "frame_cache.h"
#include "frame_index.h"

#include <opencv2/videoio.hpp>

#include <optional>
#include <vector>

namespace nb::video {

struct DecodedFrame {
    int index = -1;
    double time_s = 0.0;
    cv::Mat image;  // BGR, 8 bit; shared with the cache: read-only
};

struct ReaderStats {
    int seeks = 0;            // OpenCV seeks issued
    int retries = 0;          // seeks that landed past the target and were redone earlier
    int sequentialResets = 0; // fell back to decoding from the start
    int cacheHits = 0;
    int grabbed = 0;          // frames decoded by the reader itself (not those a seek decodes inside OpenCV)
};

// What a caller that passes over a video several times keeps of its grey frames: all of a
// video of about three and a half minutes at 640x480 or a minute and a half at 1024x768
// (30 frames/s). A longer video is decoded again on each pass.
constexpr std::size_t kPassesGrayBudget_bytes = std::size_t(1) << 30;

class FrameReader {
public:
    // Opens the indexed file; throws VideoError.
    explicit FrameReader(FrameIndex index, int cacheFrames = 64);

    const FrameIndex& index() const { return index_; }
    // Throws VideoError when frame n cannot be decoded (out of range, file changed).
    DecodedFrame read(int n);
    bool isCached(int n) const { return cache_.contains(n); }
    // Decodes frames [from, to] into the cache (clamped to the file); stops early after
    // `budget` decoded frames (<0: no limit). Returns how many it decoded. Frames of a damaged
    // stretch are passed over (playback's prefetch stopped at the first).
    int fillCache(int from, int to, int budget = -1);
    FrameCache& cache() { return cache_; }
    const ReaderStats& stats() const { return stats_; }

    // Keeps the grey picture of every frame in `span` once it is decoded (frames decoded on
    // the way to another included), when the span's fit in `budget_bytes`; else keeps none.
    // For callers that pass over a short video several times (the sync samples it, tracks
    // every frame and may track again): a noisy H.264 picture costs more to decode than to
    // track, and each pass decoded it again. Returns whether the frames are kept.
    bool keepGrayFrames(std::size_t budget_bytes, FrameSpan span = {});
    // Frame n in grey, 8 bit (shared with the store when kept: read-only). Throws as read().
    cv::Mat gray(int n);
    // The same, nothing when frame n lies in a damaged stretch (DamagedFrame) or is decoded
    // across one up to the next keyframe (its picture partly made up by the decoder; seed 605620
    // --damage case 1: H.264 with 0.57 s overwritten, the sync right at confidence 0): for passes
    // over the video, which leave such a frame out. Throws other failures as read().
    std::optional<cv::Mat> grayUnlessDamaged(int n);
    // Whether grayUnlessDamaged leaves out the frames decoded across damage (it does by default).
    void leaveOutDecodedAcrossDamage(bool on) { leaveOutAcross_ = on; }

private:
    void reopen();
    int grabNext();            // grabs one frame; returns its index (-1 end/failure, -2 unknown time)
    void keepGrabbedGray(int j);  // the grabbed frame j into the grey store, when kept and not yet there
    void seekTo(int n);        // leaves current_ <= n (or -1 after a reopen)
    bool forwardIsCheaper(int from, int to) const;

    FrameIndex index_;
    cv::VideoCapture cap_;
    int rotation_deg_ = 0;  // the file's rotation tag, turned here (orientation.h)
    FrameCache cache_;
    bool fresh_ = true;     // just opened: the next grab is frame 0
    int current_ = -1;      // index of the last grabbed frame; -1 before the first
    int firstFrameNumber_ = 0;
    bool seekable_ = true;  // OpenCV's frame seek can land near a frame (see the constructor)
    int damagedPackets_ = 0;  // packets the index found undecodable: grabs that may fail before the next frame
    bool refused_ = false;    // the decoder refused a packet on the way to the frame being read
    std::vector<bool> damaged_;  // per frame: found in a damaged stretch (read again, it throws at once)
    bool leaveOutAcross_ = true;
    ReaderStats stats_;
    std::vector<cv::Mat> gray_;  // one per frame when grey frames are kept, else empty
    FrameSpan grayKept_;         // of those, the frames whose grey picture is kept
};

}  // namespace nb::video
