#pragma once
// Session ▸ Export session…: the session's runs as CSV (with JSON sidecars and label
// interval tables), one HDF5 file, ELAN documents, and the analysis figures and tables, into
// one folder. The datasets are written by the same functions as `needlebench export`
// (core/export), in the background, with progress and Cancel; a cancelled export leaves no
// half-written file behind.

#include <QDialog>
#include <QFutureWatcher>
#include <QPointer>
#include <QProgressBar>
#include <QStringList>
#include <atomic>
#include <memory>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace nb {

class AnalysisWorkspace;
struct FilesInTheWay;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `analysis` (may be null) gives the figures and tables.
    ExportDialog(const QString& sessionDir, AnalysisWorkspace* analysis, QWidget* parent = nullptr);
    ~ExportDialog() override;

    struct Choice {
        bool csv = true, hdf5 = true, eaf = false, figures = false, tables = true;
    };
    void setChoice(const Choice& c);
    Choice choice() const;
    void setTargetDir(const QString& dir);
    QString targetDir() const;
    QString hdf5Path() const;  // where the HDF5 file goes: TARGET/SESSION.h5
    QString hdf5PathIn(const QString& target) const;
    // Starts the export (as the Export button does); finished() is emitted at the end. When
    // files are in the way, it first asks (a question named "replaceExport", not modal: the
    // window's emergency stop stays in reach) and exports only when told to replace them.
    void start();
    void cancel();
    bool isRunning() const { return watcher_.isRunning(); }
    QStringList written() const { return written_; }
    QString resultText() const;

signals:
    void exportFinished(bool ok);

private:
    struct Outcome {
        bool ok = true;
        bool cancelled = false;
        QStringList written, warnings;
        QStringList made;  // folders made for the export, taken away if left empty
        QString error;
        bool earlierRestored = false;  // failed or cancelled over an earlier export, which is back as it was
    };
    // The files an export of `c` into `target` writes (those of an earlier one are replaced).
    QStringList exportPaths(const Choice& c, const QString& target) const;
    QStringList analysisPaths(const Choice& c, const QString& target) const;
    void begin(const Choice& c, const QString& target);
    void askToReplace(const FilesInTheWay& way, const Choice& c, const QString& target);
    Outcome run(const Choice& c, const QString& target, QPointer<QProgressBar> bar);
    Outcome write(const Choice& c, const QString& target, QPointer<QProgressBar> bar);
    void finish();
    void setStatus(const QString& text);

    QString sessionDir_;
    AnalysisWorkspace* analysis_;
    QLineEdit* target_;
    QCheckBox *csv_, *hdf5_, *eaf_, *figures_, *tables_;
    QProgressBar* progress_;
    QLabel* status_;
    QDialogButtonBox* buttons_;
    QPushButton* exportButton_;
    QPushButton* cancelButton_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    QFutureWatcher<Outcome> watcher_;
    QStringList written_;
    QStringList made_;  // the target folders start() made
    QString result_;
};

}  // namespace nb
