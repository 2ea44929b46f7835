#pragma once
// Analysis by factor: each fitted quantity of a session's runs (stiffness a1/a2, puncture
// force and depth, Karnopp friction per unit length) grouped by any factors of the runs, with
// mean, standard deviation and n; and the friction table per frequency and overall in the
// layout of the thesis's Table 5. Fits come from analyseDataset (session_analysis.h).
//
// A run's factor level is its `factor_<name>` metadata (written by `needlebench plan run`),
// else its plain `<name>` metadata, so sessions recorded without a plan still group by what
// their runs say (tip, tissue, frequency_hz, velocity_mm_s).

#include "dataset.h"
#include "fit_table.h"
#include "session_analysis.h"

#include <QString>
#include <QStringList>
#include <map>
#include <vector>

namespace nb {

struct FactorQuantity {
    QString key;    // CSV column, e.g. "a1_N_per_mm"
    QString title;  // e.g. "a1"
    QString unit;   // e.g. "N/mm"
};

// Stiffness a1, a2, puncture depth and force; friction m_est, Cp, bp, Cn, bn, Dp, Dn.
const std::vector<FactorQuantity>& factorQuantities();

struct RunFactorValues {
    QString run;
    std::map<QString, QString> levels;  // factor -> level ("" when the run does not say)
    std::map<QString, double> values;   // quantity key -> value, only those fitted
};

struct FactorAnalysisOptions {
    // Re-fit the friction runs with the mass estimated (eq. 19), as the thesis's Table 5 did;
    // otherwise the known mass is removed (eq. 21) and m_est stays empty.
    bool estimateMass = false;
};

QString factorLevel(const Run& run, const QString& factor);

// The factors a dataset's runs carry as `factor_<name>` metadata (a plan's runs), in the order
// first met; empty for runs recorded without a plan.
QStringList datasetFactors(const Dataset& dataset);
// Settings the runs were made at, as factors where they differ between runs (two levels or
// more): tissue, tip, motion, velocity, frequency, amplitude. What By factor offers a session
// made without a plan, whose runs record no factor_… of their own.
QStringList datasetSettingFactors(const Dataset& dataset);

// One entry per run with at least one fitted quantity, in the dataset's order. Warnings for
// runs whose friction re-fit failed go to *warnings.
std::vector<RunFactorValues> runFactorValues(const Dataset& dataset, const SessionAnalysis& analysis, const QStringList& factors,
                                             const FactorAnalysisOptions& options = {}, QStringList* warnings = nullptr);

struct QuantityStats {
    double mean = 0.0;
    double stdDev = 0.0;  // sample standard deviation (n - 1), 0 for a single run
    std::size_t n = 0;
};

struct FactorCell {
    QStringList levels;  // one per factor, in the order asked for
    std::size_t runs = 0;
    std::map<QString, QuantityStats> stats;  // only quantities with n > 0
};

// Groups by the combination of levels; cells sorted level by level (numerically when the
// levels are numbers).
std::vector<FactorCell> groupByFactors(const std::vector<RunFactorValues>& runs, const QStringList& factors);

// Long layout: one row per cell and quantity: factors..., quantity, unit, mean, std, n.
FitTable factorTable(const std::vector<FactorCell>& cells, const QStringList& factors);

// Table 5 layout: per level of `frequencyFactor` a mean and a std row, then overall (all
// friction runs): group, statistic, freq_Hz, n, m_est_kg, Cp, bp, Cn, bn, Dp, Dn.
FitTable frictionFrequencyTable(const std::vector<RunFactorValues>& runs, const QString& frequencyFactor = QStringLiteral("frequency_hz"));

// A table as aligned plain text for a terminal (numbers with the column's decimals, empty
// cells for NaN).
QString fitTableText(const FitTable& table);

}  // namespace nb
