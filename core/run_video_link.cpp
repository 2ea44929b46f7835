#include "run_video_link.h"

#include "core/run_keys.h"
#include "core/save_file.h"
#include "core/session.h"
#include "core/tr.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <array>
#include <cmath>

namespace nb {

namespace {

const QString kFileName = QStringLiteral("videos.json");

QJsonObject readStore(const QString& path, QString* problem)
{
    QFile f(path);
    if (!f.exists())
        return {};
    if (!f.open(QIODevice::ReadOnly)) {
        if (problem)
            *problem = nb::TrCore::tr("%1: cannot read (%2)").arg(path, f.errorString());
        return {};
    }
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &error);
    if (!doc.isObject()) {
        if (problem)
            *problem = nb::TrCore::tr("%1: not a video link file (%2)").arg(path, error.errorString());
        return {};
    }
    return doc.object();
}

// Four finite numbers, or nothing.
std::optional<std::array<double, 4>> fourNumbers(const QJsonValue& v)
{
    const QJsonArray a = v.toArray();
    if (a.size() != 4)
        return std::nullopt;
    std::array<double, 4> out{};
    for (int i = 0; i < 4; ++i) {
        if (!a[i].isDouble() || !std::isfinite(a[i].toDouble()))
            return std::nullopt;
        out[std::size_t(i)] = a[i].toDouble();
    }
    return out;
}

}  // namespace

QString syncMethodKey(SyncMethod m)
{
    switch (m) {
    case SyncMethod::Manual: return QStringLiteral("manual");
    case SyncMethod::EventMarks: return QStringLiteral("event_marks");
    case SyncMethod::Automatic: return QStringLiteral("automatic");
    case SyncMethod::None: break;
    }
    return {};
}

SyncMethod syncMethodFromKey(const QString& key)
{
    for (SyncMethod m : {SyncMethod::Manual, SyncMethod::EventMarks, SyncMethod::Automatic})
        if (key == syncMethodKey(m))
            return m;
    return SyncMethod::None;
}

QString syncMethodName(SyncMethod m)
{
    switch (m) {
    case SyncMethod::Manual: return nb::TrCore::tr("set by hand");
    case SyncMethod::EventMarks: return nb::TrCore::tr("from marked events");
    case SyncMethod::Automatic: return nb::TrCore::tr("automatic");
    case SyncMethod::None: break;
    }
    return nb::TrCore::tr("not synchronised");
}

QString videoLinksPath(const QString& sessionDir) { return QDir(sessionDir).filePath(kFileName); }

const QStringList& videoSuffixes()
{
    // What imaging consoles and frame grabbers write, and what FFmpeg (through OpenCV) reads.
    static const QStringList suffixes{QStringLiteral("mp4"), QStringLiteral("avi"),  QStringLiteral("mkv"),
                                      QStringLiteral("mov"), QStringLiteral("m4v"),  QStringLiteral("webm"),
                                      QStringLiteral("mpg"), QStringLiteral("mpeg"), QStringLiteral("dv"),
                                      QStringLiteral("wmv"), QStringLiteral("ogv"),  QStringLiteral("ts")};
    return suffixes;
}

QString videoBesideRun(const QString& runPath)
{
    if (runPath.isEmpty())
        return {};
    const QFileInfo run(runPath);
    // In the suffixes' order of preference, whatever their case: cameras write ".MP4", ".MOV".
    const QFileInfoList beside = run.dir().entryInfoList({run.completeBaseName() + QStringLiteral(".*")}, QDir::Files);
    for (const QString& suffix : videoSuffixes())
        for (const QFileInfo& v : beside)
            if (v.completeBaseName() == run.completeBaseName() && v.suffix().compare(suffix, Qt::CaseInsensitive) == 0)
                return v.absoluteFilePath();
    return {};
}

std::optional<RunVideoLink> readRunVideoLink(const QString& runPath, QString* problem)
{
    const QFileInfo run(runPath);
    const QJsonObject store = readStore(videoLinksPath(run.absolutePath()), problem);
    const QJsonValue v = store.value(QStringLiteral("runs")).toObject().value(run.fileName());
    if (!v.isObject())
        return std::nullopt;
    const QJsonObject o = v.toObject();
    RunVideoLink link;
    const QString video = o.value(QStringLiteral("video")).toString();
    if (!video.isEmpty())
        link.video = QDir::cleanPath(QFileInfo(video).isAbsolute() ? video : run.absoluteDir().filePath(video));
    link.mapping.offset_s = o.value(QStringLiteral("offset_s")).toDouble(0.0);
    link.mapping.drift = o.value(QStringLiteral("drift")).toDouble(0.0);
    if (!std::isfinite(link.mapping.offset_s) || !std::isfinite(link.mapping.drift))
        link.mapping = {};
    link.method = syncMethodFromKey(o.value(QStringLiteral("method")).toString());
    if (o.value(QStringLiteral("confidence")).isDouble())
        link.confidence = o.value(QStringLiteral("confidence")).toDouble();
    // A hand-edited mark that makes no sense is dropped, not drawn: the sync then finds the needle.
    if (const auto r = fourNumbers(o.value(QStringLiteral("region"))); r && (*r)[2] >= 1 && (*r)[3] >= 1)
        link.marks.region = QRect(int((*r)[0]), int((*r)[1]), int((*r)[2]), int((*r)[3]));
    if (const auto n = fourNumbers(o.value(QStringLiteral("needle"))))
        link.marks.needle = QLineF((*n)[0], (*n)[1], (*n)[2], (*n)[3]);
    link.codedOnce = o.value(QStringLiteral("coded_once")).toBool(false);
    return link;
}

void writeRunVideoLink(const QString& runPath, const std::optional<RunVideoLink>& link)
{
    const QFileInfo run(runPath);
    const QString path = videoLinksPath(run.absolutePath());
    QString problem;
    QJsonObject store = readStore(path, &problem);
    if (!problem.isEmpty())
        throw SessionError(path, problem);
    QJsonObject runs = store.value(QStringLiteral("runs")).toObject();
    if (link) {
        QJsonObject o;
        if (!link->video.isEmpty()) {
            const QString rel = run.absoluteDir().relativeFilePath(link->video);
            o.insert(QStringLiteral("video"), rel.startsWith(QLatin1String("..")) ? QFileInfo(link->video).absoluteFilePath() : rel);
        }
        o.insert(QStringLiteral("offset_s"), link->mapping.offset_s);
        o.insert(QStringLiteral("drift"), link->mapping.drift);
        o.insert(QStringLiteral("method"), syncMethodKey(link->method));
        if (link->confidence)
            o.insert(QStringLiteral("confidence"), *link->confidence);
        const QRect& r = link->marks.region;
        if (!r.isEmpty())
            o.insert(QStringLiteral("region"), QJsonArray{r.x(), r.y(), r.width(), r.height()});
        const QLineF& n = link->marks.needle;
        if (!n.isNull())
            o.insert(QStringLiteral("needle"), QJsonArray{n.x1(), n.y1(), n.x2(), n.y2()});
        if (link->codedOnce)
            o.insert(QStringLiteral("coded_once"), true);
        runs.insert(run.fileName(), o);
    } else {
        runs.remove(run.fileName());
    }
    store.insert(QStringLiteral("runs"), runs);
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        throw SessionError(path, nb::TrCore::tr("cannot write (%1)").arg(f.errorString()));
    f.write(QJsonDocument(store).toJson());
    if (!commitWhole(f))
        throw SessionError(path, nb::TrCore::tr("cannot write (%1)").arg(f.errorString()));
}

std::optional<RunVideoLink> runVideoLinkFromRun(const Run& run, const QString& runPath)
{
    const std::optional<double> offset = run.metadata.number(key::sync_offset_s);
    if (!offset || !std::isfinite(*offset))
        return std::nullopt;
    RunVideoLink link;
    link.mapping.offset_s = *offset;
    if (const std::optional<double> drift = run.metadata.number(QStringLiteral("sync_drift")); drift && std::isfinite(*drift))
        link.mapping.drift = *drift;
    link.method = syncMethodFromKey(run.metadata.value(key::sync_method, QString()));
    if (const std::optional<double> c = run.metadata.number(key::sync_confidence); c && std::isfinite(*c))
        link.confidence = *c;
    // A method in words of its own (the demo's): found by a sync when it has a confidence.
    if (link.method == SyncMethod::None)
        link.method = link.confidence ? SyncMethod::Automatic : SyncMethod::Manual;
    const QString video = run.metadata.value(key::video_file, QString());
    if (!video.isEmpty())
        link.video = QFileInfo(video).isAbsolute() ? video : QFileInfo(runPath).absoluteDir().filePath(video);
    // A video beside the run stands in for the one named when that has moved; with none there
    // the named one stays, so that Review says it is missing (it said "No video").
    if (link.video.isEmpty() || !QFileInfo::exists(link.video))
        if (const QString beside = videoBesideRun(runPath); !beside.isEmpty() || link.video.isEmpty())
            link.video = beside;
    return link;
}

void applyRunVideoLink(Run& run, const QString& runPath, const RunVideoLink& link)
{
    if (!link.video.isEmpty()) {
        const QString rel = QFileInfo(runPath).absoluteDir().relativeFilePath(link.video);
        const QString shown = rel.startsWith(QLatin1String("..")) ? link.video : rel;
        // Another video than the one the run was recorded with: what the header says of that
        // one (its frame rate) is not this one's.
        const std::optional<QString> before = run.metadata.value(key::video_file);
        if (before && QFileInfo(QFileInfo(runPath).absoluteDir(), *before).absoluteFilePath() !=
                          QFileInfo(QFileInfo(runPath).absoluteDir(), shown).absoluteFilePath())
            run.metadata.remove(key::video_fps);
        run.metadata.set(key::video_file, shown);
    }
    run.metadata.set(key::sync_offset_s, link.mapping.offset_s);
    run.metadata.set(QStringLiteral("sync_drift"), link.mapping.drift);
    if (link.method != SyncMethod::None)
        run.metadata.set(key::sync_method, syncMethodKey(link.method));
    // A confidence belongs to the sync that found it: a manual sync has none.
    if (link.confidence)
        run.metadata.set(key::sync_confidence, *link.confidence);
    else
        run.metadata.remove(key::sync_confidence);
}

}  // namespace nb
