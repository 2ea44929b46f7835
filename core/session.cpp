#include "session.h"
#include "core/run_keys.h"
#include "core/tr.h"
#include "core/save_file.h"

#include "core/end_reason.h"
#include "core/run_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QDateTime>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QRegularExpression>
#include <algorithm>

namespace nb {

namespace {

const QString kSessionFile = QStringLiteral("session.json");
const QString kCalibrationDir = QStringLiteral("calibrations");

void writeJson(const QString& path, const QJsonObject& object)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw SessionError(path, file.errorString());
    file.write(QJsonDocument(object).toJson(QJsonDocument::Indented));
    if (!commitWhole(file))
        throw SessionError(path, file.errorString());
}

QJsonObject readJson(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw SessionError(path, file.errorString());
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError)
        throw SessionError(path, nb::TrCore::tr("not valid JSON at byte %1: %2").arg(error.offset).arg(error.errorString()));
    if (!doc.isObject())
        throw SessionError(path, nb::TrCore::tr("expected a JSON object"));
    return doc.object();
}

QJsonArray pointsJson(const std::vector<CalibrationPoint>& points)
{
    QJsonArray a;
    for (const CalibrationPoint& p : points)
        a.append(QJsonObject{{QStringLiteral("mass_g"), p.mass_g}, {QStringLiteral("voltage_V"), p.voltage_V}});
    return a;
}

std::vector<CalibrationPoint> pointsFromJson(const QJsonArray& a)
{
    std::vector<CalibrationPoint> points;
    for (const QJsonValue& v : a)
        points.push_back({v[QStringLiteral("mass_g")].toDouble(), v[QStringLiteral("voltage_V")].toDouble()});
    return points;
}

// `# key: value` lines, as in the run file format.
std::optional<std::pair<QString, QString>> metaLine(const QByteArray& raw)
{
    const QString line = QString::fromUtf8(raw).trimmed();
    if (!line.startsWith(QLatin1Char('#')))
        return std::nullopt;
    const QString body = line.mid(1).trimmed();
    const int colon = body.indexOf(QLatin1Char(':'));
    if (colon <= 0)
        return std::nullopt;
    return std::make_pair(body.left(colon).trimmed(), body.mid(colon + 1).trimmed());
}

const QRegularExpression& runNamePattern()
{
    static const QRegularExpression re(QStringLiteral(R"(^run_(\d+)(_[A-Za-z0-9-]+)?\.csv$)"));
    return re;
}

}  // namespace

Metadata sessionMetadata(const SessionInfo& i)
{
    Metadata m;
    m.set(key::organ, i.organ);
    m.set(key::specimen, i.specimen);
    m.set(key::tip, i.tip);
    m.set(key::thickness_mm, i.thickness_mm);
    m.set(key::operatorName, i.operatorName);
    m.set(key::protocol, i.protocol);
    return m;
}

QString sessionFolderName(const SessionInfo& info, const QDateTime& created)
{
    static const QRegularExpression unsafe(QStringLiteral("[^\\p{L}\\p{N}_-]+"));
    QStringList parts;
    for (QString part : {info.organ, info.specimen}) {
        part.replace(unsafe, QStringLiteral("_"));
        while (part.startsWith(QLatin1Char('_')))
            part.remove(0, 1);
        while (part.endsWith(QLatin1Char('_')))
            part.chop(1);
        if (!part.isEmpty())
            parts << part;
    }
    if (parts.isEmpty())
        parts << QStringLiteral("session");
    parts << created.toString(QStringLiteral("yyyyMMdd_HHmmss"));
    return parts.join(QLatin1Char('_'));
}

RunState runStateForEndReason(const QString& r)
{
    if (r.isEmpty())
        return RunState::Interrupted;
    const std::optional<EndReason> reason = endReasonFromFileName(r);
    if (!reason)
        return RunState::Stopped;  // a newer program's reason: at least not a normal end
    switch (*reason) {
    case EndReason::Completed: return RunState::Complete;
    case EndReason::Stopped: return RunState::Stopped;
    case EndReason::MotionStopped: return RunState::MotionStopped;
    case EndReason::EmergencyStop: return RunState::EmergencyStop;
    case EndReason::ForceLimit: return RunState::StoppedByLimit;
    case EndReason::Puncture: return RunState::Puncture;
    case EndReason::Fault: return RunState::Fault;
    case EndReason::WriteError: return RunState::WriteError;
    // Closed whole, its footer written: nothing to recover (a start rewrote it as "recovered",
    // and the signal that ended it was lost from the list).
    case EndReason::Interrupted: return RunState::ClosedOnSignal;
    case EndReason::Aborted: return RunState::Aborted;
    case EndReason::Recovered: return RunState::Recovered;
    }
    return RunState::Stopped;
}

QString runStateName(RunState state)
{
    // The same words as the footer's reason everywhere else (core/end_reason.h).
    switch (state) {
    case RunState::Interrupted: return displayName(EndReason::Interrupted);
    case RunState::ClosedOnSignal: return displayName(EndReason::Interrupted);
    case RunState::Complete: return displayName(EndReason::Completed);
    case RunState::Stopped: return displayName(EndReason::Stopped);
    case RunState::StoppedByLimit: return displayName(EndReason::ForceLimit);
    case RunState::Fault: return displayName(EndReason::Fault);
    case RunState::Recovered: return displayName(EndReason::Recovered);
    case RunState::MotionStopped: return displayName(EndReason::MotionStopped);
    case RunState::EmergencyStop: return displayName(EndReason::EmergencyStop);
    case RunState::Puncture: return displayName(EndReason::Puncture);
    case RunState::WriteError: return displayName(EndReason::WriteError);
    case RunState::Aborted: return displayName(EndReason::Aborted);
    case RunState::Unreadable: return nb::TrCore::tr("unreadable");
    }
    return {};
}

RunEntry inspectRun(const QString& path)
{
    RunEntry e;
    const QFileInfo fi(path);
    e.path = path;
    e.fileName = fi.fileName();
    e.modified = fi.lastModified();
    const auto m = runNamePattern().match(e.fileName);
    if (m.hasMatch())
        e.number = m.captured(1).toInt();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        e.state = RunState::Unreadable;
        // A name in another encoding is listed with '\uFFFD' for its odd bytes and cannot be
        // opened by that name: "no such file" of a file the folder shows.
        e.detail = e.fileName.contains(QChar::ReplacementCharacter)
                       ? nb::TrCore::tr("its name is not UTF-8, so it cannot be opened by it; rename it")
                       : file.errorString();
        return e;
    }
    // A binary file (an image or an archive saved under a run's name) has no footer either, and
    // was listed as a run still recording: export said to wait for it to end.
    if (file.peek(8192).contains('\0')) {
        e.state = RunState::Unreadable;
        e.detail = nb::TrCore::tr("binary data, not a text run file");
        return e;
    }
    // Head: metadata lines up to the header row.
    bool sawHeader = false;
    for (int i = 0; i < 200 && !file.atEnd(); ++i) {
        const QByteArray line = file.readLine();
        const auto kv = metaLine(line);
        if (!kv) {
            sawHeader = !line.trimmed().isEmpty();
            break;
        }
        if (kv->first == QLatin1String("motion"))
            e.motion = kv->second;
        else if (kv->first == QLatin1String("calibration"))
            e.calibration = kv->second;
    }
    if (!sawHeader) {
        e.state = RunState::Unreadable;
        e.detail = nb::TrCore::tr("no header row");
        return e;
    }
    // Tail: the footer is the run of `# key: value` lines at the very end.
    const qint64 tail = std::min<qint64>(file.size(), 8192);
    file.seek(file.size() - tail);
    QList<QByteArray> lines = file.read(tail).split('\n');
    while (!lines.isEmpty() && lines.last().trimmed().isEmpty())
        lines.removeLast();
    for (auto it = lines.crbegin(); it != lines.crend(); ++it) {
        const auto kv = metaLine(*it);
        if (!kv)
            break;
        if (kv->first == QLatin1String("end_reason") && e.endReason.isEmpty())
            e.endReason = kv->second;
        if (kv->first == QLatin1String("calibration") && e.calibration.isEmpty())
            e.calibration = kv->second;
    }
    e.state = runStateForEndReason(e.endReason);
    return e;
}

QStringList recoverRunFile(const QString& path)
{
    RunReadOptions options;
    options.dropTruncatedLastRow = true;
    RunReadResult result = readRunFile(path, options);
    const QString original = result.run.footer.value(QStringLiteral("end_reason"), QString());
    result.run.footer.set(QStringLiteral("end_reason"), QStringLiteral("recovered"));
    result.run.footer.set(QStringLiteral("recovered_at"), QDateTime::currentDateTime().toString(Qt::ISODate));
    result.run.footer.set(QStringLiteral("recovered_rows"), QString::number(result.run.size()));
    writeRunFile(path, result.run);
    return result.warnings;
}

Session Session::create(const QString& dir, const SessionInfo& info)
{
    QDir d(dir);
    if (!d.exists() && !QDir().mkpath(dir))
        throw SessionError(dir, nb::TrCore::tr("cannot create the folder"));
    if (QFileInfo::exists(d.filePath(kSessionFile)))
        throw SessionError(d.filePath(kSessionFile), nb::TrCore::tr("a session already exists here; open it instead"));
    if (!d.mkpath(kCalibrationDir))
        throw SessionError(d.filePath(kCalibrationDir), nb::TrCore::tr("cannot create the folder"));
    Session s;
    s.dir_ = d.absolutePath();
    s.info_ = info;
    if (!s.info_.created.isValid())
        s.info_.created = QDateTime::currentDateTime();
    s.save();
    return s;
}

bool Session::isSession(const QString& dir) { return QFileInfo::exists(QDir(dir).filePath(kSessionFile)); }

Session Session::open(const QString& dir)
{
    const QString path = QDir(dir).filePath(kSessionFile);
    if (!QFileInfo::exists(path))
        throw SessionError(dir, nb::TrCore::tr("not a session folder (no %1)").arg(kSessionFile));
    const QJsonObject o = readJson(path);
    Session s;
    s.dir_ = QDir(dir).absolutePath();
    // Text fields stay text; one typed as a number by hand (specimen: 12) is kept as written.
    auto text = [&](const char* key) {
        const QJsonValue v = o[QLatin1String(key)];
        return v.isDouble() ? QString::number(v.toDouble(), 'g', 17) : v.toString();
    };
    s.info_.organ = text("organ");
    s.info_.specimen = text("specimen");
    s.info_.tip = text("tip");
    s.info_.thickness_mm = o[QStringLiteral("thickness_mm")].toDouble();
    s.info_.operatorName = text("operator");
    s.info_.protocol = text("protocol");
    s.info_.notes = text("notes");
    s.info_.created = QDateTime::fromString(o[QStringLiteral("created")].toString(), Qt::ISODate);
    s.activeCalibration_ = o[QStringLiteral("active_calibration")].toString();
    s.simulatedRig_ = o[QStringLiteral("simulated_rig")].toObject();
    return s;
}

void Session::setSimulatedRig(const QJsonObject& settings)
{
    simulatedRig_ = settings;
    save();
}

void Session::save() const
{
    QJsonObject o{{QStringLiteral("organ"), info_.organ},
                          {QStringLiteral("specimen"), info_.specimen},
                          {QStringLiteral("tip"), info_.tip},
                          {QStringLiteral("thickness_mm"), info_.thickness_mm},
                          {QStringLiteral("operator"), info_.operatorName},
                          {QStringLiteral("protocol"), info_.protocol},
                          {QStringLiteral("notes"), info_.notes},
                          {QStringLiteral("created"), info_.created.toString(Qt::ISODate)},
                          {QStringLiteral("active_calibration"), activeCalibration_}};
    if (!simulatedRig_.isEmpty())
        o.insert(QStringLiteral("simulated_rig"), simulatedRig_);
    writeJson(QDir(dir_).filePath(kSessionFile), o);
}

void Session::setInfo(const SessionInfo& info)
{
    info_ = info;
    save();
}

QString Session::nextRunPath(const QString& motion) const
{
    int highest = 0;
    for (const QString& name : QDir(dir_).entryList({QStringLiteral("run_*.csv")}, QDir::Files)) {
        const auto m = runNamePattern().match(name);
        if (m.hasMatch())
            highest = std::max(highest, m.captured(1).toInt());
    }
    QString suffix = motion;
    suffix.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9-]")), QStringLiteral("-"));
    const QString name = QStringLiteral("run_%1%2.csv")
                             .arg(highest + 1, 3, 10, QLatin1Char('0'))
                             .arg(suffix.isEmpty() ? QString() : QLatin1Char('_') + suffix);
    return QDir(dir_).filePath(name);
}

std::vector<RunEntry> Session::runs() const
{
    std::vector<RunEntry> out;
    for (const QString& name : QDir(dir_).entryList({QStringLiteral("run_*.csv")}, QDir::Files)) {
        if (runNamePattern().match(name).hasMatch())
            out.push_back(inspectRun(QDir(dir_).filePath(name)));
    }
    std::sort(out.begin(), out.end(), [](const RunEntry& a, const RunEntry& b) { return a.number < b.number; });
    return out;
}

QStringList Session::recoverInterrupted(const QString& busyPath, QStringList* problems)
{
    QStringList recovered;
    for (const RunEntry& e : runs()) {
        if (e.state != RunState::Interrupted || QFileInfo(e.path) == QFileInfo(busyPath))
            continue;
        try {
            const QStringList warnings = recoverRunFile(e.path);
            recovered << (warnings.isEmpty() ? e.fileName : QStringLiteral("%1 (%2)").arg(e.fileName, warnings.join(QStringLiteral("; "))));
        } catch (const RunFileError& error) {
            if (problems)
                *problems << error.message();
        }
    }
    return recovered;
}

QString Session::saveCalibration(StoredCalibration c)
{
    if (!c.date.isValid())
        c.date = QDateTime::currentDateTime();
    if (c.name.isEmpty())
        c.name = QStringLiteral("cal_") + c.date.toString(QStringLiteral("yyyyMMdd_HHmmss"));
    QDir d(dir_);
    d.mkpath(kCalibrationDir);
    QJsonArray residuals;
    for (double r : c.fit.residuals_V)
        residuals.append(r);
    writeJson(d.filePath(kCalibrationDir + QLatin1Char('/') + c.name + QStringLiteral(".json")),
              QJsonObject{{QStringLiteral("name"), c.name},
                          {QStringLiteral("date"), c.date.toString(Qt::ISODate)},
                          {QStringLiteral("sensor"), c.sensor},
                          {QStringLiteral("nominal"), c.nominal},
                          {QStringLiteral("slope_V_per_g"), c.fit.slope_V_per_g},
                          {QStringLiteral("intercept_V"), c.fit.intercept_V},
                          {QStringLiteral("r2"), c.fit.r2},
                          {QStringLiteral("rms_V"), c.fit.rms_V},
                          {QStringLiteral("residuals_V"), residuals},
                          {QStringLiteral("points"), pointsJson(c.points)},
                          {QStringLiteral("removed_points"), pointsJson(c.removed)}});
    activeCalibration_ = c.name;
    save();
    return c.name;
}

std::vector<StoredCalibration> Session::calibrations() const
{
    std::vector<StoredCalibration> out;
    const QDir d(QDir(dir_).filePath(kCalibrationDir));
    for (const QString& name : d.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        try {
            const QJsonObject o = readJson(d.filePath(name));
            StoredCalibration c;
            c.name = o[QStringLiteral("name")].toString(QFileInfo(name).completeBaseName());
            c.date = QDateTime::fromString(o[QStringLiteral("date")].toString(), Qt::ISODate);
            c.sensor = o[QStringLiteral("sensor")].toString();
            c.nominal = o[QStringLiteral("nominal")].toBool();
            c.fit.slope_V_per_g = o[QStringLiteral("slope_V_per_g")].toDouble();
            c.fit.intercept_V = o[QStringLiteral("intercept_V")].toDouble();
            c.fit.r2 = o[QStringLiteral("r2")].toDouble();
            c.fit.rms_V = o[QStringLiteral("rms_V")].toDouble();
            for (const QJsonValue& v : o[QStringLiteral("residuals_V")].toArray())
                c.fit.residuals_V.push_back(v.toDouble());
            c.points = pointsFromJson(o[QStringLiteral("points")].toArray());
            c.removed = pointsFromJson(o[QStringLiteral("removed_points")].toArray());
            if (c.fit.slope_V_per_g > 0.0)
                out.push_back(std::move(c));
        } catch (const SessionError&) {
            // An unreadable calibration is simply not offered.
        }
    }
    return out;
}

std::optional<StoredCalibration> Session::activeCalibration() const
{
    for (StoredCalibration& c : calibrations())
        if (c.name == activeCalibration_)
            return std::move(c);
    return std::nullopt;
}

void Session::setActiveCalibration(const QString& name)
{
    activeCalibration_ = name;
    save();
}

SessionLock lockSession(const QString& dir)
{
    SessionLock lock;
    const QString path = QDir(dir).filePath(QStringLiteral(".needlebench.lock"));
    auto file = std::make_unique<QLockFile>(path);
    file->setStaleLockTime(0);  // held as long as its program lives, however long
    bool locked = file->tryLock(0);
    // A lock file that names no process (empty or garbled: a crash or a full disk as it was
    // written) is no one's, and QLockFile never takes it for stale: the session stayed locked
    // for good ("process 0 on "). One that young may still be being written.
    qint64 pid = 0;
    QString host, app;
    if (!locked && file->error() == QLockFile::LockFailedError && !file->getLockInfo(&pid, &host, &app) &&
        QFileInfo(path).lastModified().secsTo(QDateTime::currentDateTime()) > 10) {
        file->removeStaleLockFile();
        locked = file->tryLock(0);
    }
    if (locked) {
        lock.file = std::move(file);
    } else if (file->error() == QLockFile::LockFailedError) {
        lock.heldBy = file->getLockInfo(&pid, &host, &app)
                          ? nb::TrCore::tr("process %1 on %2").arg(pid).arg(host)
                          : nb::TrCore::tr("its lock file %1 names no process; if no NeedleBench has it open, delete that file").arg(path);
    }
    return lock;
}

}  // namespace nb
