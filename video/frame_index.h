#pragma once
// The frame index of one video file: every frame in presentation order with its true
// timestamp, keyframe flag and duplicate flag. Built once (slow: decodes the whole file),
// then every frame-exact access relies on it. OpenCV's own seek assumes a constant frame
// rate; the index is what lets the reader check where a seek really landed.

#include <QString>
#include <QStringList>
#include <opencv2/core.hpp>

#include <algorithm>
#include <atomic>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace nb::video {

struct FrameInfo {
    double time_s = 0.0;     // presentation time, as the decoder reports it
    bool keyframe = false;   // a safe point to start decoding from
    bool duplicate = false;  // the previous picture again (identical up to coding noise)
    bool timeEstimated = false;  // decoder gave no timestamp (frames drained at the end)
};

// Where a file's middle could not be decoded (a damaged copy, a bad sector): between the
// readable frames at `after_s` and `before_s` (index times), `packets` were skipped.
struct DamagedSpan {
    double after_s = 0.0;
    double before_s = 0.0;
    int packets = 0;
};

// Frames first to last of a video, both included; all of them by default.
struct FrameSpan {
    int first = 0;
    int last = std::numeric_limits<int>::max();

    // This span within a video of `frames` frames (empty: last < first).
    FrameSpan within(int frames) const
    {
        return {std::clamp(first, 0, std::max(0, frames)), std::clamp(last, -1, std::max(-1, frames - 1))};
    }
    int size() const { return std::max(0, last - first + 1); }
};

struct FrameIndex {
    QString path;
    QString codec;
    int width = 0;
    int height = 0;
    double fpsNominal = 0.0;      // what the container claims
    int containerFrames = 0;      // what the container claims (0 when unknown)
    bool keyframesKnown = false;  // false: only frame 0 is flagged (no ffprobe)
    bool timestampsMonotonic = true;
    int rotation_deg = 0;         // the file's rotation tag (0, 90, 180, 270): width and height as shown
    bool fromPackets = false;     // indexed from the container's packets, without decoding
    bool cutShort = false;        // the readable frames end short of what the container says
    int videoStreams = 1;         // video streams in the file (the first is the one read)
    int reorderFrames = 0;        // pictures shown before one they are predicted from (B-frames; 0 when unknown)
    std::vector<DamagedSpan> damaged;  // undecodable stretches that readable frames follow
    // What a user should know, in the language of the program reading the index (a stored
    // index says it in the reader's language, not the indexer's): see indexWarnings().
    QStringList warnings;
    std::vector<FrameInfo> frames;
    // Decoder time of frame 0: AVI with B-frames reports every frame late by the decoder's
    // delay; times in `frames` start at 0 for the first frame.
    double timeOrigin_s = 0.0;
    double medianInterval_s = 0.0;  // set by updateStats(); frameDuration() uses it

    // Recomputes the cached median interval after `frames` changed.
    void updateStats();

    int size() const { return int(frames.size()); }
    double frameDuration() const;  // median interval (1/fps when fewer than 2 frames)
    double duration_s() const;     // end of the last frame's display
    bool variableFrameRate() const;
    int duplicateCount() const;
    // The frame on screen at time t (the last frame starting at or before t; 0 before the start).
    int frameAt(double t) const;
    // The frame whose timestamp is t, within a quarter of the shortest interval.
    std::optional<int> frameWithTime(double t) const;
    // The last keyframe at or before frame n.
    int keyframeAtOrBefore(int n) const;
    // Whether frame n is decoded from pictures a damaged stretch took: it follows the stretch's
    // start with no keyframe after the stretch between (a codec that codes each picture alone
    // flags every frame a keyframe; a keyframe within the stretch may be damaged itself), or it is
    // the last picture given before it or one of the B-frames shown just before that. Its picture
    // is what the decoder made up for the lost ones. False when the keyframes are not known.
    bool decodedAcrossDamage(int n) const;
};

// Refused packets a reader grabs on past, beyond the damage an index found, before it takes the
// file for ended: a file indexed from its packets has its damage unknown, and at the end of a
// file each refusal is immediate (FrameReader, the packet index's first frame).
inline constexpr int kRefusedPacketsTried = 1000;

// The index's warnings, from its facts: a cut-off file, timestamps out of order, a rotation
// tag, an index from packets.
QStringList indexWarnings(const FrameIndex& index);

// The mean absolute change per pixel (and channel) from one decoded picture to another;
// infinite when they differ in size or type, or one is empty.
double pictureChange(const cv::Mat& a, const cv::Mat& b);
// Whether two decoded pictures are the same picture shown again. Lossy codecs re-encode a
// repeated picture with a little coding noise (mean change ~0.1 grey level); a real picture
// change, even sensor noise alone, is far above this. Any size and type, both alike.
inline constexpr double kSamePictureChange = 0.25;
inline bool samePicture(const cv::Mat& a, const cv::Mat& b) { return pictureChange(a, b) < kSamePictureChange; }

// Progress: frames indexed so far and the expected total (0 when unknown).
using IndexProgress = std::function<void(int done, int expected)>;

// Decodes the whole file. Throws VideoError when the file cannot be opened or holds no
// readable frame; a file that ends early keeps the frames read so far and says so in
// `warnings`. `cancel` (may be null) stops early with what was indexed.
// `listing`: the file's ffprobe listing when already made (listVideo, ffprobe.h), else it is made.
struct FfprobeListing;
FrameIndex buildFrameIndex(const QString& path, const IndexProgress& progress = {},
                           const std::atomic_bool* cancel = nullptr, const FfprobeListing* listing = nullptr);

}  // namespace nb::video
