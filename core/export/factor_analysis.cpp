#include "factor_analysis.h"
#include "core/tr.h"

#include "core/fit_error.h"
#include "core/friction_fit.h"
#include "core/statistics.h"

#include <algorithm>
#include <cmath>

namespace nb {

namespace {

TableColumn col(const QString& key, const QString& title, const QString& unit, int decimals)
{
    return {key, title, unit, decimals, {}};
}

double thicknessOf(const Run& run, const Dataset& d)
{
    for (const Metadata* m : {&run.footer, &run.metadata, &d.metadata})
        if (const auto v = m->number(QStringLiteral("thickness_mm")); v && *v > 0.0)
            return *v;
    return 0.0;
}

// The fit's coefficients, except those it flags as not physical or not determined: such values
// are not results (the run's own fit says so), and in a group's mean they would pass for one.
void putFriction(std::map<QString, double>& values, const FrictionFit& f, const QString& run, QStringList* warnings)
{
    const KarnoppPerLength& k = f.perLength;
    values[QStringLiteral("Cp_N_per_m")] = k.Cp_N_per_m;
    values[QStringLiteral("bp_Ns_per_m2")] = k.bp_Ns_per_m2;
    values[QStringLiteral("Cn_N_per_m")] = k.Cn_N_per_m;
    values[QStringLiteral("bn_Ns_per_m2")] = k.bn_Ns_per_m2;
    values[QStringLiteral("Dp_N_per_m")] = k.Dp_N_per_m;
    values[QStringLiteral("Dn_N_per_m")] = k.Dn_N_per_m;
    if (f.massEstimate_kg)
        values[QStringLiteral("m_est_kg")] = *f.massEstimate_kg;
    for (const QString& name : f.notPhysicalValues)  // "Cp" names the key "Cp_N_per_m", "bp" "bp_Ns_per_m2"
        for (auto it = values.begin(); it != values.end();)
            it = it->first.startsWith(name + QLatin1Char('_')) ? values.erase(it) : std::next(it);
    if (warnings && !f.notPhysical.isEmpty())
        *warnings << nb::TrCore::tr("%1: left out of the table: %2").arg(run, f.notPhysical.join(QStringLiteral("; ")));
    for (auto it = values.begin(); it != values.end();)
        it = std::isfinite(it->second) ? std::next(it) : values.erase(it);
}

// Numbers compare as numbers ("0.2" < "0.5" < "10"), the rest as text, empty last.
bool levelLess(const QString& a, const QString& b)
{
    if (a.isEmpty() != b.isEmpty())
        return b.isEmpty();
    bool okA = false, okB = false;
    const double x = a.toDouble(&okA), y = b.toDouble(&okB);
    if (okA && okB)
        return x < y;
    if (okA != okB)
        return okA;
    return QString::localeAwareCompare(a, b) < 0;
}

QuantityStats statsOf(const std::vector<double>& v)
{
    // One run has no spread to tell (0 would read as a measured one): left blank.
    return {mean(v), v.size() < 2 ? std::nan("") : sampleStdDev(v), v.size()};
}

}  // namespace

const std::vector<FactorQuantity>& factorQuantities()
{
    static const std::vector<FactorQuantity> q{
        {QStringLiteral("a1_N_per_mm"), QStringLiteral("a1"), QStringLiteral("N/mm")},
        {QStringLiteral("a2_N_per_mm2"), QStringLiteral("a2"), QStringLiteral("N/mm^2")},
        {QStringLiteral("puncture_depth_mm"), QStringLiteral("puncture depth"), QStringLiteral("mm")},
        {QStringLiteral("puncture_force_N"), QStringLiteral("puncture force"), QStringLiteral("N")},
        {QStringLiteral("m_est_kg"), QStringLiteral("m_est"), QStringLiteral("kg")},
        {QStringLiteral("Cp_N_per_m"), QStringLiteral("Cp"), QStringLiteral("N/m")},
        {QStringLiteral("bp_Ns_per_m2"), QStringLiteral("bp"), QStringLiteral("N s/m^2")},
        {QStringLiteral("Cn_N_per_m"), QStringLiteral("Cn"), QStringLiteral("N/m")},
        {QStringLiteral("bn_Ns_per_m2"), QStringLiteral("bn"), QStringLiteral("N s/m^2")},
        {QStringLiteral("Dp_N_per_m"), QStringLiteral("Dp"), QStringLiteral("N/m")},
        {QStringLiteral("Dn_N_per_m"), QStringLiteral("Dn"), QStringLiteral("N/m")},
    };
    return q;
}

QString factorLevel(const Run& run, const QString& factor)
{
    if (const auto v = run.meta(QStringLiteral("factor_") + factor))
        return v->trimmed();
    return run.meta(factor).value_or(QString()).trimmed();
}

QStringList datasetFactors(const Dataset& dataset)
{
    const QString prefix = QStringLiteral("factor_");
    QStringList names;
    for (const DatasetRun& r : dataset.runs)
        for (const auto& [key, value] : r.run.metadata.entries())
            if (key.startsWith(prefix) && key.size() > prefix.size() && !names.contains(key.mid(prefix.size())))
                names << key.mid(prefix.size());
    return names;
}

QStringList datasetSettingFactors(const Dataset& dataset)
{
    QStringList out;
    for (const QString& key : {QStringLiteral("tissue"), QStringLiteral("sim_tissue"), QStringLiteral("tip"), QStringLiteral("sim_tip"),
                              QStringLiteral("motion"), QStringLiteral("velocity_mm_s"), QStringLiteral("frequency_hz"),
                              QStringLiteral("amplitude_mm")}) {
        QStringList levels;
        for (const DatasetRun& r : dataset.runs)
            if (const QString level = factorLevel(r.run, key); !level.isEmpty() && !levels.contains(level))
                levels << level;
        if (levels.size() >= 2)
            out << key;
    }
    return out;
}

std::vector<RunFactorValues> runFactorValues(const Dataset& dataset, const SessionAnalysis& analysis, const QStringList& factors,
                                             const FactorAnalysisOptions& options, QStringList* warnings)
{
    std::vector<RunFactorValues> out;
    for (const DatasetRun& r : dataset.runs) {
        RunFactorValues v;
        v.run = r.name;
        for (const QString& f : factors)
            v.levels[f] = factorLevel(r.run, f);
        for (const StiffnessRunResult& s : analysis.stiffness) {
            if (s.run != r.name || !s.ok())
                continue;
            v.values[QStringLiteral("a1_N_per_mm")] = s.fit.quadratic.model.a1_N_per_mm;
            v.values[QStringLiteral("a2_N_per_mm2")] = s.fit.quadratic.model.a2_N_per_mm2;
            v.values[QStringLiteral("puncture_depth_mm")] = s.events.punctureDepth_mm();
            v.values[QStringLiteral("puncture_force_N")] = s.events.puncture.force_N;
        }
        for (const FrictionRunResult& f : analysis.friction) {
            if (f.run != r.name || !f.ok())
                continue;
            if (!options.estimateMass) {
                putFriction(v.values, f.fit, r.name, warnings);
                continue;
            }
            try {
                FrictionOptions o;
                o.thickness_mm = thicknessOf(r.run, dataset);
                o.estimateMass = true;
                putFriction(v.values, fitFriction(r.run, o, f.phases), r.name, warnings);
            } catch (const FitError& e) {
                if (warnings)
                    *warnings << nb::TrCore::tr("%1: no friction fit with the mass estimated (%2)").arg(r.name, e.message());
            }
        }
        for (auto it = v.values.begin(); it != v.values.end();)
            it = std::isfinite(it->second) ? std::next(it) : v.values.erase(it);
        if (!v.values.empty())
            out.push_back(std::move(v));
    }
    return out;
}

std::vector<FactorCell> groupByFactors(const std::vector<RunFactorValues>& runs, const QStringList& factors)
{
    std::vector<QStringList> keys;
    for (const RunFactorValues& r : runs) {
        QStringList k;
        for (const QString& f : factors)
            k << (r.levels.count(f) ? r.levels.at(f) : QString());
        if (std::find(keys.begin(), keys.end(), k) == keys.end())
            keys.push_back(k);
    }
    std::sort(keys.begin(), keys.end(), [](const QStringList& a, const QStringList& b) {
        for (qsizetype i = 0; i < a.size(); ++i) {
            if (levelLess(a[i], b[i]))
                return true;
            if (levelLess(b[i], a[i]))
                return false;
        }
        return false;
    });
    std::vector<FactorCell> cells;
    for (const QStringList& k : keys) {
        FactorCell c;
        c.levels = k;
        std::map<QString, std::vector<double>> values;
        for (const RunFactorValues& r : runs) {
            QStringList rk;
            for (const QString& f : factors)
                rk << (r.levels.count(f) ? r.levels.at(f) : QString());
            if (rk != k)
                continue;
            ++c.runs;
            for (const auto& [q, v] : r.values)
                values[q].push_back(v);
        }
        for (const auto& [q, v] : values)
            c.stats[q] = statsOf(v);
        cells.push_back(std::move(c));
    }
    return cells;
}

FitTable factorTable(const std::vector<FactorCell>& cells, const QStringList& factors)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Fitted quantities by %1: mean, standard deviation and number of runs").arg(factors.join(QStringLiteral(", ")));
    t.label = QStringLiteral("tab:by-factor");
    for (const QString& f : factors)
        t.columns.push_back(col(f, f, {}, -1));
    t.columns.push_back(col(QStringLiteral("quantity"), nb::TrCore::tr("quantity"), {}, -1));
    t.columns.push_back(col(QStringLiteral("unit"), nb::TrCore::tr("unit"), {}, -1));
    t.columns.push_back(col(QStringLiteral("mean"), nb::TrCore::tr("mean"), {}, 6));
    t.columns.push_back(col(QStringLiteral("std"), nb::TrCore::tr("std"), {}, 6));
    t.columns.push_back(col(QStringLiteral("n"), QStringLiteral("n"), {}, 0));
    for (const FactorCell& c : cells) {
        for (const FactorQuantity& q : factorQuantities()) {
            const auto it = c.stats.find(q.key);
            if (it == c.stats.end())
                continue;
            std::vector<TableCell> row;
            for (const QString& l : c.levels)
                row.emplace_back(l);
            row.emplace_back(q.key);
            row.emplace_back(q.unit);
            row.emplace_back(it->second.mean);
            row.emplace_back(it->second.stdDev);
            row.emplace_back(double(it->second.n));
            t.rows.push_back(std::move(row));
        }
    }
    return t;
}

FitTable frictionFrequencyTable(const std::vector<RunFactorValues>& runs, const QString& frequencyFactor)
{
    static const QStringList keys{QStringLiteral("m_est_kg"),     QStringLiteral("Cp_N_per_m"), QStringLiteral("bp_Ns_per_m2"),
                                  QStringLiteral("Cn_N_per_m"),   QStringLiteral("bn_Ns_per_m2"), QStringLiteral("Dp_N_per_m"),
                                  QStringLiteral("Dn_N_per_m")};
    FitTable t;
    t.caption = nb::TrCore::tr("Karnopp friction per unit length, mean and standard deviation per frequency and overall (Table 5 layout)");
    t.label = QStringLiteral("tab:friction-by-frequency");
    t.columns = {col(QStringLiteral("group"), nb::TrCore::tr("group"), {}, -1), col(QStringLiteral("statistic"), nb::TrCore::tr("statistic"), {}, -1),
                 col(QStringLiteral("freq_Hz"), QStringLiteral("f"), QStringLiteral("Hz"), 2), col(QStringLiteral("n"), QStringLiteral("n"), {}, 0)};
    for (const QString& k : keys) {
        const auto q = std::find_if(factorQuantities().begin(), factorQuantities().end(), [&](const FactorQuantity& f) { return f.key == k; });
        t.columns.push_back(col(k, q->title, q->unit, k == QLatin1String("m_est_kg") ? 4 : (k.startsWith(QLatin1Char('b')) ? 3 : 4)));
    }
    std::vector<RunFactorValues> friction;
    for (const RunFactorValues& r : runs)
        if (r.values.count(QStringLiteral("Cp_N_per_m")))
            friction.push_back(r);
    auto addGroup = [&](const QString& name, double freq, const std::vector<const RunFactorValues*>& members) {
        for (int k = 0; k < 2; ++k) {
            std::vector<TableCell> row{name, k ? QStringLiteral("std") : QStringLiteral("mean"), freq, double(members.size())};
            for (const QString& key : keys) {
                std::vector<double> v;
                for (const RunFactorValues* r : members)
                    if (const auto it = r->values.find(key); it != r->values.end())
                        v.push_back(it->second);
                row.emplace_back(v.empty() || (k && v.size() < 2) ? std::nan("") : (k ? sampleStdDev(v) : mean(v)));
            }
            t.rows.push_back(std::move(row));
        }
    };
    QStringList levels;
    for (const RunFactorValues& r : friction) {
        const QString l = r.levels.count(frequencyFactor) ? r.levels.at(frequencyFactor) : QString();
        if (!levels.contains(l))
            levels << l;
    }
    std::sort(levels.begin(), levels.end(), levelLess);
    for (const QString& l : levels) {
        std::vector<const RunFactorValues*> members;
        for (const RunFactorValues& r : friction)
            if ((r.levels.count(frequencyFactor) ? r.levels.at(frequencyFactor) : QString()) == l)
                members.push_back(&r);
        bool ok = false;
        const double f = l.toDouble(&ok);
        addGroup(l.isEmpty() ? QStringLiteral("unknown") : (ok ? QStringLiteral("%1Hz").arg(l) : l), ok ? f : std::nan(""), members);
    }
    if (!friction.empty()) {
        std::vector<const RunFactorValues*> all;
        for (const RunFactorValues& r : friction)
            all.push_back(&r);
        addGroup(QStringLiteral("all"), std::nan(""), all);
    }
    return t;
}

QString fitTableText(const FitTable& table)
{
    std::vector<QStringList> cells;
    QStringList head;
    for (const TableColumn& c : table.columns)
        head << c.key;
    cells.push_back(head);
    for (const auto& row : table.rows) {
        QStringList line;
        for (std::size_t i = 0; i < table.columns.size(); ++i) {
            if (i >= row.size()) {
                line << QString();
                continue;
            }
            if (const auto* s = std::get_if<QString>(&row[i])) {
                line << *s;
                continue;
            }
            const double v = std::get<double>(row[i]);
            line << (std::isfinite(v) ? QString::number(v, 'f', std::max(0, table.columns[i].decimals)) : QString());
        }
        cells.push_back(line);
    }
    std::vector<qsizetype> width(table.columns.size(), 0);
    for (const QStringList& l : cells)
        for (qsizetype i = 0; i < l.size(); ++i)
            width[std::size_t(i)] = std::max(width[std::size_t(i)], l[i].size());
    QString out;
    for (const QStringList& l : cells) {
        QStringList padded;
        for (qsizetype i = 0; i < l.size(); ++i) {
            // Text left, numbers right: columns of figures line up on the decimal point.
            const bool text = table.columns[std::size_t(i)].decimals < 0;
            padded << (text ? l[i].leftJustified(width[std::size_t(i)]) : l[i].rightJustified(width[std::size_t(i)]));
        }
        QString line = padded.join(QStringLiteral("  "));
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        out += line + QLatin1Char('\n');
    }
    return out;
}

}  // namespace nb
