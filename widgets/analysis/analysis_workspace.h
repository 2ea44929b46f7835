#pragma once
// The analysis workspace: a session's runs fitted to the thesis's models, in three views.
// Stiffness (Fig. 23, Table 2), Friction (Figs. 34b/35, Tables 4/5), Validation (Fig. 38),
// and By factor: any fitted quantity against a factor of a plan's runs (issue 16).
// Runs are chosen in the list on the left; results follow label edits (labels files are
// watched) and every figure and table can be saved (PNG/SVG/PDF, CSV/LaTeX).

#include "core/export/dataset.h"
#include "core/export/factor_analysis.h"
#include "core/export/session_analysis.h"

#include <QFileSystemWatcher>
#include <QTimer>
#include <QWidget>

#include <map>
#include <optional>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QLabel;
class QListWidget;
class QSettings;
class QStandardItemModel;
class QTabWidget;
class QTableView;

namespace nb {

class AnalysisWorkspace : public QWidget {
    Q_OBJECT
public:
    explicit AnalysisWorkspace(QWidget* parent = nullptr);

    // Loads the session folder and analyses every run. On failure shows the reason and
    // returns false (the previous session stays). The same session opened again (a run
    // recorded, a plan run made again) keeps the runs the operator unticked.
    bool openSession(const QString& dir);
    // An in-memory session (runs not from files: nothing to watch).
    void setDataset(Dataset dataset);
    // Only these runs take part (by name); an empty list means all.
    void setRuns(const QStringList& runNames);
    QStringList selectedRuns() const;

    // Runs cut short (force limit, emergency stop, fault...) or without tissue contact take
    // part only when this is on (the switch under the run list); off by default.
    void setIncludeJudgedOut(bool on);
    bool includeJudgedOut() const;
    QString statusText() const;
    // The operator's choices, kept across restarts: the page, the judged-out switch, By
    // factor's factor and quantity, and the runs unticked in the session they were made in.
    // restoreChoices takes them for the next openSession, which applies them as it opens.
    void saveChoices(QSettings& settings) const;
    void restoreChoices(const QSettings& settings);
    // Every table (CSV and LaTeX) / figure (PNG and PDF) of the analysis into `dir`; returns
    // the files written. Throws ExportError.
    QStringList saveAllTables(const QString& dir);
    QStringList saveAllFigures(const QString& dir);
    // The files those would write, written or not: what an export asks about replacing.
    QStringList allTablesPaths(const QString& dir) const;
    QStringList allFiguresPaths(const QString& dir) const;

    const SessionAnalysis& analysis() const { return analysis_; }
    const Dataset& dataset() const { return dataset_; }

    QTabWidget* tabs() const { return tabs_; }
    QCustomPlot* stiffnessPlot() const { return stiffnessPlot_; }
    QCustomPlot* frictionVelocityPlot() const { return frictionPlot_; }
    QCustomPlot* phasesPlot() const { return phasesPlot_; }
    QCustomPlot* validationPlot() const { return validationPlot_; }
    QStandardItemModel* stiffnessRunsModel() const { return stiffnessRunsModel_; }
    QStandardItemModel* stiffnessPooledModel() const { return stiffnessPooledModel_; }
    QStandardItemModel* frictionSummaryModel() const { return frictionSummaryModel_; }
    QStandardItemModel* frictionRunsModel() const { return frictionRunsModel_; }
    QStandardItemModel* validationModel() const { return validationModel_; }
    // By factor: the factors the runs carry, the quantity shown, and its table per level.
    QComboBox* factorChooser() const { return factorChoice_; }
    QComboBox* quantityChooser() const { return quantityChoice_; }
    QCustomPlot* factorPlot() const { return factorPlot_; }
    QStandardItemModel* factorModel() const { return factorModel_; }
    // Each fitted quantity per level of `factor` (mean, std, n), as `plan report --by` prints it.
    FitTable factorTableFor(const QString& factor) const;

public slots:
    // Re-reads every run's labels file and recomputes.
    void reloadLabels();

signals:
    void analysisUpdated();
    // The operator changed a choice saveChoices keeps.
    void choicesChanged();

private:
    std::vector<std::pair<QString, FitTable>> allTables() const;
    std::vector<std::pair<QString, QCustomPlot*>> allFigures() const;
    struct Choices {
        QString session;
        QStringList unticked;
        QString factor, quantity;
        int page = -1;
        bool includeJudgedOut = false;
    };
    // One item per dataset run, ticked unless in `unticked` (no analysis).
    void fillRunList(const QStringList& unticked);
    QStringList untickedRuns() const;
    void applyViewChoices(const Choices& c);
    std::optional<Choices> restored_;  // for the next openSession
    void recompute();
    void refreshViews();
    void showStiffness();
    void showFriction();
    void showValidation();
    void showByFactor();
    QWidget* buildFactorPage();
    void watchLabels();
    void exportCurrentFigure();
    void exportCurrentTables();

    Dataset dataset_;
    QString dir_;
    SessionAnalysis analysis_;
    QFileSystemWatcher watcher_;
    QTimer reloadTimer_;

    QListWidget* runList_ = nullptr;
    std::map<QString, QString> discardedByPlan_;  // run name -> why the plan made it again
    QLabel* status_ = nullptr;
    QCheckBox* includeJudgedOut_ = nullptr;
    void markJudgedRuns();
    QTabWidget* tabs_ = nullptr;
    QComboBox* stiffnessGroup_ = nullptr;
    QComboBox* frictionRun_ = nullptr;
    QComboBox* validationRun_ = nullptr;
    QCustomPlot* stiffnessPlot_ = nullptr;
    QCustomPlot* frictionPlot_ = nullptr;
    QCustomPlot* phasesPlot_ = nullptr;
    QCustomPlot* validationPlot_ = nullptr;
    QStandardItemModel* stiffnessRunsModel_ = nullptr;
    QStandardItemModel* stiffnessPooledModel_ = nullptr;
    QStandardItemModel* frictionRunsModel_ = nullptr;
    QStandardItemModel* frictionSummaryModel_ = nullptr;
    QStandardItemModel* validationModel_ = nullptr;
    QComboBox* factorChoice_ = nullptr;
    QComboBox* quantityChoice_ = nullptr;
    QCustomPlot* factorPlot_ = nullptr;
    QStandardItemModel* factorModel_ = nullptr;
    std::vector<RunFactorValues> factorValues_;  // every analysed run's quantities and levels
    bool updatingList_ = false;
};

// Shows a fit table in a model: headers "title [unit]", numbers right-aligned, rows whose
// last text says so (outliers, failed fits) tinted.
void fillTableModel(QStandardItemModel* model, const FitTable& table);

}  // namespace nb
