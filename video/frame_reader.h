#pragma once
// Frame-exact random access: frame N is the N-th frame in presentation order (as in the
// FrameIndex), whatever the container's frame rate claims. Seeks with OpenCV, then checks
// the decoded timestamp against the index and decodes forward (or retries earlier) until
// it holds exactly frame N. Not thread-safe: one owner thread (VideoDecoder).

#include "frame_cache.h"
#include "frame_index.h"

#include <opencv2/videoio.hpp>

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
};

class FrameReader {
public:
    // Opens the indexed file; throws VideoError.
    explicit FrameReader(FrameIndex index, int cacheFrames = 64);

    const FrameIndex& index() const { return index_; }
    // Throws VideoError when frame n cannot be decoded (out of range, file changed).
    DecodedFrame read(int n);
    bool isCached(int n) const { return cache_.contains(n); }
    // Decodes frames [from, to] into the cache (clamped to the file); stops early after
    // `budget` decoded frames (<0: no limit). Returns how many it decoded.
    int fillCache(int from, int to, int budget = -1);
    FrameCache& cache() { return cache_; }
    const ReaderStats& stats() const { return stats_; }

private:
    void reopen();
    int grabNext();            // grabs one frame; returns its index (-1 end/failure, -2 unknown time)
    void seekTo(int n);        // leaves current_ <= n (or -1 after a reopen)
    bool forwardIsCheaper(int from, int to) const;

    FrameIndex index_;
    cv::VideoCapture cap_;
    FrameCache cache_;
    bool fresh_ = true;     // just opened: the next grab is frame 0
    int current_ = -1;      // index of the last grabbed frame; -1 before the first
    int firstFrameNumber_ = 0;
    bool seekable_ = true;  // OpenCV's frame seek can land near a frame (see the constructor)
    ReaderStats stats_;
};

}  // namespace nb::video
