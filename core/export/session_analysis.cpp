#include "session_analysis.h"
#include "core/run_keys.h"
#include "core/tr.h"

#include "core/fit_error.h"
#include "core/run_judgement.h"
#include "core/statistics.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <map>

namespace nb {

namespace {

// The tissue a run's fits are grouped by: what the run names (`tissue`, from the command line
// or a plan), else the session's organ and specimen (runs recorded in the window), else the
// simulated rig's preset.
QString tissueOf(const Run& run)
{
    if (const auto tissue = run.meta(key::tissue); tissue && !tissue->trimmed().isEmpty())
        return *tissue;
    const QString organ = run.meta(key::organ).value_or(QString()).trimmed();
    const QString specimen = run.meta(key::specimen).value_or(QString()).trimmed();
    if (!organ.isEmpty() || !specimen.isEmpty())
        return QStringList{organ, specimen}.join(u' ').trimmed();
    return run.meta(QStringLiteral("sim_tissue")).value_or(QString());
}

bool hasPhaseLabels(const Labels& labels)
{
    for (const Label& l : labels)
        if (!l.isPoint() && (l.label == QLatin1String("a") || l.label == QLatin1String("c")))
            return true;
    return false;
}

double thicknessFor(const Run& run, const Dataset& d)
{
    for (const Metadata* m : {&run.footer, &run.metadata, &d.metadata})
        if (const auto v = m->number(QStringLiteral("thickness_mm")); v && *v > 0.0)
            return *v;
    return 0.0;
}

// False, with the reason in a.leftOut, for a run the judgement leaves out.
bool judged(const DatasetRun& r, SessionAnalysis& a, const AnalysisOptions& o)
{
    const RunJudgement j = judgeRun(r.run);
    if (j.usable)
        return true;
    if (!o.includeJudgedOut)
        a.leftOut << nb::TrCore::tr("%1: %2").arg(r.name, j.reason);
    return o.includeJudgedOut;
}

void analyseStiffness(const Dataset& d, SessionAnalysis& a, const AnalysisOptions& o)
{
    for (const DatasetRun& r : d.runs) {
        if (runKind(r.run) != RunKind::Insertion || !judged(r, a, o))
            continue;
        StiffnessRunResult s;
        s.run = r.name;
        s.group = tissueOf(r.run);
        s.tip = r.run.meta(QStringLiteral("tip")).value_or(QString());
        try {
            s.events = eventsWithLabels(r.run, r.labels);
            s.segment = stiffnessSegment(r.run, s.events);
            s.fit = fitStiffness(s.segment);
        } catch (const FitError& e) {
            s.error = e.message();
            a.warnings << nb::TrCore::tr("%1: no stiffness fit (%2)").arg(r.name, e.message());
        }
        a.stiffness.push_back(std::move(s));
    }
    std::map<QString, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < a.stiffness.size(); ++i)
        if (a.stiffness[i].ok())
            groups[a.stiffness[i].group].push_back(i);
    for (const auto& [name, idx] : groups) {
        StiffnessGroupResult g;
        g.group = name;
        g.tip = a.stiffness[idx.front()].tip;
        g.runs = idx;
        std::vector<StiffnessSegment> segs;
        std::vector<double> depths, forces;
        for (std::size_t i : idx) {
            segs.push_back(a.stiffness[i].segment);
            depths.push_back(a.stiffness[i].events.punctureDepth_mm());
            forces.push_back(a.stiffness[i].events.puncture.force_N);
        }
        try {
            g.summary = fitStiffnessRuns(segs);
        } catch (const FitError& e) {
            a.warnings << nb::TrCore::tr("%1: no pooled stiffness fit (%2)").arg(name, e.message());
            continue;
        }
        g.meanPunctureDepth_mm = mean(depths);
        g.meanPunctureForce_N = mean(forces);
        // Outliers: the run's model force at the group's median puncture depth far (3 scaled
        // MADs, and 15 %) from the others', or its puncture force so; needs enough runs to say.
        if (idx.size() >= 4) {
            const double x = median(depths);
            std::vector<double> f;
            for (std::size_t i : idx)
                f.push_back(a.stiffness[i].fit.quadratic.model(x));
            const QStringList byModel = robustOutlierReasons(f, nb::TrCore::tr("model force at %1 mm").arg(x, 0, 'f', 2), QStringLiteral("N"));
            const QStringList byForce = robustOutlierReasons(forces, nb::TrCore::tr("puncture force"), QStringLiteral("N"));
            for (std::size_t k = 0; k < idx.size(); ++k) {
                QStringList why;
                for (const QString& r : {byModel[qsizetype(k)], byForce[qsizetype(k)]})
                    if (!r.isEmpty())
                        why << r;
                a.stiffness[idx[k]].outlier = !why.isEmpty();
                a.stiffness[idx[k]].outlierReason = why.join(QStringLiteral("; "));
            }
        }
        a.stiffnessGroups.push_back(std::move(g));
    }
}

void analyseFriction(const Dataset& d, SessionAnalysis& a, const AnalysisOptions& options)
{
    std::vector<FrictionFit> fits;
    std::vector<std::pair<QString, RunPeaks>> peaks;  // per length, by tissue
    for (const DatasetRun& r : d.runs) {
        if (runKind(r.run) != RunKind::Sinusoid || !judged(r, a, options))
            continue;
        FrictionRunResult f;
        f.run = r.name;
        f.tissue = tissueOf(r.run);
        if (!touchedTissue(r.run)) {  // even when asked to include it: air has no friction
            f.error = nb::TrCore::tr("no tissue contact");
            a.warnings << nb::TrCore::tr("%1: no friction fit (%2)").arg(r.name, f.error);
            a.friction.push_back(std::move(f));
            continue;
        }
        try {
            FrictionOptions o;
            o.thickness_mm = thicknessFor(r.run, d);
            if (hasPhaseLabels(r.labels))
                f.phases = phasePerSample(r.labels, r.run.time_s);
            f.fit = fitFriction(r.run, o, f.phases);
            fits.push_back(f.fit);
            // Per unit length, so slabs of different thickness share the line.
            RunPeaks p = f.fit.peaks;
            for (std::optional<PeakPoint>* side : {&p.positive, &p.negative})
                if (*side)
                    (*side)->force_N /= o.thickness_mm / 1000.0;
            peaks.emplace_back(f.tissue, p);
        } catch (const FitError& e) {
            f.error = e.message();
            a.warnings << nb::TrCore::tr("%1: no friction fit (%2)").arg(r.name, e.message());
        }
        a.friction.push_back(std::move(f));
    }
    if (!fits.empty()) {
        a.frictionGroups = groupByFrequency(fits);
        a.frictionOverall = overall(fits);
    }
    QStringList tissues;
    for (const auto& [tissue, p] : peaks)
        if (!tissues.contains(tissue))
            tissues << tissue;
    for (const QString& tissue : tissues) {
        std::vector<RunPeaks> mine;
        for (const auto& [t, p] : peaks)
            if (t == tissue)
                mine.push_back(p);
        const auto line = peakSpeedLine(mine);
        if (!line)
            continue;
        a.frictionPeakLines.push_back({tissue, *line});
        for (FrictionRunResult& f : a.friction) {
            if (!f.ok() || f.tissue != tissue)
                continue;
            // The line is per unit length, the run's C in N.
            const double L = f.fit.thickness_mm / 1000.0;
            PeakSpeedLine inN = *line;
            inN.model.Cp_N *= L;
            inN.model.Cn_N *= L;
            inN.seCp_N *= L;
            inN.seCn_N *= L;
            f.peakLineDeparture = departureFromLine(f.fit, inN);
        }
    }
}

void analyseValidation(const Dataset& d, SessionAnalysis& a)
{
    for (const StiffnessGroupResult& g : a.stiffnessGroups) {
        for (std::size_t i : g.runs) {
            const StiffnessRunResult& s = a.stiffness[i];
            const auto it = std::find_if(d.runs.begin(), d.runs.end(), [&](const DatasetRun& r) { return r.name == s.run; });
            if (it == d.runs.end())
                continue;
            ValidationResult v;
            v.run = s.run;
            InsertionModel m;
            m.stiffness = g.summary.pooled.quadratic.model;
            m.contact_mm = s.events.contact.position_mm;
            m.punctureDepth_mm = g.meanPunctureDepth_mm;
            if (s.events.relaxation)
                m.relaxation_mm = std::max(0.0, s.events.puncture.position_mm - s.events.relaxation->position_mm);
            if (a.frictionOverall)
                m.friction = a.frictionOverall->mean;
            v.recorded.time_s = it->run.time_s;
            v.recorded.position_mm = it->run.position_mm;
            v.recorded.force_N = it->run.force_N;
            for (double& f : v.recorded.force_N)
                f -= s.events.zeroOffset_N;
            try {
                v.simulated = simulateInsertion(m, v.recorded.time_s, v.recorded.position_mm);
                v.rms_N = rmsDistance(v.simulated, v.recorded);
            } catch (const FitError& e) {
                v.error = e.message();
                a.warnings << nb::TrCore::tr("%1: no validation (%2)").arg(s.run, e.message());
            }
            a.validation.push_back(std::move(v));
        }
    }
}

TableColumn col(const char* key, const QString& title, const char* unit, int decimals, const char* latex = nullptr)
{
    return {QString::fromLatin1(key), title, QString::fromUtf8(unit), decimals, latex ? QString::fromUtf8(latex) : QString()};
}

std::vector<TableColumn> karnoppColumns()
{
    return {col("Cp_N_per_m", QStringLiteral("Cp"), "N/m", 4, "$C_p$"),       col("bp_Ns_per_m2", QStringLiteral("bp"), "N s/m^2", 3, "$b_p$"),
            col("Cn_N_per_m", QStringLiteral("Cn"), "N/m", 4, "$C_n$"),       col("bn_Ns_per_m2", QStringLiteral("bn"), "N s/m^2", 3, "$b_n$"),
            col("Dp_N_per_m", QStringLiteral("Dp"), "N/m", 4, "$D_p$"),       col("Dn_N_per_m", QStringLiteral("Dn"), "N/m", 4, "$D_n$")};
}

void appendKarnopp(std::vector<TableCell>& row, const KarnoppPerLength& k)
{
    for (double v : {k.Cp_N_per_m, k.bp_Ns_per_m2, k.Cn_N_per_m, k.bn_Ns_per_m2, k.Dp_N_per_m, k.Dn_N_per_m})
        row.emplace_back(v);
}

}  // namespace

RunKind runKind(const Run& run)
{
    const QString motion = run.meta(QStringLiteral("motion")).value_or(QString()).trimmed().toLower();
    const QString protocol = run.meta(QStringLiteral("protocol")).value_or(QString()).trimmed().toLower();
    if (motion == QLatin1String("sine") || motion == QLatin1String("sinusoidal") || protocol == QLatin1String("friction"))
        return RunKind::Sinusoid;
    if (motion == QLatin1String("linear") || protocol == QLatin1String("stiffness") || protocol == QLatin1String("internal") ||
        protocol == QLatin1String("prostate"))
        return RunKind::Insertion;
    return RunKind::Other;
}

SessionAnalysis analyseDataset(const Dataset& dataset, const AnalysisOptions& options)
{
    SessionAnalysis a;
    analyseStiffness(dataset, a, options);
    analyseFriction(dataset, a, options);
    analyseValidation(dataset, a);
    return a;
}

FitTable stiffnessRunsTable(const SessionAnalysis& a)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Pre-puncture stiffness fits per run, f = a1 x + a2 x^2");
    t.label = QStringLiteral("tab:stiffness-runs");
    t.columns = {col("run", nb::TrCore::tr("run"), "", -1),
                 col("tissue", nb::TrCore::tr("tissue"), "", -1),
                 col("a1_N_per_mm", QStringLiteral("a1"), "N/mm", 4, "$a_1$"),
                 col("a2_N_per_mm2", QStringLiteral("a2"), "N/mm^2", 4, "$a_2$"),
                 col("rms_N", nb::TrCore::tr("rms"), "N", 4),
                 col("r2", QStringLiteral("r2"), "", 4, "$r^2$"),
                 col("puncture_depth_mm", nb::TrCore::tr("puncture depth"), "mm", 3),
                 col("puncture_force_N", nb::TrCore::tr("puncture force"), "N", 4),
                 col("outlier", nb::TrCore::tr("outlier"), "", -1)};
    for (const StiffnessRunResult& s : a.stiffness) {
        const double nan = std::nan("");
        if (!s.ok()) {
            t.rows.push_back({s.run, s.group, nan, nan, nan, nan, nan, nan, QStringLiteral("not fitted")});
            continue;
        }
        t.rows.push_back({s.run, s.group, s.fit.quadratic.model.a1_N_per_mm, s.fit.quadratic.model.a2_N_per_mm2,
                          s.fit.quadratic.rms_N, s.fit.quadratic.r2, s.events.punctureDepth_mm(), s.events.puncture.force_N,
                          s.outlier ? QStringLiteral("yes") : QString()});
    }
    return t;
}

FitTable stiffnessPooledTable(const SessionAnalysis& a)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Pooled pre-puncture fits per tissue (Table 2 layout)");
    t.label = QStringLiteral("tab:stiffness-pooled");
    t.columns = {col("tissue", nb::TrCore::tr("tissue"), "", -1),
                 col("tip", nb::TrCore::tr("tip"), "", -1),
                 col("fit", nb::TrCore::tr("fit"), "", -1),
                 col("a1_N_per_mm", QStringLiteral("a1"), "N/mm", 4, "$a_1$"),
                 col("a2_N_per_mm2", QStringLiteral("a2"), "N/mm^2", 4, "$a_2$"),
                 col("mean_puncture_depth_mm", nb::TrCore::tr("mean puncture depth"), "mm", 4),
                 col("mean_puncture_force_N", nb::TrCore::tr("mean puncture force"), "N", 4),
                 col("runs", nb::TrCore::tr("runs"), "", 0)};
    for (const StiffnessGroupResult& g : a.stiffnessGroups) {
        t.rows.push_back({g.group, g.tip, QStringLiteral("pooled"), g.summary.pooled.quadratic.model.a1_N_per_mm,
                          g.summary.pooled.quadratic.model.a2_N_per_mm2, g.meanPunctureDepth_mm, g.meanPunctureForce_N,
                          double(g.runs.size())});
        t.rows.push_back({g.group, g.tip, QStringLiteral("mean of runs"), g.summary.meanOfRuns.a1_N_per_mm, g.summary.meanOfRuns.a2_N_per_mm2,
                          g.meanPunctureDepth_mm, g.meanPunctureForce_N, double(g.runs.size())});
    }
    return t;
}

FitTable frictionRunsTable(const SessionAnalysis& a)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Karnopp friction per unit length of needle in tissue, per run");
    t.label = QStringLiteral("tab:friction-runs");
    t.columns = {col("run", nb::TrCore::tr("run"), "", -1), col("freq_Hz", nb::TrCore::tr("f"), "Hz", 2)};
    for (const TableColumn& c : karnoppColumns())
        t.columns.push_back(c);
    t.columns.push_back(col("rms_N", nb::TrCore::tr("rms"), "N", 4));
    t.columns.push_back(col("static_from", nb::TrCore::tr("D from"), "", -1));
    // Values the fit flags (not physical, not determined by the run) are left empty and named.
    t.columns.push_back(col("not_determined", nb::TrCore::tr("not determined"), "", -1));
    for (const FrictionRunResult& f : a.friction) {
        std::vector<TableCell> row{f.run};
        if (!f.ok()) {
            for (int i = 0; i < 8; ++i)
                row.emplace_back(std::nan(""));
            row.emplace_back(QStringLiteral("not fitted"));
            row.emplace_back(QString());
        } else {
            row.emplace_back(f.fit.frequency_hz);
            KarnoppPerLength shown = f.fit.perLength;
            const std::pair<const char*, double KarnoppPerLength::*> fields[] = {
                {"Cp", &KarnoppPerLength::Cp_N_per_m},   {"Cn", &KarnoppPerLength::Cn_N_per_m},
                {"bp", &KarnoppPerLength::bp_Ns_per_m2}, {"bn", &KarnoppPerLength::bn_Ns_per_m2},
                {"Dp", &KarnoppPerLength::Dp_N_per_m},   {"Dn", &KarnoppPerLength::Dn_N_per_m}};
            for (const auto& [name, member] : fields)
                if (f.fit.notPhysicalValues.contains(QLatin1String(name)))
                    shown.*member = std::nan("");
            appendKarnopp(row, shown);
            row.emplace_back(f.fit.rms_N);
            row.emplace_back(f.fit.staticSource);
            row.emplace_back(f.fit.notPhysicalValues.join(QLatin1Char(' ')));
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

FitTable frictionSummaryTable(const SessionAnalysis& a)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Karnopp friction per unit length, mean and standard deviation per frequency and overall (Tables 4/5 layout)");
    t.label = QStringLiteral("tab:friction");
    t.columns = {col("group", nb::TrCore::tr("group"), "", -1), col("statistic", nb::TrCore::tr("statistic"), "", -1), col("freq_Hz", nb::TrCore::tr("f"), "Hz", 2),
                 col("runs", nb::TrCore::tr("runs"), "", 0)};
    for (const TableColumn& c : karnoppColumns())
        t.columns.push_back(c);
    auto add = [&](const QString& name, const FrictionGroup& g) {
        for (int k = 0; k < 2; ++k) {
            // The overall group has no single frequency.
            std::vector<TableCell> row{name, k ? QStringLiteral("std") : QStringLiteral("mean"), g.frequency_hz > 0.0 ? g.frequency_hz : std::nan(""),
                                       double(g.runs)};
            appendKarnopp(row, k ? g.stdDev : g.mean);
            if (k == 1 && g.runs < 2)  // a standard deviation of one run is undefined: left empty
                for (std::size_t c = 4; c < row.size(); ++c)
                    row[c] = std::nan("");
            t.rows.push_back(std::move(row));
        }
    };
    for (const FrictionGroup& g : a.frictionGroups)
        add(QStringLiteral("%1Hz").arg(g.frequency_hz, 0, 'g', 3), g);
    if (a.frictionOverall)
        add(QStringLiteral("overall"), *a.frictionOverall);
    for (const auto& [tissue, line] : a.frictionPeakLines) {
        // Already per unit length (see analyseFriction); D is not defined by the line.
        const KarnoppModel& k = line.model;
        std::vector<TableCell> row{tissue.isEmpty() ? QStringLiteral("peak speeds") : QStringLiteral("peak speeds, %1").arg(tissue),
                                   QStringLiteral("line"), std::nan(""), double(line.runs)};
        appendKarnopp(row, {k.Cp_N, k.Cn_N, k.bp_Ns_per_m, k.bn_Ns_per_m, std::nan(""), std::nan("")});
        t.rows.push_back(std::move(row));
    }
    return t;
}

FitTable validationTable(const SessionAnalysis& a)
{
    FitTable t;
    t.caption = nb::TrCore::tr("Summed model against the recorded insertions (Fig. 38)");
    t.label = QStringLiteral("tab:validation");
    t.columns = {col("run", nb::TrCore::tr("run"), "", -1), col("rms_N", nb::TrCore::tr("rms error"), "N", 4)};
    for (const ValidationResult& v : a.validation)
        t.rows.push_back({v.run, v.ok() ? v.rms_N : std::nan("")});
    return t;
}

}  // namespace nb
