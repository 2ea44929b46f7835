#include "frame_index_store.h"
#include "packet_index.h"
#include "video_error.h"
#include "core/save_file.h"

#include <QCryptographicHash>
#include <QDataStream>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace nb::video {

namespace {
constexpr quint32 kMagic = 0x4e424658;  // "NBFX"
// Bump whenever buildFrameIndex() would index a file differently.
// 2: width and height as shown, turned by the rotation tag; 3: the facts behind the warnings, not
// their text (a stored index spoke the language of the program that made it); 4: the count of
// video streams; 5: an MPEG-TS file's stream counted once (4 counted it in its program too); 6: the
// frames of a two- or three-frame B-frame clip timed (5 kept them all at 0); 7: the frames after a
// damaged stretch, and the stretches (6 ended the index at the first); 8: pictures made up after
// damage with times behind the frames before them left out (7 kept them: times out of order), and
// the stream's reorder depth; 9: an AVI read in the order of its index (8 numbered the frames after
// a stretch passed over early)
constexpr quint32 kVersion = 9;
// Indexes kept at most; the least recently stored go first.
constexpr int kMaxStored = 300;

QString storePath(const QString& videoPath, const QString& storeDir)
{
    const QByteArray key = QFileInfo(videoPath).absoluteFilePath().toUtf8();
    return QDir(storeDir).filePath(QString::fromLatin1(QCryptographicHash::hash(key, QCryptographicHash::Sha1).toHex()) +
                                   QStringLiteral(".nbindex"));
}

// What makes a stored index valid for a file.
struct Stamp {
    QString path;
    qint64 size = -1;
    qint64 modified_ms = 0;
    bool operator==(const Stamp&) const = default;
};

std::optional<Stamp> stampOf(const QString& videoPath)
{
    const QFileInfo info(videoPath);
    if (!info.isFile())
        return std::nullopt;
    return Stamp{info.absoluteFilePath(), info.size(), info.lastModified().toMSecsSinceEpoch()};
}
}  // namespace

QString defaultFrameIndexStore()
{
    const QString root = qEnvironmentVariableIsEmpty("NEEDLEBENCH_CACHE_DIR")
                             ? QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation) + QStringLiteral("/needlebench")
                             : qEnvironmentVariable("NEEDLEBENCH_CACHE_DIR");
    return QDir(root).filePath(QStringLiteral("frame-index"));
}

std::optional<FrameIndex> loadStoredFrameIndex(const QString& videoPath, const QString& storeDir)
{
    const auto stamp = stampOf(videoPath);
    if (!stamp)
        return std::nullopt;
    QFile f(storePath(videoPath, storeDir));
    if (!f.open(QIODevice::ReadOnly))
        return std::nullopt;
    QDataStream in(&f);
    in.setVersion(QDataStream::Qt_6_0);
    quint32 magic = 0, version = 0;
    Stamp stored;
    in >> magic >> version;
    if (magic != kMagic || version != kVersion)
        return std::nullopt;
    in >> stored.path >> stored.size >> stored.modified_ms;
    if (in.status() != QDataStream::Ok || !(stored == *stamp))
        return std::nullopt;
    FrameIndex index;
    qint32 width = 0, height = 0, containerFrames = 0;
    quint32 count = 0, damaged = 0;
    in >> index.codec >> width >> height >> index.fpsNominal >> containerFrames >> index.keyframesKnown >>
        index.timestampsMonotonic >> index.rotation_deg >> index.fromPackets >> index.cutShort >> index.videoStreams >> index.reorderFrames >> index.timeOrigin_s >> damaged;
    if (in.status() != QDataStream::Ok || damaged > 10'000'000u)
        return std::nullopt;
    index.damaged.resize(damaged);
    for (DamagedSpan& d : index.damaged) {
        qint32 packets = 0;
        in >> d.after_s >> d.before_s >> packets;
        d.packets = packets;
    }
    in >> count;
    if (in.status() != QDataStream::Ok || count == 0 || count > 100'000'000u)
        return std::nullopt;
    index.path = videoPath;
    index.width = width;
    index.height = height;
    index.containerFrames = containerFrames;
    index.frames.resize(count);
    for (FrameInfo& fr : index.frames) {
        quint8 flags = 0;
        in >> fr.time_s >> flags;
        fr.keyframe = flags & 1;
        fr.duplicate = flags & 2;
        fr.timeEstimated = flags & 4;
    }
    if (in.status() != QDataStream::Ok || !in.atEnd())
        return std::nullopt;  // truncated or trailing bytes: not ours to trust
    index.updateStats();
    index.warnings = indexWarnings(index);
    return index;
}

bool storeFrameIndex(const FrameIndex& index, const QString& storeDir)
{
    const auto stamp = stampOf(index.path);
    if (!stamp || index.frames.empty() || !QDir().mkpath(storeDir))
        return false;
    // Written aside and renamed: a reader never sees half a file.
    QSaveFile f(storePath(index.path, storeDir));
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QDataStream out(&f);
    out.setVersion(QDataStream::Qt_6_0);
    out << kMagic << kVersion << stamp->path << stamp->size << stamp->modified_ms;
    out << index.codec << qint32(index.width) << qint32(index.height) << index.fpsNominal << qint32(index.containerFrames)
        << index.keyframesKnown << index.timestampsMonotonic << qint32(index.rotation_deg) << index.fromPackets << index.cutShort << qint32(index.videoStreams)
        << qint32(index.reorderFrames) << index.timeOrigin_s << quint32(index.damaged.size());
    for (const DamagedSpan& d : index.damaged)
        out << d.after_s << d.before_s << qint32(d.packets);
    out << quint32(index.frames.size());
    for (const FrameInfo& fr : index.frames)
        out << fr.time_s << quint8((fr.keyframe ? 1 : 0) | (fr.duplicate ? 2 : 0) | (fr.timeEstimated ? 4 : 0));
    if (out.status() != QDataStream::Ok || !commitWhole(f))
        return false;
    QDir store(storeDir);
    const QFileInfoList all = store.entryInfoList({QStringLiteral("*.nbindex")}, QDir::Files, QDir::Time);  // newest first
    for (qsizetype i = kMaxStored; i < all.size(); ++i)
        QFile::remove(all[i].absoluteFilePath());
    return true;
}

FrameIndex loadOrBuildFrameIndex(const QString& path, const IndexProgress& progress, const std::atomic_bool* cancel,
                                 bool* fromStore, const QString& storeDir)
{
    const QString dir = storeDir.isEmpty() ? defaultFrameIndexStore() : storeDir;
    if (auto stored = loadStoredFrameIndex(path, dir)) {
        if (fromStore)
            *fromStore = true;
        if (progress)
            progress(stored->size(), stored->size());
        return std::move(*stored);
    }
    if (fromStore)
        *fromStore = false;
    // Long videos are indexed from their packets (seconds, not minutes); short ones are
    // decoded, which also flags repeated pictures.
    constexpr int kLongVideoFrames = 18000;  // ten minutes at 30 frames/s
    const std::optional<FfprobeListing> listing = listVideo(path);
    std::optional<FrameIndex> packets;
    if (listing && listing->packets.size() > std::size_t(kLongVideoFrames)) {
        try {
            packets = buildFrameIndexFromPackets(path, *listing);
        } catch (const VideoError&) {
            packets.reset();  // decoding below names the problem
        }
    }
    const bool fromPackets = packets.has_value();
    FrameIndex index = fromPackets ? std::move(*packets) : buildFrameIndex(path, progress, cancel, listing ? &*listing : nullptr);
    if (progress && fromPackets)
        progress(index.size(), index.size());
    if (!(cancel && cancel->load()))
        storeFrameIndex(index, dir);
    return index;
}

std::vector<double> frameTimesOf(const QString& videoPath, QString* problem)
{
    try {
        const FrameIndex index = loadOrBuildFrameIndex(videoPath);
        std::vector<double> times;
        times.reserve(index.frames.size());
        for (const FrameInfo& f : index.frames)
            times.push_back(f.time_s);
        return times;
    } catch (const VideoError& e) {
        *problem = e.message();
        return {};
    }
}

}  // namespace nb::video
