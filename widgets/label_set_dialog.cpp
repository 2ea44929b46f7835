#include "label_set_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <iterator>
#include <map>

namespace nb {

static const QColor kNewColors[] = {QColor(0, 150, 136), QColor(233, 30, 99), QColor(121, 85, 72), QColor(96, 125, 139),
                                    QColor(205, 220, 57), QColor(63, 81, 181)};

LabelSetDialog::LabelSetDialog(const QString& protocol, const QList<LabelDef>& defs, QWidget* parent)
    : QDialog(parent), table_(new QTableWidget(0, ColumnCount, this)), error_(new QLabel(this))
{
    setWindowTitle(tr("Label set: %1").arg(protocol));
    table_->setHorizontalHeaderLabels({tr("track"), tr("label"), tr("kind"), tr("hotkey")});
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->verticalHeader()->hide();
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    for (const LabelDef& d : defs)
        addRow(d);

    auto* add = new QPushButton(tr("Add label"), this);
    connect(add, &QPushButton::clicked, this, [this] {
        const QString track = table_->rowCount() ? table_->item(table_->rowCount() - 1, Track)->text() : QStringLiteral("events");  // a track name is data: never translated
        addRow({track, tr("new label"), true, 0, kNewColors[table_->rowCount() % std::size(kNewColors)]});
        table_->setCurrentCell(table_->rowCount() - 1, Name);
    });
    auto* remove = new QPushButton(tr("Remove label"), this);
    connect(remove, &QPushButton::clicked, this, [this] {
        if (table_->currentRow() >= 0)
            table_->removeRow(table_->currentRow());
    });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->addButton(add, QDialogButtonBox::ActionRole);
    buttons->addButton(remove, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &LabelSetDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &LabelSetDialog::reject);

    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #c62828"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Renaming a label does not rename the labels already placed."), this));
    layout->addWidget(table_);
    layout->addWidget(error_);
    layout->addWidget(buttons);
    resize(520, 360);
}

void LabelSetDialog::addRow(const LabelDef& d)
{
    const int row = table_->rowCount();
    table_->insertRow(row);
    table_->setItem(row, Track, new QTableWidgetItem(d.track));
    auto* name = new QTableWidgetItem(d.label);
    name->setData(Qt::DecorationRole, d.color);
    table_->setItem(row, Name, name);
    table_->setItem(row, Hotkey, new QTableWidgetItem(d.key > 0 ? QKeySequence(d.key).toString() : QString()));
    auto* kind = new QComboBox(table_);
    kind->addItem(tr("interval"));
    kind->addItem(tr("point"));
    kind->setCurrentIndex(d.point ? 1 : 0);
    table_->setCellWidget(row, Kind, kind);
}

QList<LabelDef> LabelSetDialog::definitions() const
{
    QList<LabelDef> defs;
    for (int row = 0; row < table_->rowCount(); ++row) {
        LabelDef d;
        d.track = table_->item(row, Track)->text().trimmed();
        d.label = table_->item(row, Name)->text().trimmed();
        d.color = table_->item(row, Name)->data(Qt::DecorationRole).value<QColor>();
        d.point = static_cast<QComboBox*>(table_->cellWidget(row, Kind))->currentIndex() == 1;
        const QKeySequence seq = QKeySequence::fromString(table_->item(row, Hotkey)->text().trimmed());
        d.key = seq.count() == 1 && seq[0].keyboardModifiers() == Qt::NoModifier ? int(seq[0].key()) : -1;
        defs << d;
    }
    return defs;
}

QString LabelSetDialog::problem() const
{
    // Keys the review workspace keeps for itself (frame steps, play, split, delete).
    const std::map<int, QString> reserved = {{Qt::Key_Left, tr("one frame back")}, {Qt::Key_Right, tr("one frame forward")},
                                             {Qt::Key_Space, tr("play / pause")},   {Qt::Key_S, tr("split")},
                                             {Qt::Key_Delete, tr("delete")},        {Qt::Key_Backspace, tr("delete")}};
    const QList<LabelDef> defs = definitions();
    for (int i = 0; i < defs.size(); ++i) {
        const LabelDef& d = defs[i];
        const QString name = QStringLiteral("%1/%2").arg(d.track, d.label);
        if (d.track.isEmpty() || d.label.isEmpty())
            return tr("Row %1: a label needs a track and a name.").arg(i + 1);
        if (d.key <= 0)
            return tr("%1: the hotkey must be one key without Ctrl, Shift or Alt.").arg(name);
        if (const auto it = reserved.find(d.key); it != reserved.end())
            return tr("%1: the key %2 already means “%3” in the review workspace.")
                .arg(name, QKeySequence(d.key).toString(QKeySequence::NativeText), it->second);
        for (int j = 0; j < i; ++j) {
            if (defs[j].track == d.track && defs[j].label == d.label)
                return tr("%1 is in the set twice.").arg(name);
            if (defs[j].key == d.key)
                return tr("The key %1 is given to both %2/%3 and %4.")
                    .arg(QKeySequence(d.key).toString(QKeySequence::NativeText), defs[j].track, defs[j].label, name);
        }
    }
    return {};
}

void LabelSetDialog::accept()
{
    const QString p = problem();
    error_->setText(p);
    if (p.isEmpty())
        QDialog::accept();
}

}  // namespace nb
