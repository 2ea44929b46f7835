#include "frame_index.h"
#include "core/tr.h"

#include "capture.h"
#include "keyframe_probe.h"
#include "orientation.h"
#include "video_error.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <limits>
#include <cmath>

namespace nb::video {

double FrameIndex::frameDuration() const
{
    if (medianInterval_s > 0)
        return medianInterval_s;
    if (frames.size() < 2)
        return fpsNominal > 0 ? 1.0 / fpsNominal : 1.0 / 30.0;
    std::vector<double> d;
    d.reserve(frames.size() - 1);
    for (std::size_t i = 1; i < frames.size(); ++i)
        d.push_back(frames[i].time_s - frames[i - 1].time_s);
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
}

double FrameIndex::duration_s() const
{
    if (frames.empty())
        return 0.0;
    // From the file's start: a file whose first packets are damaged has its first frame later.
    return frames.back().time_s + frameDuration();
}

void FrameIndex::updateStats()
{
    medianInterval_s = 0.0;
    medianInterval_s = frameDuration();
}

bool FrameIndex::variableFrameRate() const
{
    if (frames.size() < 3)
        return false;
    const double median = frameDuration();
    // Containers with millisecond time bases (MKV) jitter by 1 ms at 29.97 frames/s.
    const double tolerance = std::max(0.0015, 0.05 * median);
    for (std::size_t i = 1; i < frames.size(); ++i)
        if (std::abs(frames[i].time_s - frames[i - 1].time_s - median) > tolerance)
            return true;
    return false;
}

// The pictures the container's count stands for: the count itself, or, where the nominal rate
// is a time base (a variable-rate MKV says 1000 frames/s for 30 pictures a second), the count
// over as many time-base ticks as one picture takes.
static int containerPictures(const FrameIndex& index)
{
    const double picturesPerNominal = index.fpsNominal * index.frameDuration();
    return picturesPerNominal > 2.0 ? int(std::lround(index.containerFrames / picturesPerNominal)) : index.containerFrames;
}

QStringList indexWarnings(const FrameIndex& index)
{
    QStringList w;
    if (index.cutShort) {
        const int expected = containerPictures(index);
        w << nb::TrDevices::tr("only %1 of %2 frames are readable: the file is cut off, or damaged after that frame").arg(index.size()).arg(expected);
    }
    constexpr std::size_t kSpansNamed = 3;
    for (std::size_t i = 0; i < std::min(index.damaged.size(), kSpansNamed); ++i) {
        const DamagedSpan& d = index.damaged[i];
        if (!index.frames.empty() && d.before_s <= index.frames.front().time_s) {
            w << nb::TrDevices::tr("the file's first %1 s are damaged: %n packet(s) there could not be decoded; its frames start at %1 s",
                                   "", d.packets)
                     .arg(QLocale().toString(d.before_s, 'f', 3));
            continue;
        }
        w << nb::TrDevices::tr("the file is damaged between %1 s and %2 s: %n packet(s) there could not be decoded and are left out; "
                               "the frames on either side are read", "", d.packets)
                 .arg(QLocale().toString(d.after_s, 'f', 3), QLocale().toString(d.before_s, 'f', 3));
    }
    if (index.damaged.size() > kSpansNamed)
        w << nb::TrDevices::tr("and %n more damaged stretch(es)", "", int(index.damaged.size() - kSpansNamed));
    if (!index.timestampsMonotonic)
        w << nb::TrDevices::tr("frame timestamps are not increasing: frames are reached by decoding from the start");
    if (index.rotation_deg != 0)
        w << nb::TrDevices::tr("the file says its picture is turned by %1°: shown turned, as players show it").arg(index.rotation_deg);
    if (index.videoStreams > 1)
        w << nb::TrDevices::tr("the file holds %1 video streams: only the first (%2x%3) is shown and measured")
                 .arg(index.videoStreams)
                 .arg(index.width)
                 .arg(index.height);
    if (index.fromPackets)
        w << nb::TrDevices::tr("indexed from the file's packets: repeated pictures are not flagged as duplicates");
    return w;
}

double pictureChange(const cv::Mat& a, const cv::Mat& b)
{
    if (a.empty() || a.size != b.size || a.type() != b.type())
        return std::numeric_limits<double>::infinity();
    return cv::norm(a, b, cv::NORM_L1) / double(b.total() * b.channels());
}

int FrameIndex::duplicateCount() const
{
    return int(std::count_if(frames.begin(), frames.end(), [](const FrameInfo& f) { return f.duplicate; }));
}

int FrameIndex::frameAt(double t) const
{
    if (frames.empty())
        return -1;
    auto it = std::upper_bound(frames.begin(), frames.end(), t + 1e-9,
                               [](double v, const FrameInfo& f) { return v < f.time_s; });
    return it == frames.begin() ? 0 : int(it - frames.begin()) - 1;
}

std::optional<int> FrameIndex::frameWithTime(double t) const
{
    if (frames.empty() || !timestampsMonotonic)
        return std::nullopt;
    auto it = std::lower_bound(frames.begin(), frames.end(), t,
                               [](const FrameInfo& f, double v) { return f.time_s < v; });
    int best = -1;
    double bestDiff = 1e300;
    for (auto c : {it, it == frames.begin() ? it : it - 1}) {
        if (c == frames.end())
            continue;
        const double diff = std::abs(c->time_s - t);
        if (diff < bestDiff) {
            bestDiff = diff;
            best = int(c - frames.begin());
        }
    }
    if (best < 0 || bestDiff > 0.25 * frameDuration() + 1e-6)
        return std::nullopt;
    return best;
}

int FrameIndex::keyframeAtOrBefore(int n) const
{
    for (int i = std::min(n, size() - 1); i > 0; --i)
        if (frames[std::size_t(i)].keyframe)
            return i;
    return 0;
}

bool FrameIndex::decodedAcrossDamage(int n) const
{
    // Asked for every frame of every pass: an undamaged file answers at once.
    if (damaged.empty() || !keyframesKnown || n < 0 || n >= size())
        return false;
    const double at_s = frames[std::size_t(n)].time_s, key_s = frames[std::size_t(keyframeAtOrBefore(n))].time_s;
    return std::any_of(damaged.begin(), damaged.end(), [&](const DamagedSpan& d) {
        // Random bytes over an H.264 keyframe left a picture the decoder gave out (seed 2 of
        // test_frame_reader madeUpTimesAfterDamageAreLeftOut): the 60 frames from it were made up.
        if (at_s > d.after_s)
            return key_s < d.before_s;
        // The last picture given before the refusals may be made up itself (a P-frame the damage
        // began in), and the B-frames shown before it are decoded after it: all of them.
        const int lastShown = frameAt(d.after_s);
        return n >= lastShown - reorderFrames;
    });
}

namespace {

enum class Mp4Index { NotMp4, Missing, Present };

// Walks an ISO media file's top-level boxes (size, type) for its index, 'moov'.
Mp4Index mp4Index(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return Mp4Index::NotMp4;
    bool first = true;
    while (!f.atEnd()) {
        const qint64 at = f.pos();
        const QByteArray head = f.read(8);
        if (head.size() < 8)
            break;
        quint64 size = (quint64(quint8(head[0])) << 24) | (quint64(quint8(head[1])) << 16) | (quint64(quint8(head[2])) << 8) | quint8(head[3]);
        const QByteArray type = head.mid(4, 4);
        if (first && type != "ftyp")
            return Mp4Index::NotMp4;
        first = false;
        if (type == "moov")
            return Mp4Index::Present;
        if (size == 1) {  // a 64-bit size follows
            const QByteArray large = f.read(8);
            if (large.size() < 8)
                break;
            size = 0;
            for (char c : large)
                size = (size << 8) | quint8(c);
        } else if (size == 0) {  // to the end of the file
            break;
        }
        if (size < 8 || !f.seek(at + qint64(size)))
            break;
    }
    return first ? Mp4Index::NotMp4 : Mp4Index::Missing;
}

}  // namespace

// The stretches of packets (times as OpenCV gives them) that no indexed frame shows, each
// between the readable frames on either side. Packets before the first readable frame or after
// the last are no stretch between frames (a file cut off says so already).
static std::vector<DamagedSpan> packetsNotShown(const FrameIndex& index, const std::vector<double>& packets_s)
{
    std::vector<DamagedSpan> out;
    bool open = false;
    for (double p : packets_s) {
        const double t = p - index.timeOrigin_s;
        if (index.frameWithTime(t) || t < 0.0 || t > index.frames.back().time_s) {
            open = false;
            continue;
        }
        if (!open) {
            if (t < index.frames.front().time_s) {  // the file's start (its frames start later)
                out.push_back({0.0, index.frames.front().time_s, 0});
            } else {
                const std::size_t before = std::size_t(index.frameAt(t));
                out.push_back({index.frames[before].time_s, index.frames[before + 1].time_s, 0});
            }
            open = true;
        }
        ++out.back().packets;
    }
    return out;
}

// A decoder gives frames out up to this many late (H.264's largest picture buffer): refusals
// closer than that are one damaged stretch, seen between frames given out meanwhile.
constexpr int kDecoderDelayFrames = 16;

static void joinNearStretches(std::vector<DamagedSpan>& spans, double near_s)
{
    std::vector<DamagedSpan> joined;
    for (const DamagedSpan& d : spans)
        if (!joined.empty() && d.after_s - joined.back().before_s <= near_s) {
            joined.back().before_s = d.before_s;
            joined.back().packets += d.packets;
        } else {
            joined.push_back(d);
        }
    spans = std::move(joined);
}

// After a damaged stretch an inter-coded decoder gives out some pictures it made up with the
// timestamps of the packets it lost, behind frames it has already given out (a random-byte
// scratch of an H.264 MP4: 3.7704 s, then 3.2366 s; or 5.9333 s drained after the last frame,
// 7.9 s). Kept, the index's times went backwards: every later frame was then reached by decoding
// from the start, the reader could not pass the damage at all ("frame 97 could not be decoded")
// and the file was called cut off. Such a frame shows no moment of its own: it is left out, as
// part of the damaged stretch; the reader passes over it as well (FrameReader::grabNext).
static bool isStrayAfterDamage(const FrameIndex& index, double time_s, int refusedOutsideSpans)
{
    const bool afterDamage = !index.damaged.empty() || refusedOutsideSpans > 0;
    // OpenCV's 0 past the start is "no timestamp" (frames drained at the end), placed below.
    return afterDamage && time_s > 0.0 && !index.frames.empty() && time_s <= index.frames.back().time_s;
}

// Refused grabs beyond the packets the container counts before the index ends: its count can be
// a little short (a count from the duration, a last frame drained from the decoder).
constexpr int kMorePacketsThanCounted = 16;

FrameIndex buildFrameIndex(const QString& path, const IndexProgress& progress, const std::atomic_bool* cancel,
                           const FfprobeListing* listing)
{
    const QFileInfo fi(path);
    if (!fi.exists())
        throw VideoError(path, nb::TrDevices::tr("no such file"));
    if (!fi.isFile() || !fi.isReadable())
        throw VideoError(path, nb::TrDevices::tr("not a readable file"));
    if (fi.size() == 0)
        throw VideoError(path, nb::TrDevices::tr("the file is empty"));

    cv::VideoCapture cap;
    try {
        openCapture(cap, path);
    } catch (const cv::Exception& e) {
        throw VideoError(path, nb::TrDevices::tr("cannot open as video: %1").arg(QString::fromStdString(e.what())));
    }
    if (!cap.isOpened()) {
        // An MP4/MOV recording cut off before it was closed (power lost, disk full) starts as
        // one but lacks the index written at its end: say that, not "not a video file". One
        // with its index but nothing to show (a sound recording) is something else again.
        switch (mp4Index(path)) {
        case Mp4Index::Missing:
            throw VideoError(path, nb::TrDevices::tr("an MP4/MOV file without its index (the 'moov' box written when a recording "
                                                     "is closed): the recording was cut off before it was finished, and its "
                                                     "frames cannot be found without that index"));
        case Mp4Index::Present:
            throw VideoError(path, nb::TrDevices::tr("an MP4/MOV file with no video FFmpeg can read (sound only, or a video codec "
                                                     "this system lacks)"));
        case Mp4Index::NotMp4:
            break;
        }
        throw VideoError(path, nb::TrDevices::tr("cannot open as video (not a video file, or a format FFmpeg does not read)"));
    }

    FrameIndex index;
    index.path = path;
    const int rotation = takeRotation(cap);
    index.width = int(cap.get(cv::CAP_PROP_FRAME_WIDTH));
    index.height = int(cap.get(cv::CAP_PROP_FRAME_HEIGHT));
    turnIndexUpright(index, rotation);
    index.fpsNominal = cap.get(cv::CAP_PROP_FPS);
    index.containerFrames = std::max(0, int(cap.get(cv::CAP_PROP_FRAME_COUNT)));
    const int fourcc = int(cap.get(cv::CAP_PROP_FOURCC));
    for (int i = 0; i < 4; ++i) {
        const char c = char((fourcc >> (8 * i)) & 0xff);
        if (c > ' ')
            index.codec += QLatin1Char(c);
    }

    cv::Mat previous, current;
    // A packet the decoder refuses (a damaged stretch of a copied or badly stored file) ends
    // OpenCV's grab, and the first such packet used to end the index: a 20 KB scratch in the
    // middle of a 20 s H.264 file lost its last 10 s, 100 of them whole frames after the next
    // keyframe. Grabbing on reads the packets after it. At the end of the file every grab fails,
    // at once, so the packets the container says are left bound the tries.
    int refused = 0;
    int refusedBeforeFirst = 0;
    while (!(cancel && cancel->load())) {
        if (!cap.grab()) {
            if (++refused > std::max(0, index.containerFrames - index.size()) + kMorePacketsThanCounted)
                break;
            continue;
        }
        FrameInfo f;
        f.time_s = cap.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
        if (isStrayAfterDamage(index, f.time_s, refused + refusedBeforeFirst)) {
            ++refused;  // its picture is lost with the damaged stretch's
            continue;
        }
        // Where it refused, as the frames came out: a B-frame decoder gives them out some
        // frames late, so this is only roughly where the damage lies (see below).
        if (refused > 0 && !index.frames.empty())
            index.damaged.push_back({index.frames.back().time_s, f.time_s, refused});
        else if (index.frames.empty())
            refusedBeforeFirst = refused;
        refused = 0;
        if (cap.retrieve(current) && !current.empty()) {
            f.duplicate = samePicture(previous, current);
            std::swap(previous, current);
        }
        if (!index.frames.empty() && f.time_s == 0.0 && index.frames.back().time_s >= 0.0) {
            // OpenCV reports 0 for the frames drained from a B-frame decoder at the end of
            // the file; they follow the previous frame at the usual interval. In a clip of two or
            // three frames every frame is drained so, the first at 0 too.
            const std::size_t k = index.frames.size();
            const double step = k >= 2 ? index.frames[k - 1].time_s - index.frames[k - 2].time_s
                                       : 1.0 / std::max(1.0, index.fpsNominal);
            f.time_s = index.frames.back().time_s + step;
            f.timeEstimated = true;
        }
        if (!index.frames.empty() && f.time_s <= index.frames.back().time_s)
            index.timestampsMonotonic = false;
        index.frames.push_back(f);
        if (progress && index.frames.size() % 25 == 0)
            progress(index.size(), index.containerFrames);
    }
    if (index.frames.empty())
        throw VideoError(path, nb::TrDevices::tr("no frame could be decoded (truncated or corrupt file?)"));
    if (progress)
        progress(index.size(), index.containerFrames);
    // The container's count is often its duration times the nominal rate; when that rate is
    // a time base (a variable-rate MKV says 1000 frames/s for 30 pictures a second) the
    // count is as many times too high. What it stands for is then only an estimate (the
    // duration over the usual interval counts dropped frames too), taken with more slack.
    const bool timeBase = index.fpsNominal * index.frameDuration() > 2.0;
    const int expected = containerPictures(index);
    // A stream that starts later than 0 (an MKV written with a start time of 5 s) may count its
    // frames to its end time: its readable frames end there, not 5 s short of it (it was called
    // cut off: "only 120 of 270 frames").
    const std::optional<ProbeResult> probe = listing ? std::optional<ProbeResult>(probeKeyframes(*listing)) : probeKeyframes(path);
    // The file's first packets refused (random bytes over its first keyframe): its frames start
    // later than the file does, and keep their own times. The first readable frame was taken
    // for the start: every frame 0.73 s early, and the file called cut off.
    std::optional<double> fileStart_s;
    if (refusedBeforeFirst > 0 && probe && !probe->packets_s.empty()
        && probe->packets_s.front() < index.frames.front().time_s - 0.5 * index.frameDuration())
        fileStart_s = probe->packets_s.front();
    // Frames missing in the middle (a capture that dropped them: the timestamps jump) are no
    // sign of a cut file; only a file whose readable frames end short of its duration is.
    const double readSpan_s = index.frames.back().time_s - fileStart_s.value_or(index.frames.front().time_s) + index.frameDuration();
    const double start_s = probe ? std::max(0.0, probe->start_s) : 0.0;
    if (probe) {
        index.videoStreams = std::max(1, probe->videoStreams);
        index.reorderFrames = probe->reorderFrames;
    }
    const double containerSpan_s = index.fpsNominal > 0.0 ? std::max(0.0, index.containerFrames / index.fpsNominal - start_s) : 0.0;
    const bool endsShort = !index.timestampsMonotonic || readSpan_s < containerSpan_s * (timeBase ? 0.9 : 0.98) - index.frameDuration();
    index.cutShort = !(cancel && cancel->load()) && expected > 0 && index.size() < expected * (timeBase ? 0.9 : 0.98) - 1 && endsShort;

    index.timeOrigin_s = fileStart_s.value_or(index.frames.front().time_s);
    for (FrameInfo& f : index.frames)
        f.time_s -= index.timeOrigin_s;
    for (DamagedSpan& d : index.damaged) {
        d.after_s -= index.timeOrigin_s;
        d.before_s -= index.timeOrigin_s;
    }
    if (fileStart_s)
        index.damaged.insert(index.damaged.begin(), DamagedSpan{0.0, index.frames.front().time_s, refusedBeforeFirst});
    joinNearStretches(index.damaged, kDecoderDelayFrames * index.frameDuration());
    index.updateStats();
    index.frames.front().keyframe = true;
    if (probe) {
        if (!probe->codec.isEmpty())
            index.codec = probe->codec;
        for (double k : probe->keyframes_s)
            if (const auto n = index.frameWithTime(k - index.timeOrigin_s))
                index.frames[std::size_t(*n)].keyframe = true;
        index.keyframesKnown = probe->keyframes_s.size() > 0;
        if (!index.damaged.empty() && index.timestampsMonotonic && !probe->packets_s.empty()) {
            index.damaged = packetsNotShown(index, probe->packets_s);
            // Frames a B-frame decoder gives out between its refusals split one scratch in many.
            joinNearStretches(index.damaged, kDecoderDelayFrames * index.frameDuration());
        }
    }
    index.warnings = indexWarnings(index);
    return index;
}

}  // namespace nb::video
