// `needlebench plan`: experiment plans headless. templates / new / show / run / skip / redo /
// report. `plan run` keeps the plan's status in SESSION/plan.json after every run, so a plan
// cut off by a crash resumes at the first run not completed when the same command runs again.

#include "cli_support.h"
#include "interrupt_watcher.h"
#include "plan_runner.h"
#include "core/tr.h"
#include "core/save_file.h"

#include "core/export/dataset_loader.h"
#include "core/export/export_error.h"
#include "core/export/factor_analysis.h"
#include "core/plan_session.h"
#include "core/export/session_analysis.h"
#include "core/plan.h"
#include "core/run_file.h"
#include "core/session.h"

#include <QCoreApplication>
#include <QDir>
#include <QLockFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace nb::cli {

namespace {

const QString kPlanFile = planFileName();

int usage(Io io, const QString& sub, const QString& why)
{
    io.err << "needlebench plan " << sub << ": " << why << "\n\n"
           << nb::TrCli::tr("Run 'needlebench plan %1 --help' for the options.").arg(sub) << '\n';
    return Usage;
}

int fail(Io io, const QString& sub, const QString& why)
{
    io.err << "needlebench plan " << sub << ": " << why << '\n';
    return Failure;
}

void printPlanUsage(QTextStream& s)
{
    s << nb::TrCli::tr("Usage: needlebench plan templates [--json]\n"
                       "       needlebench plan new --template NAME --out PLAN.json [--order listed|random|blocked] [--seed N]\n"
                       "                            [--set KEY=VALUE]... [--levels FACTOR=L1,L2,...]...\n"
                       "       needlebench plan show PLAN.json [--json]\n"
                       "       needlebench plan run PLAN.json --session DIR [--daq DAQ --stage STAGE] [--yes]\n"
                       "       needlebench plan skip PLAN.json --run N --reason TEXT\n"
                       "       needlebench plan redo PLAN.json --run N [--reason TEXT]\n"
                       "       needlebench plan report SESSION_DIR [--by FACTOR,...] [--estimate-mass] [--json] [--out-dir DIR]\n");
}

// "0.5" -> number, "true"/"false" -> bool, else text.
QJsonValue valueFromText(const QString& text)
{
    bool ok = false;
    const double d = text.toDouble(&ok);
    if (ok)
        return d;
    if (text == QLatin1String("true") || text == QLatin1String("false"))
        return text == QLatin1String("true");
    return text;
}

int cmdTemplates(const QStringList& args, Io io)
{
    QCommandLineParser p;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    p.addOption(json);
    int code = Ok;
    if (!parseArgs(p, QStringLiteral("plan templates"), args, io, 0, 0, &code))
        return code;
    if (p.isSet(json)) {
        QJsonArray a;
        for (const PlanTemplate& t : planTemplates()) {
            const Plan plan = generatePlan(t, PlanOrder::Listed, 1);
            QJsonArray factors;
            for (const PlanFactor& f : t.factors) {
                QJsonArray levels;
                for (const QJsonValue& l : f.levels)
                    levels.append(l);
                factors.append(QJsonObject{{QStringLiteral("name"), f.name}, {QStringLiteral("levels"), levels}});
            }
            a.append(QJsonObject{{QStringLiteral("name"), t.name},
                                 {QStringLiteral("title"), t.title},
                                 {QStringLiteral("description"), t.description},
                                 {QStringLiteral("runs"), double(plan.runs.size())},
                                 {QStringLiteral("defaults"), t.defaults},
                                 {QStringLiteral("factors"), factors}});
        }
        printJson(io, QJsonObject{{QStringLiteral("templates"), a}});
        return Ok;
    }
    for (const PlanTemplate& t : planTemplates()) {
        const Plan plan = generatePlan(t, PlanOrder::Listed, 1);
        io.out << t.name.leftJustified(20) << ' ' << QString::number(plan.runs.size()).rightJustified(3) << ' '
               << nb::TrCli::tr("runs") << "  " << t.description << '\n';
    }
    return Ok;
}

int cmdNew(const QStringList& args, Io io)
{
    QCommandLineParser p;
    const QCommandLineOption tmpl(QStringLiteral("template"), nb::TrCli::tr("the template (see 'plan templates')"), QStringLiteral("NAME"));
    const QCommandLineOption out(QStringLiteral("out"), nb::TrCli::tr("the plan file to write"), QStringLiteral("PLAN.json"));
    const QCommandLineOption order(QStringLiteral("order"), nb::TrCli::tr("listed | random | blocked (by site; default listed)"), QStringLiteral("ORDER"),
                                   QStringLiteral("listed"));
    const QCommandLineOption seed(QStringLiteral("seed"), nb::TrCli::tr("seed of the random order and of the simulated runs (default 1)"),
                                  QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption set(QStringLiteral("set"), nb::TrCli::tr("change a default setting, e.g. cycles=3 (repeatable)"), QStringLiteral("KEY=VALUE"));
    const QCommandLineOption levels(QStringLiteral("levels"), nb::TrCli::tr("set a factor's levels, e.g. site=1,2,3 (repeatable; a new name adds a factor)"),
                                    QStringLiteral("FACTOR=L1,L2"));
    const QCommandLineOption overwrite(QStringLiteral("overwrite"),
                                       nb::TrCli::tr("replace an existing file (never a plan with recorded runs)"));
    for (const auto* o : {&tmpl, &out, &order, &seed, &set, &levels, &overwrite})
        p.addOption(*o);
    int code = Ok;
    const QString sub = QStringLiteral("new");
    if (!parseArgs(p, QStringLiteral("plan new"), args, io, 0, 0, &code))
        return code;
    if (!p.isSet(tmpl))
        return usage(io, sub, nb::TrCli::tr("--template NAME is required (see 'needlebench plan templates')"));
    const PlanTemplate* found = findPlanTemplate(p.value(tmpl));
    if (!found) {
        QStringList names;
        for (const PlanTemplate& t : planTemplates())
            names << t.name;
        return usage(io, sub, nb::TrCli::tr("unknown template '%1' (%2)").arg(p.value(tmpl), names.join(QLatin1Char('|'))));
    }
    if (!p.isSet(out))
        return usage(io, sub, nb::TrCli::tr("--out PLAN.json is required"));
    const auto o = planOrderFromName(p.value(order));
    if (!o)
        return usage(io, sub, nb::TrCli::tr("--order must be listed, random or blocked (got '%1')").arg(p.value(order)));
    bool ok = false;
    const quint64 s = p.value(seed).toULongLong(&ok);
    if (!ok || s > 4294967295ULL)
        return usage(io, sub, nb::TrCli::tr("--seed wants an integer from 0 to 4294967295 (got '%1')").arg(p.value(seed)));

    PlanTemplate design = *found;
    for (const QString& kv : p.values(set)) {
        const qsizetype eq = kv.indexOf(QLatin1Char('='));
        const QString key = kv.left(eq).trimmed();
        if (eq <= 0 || !knownPlanSettings().contains(key))
            return usage(io, sub, nb::TrCli::tr("--set %1: expected KEY=VALUE with KEY one of %2").arg(kv, knownPlanSettings().join(QStringLiteral(", "))));
        const QJsonValue v = valueFromText(kv.mid(eq + 1).trimmed());
        if (const QString e = checkPlanSetting(key, v); !e.isEmpty())
            return usage(io, sub, QStringLiteral("--set %1: %2").arg(kv, e));
        if (std::any_of(design.factors.begin(), design.factors.end(), [&](const PlanFactor& f) { return f.name == key; }))
            return usage(io, sub, nb::TrCli::tr("--set %1: %2 is a factor of this template; give its levels with --levels %2=...").arg(kv, key));
        design.defaults.insert(key, v);
    }
    for (const QString& kv : p.values(levels)) {
        const qsizetype eq = kv.indexOf(QLatin1Char('='));
        const QString name = kv.left(eq).trimmed();
        const QStringList values = kv.mid(eq + 1).split(QLatin1Char(','), Qt::SkipEmptyParts);
        if (eq <= 0 || values.isEmpty())
            return usage(io, sub, nb::TrCli::tr("--levels %1: expected FACTOR=L1,L2,...").arg(kv));
        PlanFactor f{name, {}, isOperatorSetting(name)};
        for (const QString& v : values) {
            f.levels.push_back(valueFromText(v.trimmed()));
            if (const QString e = checkPlanSetting(name, f.levels.back()); !e.isEmpty())
                return usage(io, sub, QStringLiteral("--levels %1: %2").arg(kv, e));
        }
        auto it = std::find_if(design.factors.begin(), design.factors.end(), [&](const PlanFactor& x) { return x.name == name; });
        if (it != design.factors.end()) {
            *it = f;
        } else {
            // Allowed (a factor the rig knows nothing of: an operator, a batch), but a typo of
            // a known name would otherwise multiply the plan without a word.
            if (!knownPlanSettings().contains(name))
                io.err << nb::TrCli::tr("needlebench plan new: note: '%1' is neither a setting of the rig nor a factor of this template "
                                        "(%2); it is added as a new factor that the operator sets")
                              .arg(name, QStringList(knownPlanSettings()).join(QStringLiteral(", ")))
                       << '\n';
            design.factors.push_back(f);
        }
        design.defaults.remove(name);
    }
    if (QFileInfo::exists(p.value(out))) {
        // Never overwrite a plan's record of what was run.
        try {
            const Plan existing = readPlanFile(p.value(out));
            if (std::any_of(existing.runs.begin(), existing.runs.end(), [](const PlannedRun& r) { return !r.attempts.empty(); }))
                return fail(io, sub, nb::TrCli::tr("%1 holds a plan with recorded runs; it is not overwritten").arg(p.value(out)));
        } catch (const PlanError&) {
            // Not a plan (or a broken one): kept unless --overwrite, as a recorded run or a
            // hand-edited plan named by mistake was replaced without a word.
        }
        if (const QString e = existingOutput(QStringLiteral("--out"), p.value(out), p.isSet(overwrite)); !e.isEmpty())
            return fail(io, sub, e);
    }
    try {
        const Plan plan = generatePlan(design, *o, s);
        writePlanFile(p.value(out), plan);
        io.out << nb::TrCli::tr("%1: %2 runs of '%3', order %4, seed %5")
                      .arg(p.value(out))
                      .arg(plan.runs.size())
                      .arg(plan.name, planOrderName(plan.order))
                      .arg(plan.seed)
               << '\n';
    } catch (const PlanError& e) {
        return fail(io, sub, e.message());
    }
    return Ok;
}

QJsonObject statusJson(const Plan& plan)
{
    QJsonArray runs;
    for (const PlannedRun& r : plan.runs) {
        QJsonObject o{{QStringLiteral("number"), r.number},
                      {QStringLiteral("description"), describeRun(plan, r)},
                      {QStringLiteral("status"), planRunStatusName(r.status)},
                      {QStringLiteral("factors"), r.factors}};
        if (const PlanAttempt* a = r.currentAttempt())
            o.insert(QStringLiteral("run_file"), a->runFile);
        if (!r.reason.isEmpty())
            o.insert(QStringLiteral("reason"), r.reason);
        runs.append(o);
    }
    return {{QStringLiteral("name"), plan.name},
            {QStringLiteral("remaining_motion_s"), remainingPlanDuration_s(plan)},
            {QStringLiteral("runs"), double(plan.runs.size())},
            {QStringLiteral("done"), plan.countWith(PlanRunStatus::Done)},
            {QStringLiteral("redone"), plan.countWith(PlanRunStatus::Redone)},
            {QStringLiteral("skipped"), plan.countWith(PlanRunStatus::Skipped)},
            {QStringLiteral("pending"), plan.countWith(PlanRunStatus::Pending) + plan.countWith(PlanRunStatus::Running)},
            {QStringLiteral("next"), plan.firstIncomplete() < 0 ? QJsonValue() : QJsonValue(plan.runs[std::size_t(plan.firstIncomplete())].number)},
            {QStringLiteral("run_list"), runs}};
}

int cmdShow(const QStringList& args, Io io)
{
    QCommandLineParser p;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    p.addOption(json);
    p.addPositionalArgument(QStringLiteral("PLAN.json"), nb::TrCli::tr("the plan file"));
    int code = Ok;
    if (!parseArgs(p, QStringLiteral("plan show"), args, io, 1, 1, &code))
        return code;
    try {
        const Plan plan = readPlanFile(p.positionalArguments().first());
        if (p.isSet(json)) {
            printJson(io, statusJson(plan));
            return Ok;
        }
        io.out << plan.name << ": " << plan.runs.size() << ' ' << nb::TrCli::tr("runs") << ", " << planOrderName(plan.order) << ", seed "
               << plan.seed << ", " << nb::TrCli::tr("%1 min of motion left").arg(remainingPlanDuration_s(plan) / 60.0, 0, 'f', 1) << '\n';
        for (const PlannedRun& r : plan.runs) {
            io.out << QString::number(r.number).rightJustified(4) << "  " << planRunStatusName(r.status).leftJustified(8) << "  "
                   << describeRun(plan, r);
            if (!r.reason.isEmpty())
                io.out << "  (" << r.reason << ')';
            io.out << '\n';
        }
    } catch (const PlanError& e) {
        return fail(io, QStringLiteral("show"), e.message());
    }
    return Ok;
}

int runIndex(const Plan& plan, const QString& text)
{
    bool ok = false;
    const int n = text.toInt(&ok);
    for (std::size_t i = 0; ok && i < plan.runs.size(); ++i)
        if (plan.runs[i].number == n)
            return int(i);
    return -1;
}

// skip / redo: change one run's status in a plan file.
int cmdMark(const QStringList& args, Io io, bool skip)
{
    const QString sub = skip ? QStringLiteral("skip") : QStringLiteral("redo");
    QCommandLineParser p;
    const QCommandLineOption run(QStringLiteral("run"), nb::TrCli::tr("the run's number"), QStringLiteral("N"));
    const QCommandLineOption reason(QStringLiteral("reason"), nb::TrCli::tr("why (required to skip)"), QStringLiteral("TEXT"));
    p.addOption(run);
    p.addOption(reason);
    p.addPositionalArgument(QStringLiteral("PLAN.json"), nb::TrCli::tr("the plan file (the session's plan.json)"));
    int code = Ok;
    if (!parseArgs(p, QStringLiteral("plan ") + sub, args, io, 1, 1, &code))
        return code;
    if (skip && p.value(reason).trimmed().isEmpty())
        return usage(io, sub, nb::TrCli::tr("--reason TEXT is required"));
    const QString path = p.positionalArguments().first();
    try {
        Plan plan = readPlanFile(path);
        const int i = runIndex(plan, p.value(run));
        if (i < 0)
            return usage(io, sub, nb::TrCli::tr("--run: no run '%1' in %2").arg(p.value(run), path));
        if (skip)
            skipRun(plan, i, p.value(reason).trimmed());
        else
            redoRun(plan, i, p.value(reason).trimmed());
        writePlanFile(path, plan);
        io.out << nb::TrCli::tr("run %1: %2").arg(plan.runs[std::size_t(i)].number).arg(planRunStatusName(plan.runs[std::size_t(i)].status)) << '\n';
    } catch (const PlanError& e) {
        return fail(io, sub, e.message());
    }
    return Ok;
}

int cmdRun(const QStringList& args, Io io)
{
    const QString sub = QStringLiteral("run");
    QCommandLineParser p;
    const QCommandLineOption session(QStringLiteral("session"), nb::TrCli::tr("the session folder (created when missing; holds plan.json and the runs)"),
                                     QStringLiteral("DIR"));
    const QCommandLineOption daq(QStringLiteral("daq"), nb::TrCli::tr("sim | u6 | u6:SERIAL (default sim)"), QStringLiteral("DAQ"));
    const QCommandLineOption stage(QStringLiteral("stage"), nb::TrCli::tr("sim | zaber:PORT (default sim)"), QStringLiteral("STAGE"));
    const QCommandLineOption yes(QStringLiteral("yes"), nb::TrCli::tr("on real devices, do not wait for Enter after an operator instruction"));
    for (const auto* o : {&session, &daq, &stage, &yes})
        p.addOption(*o);
    p.addPositionalArgument(QStringLiteral("PLAN.json"), nb::TrCli::tr("the plan (from 'plan new', or the session's plan.json)"));
    int code = Ok;
    if (!parseArgs(p, QStringLiteral("plan run"), args, io, 1, 1, &code))
        return code;
    if (!p.isSet(session))
        return usage(io, sub, nb::TrCli::tr("--session DIR is required"));
    const QString planArg = p.positionalArguments().first();
    const QString dir = p.value(session);
    const bool simulated = (!p.isSet(daq) || p.value(daq) == QLatin1String("sim")) && (!p.isSet(stage) || p.value(stage) == QLatin1String("sim"));

    Plan plan;
    QString planPath;
    std::optional<Session> s;
    SessionLock held;  // the session, while the plan runs (lockSession)
    try {
        plan = readPlanFile(planArg);
        if (!Session::isSession(dir)) {
            SessionInfo info;
            info.organ = plan.defaults.value(QStringLiteral("tissue")).toString();
            info.tip = plan.defaults.value(QStringLiteral("tip")).toString();
            info.thickness_mm = plan.defaults.value(QStringLiteral("thickness_mm")).toDouble();
            info.protocol = plan.name;
            info.notes = plan.description;
            s = Session::create(dir, info);
        } else {
            s = Session::open(dir);
        }
        planPath = QDir(s->dir()).filePath(kPlanFile);
        if (QFileInfo::exists(planPath) && QFileInfo(planPath).canonicalFilePath() != QFileInfo(planArg).canonicalFilePath()) {
            const Plan stored = readPlanFile(planPath);
            if (!stored.sameDesign(plan))
                return fail(io, sub,
                            nb::TrCli::tr("%1 holds a different plan; to resume it run 'needlebench plan run %1 --session %2', or use another session folder")
                                .arg(planPath, dir));
            plan = stored;
        }
        held = lockSession(s->dir());
        if (held.refused())
            return fail(io, sub, nb::TrCli::tr("%1 is open in another NeedleBench (%2); close it there first").arg(s->dir(), held.heldBy));
        QStringList problems;
        for (const QString& line : s->recoverInterrupted({}, &problems))
            io.out << nb::TrCli::tr("recovered %1").arg(line) << '\n';
        for (const QString& line : problems)
            io.err << line << '\n';
        const PlanResumption resumed = resumePlan(plan, s->dir());
        for (const auto& [number, file] : resumed.endedBefore)
            io.out << nb::TrCli::tr("run %1 had ended before the interruption: %2").arg(number).arg(file) << '\n';
        for (int n : resumed.interrupted)
            io.out << nb::TrCli::tr("run %1 was interrupted; it runs again").arg(n) << '\n';
        writePlanFile(planPath, plan);
    } catch (const PlanError& e) {
        return fail(io, sub, e.message());
    } catch (const SessionError& e) {
        return fail(io, sub, e.message());
    }

    const int total = int(plan.runs.size());
    QTextStream in(stdin);
    int failures = 0;
    int exitSignal = 0;
    QString stopped;
    // Ctrl+C, a closed terminal or `kill` stops the stage and closes the run as "interrupted",
    // and the plan stops there; between runs, before the next. Real devices: the `acquire`
    // command watches for itself while it records (one watcher at a time), and its run ends
    // "interrupted" as well.
    std::optional<InterruptWatcher> interrupts;
    if (simulated) {
        interrupts.emplace();
        interrupts->announceOn(io.err, QStringLiteral("plan run"));
    }
    for (int i = plan.firstIncomplete(); i >= 0 && i < total; ++i) {
        PlannedRun& run = plan.runs[std::size_t(i)];
        if (run.completed())
            continue;
        if (interrupts) {
            QCoreApplication::processEvents();  // a signal between runs
            if (interrupts->signalNumber()) {
                stopped = nb::TrCli::tr("the plan stops before run %1 (interrupted); run the same command again to resume").arg(run.number);
                exitSignal = interrupts->signalNumber();
                break;
            }
        }
        const QJsonObject settings = plan.settingsFor(run);
        if (!run.instruction.isEmpty()) {
            io.out << nb::TrCli::tr("operator: %1").arg(run.instruction) << '\n';
            if (!simulated && !p.isSet(yes)) {
                io.out << nb::TrCli::tr("press Enter when done") << '\n';
                io.out.flush();
                in.readLine();
            }
        }
        const QString runPath = unusedRunPath(plan, s->nextRunPath(settings.value(QStringLiteral("motion")).toString()));
        const QFileInfo fi(runPath);
        PlannedRunRequest req;
        req.settings = settings;
        req.runFile = runPath;
        if (simulated) {
            req.truthFile = fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".truth.json"));
            if (settings.value(QStringLiteral("video")).toBool())
                req.videoFile = fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".avi"));
        }
        req.daq = p.value(daq);
        req.stage = p.value(stage);
        try {
            beginAttempt(plan, i, fi.fileName(), req.videoFile.isEmpty() ? QString() : QFileInfo(req.videoFile).fileName(),
                         QDateTime::currentDateTimeUtc());
            writePlanFile(planPath, plan);
        } catch (const PlanError& e) {
            return fail(io, sub, e.message());
        }
        req.metadata = planRunMetadata(plan, run, kPlanFile);
        io.out << nb::TrCli::tr("run %1 of %2: %3").arg(run.number).arg(total).arg(describeRun(plan, run)) << " ... ";
        io.out.flush();
        if (interrupts)
            req.interruption = [&] { return interrupts->interruption(); };
        const PlannedRunOutcome r = runPlannedRun(req);
        const int signalled = interrupts ? interrupts->signalNumber() : 0;
        // A run recorded whole whose video or truth was not written (a signal while the video
        // was rendered, a full disk) is not done: it was kept as done, and a resume went on
        // past a run without its video for good.
        QString ended = r.endReason.isEmpty() ? QStringLiteral("not started") : r.endReason;
        if (!r.ok && isCompletingEndReason(ended))
            ended = signalled ? QStringLiteral("interrupted") : QStringLiteral("outputs not written");
        finishAttempt(plan, i, ended, QDateTime::currentDateTimeUtc());
        try {
            writePlanFile(planPath, plan);
        } catch (const PlanError& e) {
            return fail(io, sub, e.message());
        }
        if (signalled || ended == QLatin1String("interrupted")) {
            io.out << nb::TrCli::tr("interrupted") << " " << fi.fileName() << '\n';
            io.out.flush();
            stopped = nb::TrCli::tr("the plan stops at run %1 (interrupted); run the same command again to resume").arg(run.number);
            exitSignal = signalled;
            ++failures;
            break;
        }
        if (run.completed()) {
            io.out << (r.endReason == QLatin1String("completed") ? nb::TrCli::tr("done") : nb::TrCli::tr("done (%1)").arg(r.endReason))
                   << " " << fi.fileName() << '\n';
        } else {
            io.out << nb::TrCli::tr("failed") << '\n';
            io.out.flush();
            io.err << nb::TrCli::tr("run %1: %2").arg(run.number).arg(r.error.isEmpty() ? r.endReason : r.error) << '\n';
            ++failures;
            stopped = nb::TrCli::tr("the plan stops at run %1; fix the cause and run the same command again to resume").arg(run.number);
            break;
        }
        io.out.flush();
    }
    if (!stopped.isEmpty())
        io.err << stopped << '\n';
    QJsonObject summary = statusJson(plan);
    summary.insert(QStringLiteral("plan"), planPath);
    summary.insert(QStringLiteral("session"), s->dir());
    printJson(io, summary);
    if (exitSignal)
        return 128 + exitSignal;
    return failures ? Failure : Ok;
}

bool writeText(const QString& path, const QByteArray& bytes, QString* error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) < 0 || !commitWhole(f)) {
        *error = nb::TrCli::tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

QJsonArray tableJson(const FitTable& t)
{
    QJsonArray rows;
    for (const auto& row : t.rows) {
        QJsonObject o;
        for (std::size_t c = 0; c < t.columns.size() && c < row.size(); ++c) {
            if (const auto* s = std::get_if<QString>(&row[c]))
                o.insert(t.columns[c].key, *s);
            else if (std::isfinite(std::get<double>(row[c])))
                o.insert(t.columns[c].key, std::get<double>(row[c]));
        }
        rows.append(o);
    }
    return rows;
}

// One row per fitted run: its levels, then every quantity (empty where not fitted).
FitTable runsTable(const std::vector<RunFactorValues>& runs, const QStringList& factors)
{
    FitTable t;
    t.caption = nb::TrCli::tr("Fitted quantities per run with their factor levels");
    t.label = QStringLiteral("tab:runs-by-factor");
    t.columns.push_back({QStringLiteral("run"), nb::TrCli::tr("run"), {}, -1, {}});
    for (const QString& f : factors)
        t.columns.push_back({f, f, {}, -1, {}});
    for (const FactorQuantity& q : factorQuantities())
        t.columns.push_back({q.key, q.title, q.unit, 6, {}});
    for (const RunFactorValues& r : runs) {
        std::vector<TableCell> row{r.run};
        for (const QString& f : factors)
            row.emplace_back(r.levels.count(f) ? r.levels.at(f) : QString());
        for (const FactorQuantity& q : factorQuantities())
            row.emplace_back(r.values.count(q.key) ? r.values.at(q.key) : std::nan(""));
        t.rows.push_back(std::move(row));
    }
    return t;
}

int cmdReport(const QStringList& args, Io io)
{
    const QString sub = QStringLiteral("report");
    QCommandLineParser p;
    const QCommandLineOption by(QStringLiteral("by"), nb::TrCli::tr("factors to group by, comma separated (default: the plan's factors)"), QStringLiteral("F1,F2"));
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    const QCommandLineOption mass(QStringLiteral("estimate-mass"), nb::TrCli::tr("fit friction with the mass estimated (eq. 19, as Table 5)"));
    const QCommandLineOption outDir(QStringLiteral("out-dir"),
                                    nb::TrCli::tr("also write the tables here as CSV and LaTeX (by_factor, friction_by_frequency, runs_by_factor)"),
                                    QStringLiteral("DIR"));
    const QCommandLineOption all(QStringLiteral("all-runs"), nb::TrCli::tr("include runs the plan does not count (interrupted, discarded)"));
    for (const auto* o : {&by, &json, &mass, &outDir, &all})
        p.addOption(*o);
    p.addPositionalArgument(QStringLiteral("SESSION_DIR"), nb::TrCli::tr("a session folder (or any folder of run files)"));
    int code = Ok;
    if (!parseArgs(p, QStringLiteral("plan report"), args, io, 1, 1, &code))
        return code;
    const QString dir = p.positionalArguments().first();

    std::optional<Plan> plan;
    const QString planPath = QDir(dir).filePath(kPlanFile);
    if (QFileInfo::exists(planPath)) {
        try {
            plan = readPlanFile(planPath);
        } catch (const PlanError& e) {
            return fail(io, sub, e.message());
        }
    }
    QStringList factors;
    if (p.isSet(by)) {
        for (const QString& f : p.value(by).split(QLatin1Char(','), Qt::SkipEmptyParts))
            factors << (f.trimmed() == QLatin1String("frequency") ? QStringLiteral("frequency_hz") : f.trimmed());
    } else if (plan) {
        for (const PlanFactor& f : plan->factors)
            factors << f.name;
    }
    if (factors.isEmpty())
        return usage(io, sub, nb::TrCli::tr("--by FACTOR,... is required when the folder has no plan.json"));

    LoadedDataset loaded;
    try {
        loaded = loadDataset(dir);
    } catch (const ExportError& e) {
        return fail(io, sub, e.message());
    }
    // Only the attempts the plan counts: not interrupted, failed or discarded ones.
    if (plan && !p.isSet(all)) {
        QStringList counted;
        for (const PlannedRun& r : plan->runs)
            if (const PlanAttempt* a = r.currentAttempt())
                counted << QFileInfo(a->runFile).completeBaseName();
        auto& runs = loaded.dataset.runs;
        const auto notCounted = std::stable_partition(runs.begin(), runs.end(),
                                                      [&](const DatasetRun& r) { return counted.contains(QFileInfo(r.sourcePath).completeBaseName()); });
        QStringList leftOut;
        for (auto r = notCounted; r != runs.end(); ++r)
            leftOut << QFileInfo(r->sourcePath).fileName();
        runs.erase(notCounted, runs.end());
        // Said, so that a table with fewer runs than the folder holds is not taken for all of them.
        if (!leftOut.isEmpty())
            loaded.warnings << nb::TrCli::tr("%n run(s) the plan does not count (interrupted, failed or discarded) left out: %1; --all-runs includes them",
                                             nullptr, int(leftOut.size()))
                                   .arg(leftOut.join(QStringLiteral(", ")));
    }
    factors.removeDuplicates();
    // A factor no run records a level of (a typo) would put every run in one group named "".
    for (const QString& f : factors)
        if (!loaded.dataset.runs.empty() && std::none_of(loaded.dataset.runs.begin(), loaded.dataset.runs.end(),
                                                         [&](const DatasetRun& r) { return !factorLevel(r.run, f).isEmpty(); }))
            return usage(io, sub, nb::TrCli::tr("--by %1: no run in %2 records a level of it (factors recorded: %3)")
                                      .arg(f, dir, datasetFactors(loaded.dataset).isEmpty() ? nb::TrCli::tr("none; settings such as tissue or tip work too")
                                                                                            : datasetFactors(loaded.dataset).join(QStringLiteral(", "))));
    const SessionAnalysis analysis = analyseDataset(loaded.dataset);
    QStringList warnings = loaded.warnings + analysis.warnings;
    FactorAnalysisOptions options;
    options.estimateMass = p.isSet(mass);
    const std::vector<RunFactorValues> values = runFactorValues(loaded.dataset, analysis, factors, options, &warnings);
    const FitTable byFactor = factorTable(groupByFactors(values, factors), factors);
    const FitTable friction = frictionFrequencyTable(values, QStringLiteral("frequency_hz"));
    const bool anyFriction = !friction.rows.empty();

    const FitTable perRun = runsTable(values, factors);
    if (p.isSet(outDir)) {
        const QDir d(p.value(outDir));
        if (!QDir().mkpath(d.path()))
            return fail(io, sub, nb::TrCli::tr("cannot create %1").arg(d.path()));
        QString error;
        for (const auto& [name, table] : {std::pair{QStringLiteral("by_factor"), &byFactor}, std::pair{QStringLiteral("friction_by_frequency"), &friction},
                                          std::pair{QStringLiteral("runs_by_factor"), &perRun}}) {
            if (table->rows.empty())
                continue;
            if (!writeText(d.filePath(name + QStringLiteral(".csv")), fitTableCsv(*table), &error) ||
                !writeText(d.filePath(name + QStringLiteral(".tex")), fitTableLatex(*table), &error))
                return fail(io, sub, error);
        }
    }
    if (p.isSet(json)) {
        QJsonArray w;
        for (const QString& s : warnings)
            w.append(s);
        QJsonArray f;
        for (const QString& s : factors)
            f.append(s);
        QJsonObject o{{QStringLiteral("session"), dir},
                      {QStringLiteral("factors"), f},
                      {QStringLiteral("runs"), double(loaded.dataset.runs.size())},
                      {QStringLiteral("fitted_runs"), double(values.size())},
                      {QStringLiteral("by_factor"), tableJson(byFactor)},
                      {QStringLiteral("run_list"), tableJson(perRun)},
                      {QStringLiteral("warnings"), w}};
        if (anyFriction)
            o.insert(QStringLiteral("friction_by_frequency"), tableJson(friction));
        printJson(io, o);
        return values.empty() ? Failure : Ok;
    }
    for (const QString& s : warnings)
        io.err << s << '\n';
    io.out << byFactor.caption << "\n\n" << fitTableText(byFactor) << '\n';
    if (anyFriction)
        io.out << friction.caption << "\n\n" << fitTableText(friction);
    if (values.empty())
        io.err << nb::TrCli::tr("no run in %1 could be fitted").arg(dir) << '\n';
    return values.empty() ? Failure : Ok;
}

}  // namespace

int cmdPlan(const QStringList& args, Io io)
{
    const QString sub = args.value(0);
    const QStringList rest = args.mid(1);
    if (sub == QLatin1String("templates"))
        return cmdTemplates(rest, io);
    if (sub == QLatin1String("new"))
        return cmdNew(rest, io);
    if (sub == QLatin1String("show"))
        return cmdShow(rest, io);
    if (sub == QLatin1String("run"))
        return cmdRun(rest, io);
    if (sub == QLatin1String("skip") || sub == QLatin1String("redo"))
        return cmdMark(rest, io, sub == QLatin1String("skip"));
    if (sub == QLatin1String("report"))
        return cmdReport(rest, io);
    if (sub == QLatin1String("--help") || sub == QLatin1String("-h") || sub == QLatin1String("help")) {
        printPlanUsage(io.out);
        return Ok;
    }
    if (!sub.isEmpty())
        io.err << nb::TrCli::tr("needlebench plan: unknown subcommand '%1'").arg(sub) << "\n\n";
    printPlanUsage(io.err);
    return Usage;
}

}  // namespace nb::cli
