#include "timeline.h"

#include "core/data_names.h"

#include "label_commands.h"
#include "label_model.h"

#include <QMouseEvent>
#include <QPainter>
#include <QUndoStack>

#include <algorithm>
#include <map>
#include <set>
#include <cmath>

namespace nb {

Timeline::Timeline(LabelModel* model, QUndoStack* undo, QWidget* parent) : QWidget(parent), model_(model), undo_(undo)
{
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    connect(model_, &LabelModel::labelsChanged, this, [this] {
        updateGeometry();
        update();
    });
    const QStringList t = model_->tracks();
    if (!t.isEmpty())
        currentTrack_ = t.first();
}

QSize Timeline::sizeHint() const { return {600, 8 + rowHeight() * int(std::max<qsizetype>(1, model_->tracks().size())) + 18}; }

// Never less than the tracks and the time axis under them: with the sync's plot shown at
// 1366x768 the layout gave it 60 px of 70, and the axis numbers were cut off.
QSize Timeline::minimumSizeHint() const { return {160, sizeHint().height()}; }

void Timeline::setRange(double s, double e)
{
    start_ = s;
    end_ = e > s ? e : s + 1.0;
    update();
}

void Timeline::setCursorTime(double t)
{
    cursor_ = t;
    update();
}

void Timeline::setCurrentTrack(const QString& track)
{
    currentTrack_ = track;
    update();
}

void Timeline::setPending(const QString& track, const QString& label, std::optional<double> start)
{
    if (start)
        pending_ = Pending{track, label, *start};
    else
        pending_.reset();
    update();
}

// Rounded as QCustomPlot places its pixels, so marks line up with the plot above.
int Timeline::xOf(double t) const { return axisLeft() + int(std::lround((t - start_) / (end_ - start_) * axisWidth())); }
double Timeline::timeAt(int x) const { return start_ + double(x - axisLeft()) / axisWidth() * (end_ - start_); }

void Timeline::setAxisPixels(int left, int width)
{
    if (left == axisLeft_ && width == axisWidth_)
        return;
    axisLeft_ = left;
    axisWidth_ = width;
    update();
}
int Timeline::rowTop(const QString& track) const { return 4 + rowHeight() * int(model_->tracks().indexOf(track)); }

QString Timeline::trackAt(int y) const
{
    const QStringList t = model_->tracks();
    const int i = (y - 4) / rowHeight();
    return i >= 0 && i < t.size() ? t[i] : QString();
}

std::vector<Timeline::Name> Timeline::labelNames() const
{
    // A point's name runs up to the next point on its track, elided, or is left out where there
    // is no room: a run's dozen internal punctures within a second wrote over one another. Of
    // points on one pixel (a contact and a puncture a millisecond apart at this zoom) only the
    // first is named, and a phase narrower than its name is left unnamed.
    std::map<QString, std::vector<int>> pointsX;
    for (const Label& l : model_->labels())
        if (shown(l).isPoint())
            pointsX[l.track].push_back(xOf(shown(l).start_s));
    for (auto& [track, xs] : pointsX)
        std::sort(xs.begin(), xs.end());
    std::set<std::pair<QString, int>> named;  // (track, x) of the points named
    const QFontMetrics fm = fontMetrics();
    std::vector<Name> names;
    for (const Label& l : model_->labels()) {
        const Label& at = shown(l);
        const int y = rowTop(l.track);
        const QString text = labelDisplayName(l.label);
        if (at.isPoint()) {
            const int x = xOf(at.start_s);
            const std::vector<int>& xs = pointsX[l.track];
            const auto after = std::upper_bound(xs.begin(), xs.end(), x);
            const int room = (after == xs.end() ? axisLeft() + axisWidth() : *after) - x - 6;  // the axis' end clips
            if (room < fm.horizontalAdvance(QStringLiteral("ab…")) || !named.insert({l.track, x}).second)
                continue;
            const QString elided = fm.elidedText(text, Qt::ElideRight, room);
            names.push_back({QRect(x + 3, y + 2, fm.horizontalAdvance(elided), rowHeight() - 4), elided});
        } else {
            const QRect r(QPoint(xOf(at.start_s), y + 3), QPoint(xOf(at.end_s), y + rowHeight() - 4));
            const int w = fm.horizontalAdvance(text);
            if (w <= r.width() - 2)
                names.push_back({QRect(r.center().x() - w / 2, y + 2, w, rowHeight() - 4), text});
        }
    }
    return names;
}

void Timeline::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    const QStringList tracks = model_->tracks();
    for (const QString& track : tracks) {
        const int y = rowTop(track);
        if (track == currentTrack_)
            p.fillRect(QRect(0, y, width(), rowHeight()), palette().alternateBase());
        p.setPen(palette().text().color());
        p.drawText(QRect(2, y, axisLeft() - 6, rowHeight()), Qt::AlignVCenter | Qt::AlignRight,
                   fontMetrics().elidedText(trackDisplayName(track), Qt::ElideRight, std::max(8, axisLeft() - 6)));
        p.setPen(palette().mid().color());
        p.drawLine(axisLeft(), y + rowHeight() - 1, width(), y + rowHeight() - 1);
    }
    p.setClipRect(QRect(axisLeft(), 0, axisWidth() + 1, height()));
    for (const Label& l : model_->labels()) {
        const Label& at = shown(l);
        const int y = rowTop(l.track);
        const QColor c = model_->colorOf(l);
        if (at.isPoint()) {
            const int x = xOf(at.start_s);
            p.setPen(QPen(c, 2));
            p.drawLine(x, y + 2, x, y + rowHeight() - 3);
        } else {
            const QRect r(QPoint(xOf(at.start_s), y + 3), QPoint(xOf(at.end_s), y + rowHeight() - 4));
            p.fillRect(r, c.lighter(130));
            p.setPen(c.darker(140));
            p.drawRect(r);
        }
    }
    p.setPen(Qt::black);
    for (const Name& name : labelNames())
        p.drawText(name.rect, Qt::AlignVCenter | Qt::AlignLeft, name.text);
    if (pending_) {
        const int y = rowTop(pending_->track);
        p.setPen(QPen(palette().text().color(), 1, Qt::DashLine));
        p.drawRect(QRect(QPoint(xOf(pending_->start), y + 3), QPoint(xOf(cursor_), y + rowHeight() - 4)));
        p.drawText(xOf(pending_->start) + 3, y + rowHeight() - 7, pending_->label + QStringLiteral("…"));
    }
    // Time axis.
    const int axisY = 4 + rowHeight() * int(tracks.size());
    p.setPen(palette().text().color());
    const double span = end_ - start_;
    // 1, 2 or 5 times a power of ten, with labels at least 60 px apart (zoomed or narrow).
    const double minStep = span * 60.0 / std::max(1, axisWidth());
    const double decade = std::pow(10.0, std::floor(std::log10(std::max(minStep, 1e-6))));
    const double step = minStep <= decade ? decade : minStep <= 2 * decade ? 2 * decade : minStep <= 5 * decade ? 5 * decade : 10 * decade;
    // The numbers are not clipped to the axis: the last one (10 of 0-10 s) begins at the axis'
    // end and was cut to its first digit. Each is written right of its tick, or left of it where
    // the widget ends first.
    p.setClipping(false);
    for (double t = std::ceil(start_ / step) * step; t <= end_; t += step) {
        const int x = xOf(t);
        p.drawLine(x, axisY, x, axisY + 4);
        const QString text = QString::number(std::abs(t) < 1e-9 * step ? 0.0 : t, 'g', 6);
        const int textWidth = fontMetrics().horizontalAdvance(text);
        p.drawText(x + 2 + textWidth <= width() ? x + 2 : x - 2 - textWidth, axisY + 14, text);
    }
    p.setClipping(true);
    p.setPen(QPen(QColor(220, 0, 0), 2));
    p.drawLine(xOf(cursor_), 0, xOf(cursor_), height());
}

void Timeline::mousePressEvent(QMouseEvent* e)
{
    const QPoint pos = e->position().toPoint();
    const QString track = trackAt(pos.y());
    if (!track.isEmpty())
        setCurrentTrack(track);
    // An interval edge within 4 px starts a drag.
    for (const Label& l : model_->labels()) {
        if (l.isPoint() || l.track != track)
            continue;
        for (bool startEdge : {true, false}) {
            if (std::abs(xOf(startEdge ? l.start_s : l.end_s) - pos.x()) <= 4) {
                drag_ = Drag{l, startEdge, l};
                return;
            }
        }
    }
    scrubbing_ = true;
    cursor_ = timeAt(pos.x());
    emit cursorMoved(cursor_);
    update();
}

void Timeline::mouseMoveEvent(QMouseEvent* e)
{
    const int x = int(e->position().x());
    if (drag_) {
        const double t = timeAt(x);
        if (drag_->startEdge)
            drag_->current.start_s = std::min(t, drag_->current.end_s - 1e-3);
        else
            drag_->current.end_s = std::max(t, drag_->current.start_s + 1e-3);
        update();
    } else if (scrubbing_) {
        cursor_ = timeAt(x);
        emit cursorMoved(cursor_);
        update();
    } else {
        bool nearEdge = false;
        for (const Label& l : model_->labels())
            if (!l.isPoint() && l.track == trackAt(int(e->position().y())))
                nearEdge |= std::abs(xOf(l.start_s) - x) <= 4 || std::abs(xOf(l.end_s) - x) <= 4;
        setCursor(nearEdge ? Qt::SizeHorCursor : Qt::ArrowCursor);
    }
}

void Timeline::mouseReleaseEvent(QMouseEvent*)
{
    if (drag_) {
        if (!(drag_->current == drag_->original) && model_->canPlace(drag_->current, &drag_->original))
            undo_->push(new EditLabelCommand(model_, drag_->original, drag_->current));
        drag_.reset();
        update();
    }
    scrubbing_ = false;
}

}  // namespace nb
