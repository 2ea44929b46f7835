#include "plan_runner.h"
#include "core/tr.h"

#include <QFile>
#include <QJsonDocument>
#include <QSaveFile>
#include <QTextStream>

namespace nb::cli {

int cmdSimulate(const QStringList& args, Io io);
int cmdAcquire(const QStringList& args, Io io);

namespace {

bool isSimulated(const PlannedRunRequest& r)
{
    auto sim = [](const QString& s) { return s.isEmpty() || s == QLatin1String("sim"); };
    return sim(r.daq) && sim(r.stage);
}

QString number(const QJsonValue& v) { return QString::number(v.toDouble(), 'g', 12); }

}  // namespace

QStringList plannedRunArguments(const PlannedRunRequest& r, bool simulated)
{
    const QJsonObject& s = r.settings;
    QStringList a{QStringLiteral("--protocol"), s.value(QStringLiteral("protocol")).toString(), QStringLiteral("--out"), r.runFile};
    // Plan setting -> option of both commands.
    static const std::vector<std::pair<const char*, const char*>> common{
        {"velocity_mm_s", "--velocity-mm-s"}, {"depth_mm", "--depth-mm"},   {"amplitude_mm", "--amplitude-mm"},
        {"frequency_hz", "--frequency-hz"},   {"cycles", "--cycles"},       {"rate_hz", "--rate-hz"},
        {"max_force_n", "--max-force-n"}};
    for (const auto& [key, option] : common)
        if (s.contains(QLatin1String(key)))
            a << QLatin1String(option) << number(s.value(QLatin1String(key)));
    if (simulated) {
        static const std::vector<std::pair<const char*, const char*>> sim{
            {"thickness_mm", "--thickness-mm"}, {"bone_depth_mm", "--bone-depth-mm"}, {"seed", "--seed"}};
        for (const auto& [key, option] : sim)
            if (s.contains(QLatin1String(key)))
                a << QLatin1String(option) << number(s.value(QLatin1String(key)));
        for (const char* key : {"tissue", "tip"})
            if (s.contains(QLatin1String(key)))
                a << QStringLiteral("--") + QLatin1String(key) << s.value(QLatin1String(key)).toString();
        if (!r.videoFile.isEmpty())
            a << QStringLiteral("--video") << r.videoFile;
        if (!r.truthFile.isEmpty())
            a << QStringLiteral("--truth") << r.truthFile;
    } else {
        a << QStringLiteral("--daq") << (r.daq.isEmpty() ? QStringLiteral("sim") : r.daq) << QStringLiteral("--stage")
          << (r.stage.isEmpty() ? QStringLiteral("sim") : r.stage);
    }
    // Stop at puncture: the engine decides it; passed through as the commands will take it.
    if (s.contains(QStringLiteral("stop_at")))
        a << QStringLiteral("--stop-at") << s.value(QStringLiteral("stop_at")).toString();
    if (s.contains(QStringLiteral("slow_after_puncture_mm_s")))
        a << QStringLiteral("--slow-after-puncture") << number(s.value(QStringLiteral("slow_after_puncture_mm_s")));
    return a;
}

QString addRunFileMetadata(const QString& path, const Metadata& metadata)
{
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return nb::TrCli::tr("cannot read %1: %2").arg(path, in.errorString());
    const QByteArray bytes = in.readAll();
    in.close();
    // The column header is the first line that is not a `#` comment.
    qsizetype at = 0;
    while (at < bytes.size() && (bytes.at(at) == '#' || (at == 0 && bytes.startsWith("\xEF\xBB\xBF#")))) {
        const qsizetype nl = bytes.indexOf('\n', at);
        if (nl < 0)
            return nb::TrCli::tr("%1: no column header").arg(path);
        at = nl + 1;
    }
    QByteArray lines;
    for (const auto& [key, value] : metadata.entries()) {
        QString v = value;
        v.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
        lines += "# " + key.toUtf8() + ": " + v.toUtf8() + '\n';
    }
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(bytes.left(at)) < 0 || out.write(lines) < 0 || out.write(bytes.mid(at)) < 0 ||
        !out.commit())
        return nb::TrCli::tr("cannot write %1: %2").arg(path, out.errorString());
    return {};
}

PlannedRunOutcome runPlannedRun(const PlannedRunRequest& request)
{
    PlannedRunOutcome outcome;
    const bool simulated = isSimulated(request);
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    const QStringList args = plannedRunArguments(request, simulated);
    const int code = simulated ? cmdSimulate(args, {out, err}) : cmdAcquire(args, {out, err});
    out.flush();
    err.flush();
    const QJsonObject summary = QJsonDocument::fromJson(outText.mid(outText.indexOf(QLatin1Char('{'))).toUtf8()).object();
    outcome.endReason = summary.value(QStringLiteral("end_reason")).toString();
    if (outcome.endReason.isEmpty() || !QFile::exists(request.runFile)) {
        outcome.error = errText.trimmed().isEmpty() ? nb::TrCli::tr("the run did not start (exit code %1)").arg(code) : errText.trimmed();
        return outcome;
    }
    Metadata m = request.metadata;
    if (!request.truthFile.isEmpty()) {
        QFile tf(request.truthFile);
        if (tf.open(QIODevice::ReadOnly))
            outcome.videoOffset_s = QJsonDocument::fromJson(tf.readAll()).object().value(QStringLiteral("video_offset_s")).toDouble();
    }
    if (!request.videoFile.isEmpty() && QFile::exists(request.videoFile)) {
        // Relative to the run file, so the session folder can move.
        m.set(QStringLiteral("video_file"), request.videoFile.mid(request.videoFile.lastIndexOf(QLatin1Char('/')) + 1));
        m.set(QStringLiteral("video_offset_s"), outcome.videoOffset_s);
    }
    if (const QString e = addRunFileMetadata(request.runFile, m); !e.isEmpty()) {
        outcome.error = e;
        return outcome;
    }
    outcome.ok = true;
    if (outcome.endReason == QLatin1String("fault"))
        outcome.error = summary.value(QStringLiteral("fault")).toString();
    return outcome;
}

}  // namespace nb::cli
