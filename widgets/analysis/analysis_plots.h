#pragma once
// Fill a QCustomPlot with one of the analysis figures. Shared by the analysis workspace and
// the headless demo, so the figures written to files are the ones on screen.

#include "core/export/dataset.h"
#include "core/export/factor_analysis.h"
#include "core/export/session_analysis.h"

class QCustomPlot;

namespace nb {

// Thesis Fig. 23: pre-puncture force against depth past contact for the runs of `group`
// (outliers in red), each run's fit (thin) and the pooled fit (thick).
void plotStiffness(QCustomPlot* plot, const SessionAnalysis& a, const QString& group);

// Thesis Fig. 34b: friction force (mass removed) against velocity, with the fitted Karnopp model.
void plotFrictionVelocity(QCustomPlot* plot, const DatasetRun& run, const FrictionRunResult& fit);

// Thesis Fig. 35: force against time with the labelled phases shaded (a, b1, b2, c).
void plotPhases(QCustomPlot* plot, const DatasetRun& run);

// Thesis Fig. 38: the summed model against a recorded insertion, rms error in the title.
void plotValidation(QCustomPlot* plot, const ValidationResult& v);

// A fitted quantity against one factor of a plan's runs: each run (grey), and per level the
// mean ± standard deviation with n under the level (levels as groupByFactors sorts them).
void plotByFactor(QCustomPlot* plot, const std::vector<RunFactorValues>& runs, const std::vector<FactorCell>& cells,
                  const QString& factor, const FactorQuantity& quantity);

}  // namespace nb
