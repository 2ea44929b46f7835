#include "force_plots.h"

#include "core/decimate.h"

#include <QHBoxLayout>
#include <QLocale>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <qcustomplot.h>

namespace nb {

namespace {

QCustomPlot* makePlot(QWidget* parent, const QString& xLabel, const QString& yLabel)
{
    auto* plot = new QCustomPlot(parent);
    plot->xAxis->setLabel(xLabel);
    plot->yAxis->setLabel(yLabel);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot->setNoAntialiasingOnDrag(true);
    // Live curves are thin 1 px lines without antialiasing: the raster engine's fast path.
    // A reduced force-position curve of a long sine run is made of long zigzags; drawn
    // antialiased they cost tens of milliseconds per frame.
    plot->setNotAntialiasedElements(QCP::aePlottables);
    plot->setMinimumSize(240, 150);
    return plot;
}

QCPItemStraightLine* makeLimitLine(QCustomPlot* plot)
{
    auto* line = new QCPItemStraightLine(plot);
    QPen pen(QColor(200, 30, 30), 1.5, Qt::DashLine);
    line->setPen(pen);
    line->setVisible(false);
    return line;
}

// Data range with a little air; a nearly flat signal (a needle at rest, encoder noise) gets
// at least `minSpan` so that noise is not blown up to fill the plot.
QCPRange padded(double lo, double hi, double minSpan)
{
    if (hi - lo < minSpan) {
        const double mid = 0.5 * (lo + hi);
        lo = mid - 0.5 * minSpan;
        hi = mid + 0.5 * minSpan;
    }
    const double span = hi - lo;
    return {lo - 0.05 * span, hi + 0.05 * span};
}

constexpr double kMinForceSpan_N = 0.1;
constexpr double kMinPositionSpan_mm = 1.0;

}  // namespace

ForcePlots::ForcePlots(QWidget* parent) : QWidget(parent)
{
    forceTime_ = makePlot(this, tr("time [s]"), tr("force [N]"));
    positionTime_ = makePlot(this, tr("time [s]"), tr("position [mm]"));
    forcePosition_ = makePlot(this, tr("position [mm]"), tr("force [N]"));
    forceTime_->setObjectName(QStringLiteral("forceTimePlot"));
    positionTime_->setObjectName(QStringLiteral("positionTimePlot"));
    forcePosition_->setObjectName(QStringLiteral("forcePositionPlot"));

    forceGraph_ = forceTime_->addGraph();
    forceGraph_->setPen(QPen(QColor(20, 90, 180), 1));
    forceGraph_->setAdaptiveSampling(false);  // reduced here already
    forceGraph_->setName(tr("force"));
    positionGraph_ = positionTime_->addGraph();
    positionGraph_->setPen(QPen(QColor(30, 140, 60), 1));
    positionGraph_->setAdaptiveSampling(false);
    positionGraph_->setName(tr("position"));
    curve_ = new QCPCurve(forcePosition_->xAxis, forcePosition_->yAxis);
    curve_->setPen(QPen(QColor(120, 40, 160), 1));
    curve_->setName(tr("force vs position"));

    limitTime_ = makeLimitLine(forceTime_);
    limitCurve_ = makeLimitLine(forcePosition_);
    limitLabel_ = new QCPItemText(forceTime_);
    limitLabel_->position->setType(QCPItemPosition::ptAxisRectRatio);
    limitLabel_->position->setCoords(0.99, 0.02);
    limitLabel_->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
    limitLabel_->setColor(QColor(200, 30, 30));
    limitLabel_->setBrush(QBrush(QColor(255, 255, 255, 210)));
    limitLabel_->setPadding(QMargins(3, 1, 3, 1));
    limitLabel_->setVisible(false);

    // The two time plots share their time axis.
    connect(forceTime_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), positionTime_->xAxis,
            qOverload<const QCPRange&>(&QCPAxis::setRange));
    connect(positionTime_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), forceTime_->xAxis,
            qOverload<const QCPRange&>(&QCPAxis::setRange));
    connect(forceTime_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
        if (!settingRanges_)
            positionTime_->replot(QCustomPlot::rpQueuedReplot);
    });
    // Each plot reduces the samples for its own visible range right before it draws, so
    // zooming in brings back detail even while paused.
    for (QCustomPlot* plot : {forceTime_, positionTime_, forcePosition_}) {
        connect(plot, &QCustomPlot::beforeReplot, this, &ForcePlots::updateData);
        connect(plot, &QCustomPlot::mousePress, this, &ForcePlots::userMovedView);
        connect(plot, &QCustomPlot::mouseWheel, this, &ForcePlots::userMovedView);
    }

    followButton_ = new QToolButton(this);
    followButton_->setText(tr("Follow"));
    followButton_->setCheckable(true);
    followButton_->setChecked(true);
    followButton_->setToolTip(tr("Keep the newest samples in view (zooming or dragging a plot turns this off)"));
    connect(followButton_, &QToolButton::toggled, this, &ForcePlots::setFollow);
    pauseButton_ = new QToolButton(this);
    pauseButton_->setText(tr("Pause display"));
    pauseButton_->setCheckable(true);
    pauseButton_->setToolTip(tr("Freeze the plots to look closely; recording goes on and nothing is lost"));
    connect(pauseButton_, &QToolButton::toggled, this, &ForcePlots::setPaused);
    auto* all = new QToolButton(this);
    all->setText(tr("Show whole run"));
    all->setToolTip(tr("Zoom out to every sample of the run"));
    connect(all, &QToolButton::clicked, this, &ForcePlots::showAll);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(followButton_);
    buttons->addWidget(pauseButton_);
    buttons->addWidget(all);
    buttons->addStretch();

    auto* timeColumn = new QSplitter(Qt::Vertical, this);
    timeColumn->addWidget(forceTime_);
    timeColumn->addWidget(positionTime_);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(timeColumn);
    split->addWidget(forcePosition_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(buttons);
    layout->addWidget(split, 1);
}

void ForcePlots::appendSamples(std::span<const double> time_s, std::span<const double> position_mm,
                               std::span<const double> force_N)
{
    if (model_)
        return;  // the model is the one source while observed
    const std::size_t n = std::min({time_s.size(), position_mm.size(), force_N.size()});
    own_.time_s.insert(own_.time_s.end(), time_s.begin(), time_s.begin() + n);
    own_.position_mm.insert(own_.position_mm.end(), position_mm.begin(), position_mm.begin() + n);
    own_.force_N.insert(own_.force_N.end(), force_N.begin(), force_N.begin() + n);
    if (!paused_)
        dirty_ = true;
}

void ForcePlots::append(double time_s, double position_mm, double force_N)
{
    appendSamples({&time_s, 1}, {&position_mm, 1}, {&force_N, 1});
}

void ForcePlots::clear()
{
    if (!model_)
        own_.clear();
    forgetShown();
}

void ForcePlots::forgetShown()
{
    shown_ = 0;
    fMin_ = fMax_ = xMin_ = xMax_ = 0.0;
    for (QCustomPlot* plot : {forceTime_, positionTime_, forcePosition_}) {
        for (int i = plot->itemCount() - 1; i >= 0; --i) {
            QCPAbstractItem* item = plot->item(i);
            if (item != limitTime_ && item != limitCurve_ && item != limitLabel_)
                plot->removeItem(item);
        }
    }
    events_.clear();
    dirty_ = true;
    setFollow(true);
    refresh();
}

void ForcePlots::observe(const devices::LiveRun* run)
{
    if (model_)
        disconnect(model_, nullptr, this, nullptr);
    model_ = run;
    data_ = run ? &run->series() : &own_;
    forgetShown();
    if (!run)
        return;
    connect(run, &devices::LiveRun::reset, this, &ForcePlots::forgetShown);
    connect(run, &devices::LiveRun::samplesAppended, this, [this] {
        if (!paused_)
            dirty_ = true;
    });
    connect(run, &devices::LiveRun::marksChanged, this, &ForcePlots::showMarks);
    connect(run, &devices::LiveRun::pulled, this, &ForcePlots::refresh);
    connect(run, &QObject::destroyed, this, [this] { observe(nullptr); });
    showMarks();
}

QString ForcePlots::markLabel(devices::LiveMarkKind kind)
{
    using K = devices::LiveMarkKind;
    switch (kind) {
    case K::Contact: return tr("contact");
    case K::Puncture: return tr("puncture");
    case K::MinorPuncture: return QString();  // marked without text: it would clutter the plot
    case K::Withdraw: return tr("withdraw");
    case K::Stop: return tr("stop");
    case K::EmergencyStop: return tr("E-STOP");
    case K::Fault: return tr("fault");
    case K::ForceLimit: return tr("force limit");
    }
    return {};
}

void ForcePlots::showMarks()
{
    if (!model_)
        return;
    for (Event& e : events_)
        for (QCPAbstractItem* item : e.items)
            item->parentPlot()->removeItem(item);
    events_.clear();
    for (const devices::LiveMark& m : model_->marks())
        addEvent(m.time_s, markLabel(m.kind));
    dirty_ = true;
}

void ForcePlots::setForceLimit(double force_N)
{
    limit_N_ = force_N;
    const bool on = force_N > 0.0;
    limitTime_->setVisible(on);
    limitCurve_->setVisible(on);
    limitLabel_->setVisible(on);
    for (QCPItemStraightLine* line : {limitTime_, limitCurve_}) {
        line->point1->setCoords(0.0, force_N);
        line->point2->setCoords(1.0, force_N);
    }
    dirty_ = true;
}

void ForcePlots::addEvent(double time_s, const QString& label)
{
    Event event{time_s, label, {}};
    const std::size_t slot = events_.size() + 1;  // staggers the labels of nearby events
    for (QCustomPlot* plot : {forceTime_, positionTime_}) {
        auto* line = new QCPItemStraightLine(plot);
        line->setPen(QPen(QColor(230, 140, 0), 1.0, Qt::DotLine));
        line->point1->setCoords(time_s, 0.0);
        line->point2->setCoords(time_s, 1.0);
        event.items.push_back(line);
        if (label.isEmpty())
            continue;
        auto* text = new QCPItemText(plot);
        text->position->setTypeX(QCPItemPosition::ptPlotCoords);
        text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        text->position->setCoords(time_s, 0.12 + 0.08 * double(slot % 3));
        text->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        text->setText(label);
        text->setColor(QColor(180, 100, 0));
        event.items.push_back(text);
    }
    // On the force-position plot the event sits on the curve at its sample.
    const auto it = std::lower_bound(data_->time_s.begin(), data_->time_s.end(), time_s);
    if (it != data_->time_s.end()) {
        const std::size_t i = std::size_t(it - data_->time_s.begin());
        auto* mark = new QCPItemTracer(forcePosition_);
        mark->position->setCoords(data_->position_mm[i], data_->force_N[i]);
        mark->setStyle(QCPItemTracer::tsCircle);
        mark->setSize(label.isEmpty() ? 5 : 8);
        mark->setPen(QPen(QColor(230, 140, 0), 2));
        event.items.push_back(mark);
        if (!label.isEmpty()) {
            auto* text = new QCPItemText(forcePosition_);
            text->position->setCoords(data_->position_mm[i], data_->force_N[i]);
            text->setPositionAlignment(Qt::AlignLeft | (slot % 2 ? Qt::AlignTop : Qt::AlignBottom));
            text->setText(label);
            text->setColor(QColor(180, 100, 0));
            event.items.push_back(text);
        }
    }
    events_.push_back(std::move(event));
    dirty_ = true;
}

void ForcePlots::removeEvents(const QString& label)
{
    const auto gone = std::stable_partition(events_.begin(), events_.end(), [&](const Event& e) { return e.label != label; });
    for (auto it = gone; it != events_.end(); ++it)
        for (QCPAbstractItem* item : it->items)
            item->parentPlot()->removeItem(item);
    events_.erase(gone, events_.end());
    dirty_ = true;
}

QStringList ForcePlots::eventLabels() const
{
    QStringList labels;
    for (const Event& e : events_)
        labels << e.label;
    return labels;
}

void ForcePlots::setFollow(bool on)
{
    if (follow_ == on)
        return;
    follow_ = on;
    followButton_->setChecked(on);
    dirty_ = true;
    emit followChanged(on);
}

void ForcePlots::setFollowWindow(double seconds)
{
    window_s_ = std::max(0.1, seconds);
    dirty_ = true;
}

void ForcePlots::setPaused(bool on)
{
    if (paused_ == on)
        return;
    paused_ = on;
    pauseButton_->setChecked(on);
    dirty_ = true;
    emit pausedChanged(on);
}

void ForcePlots::showAll()
{
    setFollow(false);
    if (shown_ == 0)
        return;
    settingRanges_ = true;
    forceTime_->xAxis->setRange(padded(data_->time_s.front(), data_->time_s[shown_ - 1], 0.1));
    forceTime_->yAxis->setRange(padded(std::min(fMin_, 0.0), std::max(fMax_, limit_N_), kMinForceSpan_N));
    positionTime_->yAxis->setRange(padded(xMin_, xMax_, kMinPositionSpan_mm));
    forcePosition_->xAxis->setRange(padded(xMin_, xMax_, kMinPositionSpan_mm));
    forcePosition_->yAxis->setRange(padded(std::min(fMin_, 0.0), std::max(fMax_, limit_N_), kMinForceSpan_N));
    settingRanges_ = false;
    for (QCustomPlot* plot : {forceTime_, positionTime_, forcePosition_})
        plot->replot();
}

void ForcePlots::userMovedView()
{
    setFollow(false);
}

void ForcePlots::refresh()
{
    if (!dirty_)
        return;
    dirty_ = false;
    if (!paused_) {
        for (std::size_t i = shown_; i < data_->time_s.size(); ++i) {
            if (i == 0) {
                fMin_ = fMax_ = data_->force_N[0];
                xMin_ = xMax_ = data_->position_mm[0];
            }
            fMin_ = std::min(fMin_, data_->force_N[i]);
            fMax_ = std::max(fMax_, data_->force_N[i]);
            xMin_ = std::min(xMin_, data_->position_mm[i]);
            xMax_ = std::max(xMax_, data_->position_mm[i]);
        }
        shown_ = data_->time_s.size();
    }
    if (follow_ && !paused_)
        applyFollowRanges();
    if (limit_N_ > 0.0) {
        const double latest = shown_ ? data_->force_N[shown_ - 1] : 0.0;
        const bool above = forceTime_->yAxis->range().upper < limit_N_;
        const QLocale locale;  // as the control panel's spin boxes write the limit
        limitLabel_->setText(tr("limit %1 N%2 · margin %3 N")
                                 .arg(locale.toString(limit_N_, 'f', 2))
                                 .arg(above ? tr(" (above the plot)") : QString())
                                 .arg(locale.toString(margin_N_.value_or(limit_N_ - latest), 'f', 2)));
    }
    keepEventLabelsInside();
    for (QCustomPlot* plot : {forceTime_, positionTime_, forcePosition_})
        plot->replot();
    ++frames_;
}

// An event's label reads away from the nearer edge of the plot as it is now: the newest
// samples sit at the right edge, and a label written rightwards from there was cut ("E-ST").
void ForcePlots::keepEventLabelsInside()
{
    for (const Event& e : events_)
        for (QCPAbstractItem* item : e.items) {
            auto* text = qobject_cast<QCPItemText*>(item);
            if (!text)
                continue;
            const double x = text->position->coords().x();
            const bool rightHalf = x > item->parentPlot()->xAxis->range().center();
            const Qt::Alignment vertical = text->positionAlignment() & Qt::AlignVertical_Mask;
            text->setPositionAlignment((rightHalf ? Qt::AlignRight : Qt::AlignLeft) | vertical);
        }
}

void ForcePlots::applyFollowRanges()
{
    settingRanges_ = true;
    const double tEnd = shown_ ? data_->time_s[shown_ - 1] : 0.0;
    const double tStart = std::max(shown_ ? data_->time_s.front() : 0.0, tEnd - window_s_);
    forceTime_->xAxis->setRange(tStart, std::max(tEnd, tStart + window_s_));
    // The limit line comes into view once the force gets within half of it; until then a
    // label states it, so small forces are not squashed flat by a far-away limit.
    double top = std::max(fMax_ * 1.15, 0.2);
    if (limit_N_ > 0.0 && fMax_ > 0.5 * limit_N_)
        top = std::max(top, limit_N_);
    forceTime_->yAxis->setRange(padded(std::min(fMin_, 0.0), top, kMinForceSpan_N));
    positionTime_->yAxis->setRange(padded(std::min(xMin_, 0.0), xMax_, kMinPositionSpan_mm));
    forcePosition_->xAxis->setRange(padded(std::min(xMin_, 0.0), xMax_, kMinPositionSpan_mm));
    forcePosition_->yAxis->setRange(padded(std::min(fMin_, 0.0), top, kMinForceSpan_N));
    settingRanges_ = false;
}

void ForcePlots::updateData()
{
    auto* plot = qobject_cast<QCustomPlot*>(sender());
    const std::span<const double> t(data_->time_s.data(), shown_), x(data_->position_mm.data(), shown_), f(data_->force_N.data(), shown_);
    std::vector<double> keys, values, values2;
    auto fill = [&](const std::vector<std::size_t>& idx, std::span<const double> a, std::span<const double> b) {
        gather(a, idx, keys);
        gather(b, idx, values);
    };
    std::vector<std::size_t> idx;
    if (plot == forceTime_ || plot == positionTime_) {
        const bool force = plot == forceTime_;
        const std::span<const double> ch = force ? f : x;
        const QCPRange r = plot->xAxis->range();
        if (reduce_) {
            const std::span<const double> channels[] = {ch};
            idx = minMaxIndices(t, channels, r.lower, r.upper, std::max(1, plot->axisRect()->width()));
        } else {
            idx.resize(shown_);
            for (std::size_t i = 0; i < shown_; ++i)
                idx[i] = i;
        }
        fill(idx, t, ch);
        (force ? forceGraph_ : positionGraph_)->setData(QVector<double>(keys.begin(), keys.end()),
                                                         QVector<double>(values.begin(), values.end()), true);
        if (force) {
            drawnForceTime_ = idx.size();
            limitTime_->point1->setCoords(r.lower, limit_N_);
            limitTime_->point2->setCoords(r.upper, limit_N_);
        }
    } else if (plot == forcePosition_) {
        if (reduce_ && shown_ > 0) {
            const std::span<const double> channels[] = {x, f};
            idx = minMaxIndices(t, channels, t.front(), t.back(), std::max(1, plot->axisRect()->width()));
        } else {
            idx.resize(shown_);
            for (std::size_t i = 0; i < shown_; ++i)
                idx[i] = i;
        }
        gather(t, idx, values2);
        fill(idx, x, f);
        curve_->setData(QVector<double>(values2.begin(), values2.end()), QVector<double>(keys.begin(), keys.end()),
                        QVector<double>(values.begin(), values.end()), true);
        drawnForcePosition_ = idx.size();
    }
}

}  // namespace nb
