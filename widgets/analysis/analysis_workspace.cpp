#include "analysis_workspace.h"

#include "widgets/modeless_dialogs.h"
#include "core/tr.h"

#include "analysis_plots.h"
#include "figure_export.h"

#include "core/export/dataset_loader.h"
#include "core/plan.h"
#include "core/plan_session.h"
#include "core/export/export_error.h"
#include "core/run_file.h"
#include "core/run_judgement.h"
#include "core/data_names.h"

#include <map>
#include <utility>

#include <QCheckBox>
#include <QComboBox>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSettings>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>
#include <qcustomplot.h>

namespace nb {

namespace {

QTableView* tableView(QStandardItemModel* model, QWidget* parent)
{
    auto* v = new QTableView(parent);
    v->setModel(model);
    v->setEditTriggers(QAbstractItemView::NoEditTriggers);
    v->verticalHeader()->hide();
    v->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    v->setAlternatingRowColors(true);
    return v;
}

QCustomPlot* newPlot(QWidget* parent)
{
    auto* p = new QCustomPlot(parent);
    p->setMinimumSize(240, 200);
    p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    return p;
}

// The legend under the plot, not over its data (the curves fill the corners of a fit plot).
void legendBelow(QCustomPlot* p, int columns = 2)
{
    QCPLegend* l = p->legend;
    if (!l || !l->visible())
        return;
    if (l->layout() == p->axisRect()->insetLayout()) {
        p->axisRect()->insetLayout()->take(l);
        p->axisRect()->insetLayout()->simplify();
        const int row = p->plotLayout()->rowCount();
        p->plotLayout()->addElement(row, 0, l);
        p->plotLayout()->setRowStretchFactor(row, 0.001);
        l->setMargins(QMargins(4, 2, 4, 2));
    }
    l->setWrap(columns);  // two across: long fit formulas keep their room
    l->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    p->replot();
}

}  // namespace

void fillTableModel(QStandardItemModel* model, const FitTable& t)
{
    model->clear();
    QStringList headers;
    for (const TableColumn& c : t.columns)
        headers << (c.unit.isEmpty() ? c.title : QStringLiteral("%1 [%2]").arg(c.title, QString(c.unit).replace(QLatin1String("^2"), QStringLiteral("²"))));
    // Numbers as the plots beside the table write them (0,0474 in German); the exported tables
    // keep their own format.
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    model->setHorizontalHeaderLabels(headers);
    for (const auto& row : t.rows) {
        QList<QStandardItem*> items;
        bool flagged = false;
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            auto* item = new QStandardItem;
            if (c < row.size()) {
                if (const auto* s = std::get_if<QString>(&row[c])) {
                    // A tip or where D came from is data ("beveled", "phase a" in the exported table),
                    // said in the operator's language here.
                    const QString& key = t.columns[c].key;
                    item->setText(key == QLatin1String("tissue") && s->isEmpty() ? nb::TrViews::tr("no tissue given")
                                                                                  : tableCellDisplayName(key, *s));
                    // Outliers and failed fits stand out; other text columns are just text.
                    if ((t.columns[c].key == QLatin1String("outlier") && !s->isEmpty()) ||
                        *s == QLatin1String("not fitted"))
                        flagged = true;
                } else {
                    const double v = std::get<double>(row[c]);
                    item->setText(std::isnan(v) ? QStringLiteral("–") : locale.toString(v, 'f', std::max(0, t.columns[c].decimals)));
                    item->setData(v, Qt::UserRole);
                    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                }
            }
            items << item;
        }
        if (flagged)
            for (QStandardItem* i : items)
                i->setBackground(QColor(255, 220, 220));
        model->appendRow(items);
    }
}

AnalysisWorkspace::AnalysisWorkspace(QWidget* parent) : QWidget(parent)
{
    auto* split = new QSplitter(this);
    auto* left = new QWidget(split);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(new QLabel(tr("Runs in the analysis:"), left));
    runList_ = new QListWidget(left);
    leftLayout->addWidget(runList_, 1);
    includeJudgedOut_ = new QCheckBox(tr("Include runs cut short\nor without contact"), left);
    includeJudgedOut_->setObjectName(QStringLiteral("includeJudgedOut"));
    includeJudgedOut_->setToolTip(tr("Runs ended by the force limit, an emergency stop or a fault end where the protection "
                                     "acted, not where the tissue gave way; runs that never touched tissue have nothing to fit. "
                                     "They are left out unless this is on."));
    leftLayout->addWidget(includeJudgedOut_);
    auto* reload = new QPushButton(tr("Reload labels"), left);
    leftLayout->addWidget(reload);
    status_ = new QLabel(left);
    status_->setObjectName(QStringLiteral("analysisStatus"));
    status_->setWordWrap(true);
    status_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Long lists of left-out runs and outlier reasons scroll instead of growing the window.
    auto* statusScroll = new QScrollArea(left);
    statusScroll->setWidget(status_);
    statusScroll->setWidgetResizable(true);
    statusScroll->setFrameShape(QFrame::NoFrame);
    statusScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    leftLayout->addWidget(statusScroll, 1);
    // The switch's two lines never clip (German is wider than the 160 px the list needs).
    left->setMinimumWidth(std::max(160, includeJudgedOut_->sizeHint().width()));
    split->addWidget(left);

    tabs_ = new QTabWidget(split);
    stiffnessRunsModel_ = new QStandardItemModel(this);
    stiffnessPooledModel_ = new QStandardItemModel(this);
    frictionRunsModel_ = new QStandardItemModel(this);
    frictionSummaryModel_ = new QStandardItemModel(this);
    validationModel_ = new QStandardItemModel(this);

    std::vector<QTabWidget*> tableTabs;
    auto addTab = [&](const QString& title, QComboBox*& chooser, const QString& chooserLabel,
                      std::initializer_list<QCustomPlot**> plots, std::initializer_list<QStandardItemModel*> models) {
        auto* page = new QWidget(tabs_);
        auto* v = new QVBoxLayout(page);
        auto* bar = new QHBoxLayout;
        bar->addWidget(new QLabel(chooserLabel, page));
        chooser = new QComboBox(page);
        // Long run names elide in the box instead of widening the window.
        chooser->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        chooser->setMinimumContentsLength(12);
        bar->addWidget(chooser);
        bar->addStretch(1);
        auto* fig = new QPushButton(tr("Save figure…"), page);
        auto* tab = new QPushButton(tr("Save tables…"), page);
        bar->addWidget(fig);
        bar->addWidget(tab);
        v->addLayout(bar);
        auto* body = new QSplitter(Qt::Vertical, page);
        auto* plotRow = new QSplitter(Qt::Horizontal, body);
        for (QCustomPlot** p : plots) {
            *p = newPlot(plotRow);
            plotRow->addWidget(*p);
        }
        body->addWidget(plotRow);
        // Two tables share one place as tabs: on a laptop the figure keeps its height, and each
        // table shows more than a row.
        if (models.size() > 1) {
            auto* tables = new QTabWidget(body);
            tables->setDocumentMode(true);
            tables->setObjectName(QStringLiteral("analysisTables"));
            for (QStandardItemModel* m : models)
                tables->addTab(tableView(m, tables), QString());
            body->addWidget(tables);
            tableTabs.push_back(tables);
        } else {
            for (QStandardItemModel* m : models)
                body->addWidget(tableView(m, body));
        }
        // The figure first: two thirds of the height, whatever the window's size, and the
        // tables (which scroll) the rest. Without the tables' share every change of the
        // window's height went to the figure, down to its minimum on a laptop.
        body->setStretchFactor(0, 2);
        body->setStretchFactor(1, 1);
        body->setSizes({400, 200});
        v->addWidget(body, 1);
        tabs_->addTab(page, title);
        connect(fig, &QPushButton::clicked, this, &AnalysisWorkspace::exportCurrentFigure);
        connect(tab, &QPushButton::clicked, this, &AnalysisWorkspace::exportCurrentTables);
    };
    addTab(tr("Stiffness"), stiffnessGroup_, tr("Tissue:"), {&stiffnessPlot_}, {stiffnessRunsModel_, stiffnessPooledModel_});
    addTab(tr("Friction"), frictionRun_, tr("Run:"), {&frictionPlot_, &phasesPlot_}, {frictionRunsModel_, frictionSummaryModel_});
    addTab(tr("Validation"), validationRun_, tr("Run:"), {&validationPlot_}, {validationModel_});
    tableTabs[0]->setTabText(0, tr("Per run"));
    tableTabs[0]->setTabText(1, tr("Pooled per tissue"));
    tableTabs[1]->setTabText(0, tr("Per run"));
    tableTabs[1]->setTabText(1, tr("Summary"));
    tabs_->addTab(buildFactorPage(), tr("By factor"));
    split->addWidget(tabs_);
    split->setStretchFactor(1, 1);
    split->setSizes({200, 900});

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(split);

    connect(stiffnessGroup_, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::showStiffness);
    connect(frictionRun_, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::showFriction);
    connect(validationRun_, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::showValidation);
    connect(factorChoice_, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::showByFactor);
    connect(quantityChoice_, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::showByFactor);
    connect(runList_, &QListWidget::itemChanged, this, [this] {
        if (updatingList_)
            return;
        recompute();
        emit choicesChanged();
    });
    for (QComboBox* box : {factorChoice_, quantityChoice_})
        connect(box, &QComboBox::currentIndexChanged, this, &AnalysisWorkspace::choicesChanged);
    connect(tabs_, &QTabWidget::currentChanged, this, &AnalysisWorkspace::choicesChanged);
    connect(includeJudgedOut_, &QCheckBox::toggled, this, &AnalysisWorkspace::choicesChanged);
    connect(reload, &QPushButton::clicked, this, &AnalysisWorkspace::reloadLabels);
    connect(includeJudgedOut_, &QCheckBox::toggled, this, &AnalysisWorkspace::recompute);
    // Editors save labels in bursts (temporary + rename): settle before re-reading.
    reloadTimer_.setSingleShot(true);
    reloadTimer_.setInterval(250);
    connect(&reloadTimer_, &QTimer::timeout, this, &AnalysisWorkspace::reloadLabels);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, &reloadTimer_, qOverload<>(&QTimer::start));
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, &reloadTimer_, qOverload<>(&QTimer::start));
}

namespace {

// The runs a session's plan made again (Redo, with a reason), by run name: not its results, so
// they start unticked, saying why, as `plan report` leaves them out. They are fitted with the rest.
std::map<QString, QString> runsMadeAgain(const QString& dir)
{
    std::map<QString, QString> out;
    const QString planPath = QDir(dir).filePath(planFileName());
    if (!QFileInfo::exists(planPath))
        return out;
    try {
        for (const PlannedRun& r : readPlanFile(planPath).runs)
            for (const PlanAttempt& a : r.attempts)
                if (!a.discarded.isEmpty())
                    out[QFileInfo(a.runFile).completeBaseName()] = a.discarded;
    } catch (const PlanError&) {
        return {};  // the plan dock says what is wrong with it
    }
    return out;
}

}  // namespace

bool AnalysisWorkspace::openSession(const QString& dir)
{
    try {
        LoadedDataset loaded = loadDataset(dir);
        // What stays unticked: reading the same session again (a run recorded, one made again)
        // keeps the operator's choice, which stayed only until then; another session takes the
        // choices restored for it. All before the one analysis the opening costs.
        const std::optional<Choices> restored = std::exchange(restored_, std::nullopt);
        QStringList unticked;
        if (dir == dir_)
            unticked = untickedRuns();
        else if (restored && restored->session == dir)
            unticked = restored->unticked;
        if (restored) {
            const QSignalBlocker block(includeJudgedOut_);  // analysed below
            includeJudgedOut_->setChecked(restored->includeJudgedOut);
        }
        dir_ = dir;
        dataset_ = std::move(loaded.dataset);
        discardedByPlan_ = runsMadeAgain(dir);
        for (const auto& [name, why] : discardedByPlan_)
            unticked << name;
        fillRunList(unticked);
        recompute();
        if (restored)
            applyViewChoices(*restored);
        if (!loaded.warnings.isEmpty())
            status_->setText(status_->text() + QLatin1Char('\n') + loaded.warnings.join(QLatin1Char('\n')));
        watchLabels();
        return true;
    } catch (const ExportError& e) {
        status_->setText(e.message());
        return false;
    }
}

void AnalysisWorkspace::fillRunList(const QStringList& unticked)
{
    updatingList_ = true;
    runList_->clear();
    for (const DatasetRun& r : dataset_.runs) {
        auto* item = new QListWidgetItem(r.name, runList_);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(unticked.contains(r.name) ? Qt::Unchecked : Qt::Checked);
    }
    updatingList_ = false;
}

void AnalysisWorkspace::setDataset(Dataset dataset)
{
    dataset_ = std::move(dataset);
    discardedByPlan_.clear();
    fillRunList({});
    recompute();
}

void AnalysisWorkspace::setRuns(const QStringList& names)
{
    updatingList_ = true;
    for (int i = 0; i < runList_->count(); ++i) {
        QListWidgetItem* item = runList_->item(i);
        item->setCheckState(names.isEmpty() || names.contains(item->text()) ? Qt::Checked : Qt::Unchecked);
    }
    updatingList_ = false;
    recompute();
}

QStringList AnalysisWorkspace::untickedRuns() const
{
    QStringList out;
    for (int i = 0; i < runList_->count(); ++i)
        if (runList_->item(i)->checkState() != Qt::Checked)
            out << runList_->item(i)->text();
    return out;
}

void AnalysisWorkspace::saveChoices(QSettings& settings) const
{
    settings.setValue(QStringLiteral("analysis/page"), tabs_->currentIndex());
    settings.setValue(QStringLiteral("analysis/include_judged_out"), includeJudgedOut_->isChecked());
    settings.setValue(QStringLiteral("analysis/factor"), factorChoice_->currentData().toString());
    settings.setValue(QStringLiteral("analysis/quantity"), quantityChoice_->currentData().toString());
    settings.setValue(QStringLiteral("analysis/session"), dir_);
    settings.setValue(QStringLiteral("analysis/unticked"), untickedRuns());
}

void AnalysisWorkspace::restoreChoices(const QSettings& settings)
{
    restored_ = Choices{settings.value(QStringLiteral("analysis/session")).toString(),
                        settings.value(QStringLiteral("analysis/unticked")).toStringList(),
                        settings.value(QStringLiteral("analysis/factor")).toString(),
                        settings.value(QStringLiteral("analysis/quantity")).toString(),
                        settings.value(QStringLiteral("analysis/page"), -1).toInt(),
                        settings.value(QStringLiteral("analysis/include_judged_out"), false).toBool()};
}

void AnalysisWorkspace::applyViewChoices(const Choices& c)
{
    auto choose = [](QComboBox* box, const QString& key) {
        if (const int i = box->findData(key); i >= 0)
            box->setCurrentIndex(i);
    };
    choose(factorChoice_, c.factor);
    choose(quantityChoice_, c.quantity);
    if (c.page >= 0 && c.page < tabs_->count())
        tabs_->setCurrentIndex(c.page);
}

QStringList AnalysisWorkspace::selectedRuns() const
{
    QStringList out;
    for (int i = 0; i < runList_->count(); ++i)
        if (runList_->item(i)->checkState() == Qt::Checked)
            out << runList_->item(i)->text();
    return out;
}

void AnalysisWorkspace::reloadLabels()
{
    QStringList problems;
    for (DatasetRun& r : dataset_.runs) {
        if (r.sourcePath.isEmpty())
            continue;
        const QString path = labelsPathFor(r.sourcePath);
        if (!QFileInfo::exists(path)) {
            r.labels.clear();
            continue;
        }
        try {
            LabelsRead read = readLabels(path);
            r.labels = std::move(read.labels);
            problems << read.problems();
        } catch (const RunFileError& e) {
            // A labels file caught mid-save or broken: keep the last good labels and say so.
            problems << e.message();
        }
    }
    watchLabels();
    recompute();
    if (!problems.isEmpty())
        status_->setText(status_->text() + QLatin1Char('\n') + problems.join(QLatin1Char('\n')));
}

void AnalysisWorkspace::watchLabels()
{
    if (!watcher_.files().isEmpty())
        watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty())
        watcher_.removePaths(watcher_.directories());
    if (!dir_.isEmpty())
        watcher_.addPath(dir_);
    for (const DatasetRun& r : dataset_.runs) {
        const QString path = r.sourcePath.isEmpty() ? QString() : labelsPathFor(r.sourcePath);
        if (!path.isEmpty() && QFileInfo::exists(path))
            watcher_.addPath(path);
    }
}

void AnalysisWorkspace::recompute()
{
    Dataset chosen;
    chosen.name = dataset_.name;
    chosen.metadata = dataset_.metadata;
    const QStringList names = selectedRuns();
    for (const DatasetRun& r : dataset_.runs)
        if (names.contains(r.name))
            chosen.runs.push_back(r);
    AnalysisOptions options;
    options.includeJudgedOut = includeJudgedOut_->isChecked();
    analysis_ = analyseDataset(chosen, options);
    QStringList lines{tr("%n run(s) analysed", nullptr, int(chosen.runs.size() - std::size_t(analysis_.leftOut.size())))};
    if (!analysis_.leftOut.isEmpty())
        lines << tr("Left out (switch above to include them):") << analysis_.leftOut;
    QStringList outliers;
    for (const StiffnessRunResult& r : analysis_.stiffness)
        if (r.outlier)
            outliers << tr("%1: %2").arg(r.run, r.outlierReason);
    if (!outliers.isEmpty())
        lines << tr("Outliers:") << outliers;
    // A run whose own C is off the line through the peak speeds (the tissue moving as the
    // needle slows) is named: its row in the table looks as good as the others.
    QStringList doubts;
    for (const FrictionRunResult& f : analysis_.friction)
        if (f.peakLineDeparture && f.peakLineDeparture->significant)
            doubts << tr("%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %); see Friction ▸ Summary")
                         .arg(f.run, QLocale().toString(f.peakLineDeparture->Cp_percent, 'f', 1),
                              QLocale().toString(f.peakLineDeparture->Cn_percent, 'f', 1));
    // Values a run does not determine are empty in its row; the reason is only here.
    for (const FrictionRunResult& f : analysis_.friction)
        if (f.ok() && !f.fit.notPhysical.isEmpty())
            doubts << tr("%1: %2").arg(f.run, f.fit.notPhysical.join(QStringLiteral("; ")));
    // Each list under its own heading: a run that was taken and could not be fitted is not one
    // the judgement left out, though it followed that list unheaded.
    if (!doubts.isEmpty())
        lines << tr("Fitted, with doubts:") << doubts;
    if (!analysis_.warnings.isEmpty())
        lines << tr("Not fitted:") << analysis_.warnings;
    status_->setText(lines.join(QLatin1Char('\n')));
    markJudgedRuns();
    refreshViews();
    // Open on what there is: friction runs only, the Friction page; insertions only, Stiffness.
    if (tabs_->currentIndex() == 0 && analysis_.stiffness.empty() && !analysis_.friction.empty())
        tabs_->setCurrentIndex(1);
    else if (tabs_->currentIndex() == 1 && analysis_.friction.empty() && !analysis_.stiffness.empty())
        tabs_->setCurrentIndex(0);
    emit analysisUpdated();
}

void AnalysisWorkspace::setIncludeJudgedOut(bool on) { includeJudgedOut_->setChecked(on); }
bool AnalysisWorkspace::includeJudgedOut() const { return includeJudgedOut_->isChecked(); }
QString AnalysisWorkspace::statusText() const { return status_->text(); }

void AnalysisWorkspace::markJudgedRuns()
{
    // The list says which runs the analysis leaves out and why, in the run's own row.
    const QSignalBlocker block(runList_);
    for (int i = 0; i < runList_->count(); ++i) {
        QListWidgetItem* item = runList_->item(i);
        const auto it = std::find_if(dataset_.runs.begin(), dataset_.runs.end(), [&](const DatasetRun& r) { return r.name == item->text(); });
        RunJudgement j = it == dataset_.runs.end() ? RunJudgement{} : judgeRun(it->run);
        if (const auto d = discardedByPlan_.find(item->text()); d != discardedByPlan_.end())
            j = {false, tr("made again in the plan: %1").arg(d->second)};
        item->setToolTip(j.usable ? QString() : tr("left out by default: %1").arg(j.reason));
        item->setForeground(j.usable ? palette().text() : QBrush(QColor(150, 150, 150)));
        QFont f = item->font();
        f.setItalic(!j.usable);
        item->setFont(f);
    }
}

std::vector<std::pair<QString, FitTable>> AnalysisWorkspace::allTables() const
{
    std::vector<std::pair<QString, FitTable>> all{{QStringLiteral("stiffness_runs"), stiffnessRunsTable(analysis_)},
                                                  {QStringLiteral("stiffness_pooled"), stiffnessPooledTable(analysis_)},
                                                  {QStringLiteral("friction_runs"), frictionRunsTable(analysis_)},
                                                  {QStringLiteral("friction_summary"), frictionSummaryTable(analysis_)},
                                                  {QStringLiteral("validation"), validationTable(analysis_)}};
    // A plan's runs: each quantity per level of each of their factors.
    for (const QString& factor : datasetFactors(dataset_))
        all.emplace_back(QStringLiteral("by_factor_") + factor, factorTableFor(factor));
    return all;
}

std::vector<std::pair<QString, QCustomPlot*>> AnalysisWorkspace::allFigures() const
{
    std::vector<std::pair<QString, QCustomPlot*>> all{{QStringLiteral("stiffness"), stiffnessPlot_},
                                                      {QStringLiteral("friction_velocity"), frictionPlot_},
                                                      {QStringLiteral("friction_phases"), phasesPlot_},
                                                      {QStringLiteral("validation"), validationPlot_}};
    if (!factorChoice_->currentData().toString().isEmpty())
        all.emplace_back(QStringLiteral("by_factor"), factorPlot_);
    return all;
}

namespace {

template <typename T>
QStringList pathsOf(const QString& dir, const std::vector<std::pair<QString, T>>& items, std::initializer_list<const char*> exts)
{
    QStringList paths;
    for (const auto& item : items)
        for (const char* ext : exts)
            paths << QDir(dir).filePath(item.first + QLatin1String(ext));
    return paths;
}

}  // namespace

QStringList AnalysisWorkspace::allTablesPaths(const QString& dir) const { return pathsOf(dir, allTables(), {".csv", ".tex"}); }
QStringList AnalysisWorkspace::allFiguresPaths(const QString& dir) const { return pathsOf(dir, allFigures(), {".png", ".pdf"}); }

QStringList AnalysisWorkspace::saveAllTables(const QString& dir)
{
    if (!QDir().mkpath(dir))
        throw ExportError(dir, tr("cannot create the folder"));
    QStringList written;
    for (const auto& [name, table] : allTables()) {
        const QString csv = QDir(dir).filePath(name + QStringLiteral(".csv")), tex = QDir(dir).filePath(name + QStringLiteral(".tex"));
        writeFitTableCsv(csv, table);
        written << csv;
        writeFitTableLatex(tex, table);
        written << tex;
    }
    return written;
}

QStringList AnalysisWorkspace::saveAllFigures(const QString& dir)
{
    if (!QDir().mkpath(dir))
        throw ExportError(dir, tr("cannot create the folder"));
    QStringList written;
    for (const auto& [name, plot] : allFigures())
        for (const char* ext : {".png", ".pdf"}) {
            const QString path = QDir(dir).filePath(name + QLatin1String(ext));
            saveFigure(plot, path);
            written << path;
        }
    return written;
}

void AnalysisWorkspace::refreshViews()
{
    fillTableModel(stiffnessRunsModel_, stiffnessRunsTable(analysis_));
    fillTableModel(stiffnessPooledModel_, stiffnessPooledTable(analysis_));
    fillTableModel(frictionRunsModel_, frictionRunsTable(analysis_));
    fillTableModel(frictionSummaryModel_, frictionSummaryTable(analysis_));
    fillTableModel(validationModel_, validationTable(analysis_));

    // Keep the user's choice in each view when it still exists.
    auto refill = [](QComboBox* box, const QStringList& items) {
        const QString keep = box->currentText();
        const QSignalBlocker block(box);
        box->clear();
        // The item's data is the name in the runs; runs that name no tissue are said so.
        for (const QString& item : items)
            box->addItem(item.isEmpty() ? nb::TrViews::tr("no tissue given") : item, item);
        const int i = box->findText(keep);
        box->setCurrentIndex(i >= 0 ? i : (items.isEmpty() ? -1 : 0));
    };
    QStringList groups, friction, validation;
    for (const auto& g : analysis_.stiffnessGroups)
        groups << g.group;
    for (const auto& f : analysis_.friction)
        friction << f.run;
    for (const auto& v : analysis_.validation)
        validation << v.run;
    refill(stiffnessGroup_, groups);
    refill(frictionRun_, friction);
    refill(validationRun_, validation);
    // By factor: the factors of every run in the session (so the choice survives unticking),
    // the quantities of the runs analysed.
    // A session made without a plan records no factors: the settings its runs differ in stand
    // in (it showed an empty plot titled "a1 by no factor").
    QStringList factors = datasetFactors(dataset_);
    if (factors.isEmpty())
        factors = datasetSettingFactors(dataset_);
    factorValues_ = runFactorValues(dataset_, analysis_, factors);
    {
        // The factor's key is the item's data (plans, tables and file names use it), its
        // name in the operator's language the text.
        const QString keep = factorChoice_->currentData().toString();
        const QSignalBlocker block(factorChoice_);
        factorChoice_->clear();
        for (const QString& f : factors)
            factorChoice_->addItem(factorDisplayName(f), f);
        const int i = factorChoice_->findData(keep);
        factorChoice_->setCurrentIndex(i >= 0 ? i : (factors.isEmpty() ? -1 : 0));
    }
    {
        const QString keep = quantityChoice_->currentData().toString();
        const QSignalBlocker block(quantityChoice_);
        quantityChoice_->clear();
        for (const FactorQuantity& q : factorQuantities())
            if (std::any_of(factorValues_.begin(), factorValues_.end(), [&](const RunFactorValues& r) { return r.values.count(q.key) > 0; }))
                quantityChoice_->addItem(q.unit.isEmpty() ? q.title : QStringLiteral("%1 [%2]").arg(q.title, q.unit), q.key);
        const int i = quantityChoice_->findData(keep);
        quantityChoice_->setCurrentIndex(i >= 0 ? i : (quantityChoice_->count() ? 0 : -1));
    }
    showStiffness();
    showFriction();
    showValidation();
    showByFactor();
}

QWidget* AnalysisWorkspace::buildFactorPage()
{
    auto* page = new QWidget(tabs_);
    page->setObjectName(QStringLiteral("analysisByFactor"));
    auto* v = new QVBoxLayout(page);
    auto* bar = new QHBoxLayout;
    factorChoice_ = new QComboBox(page);
    factorChoice_->setObjectName(QStringLiteral("analysisFactor"));
    factorChoice_->setToolTip(tr("The factors of a plan's runs (their factor_… metadata)"));
    quantityChoice_ = new QComboBox(page);
    quantityChoice_->setObjectName(QStringLiteral("analysisFactorQuantity"));
    // Long names elide in the boxes instead of widening the window (as the other tabs' choosers).
    for (QComboBox* box : {factorChoice_, quantityChoice_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(8);
    }
    bar->addWidget(new QLabel(tr("Quantity:"), page));
    bar->addWidget(quantityChoice_, 1);
    bar->addWidget(new QLabel(tr("against factor:"), page));
    bar->addWidget(factorChoice_, 1);
    v->addLayout(bar);
    // The saves on a row of their own: two choosers and two buttons side by side would make the
    // window wider than a 1366 px laptop in German.
    auto* saves = new QHBoxLayout;
    saves->addStretch(1);
    auto* fig = new QPushButton(tr("Save figure…"), page);
    auto* tab = new QPushButton(tr("Save tables…"), page);
    saves->addWidget(fig);
    saves->addWidget(tab);
    v->addLayout(saves);
    factorModel_ = new QStandardItemModel(this);
    auto* body = new QSplitter(Qt::Vertical, page);
    factorPlot_ = newPlot(body);
    body->addWidget(factorPlot_);
    body->addWidget(tableView(factorModel_, body));
    // As the other tabs: the figure two thirds of the height, the table the rest.
    body->setStretchFactor(0, 2);
    body->setStretchFactor(1, 1);
    body->setSizes({400, 200});
    v->addWidget(body, 1);
    connect(fig, &QPushButton::clicked, this, &AnalysisWorkspace::exportCurrentFigure);
    connect(tab, &QPushButton::clicked, this, &AnalysisWorkspace::exportCurrentTables);
    return page;
}

FitTable AnalysisWorkspace::factorTableFor(const QString& factor) const
{
    return factorTable(groupByFactors(factorValues_, {factor}), {factor});
}

void AnalysisWorkspace::showByFactor()
{
    const QString factor = factorChoice_->currentData().toString();
    const QString key = quantityChoice_->currentData().toString();
    const auto q = std::find_if(factorQuantities().begin(), factorQuantities().end(), [&](const FactorQuantity& x) { return x.key == key; });
    if (factor.isEmpty() || q == factorQuantities().end()) {
        factorModel_->clear();
        plotByFactor(factorPlot_, {}, {}, factor.isEmpty() ? tr("no factor") : factor,
                     q == factorQuantities().end() ? FactorQuantity{{}, tr("no fitted quantity"), {}} : *q);
        return;
    }
    const std::vector<FactorCell> cells = groupByFactors(factorValues_, {factor});
    // The table of the quantity shown: its rows of the long by-factor table.
    FitTable table = factorTable(cells, {factor});
    const auto quantityColumn = std::find_if(table.columns.begin(), table.columns.end(), [](const TableColumn& c) { return c.key == QLatin1String("quantity"); });
    const std::size_t qc = std::size_t(quantityColumn - table.columns.begin());
    table.rows.erase(std::remove_if(table.rows.begin(), table.rows.end(),
                                    [&](const std::vector<TableCell>& row) {
                                        const auto* text = qc < row.size() ? std::get_if<QString>(&row[qc]) : nullptr;
                                        return !text || *text != key;
                                    }),
                     table.rows.end());
    fillTableModel(factorModel_, table);
    plotByFactor(factorPlot_, factorValues_, cells, factor, *q);
    legendBelow(factorPlot_);
}

void AnalysisWorkspace::showStiffness()
{
    plotStiffness(stiffnessPlot_, analysis_, stiffnessGroup_->currentData().toString());
    legendBelow(stiffnessPlot_);
}

void AnalysisWorkspace::showFriction()
{
    const QString name = frictionRun_->currentText();
    const auto fit = std::find_if(analysis_.friction.begin(), analysis_.friction.end(),
                                  [&](const FrictionRunResult& f) { return f.run == name; });
    const auto run = std::find_if(dataset_.runs.begin(), dataset_.runs.end(), [&](const DatasetRun& r) { return r.name == name; });
    if (fit == analysis_.friction.end() || run == dataset_.runs.end()) {
        FrictionRunResult none;
        none.error = tr("no run");
        plotFrictionVelocity(frictionPlot_, DatasetRun{}, none);
        plotPhases(phasesPlot_, DatasetRun{});
        return;
    }
    plotFrictionVelocity(frictionPlot_, *run, *fit);
    legendBelow(frictionPlot_);
    plotPhases(phasesPlot_, *run);
    // In the window the phases plot is half as wide as a figure: its one-row legend ran past
    // the plot's edge and over the force.
    legendBelow(phasesPlot_);
}

void AnalysisWorkspace::showValidation()
{
    const QString name = validationRun_->currentText();
    for (const ValidationResult& v : analysis_.validation) {
        if (v.run == name) {
            plotValidation(validationPlot_, v);
            legendBelow(validationPlot_);
            return;
        }
    }
    plotValidation(validationPlot_, ValidationResult{{}, tr("no run"), {}, {}, 0.0});
}

void AnalysisWorkspace::exportCurrentFigure()
{
    const int tab = tabs_->currentIndex();
    std::vector<QCustomPlot*> plots = tab == 0   ? std::vector<QCustomPlot*>{stiffnessPlot_}
                                      : tab == 1 ? std::vector<QCustomPlot*>{frictionPlot_, phasesPlot_}
                                      : tab == 2 ? std::vector<QCustomPlot*>{validationPlot_}
                                                 : std::vector<QCustomPlot*>{factorPlot_};
    // Modeless: a run may be recording meanwhile (modeless_dialogs.h).
    // In the session's folder, named after what it shows.
    const QString name = tab == 0 ? QStringLiteral("stiffness")
                         : tab == 1 ? QStringLiteral("friction")
                         : tab == 2 ? QStringLiteral("validation")
                                    : QStringLiteral("by_factor_") + factorChoice_->currentData().toString();
    FileChoice choice{tr("Save figure"), dir_, tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"),
                      QFileDialog::AnyFile, QFileDialog::AcceptSave, name};
    chooseFileModeless(this, choice, [this, plots](const QString& path) {
        try {
            const QFileInfo fi(path);
            for (std::size_t i = 0; i < plots.size(); ++i) {
                const QString p = i == 0 ? path : fi.dir().filePath(QStringLiteral("%1_%2.%3").arg(fi.completeBaseName()).arg(i + 1).arg(fi.suffix()));
                saveFigure(plots[i], p);
            }
        } catch (const ExportError& e) {
            warnModeless(this, tr("Save figure"), e.message());
        }
    });
}

void AnalysisWorkspace::exportCurrentTables()
{
    const int tab = tabs_->currentIndex();
    std::vector<std::pair<QString, FitTable>> tables;
    if (tab == 0)
        tables = {{QStringLiteral("stiffness_runs"), stiffnessRunsTable(analysis_)}, {QStringLiteral("stiffness_pooled"), stiffnessPooledTable(analysis_)}};
    else if (tab == 1)
        tables = {{QStringLiteral("friction_runs"), frictionRunsTable(analysis_)}, {QStringLiteral("friction_summary"), frictionSummaryTable(analysis_)}};
    else if (tab == 2)
        tables = {{QStringLiteral("validation"), validationTable(analysis_)}};
    else
        tables = {{QStringLiteral("by_factor_") + factorChoice_->currentData().toString(), factorTableFor(factorChoice_->currentData().toString())}};
    const FileChoice choice = FileChoice::folder(tr("Save tables (CSV and LaTeX) into"), dir_);
    chooseFileModeless(this, choice, [this, tables](const QString& dir) {
        try {
            for (const auto& [name, table] : tables) {
                writeFitTableCsv(QDir(dir).filePath(name + QStringLiteral(".csv")), table);
                writeFitTableLatex(QDir(dir).filePath(name + QStringLiteral(".tex")), table);
            }
        } catch (const ExportError& e) {
            warnModeless(this, tr("Save tables"), e.message());
        }
    });
}

}  // namespace nb
