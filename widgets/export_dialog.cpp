#include "export_dialog.h"

#include "widgets/modeless_dialogs.h"

#include "widgets/analysis/analysis_workspace.h"

#include "core/export/dataset_loader.h"
#include "core/export/eaf_export.h"
#include "core/export/earlier_export.h"
#include "core/export/export_error.h"
#include "core/export/kept_export.h"
#include "core/export/label_intervals.h"
#include "core/export/made_folders.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_hdf5.h"
#include "core/run_video_link.h"
#include "video/frame_index_store.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QScreen>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <optional>

namespace nb {

namespace {

// The video an ELAN document links: the one attached in the window, else one named like the run.
QString videoOf(const DatasetRun& r)
{
    if (r.sourcePath.isEmpty())
        return {};
    if (const auto link = readRunVideoLink(r.sourcePath); link && QFileInfo::exists(link->video))
        return link->video;
    return videoBesideRun(r.sourcePath);
}

}  // namespace

ExportDialog::ExportDialog(const QString& sessionDir, AnalysisWorkspace* analysis, QWidget* parent)
    : QDialog(parent), sessionDir_(sessionDir), analysis_(analysis), cancel_(std::make_shared<std::atomic<bool>>(false))
{
    setObjectName(QStringLiteral("exportDialog"));
    setWindowTitle(tr("Export session"));
    target_ = new QLineEdit(QDir(sessionDir).filePath(QStringLiteral("export")), this);
    target_->setObjectName(QStringLiteral("exportTarget"));
    auto* browse = new QPushButton(tr("Choose…"), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        chooseFileModeless(this, FileChoice::folder(tr("Export into"), target_->text()),
                           [this](const QString& d) { target_->setText(d); });
    });
    auto* where = new QHBoxLayout;
    where->addWidget(target_, 1);
    where->addWidget(browse);

    csv_ = new QCheckBox(tr("CSV per run, with JSON sidecar and label intervals"), this);
    hdf5_ = new QCheckBox(tr("HDF5: the whole session in one file"), this);
    eaf_ = new QCheckBox(tr("ELAN documents (.eaf) linking force and video"), this);
    figures_ = new QCheckBox(tr("Analysis figures (PNG and PDF)"), this);
    tables_ = new QCheckBox(tr("Analysis tables (CSV and LaTeX)"), this);
    csv_->setObjectName(QStringLiteral("exportCsv"));
    hdf5_->setObjectName(QStringLiteral("exportHdf5"));
    eaf_->setObjectName(QStringLiteral("exportEaf"));
    figures_->setObjectName(QStringLiteral("exportFigures"));
    tables_->setObjectName(QStringLiteral("exportTables"));
    figures_->setEnabled(analysis_);
    tables_->setEnabled(analysis_);
    setChoice({});

    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1);
    progress_->setValue(0);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    buttons_ = new QDialogButtonBox(this);
    exportButton_ = buttons_->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    exportButton_->setObjectName(QStringLiteral("exportStart"));
    cancelButton_ = buttons_->addButton(QDialogButtonBox::Cancel);
    connect(exportButton_, &QPushButton::clicked, this, &ExportDialog::start);
    connect(cancelButton_, &QPushButton::clicked, this, [this] {
        if (isRunning())
            cancel();
        else
            reject();
    });

    auto* form = new QFormLayout;
    form->addRow(tr("Session"), new QLabel(QDir::toNativeSeparators(sessionDir), this));
    form->addRow(tr("Into folder"), where);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    for (QCheckBox* b : {csv_, hdf5_, eaf_, figures_, tables_})
        layout->addWidget(b);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(buttons_);
    connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, &ExportDialog::finish);
    resize(640, sizeHint().height());
}

ExportDialog::~ExportDialog()
{
    cancel_->store(true);
    watcher_.waitForFinished();
}

void ExportDialog::setChoice(const Choice& c)
{
    csv_->setChecked(c.csv);
    hdf5_->setChecked(c.hdf5);
    eaf_->setChecked(c.eaf);
    figures_->setChecked(c.figures && analysis_);
    tables_->setChecked(c.tables && analysis_);
}

ExportDialog::Choice ExportDialog::choice() const
{
    return {csv_->isChecked(), hdf5_->isChecked(), eaf_->isChecked(), figures_->isChecked(), tables_->isChecked()};
}

void ExportDialog::setTargetDir(const QString& dir) { target_->setText(dir); }
QString ExportDialog::targetDir() const { return target_->text().trimmed(); }
QString ExportDialog::hdf5Path() const
{
    return hdf5PathIn(targetDir());
}
QString ExportDialog::hdf5PathIn(const QString& target) const
{
    return QDir(target).filePath(QDir(sessionDir_).dirName() + QStringLiteral(".h5"));
}
QString ExportDialog::resultText() const { return status_->text(); }

QStringList ExportDialog::exportPaths(const Choice& c, const QString& target) const
{
    const QStringList names = runNamesIn(sessionDir_);
    QStringList paths;
    if (c.csv)
        paths << runExportPaths(QDir(target).filePath(QStringLiteral("csv")), names, false);
    if (c.eaf)
        paths << runExportPaths(QDir(target).filePath(QStringLiteral("eaf")), names, true);
    if (c.hdf5)
        paths << hdf5PathIn(target);
    return paths;
}

QStringList ExportDialog::analysisPaths(const Choice& c, const QString& target) const
{
    QStringList paths;
    const QString dir = QDir(target).filePath(QStringLiteral("analysis"));
    if (analysis_ && c.tables)
        paths << analysis_->allTablesPaths(dir);
    if (analysis_ && c.figures)
        paths << analysis_->allFiguresPaths(dir);
    return paths;
}

void ExportDialog::start()
{
    if (isRunning())
        return;
    const Choice c = choice();
    const QString target = targetDir();
    if (target.isEmpty()) {
        progress_->setValue(0);
        setStatus(tr("Choose a folder to export into."));
        return;
    }
    FilesInTheWay way = filesInTheWay(exportPaths(c, target));
    // The analysis's tables and figures, under their own names in the export's own folder, are
    // an earlier export's; the question counted the data files alone and replaced these unsaid.
    for (const QString& path : analysisPaths(c, target))
        if (QFileInfo::exists(path))
            way.earlierExport << path;
    if (!way.empty()) {
        askToReplace(way, c, target);
        return;
    }
    begin(c, target);
}

void ExportDialog::askToReplace(const FilesInTheWay& way, const Choice& c, const QString& target)
{
    const QDir dir(target);
    QStringList listed;
    for (const QString& f : way.other + way.earlierExport)
        listed << QDir::toNativeSeparators(dir.relativeFilePath(f));
    auto* question = new QMessageBox(QMessageBox::Warning, windowTitle(), {}, QMessageBox::Cancel, this);
    question->setObjectName(QStringLiteral("replaceExport"));
    question->setAttribute(Qt::WA_DeleteOnClose);
    question->setWindowModality(Qt::NonModal);
    if (way.other.isEmpty()) {
        question->setIcon(QMessageBox::Question);
        question->setText(tr("%1 already holds an earlier export: %n file(s) will be replaced.", nullptr, int(way.earlierExport.size()))
                              .arg(QDir::toNativeSeparators(target)));
    } else {
        question->setText(tr("%n file(s) in %1 are not an earlier export's (a recorded run, a table made by hand?) and "
                             "would be replaced and lost.", nullptr, int(way.other.size()))
                              .arg(QDir::toNativeSeparators(target)));
        question->setInformativeText(tr("Choose another folder unless you are sure."));
    }
    question->setDetailedText(listed.join(QLatin1Char('\n')));
    QPushButton* replace = question->addButton(tr("Replace"), QMessageBox::DestructiveRole);
    question->setDefaultButton(way.other.isEmpty() ? replace : qobject_cast<QPushButton*>(question->button(QMessageBox::Cancel)));
    exportButton_->setEnabled(false);
    connect(question, &QMessageBox::finished, this, [this, question, replace, c, target] {
        exportButton_->setEnabled(true);
        if (question->clickedButton() == replace)
            begin(c, target);
        else
            setStatus(tr("Not exported: the files in %1 are kept.").arg(QDir::toNativeSeparators(target)));
    });
    question->show();
}

void ExportDialog::begin(const Choice& c, const QString& target)
{
    bool made = false;
    made_ = makeFolders(target, &made);
    if (!made) {
        progress_->setValue(0);  // not the last export's full bar beside this failure
        setStatus(tr("%1: cannot create the folder").arg(QDir::toNativeSeparators(target)));
        emit exportFinished(false);
        return;
    }
    cancel_->store(false);
    written_.clear();
    exportButton_->setEnabled(false);
    for (QCheckBox* b : {csv_, hdf5_, eaf_, figures_, tables_})
        b->setEnabled(false);
    progress_->setRange(0, 0);
    setStatus(tr("Exporting…"));
    QPointer<QProgressBar> bar = progress_;  // made here: the worker only reads it
    watcher_.setFuture(QtConcurrent::run([this, c, target, bar] { return run(c, target, bar); }));
}

void ExportDialog::cancel()
{
    cancel_->store(true);
    setStatus(tr("Cancelling…"));
}

// In a worker thread. The earlier export's files stay whole until this one is (kept_export.h):
// a failure or a cancel half-way left half of each export.
ExportDialog::Outcome ExportDialog::run(const Choice& c, const QString& target, QPointer<QProgressBar> bar)
{
    std::optional<KeptExport> kept;
    try {
        if (const QStringList earlier = filesInTheWay(exportPaths(c, target)).earlierExport; !earlier.isEmpty())
            kept.emplace(earlier);
    } catch (const Error& e) {
        Outcome refused;
        refused.ok = false;
        refused.error = e.message();
        return refused;
    }
    Outcome out = write(c, target, bar);
    if (kept && out.ok && !out.cancelled) {
        kept->release();
    } else if (kept && kept->restore(out.written)) {
        out.earlierRestored = true;
        out.written.clear();
    }
    return out;
}

// Only the core exporters, no widgets.
ExportDialog::Outcome ExportDialog::write(const Choice& c, const QString& target, QPointer<QProgressBar> bar)
{
    Outcome out;
    const auto cancel = cancel_;
    const auto report = [bar](qint64 done, qint64 total) {
        QMetaObject::invokeMethod(bar, [bar, done, total] {
            if (bar) {
                bar->setRange(0, int(total));
                bar->setValue(int(done));
            }
        }, Qt::QueuedConnection);
    };
    try {
        LoadedDataset loaded = loadDataset(sessionDir_);
        addVideoFrameTimes(loaded.dataset, video::frameTimesOf, &loaded.warnings);
        out.warnings = loaded.warnings;
        const Dataset& d = loaded.dataset;
        if (d.runs.empty()) {
            out.ok = false;
            out.error = tr("%1: no runs to export").arg(QDir::toNativeSeparators(sessionDir_));
            return out;
        }
        const qint64 steps = qint64(d.runs.size()) * ((c.csv ? 1 : 0) + (c.eaf ? 1 : 0)) + (c.hdf5 ? qint64(d.runs.size()) : 0);
        qint64 done = 0;
        const QDir outDir(target);
        const auto perRun = [&](const QString& sub, bool eaf) {
            const QDir dir(outDir.filePath(sub));
            bool made = false;
            out.made << makeFolders(dir.path(), &made);  // one not made fails at its first file, saying why
            for (const DatasetRun& r : d.runs) {
                const QString csv = dir.filePath(r.name + QStringLiteral(".csv"));
                if (!writeRunCsv(csv, r, [&](qint64, qint64) { return !cancel->load(); }))
                    return false;
                out.written << csv << sidecarPath(csv);
                if (eaf) {
                    const QString path = dir.filePath(r.name + QStringLiteral(".eaf"));
                    writeEaf(path, r, {csv, videoOf(r), QString()});
                    out.written << path;
                } else {
                    const QString intervals = dir.filePath(r.name + QStringLiteral(".intervals.csv"));
                    writeLabelIntervalsCsv(intervals, labelIntervals(r.run, r.labels, frameClockFor(r.run)));
                    out.written << intervals;
                }
                report(++done, steps);
                if (cancel->load())
                    return false;
            }
            return true;
        };
        if (c.csv && !perRun(QStringLiteral("csv"), false)) {
            out.cancelled = true;
            return out;
        }
        if (c.hdf5) {
            const QString h5 = hdf5PathIn(target);
            const qint64 base = done;
            if (!writeSessionHdf5(h5, d, [&](qint64 k, qint64) {
                    report(base + k, steps);
                    return !cancel->load();
                })) {
                out.cancelled = true;
                return out;
            }
            done = base + qint64(d.runs.size());
            out.written << h5;
        }
        if (c.eaf && !perRun(QStringLiteral("eaf"), true)) {
            out.cancelled = true;
            return out;
        }
    } catch (const Error& e) {
        out.ok = false;
        out.error = e.message();
    }
    return out;
}

// The dialog grows to show the whole message: a result with the runs left out below it was cut
// off after its first lines at 1366x768, the warning unseen (the window does not grow for a
// wrapped label's height by itself).
void ExportDialog::setStatus(const QString& text)
{
    status_->setText(text);
    const QScreen* screen = this->screen();
    const int room = screen ? screen->availableGeometry().height() - 60 : 700;
    int need = layout()->totalHeightForWidth(width());
    if (need < 0)
        need = sizeHint().height();
    if (need > height())
        resize(width(), std::min(need, room));
}

void ExportDialog::finish()
{
    Outcome out = watcher_.result();
    const Choice c = choice();
    // Figures and tables are drawn by widgets: here, in the window's thread, after the data.
    if (out.ok && !out.cancelled && analysis_ && (c.figures || c.tables)) {
        try {
            const QString dir = QDir(targetDir()).filePath(QStringLiteral("analysis"));  // as analysisPaths
            if (c.tables)
                out.written << analysis_->saveAllTables(dir);
            if (c.figures)
                out.written << analysis_->saveAllFigures(dir);
        } catch (const Error& e) {
            out.ok = false;
            out.error = e.message();
        }
    }
    written_ = out.written;
    if (!out.ok || out.cancelled)
        removeEmptyFolders(made_ + out.made);
    progress_->setRange(0, 1);
    progress_->setValue(out.ok && !out.cancelled ? 1 : 0);
    QString text;
    if (out.cancelled && out.earlierRestored)
        text = tr("Cancelled: the earlier export in %1 is as it was.").arg(QDir::toNativeSeparators(targetDir()));
    else if (out.cancelled)
        text = tr("Cancelled: the files finished before (%1) are kept; none is half written.").arg(out.written.size());
    else if (!out.ok && out.earlierRestored)
        text = tr("Export failed: %1. The earlier export in %2 is as it was.").arg(out.error, QDir::toNativeSeparators(targetDir()));
    else if (!out.ok)
        text = tr("Export failed: %1").arg(out.error);
    else
        text = tr("Exported %n file(s) into %1", nullptr, int(out.written.size())).arg(QDir::toNativeSeparators(targetDir()));
    if (!out.warnings.isEmpty())
        text += QLatin1Char('\n') + out.warnings.join(QLatin1Char('\n'));
    setStatus(text);
    exportButton_->setEnabled(true);
    for (QCheckBox* b : {csv_, hdf5_, eaf_})
        b->setEnabled(true);
    figures_->setEnabled(analysis_);
    tables_->setEnabled(analysis_);
    cancelButton_->setText(tr("Close"));
    emit exportFinished(out.ok && !out.cancelled);
}

}  // namespace nb
