#pragma once
// The live plots of a run: force vs time, position vs time (sharing the time axis) and
// force vs position (thesis Fig. 20). In the workbench they observe the live run
// (devices::LiveRun: its samples and marks); standing alone (benchmarks, tests) they are fed
// with appendSamples. Each redraw reduces what is visible to min/max per pixel column, so a
// 10 kHz recording costs the same to draw as a slow one.

#include "devices/live_run.h"

#include <QString>
#include <QStringList>
#include <QWidget>
#include <optional>
#include <span>
#include <vector>

class QCustomPlot;
class QCPAbstractItem;
class QCPGraph;
class QCPCurve;
class QCPItemStraightLine;
class QCPItemText;
class QToolButton;
class QLabel;

namespace nb {

class ForcePlots : public QWidget {
    Q_OBJECT
public:
    explicit ForcePlots(QWidget* parent = nullptr);

    // Shows the live run's samples and marks from now on, redrawing after each of its pulls
    // (null: stand alone again, with no samples).
    void observe(const devices::LiveRun* run);
    // Stand alone only (ignored while observing a live run).
    void appendSamples(std::span<const double> time_s, std::span<const double> position_mm,
                       std::span<const double> force_N);
    void append(double time_s, double position_mm, double force_N);
    // Forgets every sample and event (stand alone) or what was drawn of the observed run.
    void clear();
    // The text an observed mark is drawn with.
    static QString markLabel(devices::LiveMarkKind kind);
    // Draws the maximum-force limit as a line on both force plots; <= 0 hides it.
    void setForceLimit(double force_N);
    // The engine's margin to where the stage stops (the limit, or the end of what the load cell
    // reads, whichever comes first); without one, the limit less the latest force. The plot
    // said 8.00 N of margin where the panel said 7.78 N.
    void setForceMargin(std::optional<double> margin_N) { margin_N_ = margin_N; }
    // Marks a detected event (puncture, contact, ...) at a time; an empty label marks it
    // without text (minor events that would clutter the plot).
    void addEvent(double time_s, const QString& label);
    // Removes the marks of every event with this label (live marks replaced by refined ones).
    void removeEvents(const QString& label);
    QStringList eventLabels() const;

    // Follow: the time axis shows the last followWindow() seconds and the axes track the
    // data. Zooming or dragging a plot turns following off.
    bool follows() const { return follow_; }
    void setFollow(bool on);
    double followWindow() const { return window_s_; }
    void setFollowWindow(double seconds);
    // Paused: the plots keep showing what they showed; samples keep arriving and appear
    // when resumed (nothing is lost).
    bool isPaused() const { return paused_; }
    void setPaused(bool on);
    // Shows the whole run (and stops following).
    void showAll();

    // Off only to measure what the reduction saves (bench/bench_plot.cpp).
    void setReduction(bool on) { reduce_ = on; }

    // Redraws if anything changed since the last call; called by the drain timer.
    void refresh();

    std::size_t sampleCount() const { return data_->size(); }
    const std::vector<double>& times() const { return data_->time_s; }
    const std::vector<double>& positions() const { return data_->position_mm; }
    const std::vector<double>& forces() const { return data_->force_N; }
    // Points handed to the plots at the last redraw (after reduction), per plot.
    std::size_t pointsDrawnForceTime() const { return drawnForceTime_; }
    std::size_t pointsDrawnForcePosition() const { return drawnForcePosition_; }
    int framesDrawn() const { return frames_; }
    int eventCount() const { return int(events_.size()); }

    QCustomPlot* forceTimePlot() const { return forceTime_; }
    QCustomPlot* positionTimePlot() const { return positionTime_; }
    QCustomPlot* forcePositionPlot() const { return forcePosition_; }

signals:
    void followChanged(bool on);
    void pausedChanged(bool on);

private:
    void updateData();
    void forgetShown();
    void showMarks();
    void applyFollowRanges();
    void keepEventLabelsInside();
    void userMovedView();

    QCustomPlot* forceTime_ = nullptr;
    QCustomPlot* positionTime_ = nullptr;
    QCustomPlot* forcePosition_ = nullptr;
    QCPGraph* forceGraph_ = nullptr;
    QCPGraph* positionGraph_ = nullptr;
    QCPCurve* curve_ = nullptr;
    QCPItemStraightLine* limitTime_ = nullptr;
    QCPItemStraightLine* limitCurve_ = nullptr;
    QCPItemText* limitLabel_ = nullptr;
    QToolButton* followButton_ = nullptr;
    QToolButton* pauseButton_ = nullptr;

    devices::LiveSeries own_;
    const devices::LiveRun* model_ = nullptr;
    const devices::LiveSeries* data_ = &own_;
    std::size_t shown_ = 0;  // samples the plots show (frozen while paused)
    double fMin_ = 0.0, fMax_ = 0.0, xMin_ = 0.0, xMax_ = 0.0;
    struct Event {
        double time_s;
        QString label;
        std::vector<QCPAbstractItem*> items;  // its marks on the three plots
    };
    std::vector<Event> events_;
    double limit_N_ = 0.0;
    std::optional<double> margin_N_;
    double window_s_ = 10.0;
    bool follow_ = true;
    bool paused_ = false;
    bool reduce_ = true;
    bool dirty_ = true;
    bool settingRanges_ = false;
    std::size_t drawnForceTime_ = 0, drawnForcePosition_ = 0;
    int frames_ = 0;
};

}  // namespace nb
