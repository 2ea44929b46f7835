#pragma once
// Every model fitted over a session's runs, as the analysis views and the demo show them:
// stiffness per run and pooled per tissue (Table 2), friction per run, per frequency and
// overall (Tables 4/5), and the summed model against each insertion (Fig. 38).
// Labels refine the automatic results: `contact`/`puncture` points move the detected events,
// phase intervals (a, b1, b2, c) choose the friction samples.

#include "dataset.h"
#include "fit_table.h"

#include "core/events.h"
#include "core/friction_fit.h"
#include "core/friction_peak_line.h"
#include "core/insertion_model.h"
#include "core/stiffness_fit.h"

#include <optional>

namespace nb {

enum class RunKind { Insertion, Sinusoid, Other };

// Sinusoidal (friction) runs by `motion: sine` or `protocol: friction`; linear insertions by
// `motion: linear` or a stiffness/internal/prostate protocol.
RunKind runKind(const Run& run);

struct StiffnessRunResult {
    QString run;
    QString group;  // tissue (e.g. liver1); "" when the run does not say
    QString tip;
    QString error;  // why no fit (detection or fit failed); empty when fitted
    InsertionEvents events;
    StiffnessSegment segment;
    StiffnessFit fit;
    bool outlier = false;  // far from the group's other runs (robust, median-based)
    QString outlierReason; // which value, how far, by which rule (core/run_judgement.h)
    bool ok() const { return error.isEmpty(); }
};

struct StiffnessGroupResult {
    QString group;
    QString tip;
    std::vector<std::size_t> runs;  // indices into SessionAnalysis::stiffness (fitted ones)
    StiffnessSummary summary;
    double meanPunctureDepth_mm = 0.0;
    double meanPunctureForce_N = 0.0;
};

struct FrictionRunResult {
    QString run;
    QString error;
    FrictionFit fit;
    QStringList phases;  // per sample, as used for the fit (empty when the velocity band decided)
    QString tissue;      // what the run is grouped by
    // Against its tissue's line through the peak speeds, when there is one.
    std::optional<LineDeparture> peakLineDeparture;
    bool ok() const { return error.isEmpty(); }
};

struct ValidationResult {
    QString run;
    QString error;
    Run recorded;   // zeroed force
    Run simulated;  // the summed model along the recorded trajectory
    double rms_N = 0.0;
    bool ok() const { return error.isEmpty(); }
};

struct SessionAnalysis {
    std::vector<StiffnessRunResult> stiffness;
    std::vector<StiffnessGroupResult> stiffnessGroups;
    std::vector<FrictionRunResult> friction;
    std::vector<FrictionGroup> frictionGroups;
    std::optional<FrictionGroup> frictionOverall;
    // Per tissue, C and b through the runs' peak speeds (core/friction_peak_line.h), per unit
    // length; only for tissues whose runs span frequencies enough to make the line.
    struct FrictionPeakLine {
        QString tissue;
        PeakSpeedLine line;
    };
    std::vector<FrictionPeakLine> frictionPeakLines;
    std::vector<ValidationResult> validation;
    QStringList warnings;  // one line per run that could not be fitted, naming it
    QStringList leftOut;   // "run: reason" per run judged out (core/run_judgement.h)
};

struct AnalysisOptions {
    bool includeJudgedOut = false;  // take runs cut short or without contact as well
};

SessionAnalysis analyseDataset(const Dataset& dataset, const AnalysisOptions& options = {});

// Tables for CSV/LaTeX export and the views.
FitTable stiffnessRunsTable(const SessionAnalysis& a);
FitTable stiffnessPooledTable(const SessionAnalysis& a);  // Table 2 layout
FitTable frictionRunsTable(const SessionAnalysis& a);
FitTable frictionSummaryTable(const SessionAnalysis& a);  // Tables 4/5 layout
FitTable validationTable(const SessionAnalysis& a);

}  // namespace nb
