#include "session_view.h"

#include "core/data_names.h"

#include <QBrush>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableView>
#include <QVBoxLayout>

namespace nb {

void RunListModel::setRuns(std::vector<RunEntry> runs)
{
    beginResetModel();
    runs_ = std::move(runs);
    endResetModel();
}

void RunListModel::setBusyPath(const QString& path)
{
    busy_ = path;
    if (!runs_.empty())
        emit dataChanged(index(0, State), index(int(runs_.size()) - 1, State));
}

int RunListModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : int(runs_.size()); }
int RunListModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant RunListModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= int(runs_.size()))
        return {};
    const RunEntry& r = runs_[std::size_t(index.row())];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case Number: return r.number;
        case File: return r.fileName;
        case Motion: return motionDisplayName(r.motion);
        case State:
            return (!busy_.isEmpty() && r.path == busy_) ? tr("recording") : runStateName(r.state);
        case Calibration: return calibrationDisplayName(r.calibration);
        case Modified: return QLocale().toString(r.modified, QLocale::ShortFormat);
        }
    } else if (role == Qt::ToolTipRole) {
        return r.detail.isEmpty() ? r.path : r.path + QLatin1Char('\n') + r.detail;
    } else if (role == Qt::ForegroundRole && index.column() == State) {
        if (!busy_.isEmpty() && r.path == busy_)
            return QBrush(QColor(20, 90, 180));
        switch (r.state) {
        case RunState::Complete:
        case RunState::Puncture: return QBrush(QColor(30, 120, 40));
        case RunState::EmergencyStop:
        case RunState::WriteError:
        case RunState::StoppedByLimit:
        case RunState::Fault:
        case RunState::Unreadable: return QBrush(QColor(190, 30, 30));
        case RunState::Interrupted:
        case RunState::ClosedOnSignal:
        case RunState::Recovered:
        case RunState::Stopped:
        case RunState::MotionStopped:
        case RunState::Aborted: return QBrush(QColor(180, 110, 0));
        }
    } else if (role == Qt::UserRole) {
        return r.path;
    }
    return {};
}

QVariant RunListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Number: return tr("#");
    case File: return tr("File");
    case Motion: return tr("Motion");
    case State: return tr("State");
    case Calibration: return tr("Calibration");
    case Modified: return tr("Saved");
    }
    return {};
}

SessionView::SessionView(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("sessionView"));
    header_ = new QLabel(this);
    header_->setObjectName(QStringLiteral("sessionHeader"));
    header_->setWordWrap(true);
    header_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    model_ = new RunListModel(this);
    view_ = new QTableView(this);
    view_->setModel(model_);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->verticalHeader()->setVisible(false);
    // Rows as high as their text: at 1366x768 the dock shows two and a half runs, where the
    // style's own height showed two at most.
    view_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view_->horizontalHeader()->setStretchLastSection(true);
    connect(view_, &QTableView::activated, this,
            [this](const QModelIndex& i) { emit runActivated(i.siblingAtColumn(0).data(Qt::UserRole).toString()); });
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(header_);
    layout->addWidget(view_, 1);
    setSession(nullptr);
}

void SessionView::setSession(const Session* session)
{
    session_ = session;
    refresh();
}

void SessionView::setBusyPath(const QString& path) { model_->setBusyPath(path); }

void SessionView::selectRun(const QString& path)
{
    selected_ = path;
    for (int row = 0; row < model_->rowCount(); ++row)
        if (model_->index(row, 0).data(Qt::UserRole).toString() == path) {
            view_->selectRow(row);
            view_->scrollTo(model_->index(row, 0));
            return;
        }
}

// A session's free text that names several file values ("beveled/diamond", "stiffness +
// friction", as the demo writes them), each known one said in the operator's language.
static QString eachPartNamed(const QString& text, const QString& separator, QString (*displayName)(const QString&))
{
    QStringList parts = text.split(separator.trimmed());
    for (QString& p : parts)
        p = displayName(p.trimmed());
    return parts.join(separator);
}

// The tip as stored (beveled, diamond, blunt: file values) said in the operator's language.
static QString tipName(const QString& tip)
{
    if (tip == QLatin1String("beveled"))
        return SessionView::tr("beveled tip");
    if (tip == QLatin1String("diamond"))
        return SessionView::tr("diamond tip");
    if (tip == QLatin1String("blunt"))
        return SessionView::tr("blunt tip");
    return SessionView::tr("%1 tip").arg(eachPartNamed(tip, QStringLiteral("/"), tipDisplayName));
}

void SessionView::refresh()
{
    if (!session_) {
        header_->setText(tr("No session open (Session ▸ New or Open)."));
        model_->setRuns({});
        return;
    }
    const SessionInfo& i = session_->info();
    const auto cal = session_->activeCalibration();
    QStringList specimen;
    for (const QString& part : {i.organ, i.specimen.isEmpty() ? QString() : tr("specimen %1").arg(i.specimen),
                                i.tip.isEmpty() ? QString() : tipName(i.tip),
                                i.thickness_mm > 0 ? tr("%1 mm thick").arg(i.thickness_mm) : QString(),
                                i.operatorName.isEmpty() ? QString() : tr("operator %1").arg(i.operatorName),
                                eachPartNamed(i.protocol, QStringLiteral(" + "), protocolDisplayName)})
        if (!part.isEmpty())
            specimen << part.toHtmlEscaped();
    header_->setText(tr("<b>%1</b> – %2<br>active calibration: %3")
                         .arg(session_->dir().section(QLatin1Char('/'), -1).toHtmlEscaped(),
                              specimen.isEmpty() ? tr("no specimen details") : specimen.join(QStringLiteral(", ")),
                              cal ? cal->name.toHtmlEscaped() : tr("none saved in this session (the sensor's nominal one is used)")));
    const int before = model_->rowCount();
    model_->setRuns(session_->runs());
    if (!selected_.isEmpty())
        selectRun(selected_);
    // A run just saved comes into view: it was half hidden below the list's edge.
    if (before > 0 && model_->rowCount() > before)
        view_->scrollToBottom();
}

}  // namespace nb
