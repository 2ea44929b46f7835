#pragma once
// Label tracks under the video and the plots: one row per track, intervals as coloured
// bars, point events as ticks, one cursor (recording time). Click moves the cursor and picks
// the current track; dragging an interval's edge moves it (one undoable edit on release).

#include "core/labels.h"

#include <QWidget>
#include <algorithm>
#include <optional>
#include <vector>

class QUndoStack;

namespace nb {

class LabelModel;

class Timeline : public QWidget {
    Q_OBJECT
public:
    Timeline(LabelModel* model, QUndoStack* undo, QWidget* parent = nullptr);

    void setRange(double start_s, double end_s);
    // Where the time axis lies in this widget (left pixel and width), so that it matches a
    // plot above to the pixel; the track names go left of it. Negative: the default margins.
    void setAxisPixels(int left, int width);
    double cursorTime() const { return cursor_; }
    void setCursorTime(double t);
    QString currentTrack() const { return currentTrack_; }
    void setCurrentTrack(const QString& track);
    // A started interval not yet closed (shown dashed), or none.
    void setPending(const QString& track, const QString& label, std::optional<double> start);
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    // Geometry, public for tests that drive the mouse.
    int xOf(double t) const;
    double timeAt(int x) const;
    int rowTop(const QString& track) const;
    int rowHeight() const { return 22; }
    // The labels' names as drawn: each within its own room, none over another.
    struct Name {
        QRect rect;
        QString text;
    };
    std::vector<Name> labelNames() const;

signals:
    void cursorMoved(double t);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;

private:
    QString trackAt(int y) const;
    const Label& shown(const Label& l) const { return drag_ && l == drag_->original ? drag_->current : l; }
    LabelModel* model_;
    QUndoStack* undo_;
    double start_ = 0.0, end_ = 10.0, cursor_ = 0.0;
    QString currentTrack_;
    struct Pending {
        QString track, label;
        double start;
    };
    std::optional<Pending> pending_;
    struct Drag {
        Label original;
        bool startEdge;
        Label current;
    };
    std::optional<Drag> drag_;
    bool scrubbing_ = false;
    static constexpr int kLeft = 86;  // track names
    int axisLeft_ = -1, axisWidth_ = -1;
    int axisLeft() const { return axisLeft_ >= 0 ? axisLeft_ : kLeft; }
    int axisWidth() const { return axisWidth_ > 0 ? axisWidth_ : std::max(1, width() - kLeft - 8); }
};

}  // namespace nb
