#include "plan.h"
#include "core/data_names.h"
#include "core/tr.h"
#include "core/save_file.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <map>
#include <set>

namespace nb {

PlanError::PlanError(QString file, QString field, QString reason)
    : std::runtime_error((file + QStringLiteral(": ") + field + QStringLiteral(": ") + reason).toStdString()),
      file_(std::move(file)), field_(std::move(field)), reason_(std::move(reason))
{
}

QString PlanError::message() const
{
    QStringList parts;
    for (const QString* p : {&file_, &field_, &reason_})
        if (!p->isEmpty())
            parts << *p;
    return parts.join(QStringLiteral(": "));
}

namespace {

const QString kFormat = QStringLiteral("needlebench-plan");
constexpr int kVersion = 1;

const std::vector<std::pair<PlanOrder, QString>>& orderNames()
{
    static const std::vector<std::pair<PlanOrder, QString>> n{
        {PlanOrder::Listed, QStringLiteral("listed")}, {PlanOrder::Random, QStringLiteral("random")}, {PlanOrder::Blocked, QStringLiteral("blocked")}};
    return n;
}

const std::vector<std::pair<PlanRunStatus, QString>>& statusNames()
{
    static const std::vector<std::pair<PlanRunStatus, QString>> n{
        {PlanRunStatus::Pending, QStringLiteral("pending")}, {PlanRunStatus::Running, QStringLiteral("running")},
        {PlanRunStatus::Done, QStringLiteral("done")},       {PlanRunStatus::Skipped, QStringLiteral("skipped")},
        {PlanRunStatus::Redone, QStringLiteral("redone")}};
    return n;
}

bool isScalar(const QJsonValue& v) { return v.isDouble() || v.isString(); }

QJsonArray numbers(std::initializer_list<double> values)
{
    QJsonArray a;
    for (double v : values)
        a.append(v);
    return a;
}

std::vector<QJsonValue> range(int from, int to)
{
    std::vector<QJsonValue> v;
    for (int i = from; i <= to; ++i)
        v.emplace_back(i);
    return v;
}

PlanFactor factor(const QString& name, std::vector<QJsonValue> levels)
{
    return {name, std::move(levels), isOperatorSetting(name)};
}

// The effective protocol and motion agree (a sine needs the friction platform).
QString checkRunSettings(const QJsonObject& s)
{
    const QString motion = s.value(QStringLiteral("motion")).toString();
    const QString protocol = s.value(QStringLiteral("protocol")).toString();
    if (motion.isEmpty() && protocol.isEmpty())
        return nb::TrCore::tr("neither motion nor protocol is set");
    if (!motion.isEmpty() && !protocol.isEmpty() && (motion == QLatin1String("sine")) != (protocol == QLatin1String("friction")))
        return nb::TrCore::tr("motion '%1' does not go with protocol '%2' (sine motion is the friction protocol)").arg(motion, protocol);
    return {};
}

// Deterministic on every platform: std::shuffle and the distributions are not specified
// exactly, mt19937_64's output is.
template <typename T>
void shuffle(std::vector<T>& v, std::mt19937_64& rng)
{
    for (std::size_t i = v.size(); i > 1; --i) {
        const std::uint64_t n = i;
        const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
        std::uint64_t r;
        do
            r = rng();
        while (r >= limit);
        std::swap(v[i - 1], v[r % n]);
    }
}

// A level as the operator reads it: numbers in the operator's notation ("0,5" in German).
QString shownLevel(const QJsonValue& value)
{
    return value.isDouble() ? QLocale().toString(value.toDouble(), 'g', 12) : levelText(value);
}

QString settingText(const QString& key, const QJsonValue& value, bool sine)
{
    const QString v = shownLevel(value);
    if (key == QLatin1String("site"))
        return sine ? nb::TrCore::tr("Move the slab to site %1.").arg(v) : nb::TrCore::tr("Move the specimen to site %1.").arg(v);
    if (key == QLatin1String("tip"))
        return nb::TrCore::tr("Change to the %1 tip.").arg(tipDisplayName(v));
    if (key == QLatin1String("tissue"))
        return nb::TrCore::tr("Mount %1.").arg(tissueDisplayName(v));
    if (key == QLatin1String("thickness_mm"))
        return nb::TrCore::tr("Mount the %1 mm slab.").arg(v);
    return nb::TrCore::tr("Set %1 to %2.").arg(key, v);
}

}  // namespace

QString planOrderName(PlanOrder order)
{
    for (const auto& [o, n] : orderNames())
        if (o == order)
            return n;
    return {};
}

std::optional<PlanOrder> planOrderFromName(const QString& name)
{
    for (const auto& [o, n] : orderNames())
        if (n == name)
            return o;
    return std::nullopt;
}

QString planRunStatusName(PlanRunStatus status)
{
    for (const auto& [s, n] : statusNames())
        if (s == status)
            return n;
    return {};
}

std::optional<PlanRunStatus> planRunStatusFromName(const QString& name)
{
    for (const auto& [s, n] : statusNames())
        if (n == name)
            return s;
    return std::nullopt;
}

bool PlannedRun::completed() const
{
    return status == PlanRunStatus::Done || status == PlanRunStatus::Redone || status == PlanRunStatus::Skipped;
}

const PlanAttempt* PlannedRun::currentAttempt() const
{
    if ((status == PlanRunStatus::Done || status == PlanRunStatus::Redone) && !attempts.empty())
        return &attempts.back();
    return nullptr;
}

QJsonObject Plan::settingsFor(const PlannedRun& run) const
{
    QJsonObject s = defaults;
    for (auto it = run.factors.begin(); it != run.factors.end(); ++it)
        s.insert(it.key(), it.value());
    for (auto it = run.settings.begin(); it != run.settings.end(); ++it)
        s.insert(it.key(), it.value());
    if (!s.contains(QStringLiteral("motion")) && s.contains(QStringLiteral("protocol")))
        s.insert(QStringLiteral("motion"), s.value(QStringLiteral("protocol")).toString() == QLatin1String("friction") ? QStringLiteral("sine")
                                                                                                                        : QStringLiteral("linear"));
    if (!s.contains(QStringLiteral("protocol")) && s.contains(QStringLiteral("motion")))
        s.insert(QStringLiteral("protocol"), s.value(QStringLiteral("motion")).toString() == QLatin1String("sine") ? QStringLiteral("friction")
                                                                                                                   : QStringLiteral("stiffness"));
    return s;
}

int Plan::firstIncomplete() const
{
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (!runs[i].completed())
            return int(i);
    return -1;
}

int Plan::countWith(PlanRunStatus status) const
{
    return int(std::count_if(runs.begin(), runs.end(), [&](const PlannedRun& r) { return r.status == status; }));
}

bool Plan::sameDesign(const Plan& other) const
{
    if (runs.size() != other.runs.size())
        return false;
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (runs[i].number != other.runs[i].number || settingsFor(runs[i]) != other.settingsFor(other.runs[i]))
            return false;
    return true;
}

const QStringList& knownPlanSettings()
{
    static const QStringList k{
        QStringLiteral("protocol"),      QStringLiteral("motion"),       QStringLiteral("tissue"),       QStringLiteral("tip"),
        QStringLiteral("site"),          QStringLiteral("repeat"),       QStringLiteral("velocity_mm_s"), QStringLiteral("depth_mm"),
        QStringLiteral("frequency_hz"),  QStringLiteral("amplitude_mm"), QStringLiteral("cycles"),       QStringLiteral("thickness_mm"),
        QStringLiteral("bone_depth_mm"), QStringLiteral("rate_hz"),      QStringLiteral("max_force_n"),  QStringLiteral("seed"),
        QStringLiteral("video"),         QStringLiteral("stop_at"),      QStringLiteral("slow_after_puncture_mm_s")};
    return k;
}

bool isOperatorSetting(const QString& key)
{
    return key == QLatin1String("site") || key == QLatin1String("tip") || key == QLatin1String("tissue") || key == QLatin1String("thickness_mm");
}

QString checkPlanSetting(const QString& key, const QJsonValue& value)
{
    auto oneOf = [&](const QStringList& allowed) -> QString {
        if (!value.isString() || !allowed.contains(value.toString()))
            return nb::TrCore::tr("'%1' is not one of %2").arg(levelText(value), allowed.join(QLatin1Char('|')));
        return {};
    };
    if (key == QLatin1String("protocol"))
        return oneOf({QStringLiteral("stiffness"), QStringLiteral("internal"), QStringLiteral("friction"), QStringLiteral("prostate")});
    if (key == QLatin1String("motion"))
        return oneOf({QStringLiteral("linear"), QStringLiteral("sine")});
    if (key == QLatin1String("tip"))
        return oneOf({QStringLiteral("beveled"), QStringLiteral("diamond"), QStringLiteral("blunt")});
    if (key == QLatin1String("tissue"))
        return value.isString() && !value.toString().trimmed().isEmpty() ? QString() : nb::TrCore::tr("expected a tissue name");
    if (key == QLatin1String("site"))
        return (value.isDouble() && std::isfinite(value.toDouble())) || (value.isString() && !value.toString().trimmed().isEmpty())
                   ? QString()
                   : nb::TrCore::tr("expected a site number or name");
    if (key == QLatin1String("video"))
        return value.isBool() ? QString() : nb::TrCore::tr("expected true or false");
    if (key == QLatin1String("stop_at")) {
        static const QRegularExpression re(QStringLiteral("^puncture(:[1-9][0-9]*)?$"));
        return value.isString() && re.match(value.toString()).hasMatch() ? QString()
                                                                         : nb::TrCore::tr("expected \"puncture\" or \"puncture:N\" (N >= 1)");
    }
    if (key == QLatin1String("cycles") || key == QLatin1String("repeat") || key == QLatin1String("seed")) {
        const double v = value.toDouble(-1.0);
        const double lo = key == QLatin1String("seed") ? 0.0 : 1.0;
        if (key == QLatin1String("cycles") && value.isDouble() && v > 1000.0)
            return nb::TrCore::tr("%1 is outside %2 to %3").arg(levelText(value)).arg(1).arg(1000);
        if (!value.isDouble() || v < lo || v != std::floor(v) || v > 9.0e15)
            return key == QLatin1String("seed") ? nb::TrCore::tr("expected a non-negative integer") : nb::TrCore::tr("expected a positive integer");
        return {};
    }
    if (knownPlanSettings().contains(key)) {
        if (!value.isDouble() || !std::isfinite(value.toDouble()) || value.toDouble() <= 0.0)
            return nb::TrCore::tr("expected a positive number, got %1").arg(value.isString() ? QLatin1Char('"') + value.toString() + QLatin1Char('"')
                                                                                           : levelText(value));
        // The ranges `acquire` takes: a plan checked when it is made, not at the run that
        // fails (a frequency of 10^-6 Hz recorded until the disk was full).
        static const std::map<QString, std::pair<double, double>> ranges{
            {QStringLiteral("velocity_mm_s"), {0.01, 50.0}},  {QStringLiteral("depth_mm"), {0.01, 150.0}},
            {QStringLiteral("amplitude_mm"), {0.01, 10.0}},   {QStringLiteral("frequency_hz"), {0.01, 5.0}},
            {QStringLiteral("rate_hz"), {100.0, 10000.0}},    {QStringLiteral("max_force_n"), {0.01, 20.0}},
            {QStringLiteral("slow_after_puncture_mm_s"), {0.001, 50.0}}, {QStringLiteral("thickness_mm"), {1.0, 200.0}},
            {QStringLiteral("bone_depth_mm"), {0.01, 150.0}}};
        if (const auto r = ranges.find(key); r != ranges.end() && (value.toDouble() < r->second.first || value.toDouble() > r->second.second))
            return nb::TrCore::tr("%1 is outside %2 to %3").arg(levelText(value)).arg(r->second.first).arg(r->second.second);
        return {};
    }
    return isScalar(value) ? QString() : nb::TrCore::tr("expected a number or a text");
}

const std::vector<PlanTemplate>& planTemplates()
{
    static const std::vector<PlanTemplate> all = [] {
        const QJsonArray freqs = numbers({0.2, 0.5, 0.8});
        std::vector<QJsonValue> f(freqs.begin(), freqs.end());
        auto linear = [](const char* protocol, const char* tissue, const char* tip, double v) {
            return QJsonObject{{QStringLiteral("protocol"), QLatin1String(protocol)}, {QStringLiteral("motion"), QStringLiteral("linear")},
                               {QStringLiteral("tissue"), QLatin1String(tissue)},     {QStringLiteral("tip"), QLatin1String(tip)},
                               {QStringLiteral("velocity_mm_s"), v},                  {QStringLiteral("depth_mm"), 40.0}};
        };
        auto sine = [](const char* tissue, const char* tip) {
            return QJsonObject{{QStringLiteral("protocol"), QStringLiteral("friction")}, {QStringLiteral("motion"), QStringLiteral("sine")},
                               {QStringLiteral("tissue"), QLatin1String(tissue)},        {QStringLiteral("tip"), QLatin1String(tip)},
                               {QStringLiteral("amplitude_mm"), 10.0},                   {QStringLiteral("cycles"), 7},
                               {QStringLiteral("thickness_mm"), 30.0}};
        };
        QJsonObject stiffVideo = linear("stiffness", "liver5", "diamond", 4.0);
        stiffVideo.insert(QStringLiteral("video"), true);
        QJsonObject frictionVideo = sine("liver7", "diamond");
        frictionVideo.insert(QStringLiteral("video"), true);
        return std::vector<PlanTemplate>{
            {QStringLiteral("overall-stiffness"), QStringLiteral("overall stiffness"),
             nb::TrCore::tr("21 insertions into whole liver 1, beveled tip, 4 mm/s (Table 2)"), linear("stiffness", "liver1", "beveled", 4.0),
             {factor(QStringLiteral("site"), range(1, 21))}},
            {QStringLiteral("internal-stiffness"), QStringLiteral("internal stiffness"),
             nb::TrCore::tr("7 insertions into liver 7 with the capsule removed, blunt tip, 2.5 mm/s (Table 3)"),
             linear("internal", "liver7", "blunt", 2.5), {factor(QStringLiteral("site"), range(1, 7))}},
            {QStringLiteral("friction"), QStringLiteral("friction"),
             nb::TrCore::tr("liver 3 slab, sine 10 mm at 0.2/0.5/0.8 Hz at 7 locations, beveled tip (Table 4)"), sine("liver3", "beveled"),
             {factor(QStringLiteral("site"), range(1, 7)), factor(QStringLiteral("frequency_hz"), f)}},
            {QStringLiteral("stiffness-imaging"), QStringLiteral("stiffness under imaging"),
             nb::TrCore::tr("11 insertions into whole liver 5 with video, diamond tip, 4 mm/s"), stiffVideo,
             {factor(QStringLiteral("site"), range(1, 11))}},
            {QStringLiteral("friction-imaging"), QStringLiteral("friction under imaging"),
             nb::TrCore::tr("liver 7 slab with video, sine 10 mm at 0.2/0.5/0.8 Hz at 5 locations, diamond tip (Table 5)"), frictionVideo,
             {factor(QStringLiteral("site"), range(1, 5)), factor(QStringLiteral("frequency_hz"), f)}},
            {QStringLiteral("prostate"), QStringLiteral("prostate"), nb::TrCore::tr("9 insertions into a canine prostate, diamond tip, 4 mm/s"),
             linear("prostate", "prostate", "diamond", 4.0), {factor(QStringLiteral("site"), range(1, 9))}},
        };
    }();
    return all;
}

const PlanTemplate* findPlanTemplate(const QString& name)
{
    for (const PlanTemplate& t : planTemplates())
        if (t.name == name)
            return &t;
    return nullptr;
}

Plan generatePlan(const PlanTemplate& design, PlanOrder order, quint64 seed)
{
    Plan plan;
    plan.name = design.title;
    plan.templateName = design.name;
    plan.description = design.description;
    plan.order = order;
    plan.seed = seed;
    plan.defaults = design.defaults;
    plan.factors = design.factors;
    for (auto it = plan.defaults.begin(); it != plan.defaults.end(); ++it)
        if (const QString e = checkPlanSetting(it.key(), it.value()); !e.isEmpty())
            throw PlanError({}, QStringLiteral("defaults.") + it.key(), e);
    for (std::size_t i = 0; i < plan.factors.size(); ++i) {
        const PlanFactor& f = plan.factors[i];
        const QString field = QStringLiteral("factors[%1]").arg(i);
        if (f.levels.empty())
            throw PlanError({}, field + QStringLiteral(".levels"), nb::TrCore::tr("a factor needs at least one level"));
        for (std::size_t j = 0; j < f.levels.size(); ++j)
            if (const QString e = checkPlanSetting(f.name, f.levels[j]); !e.isEmpty())
                throw PlanError({}, field + QStringLiteral(".levels[%1]").arg(j), e);
    }

    // Full factorial, the last factor varying fastest.
    std::vector<QJsonObject> cells{QJsonObject{}};
    for (const PlanFactor& f : plan.factors) {
        std::vector<QJsonObject> next;
        for (const QJsonObject& c : cells)
            for (const QJsonValue& level : f.levels) {
                QJsonObject o = c;
                o.insert(f.name, level);
                next.push_back(o);
            }
        cells = std::move(next);
    }
    std::mt19937_64 rng(seed);
    if (order == PlanOrder::Random) {
        shuffle(cells, rng);
    } else if (order == PlanOrder::Blocked) {
        const auto site = std::find_if(plan.factors.begin(), plan.factors.end(), [](const PlanFactor& f) { return f.name == QLatin1String("site"); });
        if (site == plan.factors.end())
            throw PlanError({}, QStringLiteral("order"), nb::TrCore::tr("blocked order needs a factor named site"));
        std::vector<QJsonObject> ordered;
        for (const QJsonValue& level : site->levels) {
            std::vector<QJsonObject> block;
            for (const QJsonObject& c : cells)
                if (c.value(QStringLiteral("site")) == level)
                    block.push_back(c);
            shuffle(block, rng);
            ordered.insert(ordered.end(), block.begin(), block.end());
        }
        cells = std::move(ordered);
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
        PlannedRun r;
        r.number = int(i) + 1;
        r.factors = cells[i];
        r.settings.insert(QStringLiteral("seed"), double(seed * 1000 + quint64(r.number)));
        if (const QString e = checkRunSettings(plan.settingsFor(r)); !e.isEmpty())
            throw PlanError({}, QStringLiteral("runs[%1]").arg(i), e);
        plan.runs.push_back(std::move(r));
    }
    refreshInstructions(plan);
    return plan;
}

QString levelText(const QJsonValue& value)
{
    if (value.isDouble())
        return QString::number(value.toDouble(), 'g', 12);
    if (value.isBool())
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (value.isString())
        return value.toString();
    const QJsonDocument doc = value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
    return QString::fromUtf8(doc.toJson(QJsonDocument::Compact));
}

QString operatorInstruction(const Plan& plan, const PlannedRun* previous, const PlannedRun& next)
{
    const QJsonObject now = plan.settingsFor(next);
    const QJsonObject before = previous ? plan.settingsFor(*previous) : QJsonObject{};
    const bool sine = now.value(QStringLiteral("motion")).toString() == QLatin1String("sine");
    QStringList steps;
    // Specimen first, then the needle, then where: the order an operator works in.
    QStringList keys{QStringLiteral("tissue"), QStringLiteral("thickness_mm"), QStringLiteral("tip")};
    for (const PlanFactor& f : plan.factors)
        if (f.operatorSet && !keys.contains(f.name) && f.name != QLatin1String("site"))
            keys << f.name;
    keys << QStringLiteral("site");
    for (const QString& key : keys) {
        if (!now.contains(key))
            continue;
        if (key == QLatin1String("thickness_mm") && !sine)
            continue;
        if (previous && before.value(key) == now.value(key))
            continue;
        if (!previous && key == QLatin1String("tip")) {
            steps << nb::TrCore::tr("Fit the %1 tip.").arg(tipDisplayName(levelText(now.value(key))));
            continue;
        }
        steps << settingText(key, now.value(key), sine);
    }
    return steps.join(QLatin1Char(' '));
}

void refreshInstructions(Plan& plan)
{
    for (std::size_t i = 0; i < plan.runs.size(); ++i)
        plan.runs[i].instruction = operatorInstruction(plan, i ? &plan.runs[i - 1] : nullptr, plan.runs[i]);
}

QString describeRun(const Plan& plan, const PlannedRun& run)
{
    const QJsonObject s = plan.settingsFor(run);
    QStringList parts{protocolDisplayName(s.value(QStringLiteral("protocol")).toString())};
    std::vector<QString> names;
    for (const PlanFactor& f : plan.factors)
        names.push_back(f.name);
    for (auto it = run.factors.begin(); it != run.factors.end(); ++it)
        if (std::find(names.begin(), names.end(), it.key()) == names.end())
            names.push_back(it.key());
    for (const QString& key : names) {
        if (!run.factors.contains(key))
            continue;
        const QString v = shownLevel(run.factors.value(key));
        if (key == QLatin1String("frequency_hz"))
            parts << nb::TrCore::tr("%1 Hz").arg(v);
        else if (key == QLatin1String("velocity_mm_s"))
            parts << nb::TrCore::tr("%1 mm/s").arg(v);
        else if (key == QLatin1String("amplitude_mm"))
            parts << nb::TrCore::tr("amplitude %1 mm").arg(v);
        else if (key == QLatin1String("depth_mm"))
            parts << nb::TrCore::tr("depth %1 mm").arg(v);
        else if (key == QLatin1String("site"))
            parts << nb::TrCore::tr("site %1").arg(v);
        else if (key == QLatin1String("repeat"))
            parts << nb::TrCore::tr("repeat %1").arg(v);
        else if (key == QLatin1String("tip"))
            parts << nb::TrCore::tr("%1 tip").arg(tipDisplayName(v));
        else if (key == QLatin1String("cycles"))
            parts << nb::TrCore::tr("%1 cycles").arg(v);
        else if (key == QLatin1String("thickness_mm"))
            parts << nb::TrCore::tr("%1 mm slab").arg(v);
        else if (key == QLatin1String("tissue"))
            parts << tissueDisplayName(v);
        else if (key == QLatin1String("motion"))
            parts << motionDisplayName(v);
        else
            parts << key + QLatin1Char(' ') + v;
    }
    return parts.join(QLatin1Char(' '));
}

std::vector<int> recoverInterruptedRuns(Plan& plan)
{
    std::vector<int> recovered;
    for (PlannedRun& r : plan.runs) {
        if (r.status != PlanRunStatus::Running)
            continue;
        if (!r.attempts.empty() && r.attempts.back().result.isEmpty())
            r.attempts.back().result = QStringLiteral("interrupted");
        r.status = PlanRunStatus::Pending;
        recovered.push_back(r.number);
    }
    return recovered;
}

void beginAttempt(Plan& plan, int index, const QString& runFile, const QString& videoFile, const QDateTime& now)
{
    PlannedRun& r = plan.runs.at(std::size_t(index));
    PlanAttempt a;
    a.runFile = runFile;
    a.videoFile = videoFile;
    a.started = now;
    r.attempts.push_back(a);
    r.status = PlanRunStatus::Running;
    r.reason.clear();
}

bool isCompletingEndReason(const QString& endReason)
{
    return endReason == QLatin1String("completed") || endReason == QLatin1String("force_limit") || endReason.startsWith(QLatin1String("puncture"));
}

void finishAttempt(Plan& plan, int index, const QString& endReason, const QDateTime& now)
{
    PlannedRun& r = plan.runs.at(std::size_t(index));
    if (r.attempts.empty())
        r.attempts.push_back({});
    r.attempts.back().result = endReason;
    r.attempts.back().ended = now;
    if (!isCompletingEndReason(endReason))
        r.status = PlanRunStatus::Pending;
    else
        r.status = r.attempts.size() > 1 ? PlanRunStatus::Redone : PlanRunStatus::Done;
}

void skipRun(Plan& plan, int index, const QString& reason)
{
    PlannedRun& r = plan.runs.at(std::size_t(index));
    r.status = PlanRunStatus::Skipped;
    r.reason = reason;
}

void redoRun(Plan& plan, int index, const QString& reason)
{
    PlannedRun& r = plan.runs.at(std::size_t(index));
    if (!r.attempts.empty() && r.attempts.back().discarded.isEmpty())
        r.attempts.back().discarded = reason.isEmpty() ? nb::TrCore::tr("redone") : reason;
    r.status = PlanRunStatus::Pending;
    r.reason.clear();
}

Metadata planRunMetadata(const Plan& plan, const PlannedRun& run, const QString& planFile)
{
    Metadata m;
    QStringList names;
    for (const PlanFactor& f : plan.factors)
        names << f.name;
    for (auto it = run.factors.begin(); it != run.factors.end(); ++it)
        if (!names.contains(it.key()))
            names << it.key();
    for (const QString& n : names)
        if (run.factors.contains(n))
            m.set(QStringLiteral("factor_") + n, levelText(run.factors.value(n)));
    m.set(QStringLiteral("plan_name"), plan.name);
    if (!plan.templateName.isEmpty())
        m.set(QStringLiteral("plan_template"), plan.templateName);
    m.set(QStringLiteral("plan_file"), planFile);
    m.set(QStringLiteral("plan_run"), QString::number(run.number));
    m.set(QStringLiteral("plan_runs"), QString::number(plan.runs.size()));
    m.set(QStringLiteral("plan_attempt"), QString::number(std::max<std::size_t>(1, run.attempts.size())));
    m.set(QStringLiteral("plan_order"), planOrderName(plan.order));
    return m;
}

QString unusedRunPath(const Plan& plan, const QString& proposedPath)
{
    static const QRegularExpression number(QStringLiteral("run_(\\d+)"));
    const qsizetype slash = proposedPath.lastIndexOf(QLatin1Char('/'));
    const QString folder = proposedPath.left(slash + 1);
    QString name = proposedPath.mid(slash + 1);
    const auto m = number.match(name);
    if (!m.hasMatch() || m.capturedStart() != 0)
        return proposedPath;
    int highest = m.captured(1).toInt() - 1;
    for (const PlannedRun& r : plan.runs)
        for (const PlanAttempt& a : r.attempts)
            if (const auto am = number.match(a.runFile); am.hasMatch() && am.capturedStart() == 0)
                highest = std::max(highest, am.captured(1).toInt());
    name.replace(0, m.capturedLength(), QStringLiteral("run_%1").arg(highest + 1, 3, 10, QLatin1Char('0')));
    return folder + name;
}

double expectedRunDuration_s(const QJsonObject& s)
{
    const bool sine = s.value(QStringLiteral("motion")).toString() == QLatin1String("sine") ||
                      s.value(QStringLiteral("protocol")).toString() == QLatin1String("friction");
    if (sine)
        return s.value(QStringLiteral("cycles")).toDouble(7.0) / s.value(QStringLiteral("frequency_hz")).toDouble(0.5);
    const bool internal = s.value(QStringLiteral("protocol")).toString() == QLatin1String("internal");
    return s.value(QStringLiteral("depth_mm")).toDouble(40.0) / s.value(QStringLiteral("velocity_mm_s")).toDouble(internal ? 2.5 : 4.0);
}

double remainingPlanDuration_s(const Plan& plan)
{
    double t = 0.0;
    for (const PlannedRun& r : plan.runs)
        if (!r.completed())
            t += expectedRunDuration_s(plan.settingsFor(r));
    return t;
}

QJsonObject planToJson(const Plan& plan)
{
    QJsonObject o;
    o.insert(QStringLiteral("format"), kFormat);
    o.insert(QStringLiteral("version"), kVersion);
    o.insert(QStringLiteral("name"), plan.name);
    if (!plan.templateName.isEmpty())
        o.insert(QStringLiteral("template"), plan.templateName);
    if (!plan.description.isEmpty())
        o.insert(QStringLiteral("description"), plan.description);
    o.insert(QStringLiteral("order"), planOrderName(plan.order));
    o.insert(QStringLiteral("seed"), double(plan.seed));
    o.insert(QStringLiteral("defaults"), plan.defaults);
    QJsonArray factors;
    for (const PlanFactor& f : plan.factors) {
        QJsonObject fo{{QStringLiteral("name"), f.name}};
        QJsonArray levels;
        for (const QJsonValue& l : f.levels)
            levels.append(l);
        fo.insert(QStringLiteral("levels"), levels);
        if (f.operatorSet != isOperatorSetting(f.name))
            fo.insert(QStringLiteral("operator"), f.operatorSet);
        factors.append(fo);
    }
    o.insert(QStringLiteral("factors"), factors);
    QJsonArray runs;
    for (const PlannedRun& r : plan.runs) {
        QJsonObject ro{{QStringLiteral("number"), r.number}, {QStringLiteral("factors"), r.factors},
                       {QStringLiteral("status"), planRunStatusName(r.status)}};
        if (!r.settings.isEmpty())
            ro.insert(QStringLiteral("settings"), r.settings);
        if (!r.instruction.isEmpty())
            ro.insert(QStringLiteral("instruction"), r.instruction);
        if (!r.reason.isEmpty())
            ro.insert(QStringLiteral("reason"), r.reason);
        QJsonArray attempts;
        for (const PlanAttempt& a : r.attempts) {
            QJsonObject ao{{QStringLiteral("run_file"), a.runFile}, {QStringLiteral("result"), a.result}};
            if (!a.videoFile.isEmpty())
                ao.insert(QStringLiteral("video_file"), a.videoFile);
            if (!a.discarded.isEmpty())
                ao.insert(QStringLiteral("discarded"), a.discarded);
            if (a.started.isValid())
                ao.insert(QStringLiteral("started"), a.started.toString(Qt::ISODateWithMs));
            if (a.ended.isValid())
                ao.insert(QStringLiteral("ended"), a.ended.toString(Qt::ISODateWithMs));
            attempts.append(ao);
        }
        if (!attempts.isEmpty())
            ro.insert(QStringLiteral("attempts"), attempts);
        runs.append(ro);
    }
    o.insert(QStringLiteral("runs"), runs);
    return o;
}

namespace {

// Reads fields of one JSON object, naming the file and the field in every error.
struct FieldReader {
    const QString& file;
    QString path;  // e.g. "runs[3]"
    QJsonObject o;

    QString field(const QString& key) const { return path.isEmpty() ? key : path + QLatin1Char('.') + key; }
    [[noreturn]] void fail(const QString& key, const QString& reason) const { throw PlanError(file, field(key), reason); }

    QString text(const QString& key, bool required = false) const
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined() || v.isNull()) {
            if (required)
                fail(key, nb::TrCore::tr("missing"));
            return {};
        }
        if (!v.isString())
            fail(key, nb::TrCore::tr("expected a text"));
        return v.toString();
    }
    QJsonObject object(const QString& key) const
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined() || v.isNull())
            return {};
        if (!v.isObject())
            fail(key, nb::TrCore::tr("expected an object {...}"));
        return v.toObject();
    }
    QJsonArray array(const QString& key, bool required) const
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined() || v.isNull()) {
            if (required)
                fail(key, nb::TrCore::tr("missing"));
            return {};
        }
        if (!v.isArray())
            fail(key, nb::TrCore::tr("expected a list [...]"));
        return v.toArray();
    }
    QDateTime time(const QString& key) const
    {
        const QString t = text(key);
        if (t.isEmpty())
            return {};
        const QDateTime d = QDateTime::fromString(t, Qt::ISODateWithMs);
        if (!d.isValid())
            fail(key, nb::TrCore::tr("'%1' is not an ISO 8601 date and time").arg(t));
        return d;
    }
};

}  // namespace

Plan planFromJson(const QJsonObject& object, const QString& file)
{
    const FieldReader top{file, {}, object};
    if (const QString format = top.text(QStringLiteral("format")); !format.isEmpty() && format != kFormat)
        top.fail(QStringLiteral("format"), nb::TrCore::tr("'%1' is not a NeedleBench plan (expected %2)").arg(format, kFormat));
    if (const QJsonValue v = object.value(QStringLiteral("version")); !v.isUndefined() && (!v.isDouble() || v.toDouble() > kVersion || v.toDouble() < 1))
        top.fail(QStringLiteral("version"), nb::TrCore::tr("version %1 is not supported (this program reads version %2)").arg(levelText(v)).arg(kVersion));
    Plan plan;
    plan.name = top.text(QStringLiteral("name"));
    plan.templateName = top.text(QStringLiteral("template"));
    plan.description = top.text(QStringLiteral("description"));
    if (const QString order = top.text(QStringLiteral("order")); !order.isEmpty()) {
        const auto o = planOrderFromName(order);
        if (!o)
            top.fail(QStringLiteral("order"), nb::TrCore::tr("'%1' is not one of listed|random|blocked").arg(order));
        plan.order = *o;
    }
    if (const QJsonValue v = object.value(QStringLiteral("seed")); !v.isUndefined()) {
        if (const QString e = checkPlanSetting(QStringLiteral("seed"), v); !e.isEmpty())
            top.fail(QStringLiteral("seed"), e);
        plan.seed = quint64(v.toDouble());
    }

    const QJsonArray factors = top.array(QStringLiteral("factors"), false);
    QStringList factorNames;
    for (qsizetype i = 0; i < factors.size(); ++i) {
        const QString path = QStringLiteral("factors[%1]").arg(i);
        if (!factors[i].isObject())
            throw PlanError(file, path, nb::TrCore::tr("expected an object {...}"));
        const FieldReader fr{file, path, factors[i].toObject()};
        PlanFactor f;
        f.name = fr.text(QStringLiteral("name"), true).trimmed();
        if (f.name.isEmpty() || factorNames.contains(f.name))
            fr.fail(QStringLiteral("name"), f.name.isEmpty() ? nb::TrCore::tr("empty") : nb::TrCore::tr("'%1' is listed twice").arg(f.name));
        const QJsonArray levels = fr.array(QStringLiteral("levels"), true);
        if (levels.isEmpty())
            fr.fail(QStringLiteral("levels"), nb::TrCore::tr("a factor needs at least one level"));
        for (qsizetype j = 0; j < levels.size(); ++j) {
            if (const QString e = checkPlanSetting(f.name, levels[j]); !e.isEmpty())
                fr.fail(QStringLiteral("levels[%1]").arg(j), e);
            f.levels.push_back(levels[j]);
        }
        const QJsonValue op = fr.o.value(QStringLiteral("operator"));
        if (!op.isUndefined() && !op.isBool())
            fr.fail(QStringLiteral("operator"), nb::TrCore::tr("expected true or false"));
        f.operatorSet = op.isBool() ? op.toBool() : isOperatorSetting(f.name);
        factorNames << f.name;
        plan.factors.push_back(std::move(f));
    }

    auto checkSettings = [&](const QJsonObject& o, const QString& path) {
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString field = path + QLatin1Char('.') + it.key();
            if (!knownPlanSettings().contains(it.key()) && !factorNames.contains(it.key()))
                throw PlanError(file, field,
                                nb::TrCore::tr("unknown setting (known: %1; declare other factors under \"factors\")").arg(knownPlanSettings().join(QStringLiteral(", "))));
            if (const QString e = checkPlanSetting(it.key(), it.value()); !e.isEmpty())
                throw PlanError(file, field, e);
        }
    };
    plan.defaults = top.object(QStringLiteral("defaults"));
    checkSettings(plan.defaults, QStringLiteral("defaults"));

    const QJsonArray runs = top.array(QStringLiteral("runs"), true);
    std::set<int> numbers;
    bool anyInstruction = false;
    for (qsizetype i = 0; i < runs.size(); ++i) {
        const QString path = QStringLiteral("runs[%1]").arg(i);
        if (!runs[i].isObject())
            throw PlanError(file, path, nb::TrCore::tr("expected an object {...}"));
        const FieldReader rr{file, path, runs[i].toObject()};
        PlannedRun r;
        const QJsonValue n = rr.o.value(QStringLiteral("number"));
        if (n.isUndefined())
            r.number = int(i) + 1;
        else if (!n.isDouble() || n.toDouble() < 1 || n.toDouble() != std::floor(n.toDouble()) || n.toDouble() > 1e6)
            rr.fail(QStringLiteral("number"), nb::TrCore::tr("expected a positive integer"));
        else
            r.number = n.toInt();
        if (!numbers.insert(r.number).second)
            rr.fail(QStringLiteral("number"), nb::TrCore::tr("run %1 is listed twice").arg(r.number));
        r.factors = rr.object(QStringLiteral("factors"));
        checkSettings(r.factors, path + QStringLiteral(".factors"));
        r.settings = rr.object(QStringLiteral("settings"));
        checkSettings(r.settings, path + QStringLiteral(".settings"));
        if (rr.o.contains(QStringLiteral("instruction"))) {
            r.instruction = rr.text(QStringLiteral("instruction"));
            anyInstruction = true;
        }
        if (const QString s = rr.text(QStringLiteral("status")); !s.isEmpty()) {
            const auto st = planRunStatusFromName(s);
            if (!st)
                rr.fail(QStringLiteral("status"), nb::TrCore::tr("'%1' is not one of pending|running|done|skipped|redone").arg(s));
            r.status = *st;
        }
        // Versions before this one wrote a reason longer than a line as {}: such a plan is read,
        // its reason lost, rather than refused (its runs and attempts are all there).
        const QJsonValue reason = rr.o.value(QStringLiteral("reason"));
        if (reason.isObject() && reason.toObject().isEmpty())
            r.reason = nb::TrCore::tr("(the reason was lost by an earlier version of NeedleBench)");
        else
            r.reason = rr.text(QStringLiteral("reason"));
        const QJsonArray attempts = rr.array(QStringLiteral("attempts"), false);
        for (qsizetype j = 0; j < attempts.size(); ++j) {
            const QString apath = path + QStringLiteral(".attempts[%1]").arg(j);
            if (!attempts[j].isObject())
                throw PlanError(file, apath, nb::TrCore::tr("expected an object {...}"));
            const FieldReader ar{file, apath, attempts[j].toObject()};
            PlanAttempt a;
            a.runFile = ar.text(QStringLiteral("run_file"));
            a.videoFile = ar.text(QStringLiteral("video_file"));
            a.result = ar.text(QStringLiteral("result"));
            a.discarded = ar.text(QStringLiteral("discarded"));
            a.started = ar.time(QStringLiteral("started"));
            a.ended = ar.time(QStringLiteral("ended"));
            r.attempts.push_back(a);
        }
        if ((r.status == PlanRunStatus::Done || r.status == PlanRunStatus::Redone) && r.attempts.empty())
            rr.fail(QStringLiteral("status"), nb::TrCore::tr("a run marked %1 needs the attempt that made it").arg(planRunStatusName(r.status)));
        if (const QString e = checkRunSettings(plan.settingsFor(r)); !e.isEmpty())
            throw PlanError(file, path, e);
        plan.runs.push_back(std::move(r));
    }
    if (!anyInstruction)
        refreshInstructions(plan);
    return plan;
}

namespace {

// plan.json is meant to be read and edited by a person: keys in a sensible order (not
// QJsonObject's alphabetical one) and short flat objects and lists on one line.
int keyRank(const QString& key)
{
    static const QStringList order{
        QStringLiteral("format"),   QStringLiteral("version"),     QStringLiteral("number"),   QStringLiteral("name"),     QStringLiteral("template"),
        QStringLiteral("description"), QStringLiteral("order"),    QStringLiteral("seed"),     QStringLiteral("defaults"),
        QStringLiteral("factors"),  QStringLiteral("levels"),      QStringLiteral("operator"), QStringLiteral("runs"),
        QStringLiteral("status"),      QStringLiteral("reason"),   QStringLiteral("settings"),
        QStringLiteral("instruction"), QStringLiteral("attempts"), QStringLiteral("run_file"), QStringLiteral("video_file"),
        QStringLiteral("result"),   QStringLiteral("discarded"),   QStringLiteral("started"),  QStringLiteral("ended")};
    const qsizetype i = order.indexOf(key);
    return i < 0 ? int(order.size()) : int(i);
}

QStringList orderedKeys(const QJsonObject& o)
{
    QStringList keys = o.keys();
    std::stable_sort(keys.begin(), keys.end(), [](const QString& a, const QString& b) { return keyRank(a) < keyRank(b); });
    return keys;
}

QByteArray scalarJson(const QJsonValue& v)
{
    const QByteArray a = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return a.mid(1, a.size() - 2);
}

bool isFlat(const QJsonValue& v)
{
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        return std::all_of(a.begin(), a.end(), [](const QJsonValue& x) { return !x.isArray() && !x.isObject(); });
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        return std::all_of(o.begin(), o.end(), [](const QJsonValue& x) { return !x.isArray() && !x.isObject(); });
    }
    return true;
}

QByteArray inlineJson(const QJsonValue& v)
{
    if (v.isArray()) {
        QByteArrayList parts;
        for (const QJsonValue& x : v.toArray())
            parts << inlineJson(x);
        return '[' + parts.join(", ") + ']';
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QByteArrayList parts;
        for (const QString& k : orderedKeys(o))
            parts << scalarJson(k) + ": " + inlineJson(o.value(k));
        return '{' + parts.join(", ") + '}';
    }
    return scalarJson(v);
}

void writeJson(QByteArray& out, const QJsonValue& v, int indent)
{
    // A text, number or truth value as it is, however long: a reason of more than a line's
    // width went on to the object branch below and was written as {} (the plan then unreadable).
    if (!v.isArray() && !v.isObject()) {
        out += scalarJson(v);
        return;
    }
    // Flat and short (or an object whose values are all flat and short): one line.
    if (isFlat(v) || (v.isObject() && std::all_of(v.toObject().begin(), v.toObject().end(), [](const QJsonValue& x) { return isFlat(x); }))) {
        const QByteArray one = inlineJson(v);
        if (one.size() + indent <= 110) {
            out += one;
            return;
        }
    }
    const QByteArray pad(indent + 2, ' ');
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        out += "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            out += pad;
            writeJson(out, a[i], indent + 2);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out += QByteArray(indent, ' ') + ']';
        return;
    }
    const QJsonObject o = v.toObject();
    const QStringList keys = orderedKeys(o);
    out += "{\n";
    for (qsizetype i = 0; i < keys.size(); ++i) {
        out += pad + scalarJson(keys[i]) + ": ";
        writeJson(out, o.value(keys[i]), indent + 2);
        out += i + 1 < keys.size() ? ",\n" : "\n";
    }
    out += QByteArray(indent, ' ') + '}';
}

}  // namespace

QByteArray planJsonText(const Plan& plan)
{
    QByteArray out;
    writeJson(out, planToJson(plan), 0);
    return out + '\n';
}

Plan readPlanFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw PlanError(path, {}, f.exists() ? nb::TrCore::tr("cannot read: %1").arg(f.errorString()) : nb::TrCore::tr("no such file"));
    QJsonParseError pe{};
    const QByteArray bytes = f.readAll();
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &pe);
    if (bytes.trimmed().isEmpty())
        throw PlanError(path, {}, nb::TrCore::tr("the file is empty; a plan is a JSON file (needlebench plan new writes one)"));
    if (pe.error != QJsonParseError::NoError) {
        const int line = int(bytes.left(pe.offset).count('\n')) + 1;
        // Qt's parser says "illegal value" of a CSV as of a typo; say what was expected.
        throw PlanError(path, nb::TrCore::tr("line %1").arg(line),
                        nb::TrCore::tr("not JSON as a plan is written (%1)").arg(pe.errorString()));
    }
    if (!doc.isObject())
        throw PlanError(path, {}, nb::TrCore::tr("expected a JSON object {...}"));
    return planFromJson(doc.object(), path);
}

void writePlanFile(const QString& path, const Plan& plan)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(planJsonText(plan)) < 0 || !commitWhole(f))
        throw PlanError(path, {}, nb::TrCore::tr("cannot write: %1").arg(f.errorString()));
}

}  // namespace nb
