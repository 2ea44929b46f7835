#include "label_model.h"

#include <QSettings>

#include <algorithm>
#include <cmath>

namespace nb {

QList<LabelDef> protocolLabelSet(const QString& protocol)
{
    QList<LabelDef> defs;
    if (protocol == QLatin1String("friction")) {
        const QColor colors[4] = {QColor(76, 175, 80), QColor(255, 193, 7), QColor(255, 112, 67), QColor(66, 133, 244)};
        const char* names[4] = {"a", "b1", "b2", "c"};
        for (int d = 0; d < 2; ++d)
            for (int i = 0; i < 4; ++i)
                defs.append({d == 0 ? QStringLiteral("insertion") : QStringLiteral("withdrawal"), QLatin1String(names[i]),
                             false, Qt::Key_1 + d * 4 + i, colors[i]});
        return defs;
    }
    defs.append({QStringLiteral("events"), QStringLiteral("contact"), true, Qt::Key_C, QColor(76, 175, 80)});
    defs.append({QStringLiteral("events"), QStringLiteral("puncture"), true, Qt::Key_P, QColor(229, 57, 53)});
    defs.append({QStringLiteral("events"), QStringLiteral("relaxation"), true, Qt::Key_R, QColor(66, 133, 244)});
    defs.append({QStringLiteral("events"), QStringLiteral("internal puncture"), true, Qt::Key_I, QColor(171, 71, 188)});
    return defs;
}

static QString settingsGroup(const QString& protocol) { return QStringLiteral("labelSets/") + protocol; }

QList<LabelDef> savedLabelSet(const QString& protocol)
{
    QSettings settings;
    const int n = settings.beginReadArray(settingsGroup(protocol));
    QList<LabelDef> defs;
    for (int i = 0; i < n; ++i) {
        settings.setArrayIndex(i);
        defs.append({settings.value("track").toString(), settings.value("label").toString(), settings.value("point").toBool(),
                     settings.value("key").toInt(), settings.value("color").value<QColor>()});
    }
    settings.endArray();
    return defs.isEmpty() ? protocolLabelSet(protocol) : defs;
}

void saveLabelSet(const QString& protocol, const QList<LabelDef>& defs)
{
    QSettings settings;
    settings.remove(settingsGroup(protocol));
    settings.beginWriteArray(settingsGroup(protocol), int(defs.size()));
    for (int i = 0; i < defs.size(); ++i) {
        settings.setArrayIndex(i);
        settings.setValue("track", defs[i].track);
        settings.setValue("label", defs[i].label);
        settings.setValue("point", defs[i].point);
        settings.setValue("key", defs[i].key);
        settings.setValue("color", defs[i].color);
    }
    settings.endArray();
}

LabelModel::LabelModel(QObject* parent) : QAbstractTableModel(parent), defs_(protocolLabelSet(QStringLiteral("friction"))) {}

int LabelModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : int(labels_.size()); }
int LabelModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant LabelModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Label& l = labels_[std::size_t(index.row())];
    if (role == Qt::DecorationRole && index.column() == Name)
        return colorOf(l);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case Track: return l.track;
    case Name: return l.label;
    case Start: return QString::number(l.start_s, 'f', 3);
    case End: return QString::number(l.end_s, 'f', 3);
    case Comment: return l.comment;
    }
    return {};
}

QVariant LabelModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Track: return tr("track");
    case Name: return tr("label");
    case Start: return tr("start [s]");
    case End: return tr("end [s]");
    case Comment: return tr("comment");
    }
    return {};
}

static bool before(const Label& a, const Label& b)
{
    return std::tie(a.track, a.start_s, a.end_s, a.label) < std::tie(b.track, b.start_s, b.end_s, b.label);
}

void LabelModel::setLabels(Labels labels)
{
    beginResetModel();
    labels_ = std::move(labels);
    std::stable_sort(labels_.begin(), labels_.end(), before);
    endResetModel();
    emit labelsChanged();
}

void LabelModel::setDefinitions(QList<LabelDef> defs)
{
    defs_ = std::move(defs);
    emit labelsChanged();
}

const LabelDef* LabelModel::definitionForKey(int key) const
{
    for (const LabelDef& d : defs_)
        if (d.key == key)
            return &d;
    return nullptr;
}

QColor LabelModel::colorOf(const Label& l) const
{
    for (const LabelDef& d : defs_)
        if (d.label == l.label && (d.track == l.track || d.point == l.isPoint()))
            return d.color;
    return QColor(120, 120, 120);
}

QStringList LabelModel::tracks() const
{
    QStringList t;
    for (const LabelDef& d : defs_)
        if (!t.contains(d.track))
            t << d.track;
    for (const Label& l : labels_)
        if (!t.contains(l.track))
            t << l.track;
    return t;
}

bool LabelModel::canPlace(const Label& l, const Label* ignore) const
{
    if (l.end_s < l.start_s || l.label.isEmpty())
        return false;
    // The same event again on its track (within a millisecond): Suggest pressed twice placed
    // every event twice, then three times, and saved them so (video probe).
    if (l.isPoint())
        return std::none_of(labels_.begin(), labels_.end(), [&](const Label& o) {
            return o.isPoint() && o.track == l.track && o.label == l.label && std::abs(o.start_s - l.start_s) < 1e-3
                   && !(ignore && o == *ignore);
        });
    for (const Label& o : labels_) {
        if (o.isPoint() || o.track != l.track || (ignore && o == *ignore))
            continue;
        if (l.start_s < o.end_s && o.start_s < l.end_s)
            return false;
    }
    return true;
}

bool LabelModel::insertLabel(const Label& l)
{
    if (!canPlace(l))
        return false;
    const auto it = std::upper_bound(labels_.begin(), labels_.end(), l, before);
    const int row = int(it - labels_.begin());
    beginInsertRows({}, row, row);
    labels_.insert(it, l);
    endInsertRows();
    emit labelsChanged();
    return true;
}

bool LabelModel::removeLabel(const Label& l)
{
    const auto it = std::find(labels_.begin(), labels_.end(), l);
    if (it == labels_.end())
        return false;
    const int row = int(it - labels_.begin());
    beginRemoveRows({}, row, row);
    labels_.erase(it);
    endRemoveRows();
    emit labelsChanged();
    return true;
}

bool LabelModel::replaceLabel(const Label& b, const Label& a)
{
    if (std::find(labels_.begin(), labels_.end(), b) == labels_.end() || !canPlace(a, &b))
        return false;
    removeLabel(b);
    return insertLabel(a);
}

const Label* LabelModel::intervalAt(const QString& track, double t) const
{
    for (const Label& l : labels_)
        if (!l.isPoint() && l.track == track && t >= l.start_s && t <= l.end_s)
            return &l;
    return nullptr;
}

}  // namespace nb
