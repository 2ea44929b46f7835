#pragma once
// The session's runs as a table (Qt model/view): number, file, motion, state (complete,
// stopped by limit, fault, recovered, ...), calibration, time. Above it the specimen and
// protocol of the session.

#include "core/session.h"

#include <QAbstractTableModel>
#include <QWidget>
#include <vector>

class QLabel;
class QTableView;

namespace nb {

class RunListModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, File, Motion, State, Calibration, Modified, ColumnCount };
    using QAbstractTableModel::QAbstractTableModel;

    void setRuns(std::vector<RunEntry> runs);
    // The run being recorded now: shown as "recording", not as interrupted.
    void setBusyPath(const QString& path);
    const std::vector<RunEntry>& runs() const { return runs_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    std::vector<RunEntry> runs_;
    QString busy_;
};

class SessionView : public QWidget {
    Q_OBJECT
public:
    explicit SessionView(QWidget* parent = nullptr);
    // Shows this session (re-reads its runs); nullptr shows "no session".
    void setSession(const Session* session);
    void refresh();
    void setBusyPath(const QString& path);
    // Selects (and scrolls to) the run at `path`, the one in review, now and after each refresh.
    void selectRun(const QString& path);
    RunListModel* model() const { return model_; }
    QTableView* view() const { return view_; }

signals:
    void runActivated(const QString& path);

private:
    const Session* session_ = nullptr;
    QLabel* header_ = nullptr;
    RunListModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    QString selected_;  // the run in review, selected again when the list is read again
};

}  // namespace nb
