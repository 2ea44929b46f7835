#include "plan_runner.h"
#include "simulated_run.h"
#include "core/end_reason.h"
#include "core/tr.h"
#include "core/save_file.h"

#include <QFile>
#include <QJsonDocument>
#include <QTextStream>

namespace nb::cli {

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
        !commitWhole(out))
        return nb::TrCli::tr("cannot write %1: %2").arg(path, out.errorString());
    return {};
}

namespace {

// The simulated rig through simulateRun, as `simulate` does, with the simulate command's
// defaults for what the plan leaves out.
PlannedRunOutcome runSimulated(const PlannedRunRequest& r)
{
    using namespace devices::sim;
    PlannedRunOutcome outcome;
    const QJsonObject& s = r.settings;
    SimulatedRunRequest q;
    q.protocol = s.value(QStringLiteral("protocol")).toString();
    const bool internal = q.protocol == QLatin1String("internal"), friction = q.protocol == QLatin1String("friction");
    q.rig.tissue = s.contains(QStringLiteral("tissue"))              ? s.value(QStringLiteral("tissue")).toString()
                   : q.protocol == QLatin1String("prostate") ? QStringLiteral("prostate")
                   : (internal || friction)                  ? QStringLiteral("liver7")
                                                             : QStringLiteral("liver1");
    if (!tissueNames().contains(q.rig.tissue)) {
        outcome.error = nb::TrCli::tr("unknown tissue '%1' (%2)").arg(q.rig.tissue, tissueNames().join(QLatin1Char('|')));
        return outcome;
    }
    if (s.contains(QStringLiteral("tip"))) {
        const auto tip = tipFromName(s.value(QStringLiteral("tip")).toString());
        if (!tip) {
            outcome.error = nb::TrCli::tr("unknown tip '%1' (beveled|diamond|blunt)").arg(s.value(QStringLiteral("tip")).toString());
            return outcome;
        }
        q.rig.tip = *tip;
    } else {
        q.rig.tip = usualTip(q.rig.tissue, internal);
    }
    q.rig.setup = friction ? Setup::Platform : Setup::Organ;
    q.rig.seed = std::uint64_t(s.value(QStringLiteral("seed")).toDouble(1.0));
    q.rig.realtime = false;
    q.rig.thickness_mm = s.value(QStringLiteral("thickness_mm")).toDouble(q.rig.thickness_mm);
    if (s.contains(QStringLiteral("bone_depth_mm")))
        q.rig.boneDepth_mm = s.value(QStringLiteral("bone_depth_mm")).toDouble();
    q.rateHz = s.value(QStringLiteral("rate_hz")).toDouble(500.0);
    const devices::RunPlan motion = runPlanForSettings(s);
    q.velocity_mm_s = motion.linear.velocity_mm_s;
    q.depth_mm = motion.linear.target_mm;
    q.sine = motion.sine;
    q.maxForce_N = s.value(QStringLiteral("max_force_n")).toDouble(8.0);
    q.stopAtPuncture = motion.stopAtPuncture;
    q.slowAfterPuncture_mm_s = motion.slowAfterPuncture_mm_s;
    q.out = r.runFile;
    q.truth = r.truthFile;
    q.video = r.videoFile;
    q.extraMetadata = r.metadata;
    if (!q.video.isEmpty()) {
        q.extraMetadata.set(QStringLiteral("video_file"), q.video.mid(q.video.lastIndexOf(QLatin1Char('/')) + 1));
        q.extraMetadata.set(QStringLiteral("video_offset_s"), q.videoOffset_s);
    }
    devices::RunOnceOptions options;
    options.interruption = r.interruption;
    const SimulatedRunResult result = simulateRun(q, options);
    if (!result.summary) {
        outcome.error = result.error;
        return outcome;
    }
    outcome.endReason = fileName(result.summary->endReason);
    outcome.videoOffset_s = result.videoOffset_s;
    outcome.ok = result.error.isEmpty();
    outcome.error = !result.error.isEmpty() ? result.error : result.summary->fault;
    return outcome;
}

}  // namespace

devices::RunPlan runPlanForSettings(const QJsonObject& s)
{
    devices::RunPlan plan;
    const bool internal = s.value(QStringLiteral("protocol")).toString() == QLatin1String("internal");
    const bool sine = s.value(QStringLiteral("motion")).toString() == QLatin1String("sine") ||
                      (!s.contains(QStringLiteral("motion")) && s.value(QStringLiteral("protocol")).toString() == QLatin1String("friction"));
    plan.motion = sine ? devices::RunPlan::Motion::Sine : devices::RunPlan::Motion::Linear;
    plan.linear.velocity_mm_s = s.value(QStringLiteral("velocity_mm_s")).toDouble(internal ? 2.5 : 4.0);
    plan.linear.target_mm = s.value(QStringLiteral("depth_mm")).toDouble(40.0);
    plan.sine = {s.value(QStringLiteral("amplitude_mm")).toDouble(10.0), s.value(QStringLiteral("frequency_hz")).toDouble(0.5),
                 int(s.value(QStringLiteral("cycles")).toDouble(7.0))};
    const QString stopAt = s.value(QStringLiteral("stop_at")).toString();
    if (stopAt.startsWith(QLatin1String("puncture")))
        plan.stopAtPuncture = stopAt.contains(QLatin1Char(':')) ? stopAt.section(QLatin1Char(':'), 1).toInt() : 1;
    plan.slowAfterPuncture_mm_s = s.value(QStringLiteral("slow_after_puncture_mm_s")).toDouble(0.0);
    return plan;
}

devices::SimulatedRigSpec simulatedRigForSettings(const QJsonObject& s, devices::SimulatedRigSpec rig)
{
    const QString protocol = s.value(QStringLiteral("protocol")).toString();
    const bool friction = protocol == QLatin1String("friction");
    rig.tissue = s.contains(QStringLiteral("tissue"))         ? s.value(QStringLiteral("tissue")).toString()
                 : protocol == QLatin1String("prostate")      ? QStringLiteral("prostate")
                 : (protocol == QLatin1String("internal") || friction) ? QStringLiteral("liver7")
                                                               : QStringLiteral("liver1");
    rig.tip = s.value(QStringLiteral("tip")).toString();
    rig.setup = friction ? QStringLiteral("platform") : QStringLiteral("organ");
    rig.seed = quint64(s.value(QStringLiteral("seed")).toDouble(1.0));
    return rig;
}

PlannedRunOutcome runPlannedRun(const PlannedRunRequest& request)
{
    if (isSimulated(request))
        return runSimulated(request);
    // Real devices: the acquire command, then the plan's lines into the run file's header.
    PlannedRunOutcome outcome;
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    const int code = cmdAcquire(plannedRunArguments(request, false), {out, err});
    out.flush();
    err.flush();
    const QJsonObject summary = QJsonDocument::fromJson(outText.mid(outText.indexOf(QLatin1Char('{'))).toUtf8()).object();
    outcome.endReason = summary.value(QStringLiteral("end_reason")).toString();
    if (outcome.endReason.isEmpty() || !QFile::exists(request.runFile)) {
        outcome.error = errText.trimmed().isEmpty() ? nb::TrCli::tr("the run did not start (exit code %1)").arg(code) : errText.trimmed();
        return outcome;
    }
    if (const QString e = addRunFileMetadata(request.runFile, request.metadata); !e.isEmpty()) {
        outcome.error = e;
        return outcome;
    }
    outcome.ok = true;
    outcome.error = summary.value(QStringLiteral("fault")).toString();
    return outcome;
}

}  // namespace nb::cli
