#include "dataset.h"

#include "core/run_video_link.h"
#include "core/signal.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <cmath>
#include <algorithm>

namespace nb {

std::vector<SignalColumn> exportSignals(const Run& run)
{
    std::vector<SignalColumn> cols;
    cols.push_back({QStringLiteral("time_s"), QStringLiteral("s"), nb::TrCore::tr("time since the start of the recording"), run.time_s});
    cols.push_back({QStringLiteral("position_mm"), QStringLiteral("mm"), nb::TrCore::tr("needle tip depth, grows as the needle goes deeper"),
                    run.position_mm});
    const auto* v = run.numericColumn(QStringLiteral("velocity_mm_s"));
    const std::vector<double> velocity = v && v->size() == run.size() ? *v : derivative(run.time_s, run.position_mm);
    const auto* a = run.numericColumn(QStringLiteral("acceleration_mm_s2"));
    const std::vector<double> accel = a && a->size() == run.size() ? *a : derivative(run.time_s, velocity);
    cols.push_back({QStringLiteral("velocity_mm_s"), QStringLiteral("mm/s"),
                    v ? nb::TrCore::tr("needle velocity, recorded") : nb::TrCore::tr("needle velocity, central differences of position"), velocity});
    cols.push_back({QStringLiteral("acceleration_mm_s2"), QStringLiteral("mm/s^2"),
                    a ? nb::TrCore::tr("needle acceleration, recorded") : nb::TrCore::tr("needle acceleration, central differences of velocity"),
                    accel});
    cols.push_back({QStringLiteral("force_N"), QStringLiteral("N"), nb::TrCore::tr("axial force, positive when the tissue pushes back"),
                    run.force_N});
    for (const auto& [name, values] : run.numeric) {
        if (name == QLatin1String("velocity_mm_s") || name == QLatin1String("acceleration_mm_s2") ||
            values.size() != run.size())
            continue;
        if (name == QLatin1String("seq"))
            cols.push_back({name, QStringLiteral("1"), nb::TrCore::tr("the sensor's sample counter (a gap is a lost sample)"), values, true});
        else
            cols.push_back({name, unitFromName(name), QString(), values});
    }
    return cols;
}

std::vector<TextColumn> exportTextColumns(const Run& run, const Labels& labels)
{
    // The signals' names without computing them (exportSignals differentiates the whole run):
    // its own five, and the run's numeric columns.
    QStringList taken{QStringLiteral("labels"), QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("velocity_mm_s"),
                      QStringLiteral("acceleration_mm_s2"), QStringLiteral("force_N")};
    for (const auto& [name, values] : run.numeric)
        taken << name;
    for (const QString& t : labelTracks(labels))
        taken << QStringLiteral("label_") + t;
    std::vector<TextColumn> out;
    for (const auto& [name, values] : run.text) {
        if (values.size() != run.size() || taken.contains(name))
            continue;
        const QString description = name == QLatin1String("phase") ? nb::TrCore::tr("friction phase recorded with the run (the simulated rig's own)")
                                    : name == QLatin1String("event") ? nb::TrCore::tr("event recorded with the run at the sample")
                                                                     : nb::TrCore::tr("text recorded with the run");
        out.push_back({name, description, QStringList(values.begin(), values.end())});
    }
    return out;
}

QStringList labelTracks(const Labels& labels)
{
    QStringList tracks;
    for (const Label& l : labels)
        if (!tracks.contains(l.track))
            tracks << l.track;
    return tracks;
}

QStringList labelsPerSample(const Labels& labels, const std::vector<double>& time_s, const QString& track)
{
    QStringList out(qsizetype(time_s.size()));
    for (const Label& l : labels) {
        if (l.track != track)
            continue;
        // Samples are in time order: find the covered range by bisection, not a scan.
        const auto first = std::lower_bound(time_s.begin(), time_s.end(), l.start_s);
        // Where labels overlap the one earlier in the list stands, as in phasePerSample (and as
        // the loader's warning says): the fit and the exported column read the same phase.
        if (l.isPoint()) {
            if (first != time_s.end() && out[first - time_s.begin()].isEmpty())
                out[first - time_s.begin()] = l.label;
            continue;
        }
        const auto last = std::lower_bound(first, time_s.end(), l.end_s);
        for (auto it = first; it != last; ++it)
            if (out[it - time_s.begin()].isEmpty())
                out[it - time_s.begin()] = l.label;
    }
    return out;
}

QString unitFromName(const QString& name)
{
    // Longest suffixes first so `_mm_s2` is not read as `_s2`.
    static const std::pair<const char*, const char*> suffixes[] = {
        {"_mm_s2", "mm/s^2"}, {"_m_s2", "m/s^2"},   {"_mm_s", "mm/s"},   {"_m_s", "m/s"},     {"_n_per_mm2", "N/mm^2"},
        {"_n_per_mm", "N/mm"}, {"_n_per_m", "N/m"}, {"_ns_per_m2", "N s/m^2"}, {"_ns_per_m", "N s/m"},
        {"_v_per_g", "V/g"},   {"_hz", "Hz"},       {"_ms", "ms"},       {"_mm", "mm"},       {"_kg", "kg"},
        {"_mv", "mV"},         {"_v", "V"},         {"_n", "N"},         {"_g", "g"},         {"_s", "s"},
        {"_m", "m"},           {"_fps", "1/s"},     {"_percent", "%"},
    };
    const QString lower = name.toLower();
    for (const auto& [suffix, unit] : suffixes)
        if (lower.endsWith(QLatin1String(suffix)))
            return QString::fromLatin1(unit);
    return {};
}

MetadataValueKind metadataValueKind(const QString& key, const QString& value)
{
    static const QStringList textKeys{
        QStringLiteral("organ"),    QStringLiteral("specimen"), QStringLiteral("tip"),      QStringLiteral("operator"),
        QStringLiteral("protocol"), QStringLiteral("notes"),    QStringLiteral("tissue"),   QStringLiteral("name"),
        QStringLiteral("device"),   QStringLiteral("calibration"), QStringLiteral("created"), QStringLiteral("session"),
        QStringLiteral("comment"),  QStringLiteral("daq"),      QStringLiteral("stage"),    QStringLiteral("end_reason"),
    };
    if (textKeys.contains(key))
        return MetadataValueKind::Text;
    static const QRegularExpression integer(QStringLiteral("^[+-]?[0-9]{1,18}$"));
    static const QRegularExpression number(QStringLiteral("^[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?$"));
    const QString v = value.trimmed();
    if (integer.match(v).hasMatch())
        return MetadataValueKind::Integer;
    if (number.match(v).hasMatch() && std::isfinite(v.toDouble()))
        return MetadataValueKind::Number;
    return MetadataValueKind::Text;
}

QString findRunVideo(const QString& runPath, const Run& run)
{
    if (runPath.isEmpty())
        return {};
    const QFileInfo fi(runPath);
    for (const char* key : {"video", "video_file", "video_path"}) {
        if (const auto v = run.meta(QString::fromLatin1(key)); v && !v->trimmed().isEmpty()) {
            const QString p = QFileInfo(v->trimmed()).isAbsolute() ? v->trimmed() : fi.dir().filePath(v->trimmed());
            if (QFileInfo(p).isFile())
                return QFileInfo(p).absoluteFilePath();
        }
    }
    return videoBesideRun(runPath);
}

QString relativeLink(const QString& fromFile, const QString& target)
{
    if (target.isEmpty())
        return {};
    return QDir(QFileInfo(fromFile).absolutePath()).relativeFilePath(QFileInfo(target).absoluteFilePath());
}

QString portableLink(const QString& fromFile, const QString& target)
{
    const QString rel = relativeLink(fromFile, target);
    if (rel.isEmpty() || rel == QLatin1String("..") || rel.startsWith(QLatin1String("../")))
        return target.isEmpty() ? QString() : QFileInfo(target).absoluteFilePath();
    return rel;
}

std::optional<double> namedSyncOffset(const Run& run)
{
    for (const char* key : {"sync_offset_s", "video_offset_s"}) {
        const auto v = run.meta(QString::fromLatin1(key));
        bool ok = false;
        const double d = v ? v->trimmed().toDouble(&ok) : 0.0;
        if (ok && std::isfinite(d))
            return d;
    }
    return std::nullopt;
}

double syncOffset(const Run& run)
{
    return namedSyncOffset(run).value_or(0.0);
}

double syncDrift(const Run& run)
{
    bool ok = false;
    const auto v = run.meta(QStringLiteral("sync_drift"));
    const double d = v ? v->trimmed().toDouble(&ok) : 0.0;
    return ok && std::isfinite(d) && std::abs(d) < 0.1 ? d : 0.0;  // a larger one is no clock's
}

double videoFps(const Run& run)
{
    for (const char* key : {"video_fps", "fps"}) {
        const auto v = run.meta(QString::fromLatin1(key));
        bool ok = false;
        const double d = v ? v->trimmed().toDouble(&ok) : 0.0;
        if (ok && d > 0.0)
            return d;
    }
    return kDefaultVideoFps;
}

void addVideoFrameTimes(Dataset& d, const std::function<std::vector<double>(const QString&, QString*)>& frameTimesOf,
                        QStringList* warnings)
{
    for (DatasetRun& r : d.runs) {
        if (r.videoPath.isEmpty())
            continue;
        QString problem;
        r.videoFrameTimes_s = frameTimesOf(r.videoPath, &problem);
        if (r.videoFrameTimes_s.empty())
            *warnings << nb::TrCore::tr("%1: frames numbered from the run's frame rate, the video could not be indexed (%2)")
                             .arg(r.videoPath, problem.isEmpty() ? nb::TrCore::tr("no frames") : problem);
    }
}

}  // namespace nb
