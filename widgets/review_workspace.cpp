#include "review_workspace.h"
#include "core/local_number.h"

#include "widgets/modeless_dialogs.h"

#include "label_commands.h"
#include "label_model.h"
#include "label_set_dialog.h"
#include "timeline.h"
#include "video_view.h"

#include "core/data_names.h"
#include "core/label_suggest.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "video/frame_reader.h"
#include "video/video_sync.h"
#include "video/video_error.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDir>
#include <QStandardPaths>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPointer>
#include <QSignalBlocker>
#include <QPushButton>
#include <QSplitter>
#include <QTimer>
#include <QUndoCommand>
#include <QUndoStack>
#include <QUnhandledException>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <qcustomplot.h>

#include <algorithm>
#include <limits>
#include <functional>
#include <cmath>
#include <utility>

namespace nb {

namespace {

// What went wrong in a background job, in its own words: QtConcurrent hands on an exception that
// is no QException as a QUnhandledException, whose what() is "std::exception" (the window said
// "Automatic sync failed: std::exception" for a line outside the region, a video too short...).
QString jobFailure(const std::exception& e)
{
    if (const auto* unhandled = dynamic_cast<const QUnhandledException*>(&e); unhandled && unhandled->exception()) {
        try {
            std::rethrow_exception(unhandled->exception());
        } catch (const std::exception& thrown) {
            return QString::fromUtf8(thrown.what());
        } catch (...) {
        }
    }
    return QString::fromUtf8(e.what());
}

// One change of the sync (ReviewWorkspace::changeSync); `apply` sets a state on the workspace.
template <typename State>
class SyncCommand : public QUndoCommand {
public:
    SyncCommand(State before, State after, std::function<void(const State&)> apply, const QString& text, int mergeId)
        : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), apply_(std::move(apply)), mergeId_(mergeId)
    {
    }
    void redo() override { apply_(after_); }
    void undo() override { apply_(before_); }
    int id() const override { return mergeId_; }
    bool mergeWith(const QUndoCommand* other) override
    {
        after_ = static_cast<const SyncCommand*>(other)->after_;
        return true;
    }

private:
    State before_, after_;
    std::function<void(const State&)> apply_;
    int mergeId_;
};

enum SyncMergeId { OffsetTyped = 0x5e01, DriftTyped };

}  // namespace

ReviewWorkspace::ReviewWorkspace(QWidget* parent)
    : QWidget(parent), model_(new LabelModel(this)), undo_(new QUndoStack(this)), decoder_(new video::VideoDecoder(this))
{
    setFocusPolicy(Qt::StrongFocus);
    buildUi();
    connect(decoder_, &video::VideoDecoder::indexProgress, this, [this](int done, int expected) {
        video_->setMessage(expected > 0 ? tr("Indexing the video: %1 of %2 frames").arg(done).arg(expected)
                                        : tr("Indexing the video: %1 frames").arg(done));
    });
    connect(decoder_, &video::VideoDecoder::opened, this, [this](video::FrameIndexPtr index) {
        if (videoPath_.isEmpty())
            return;  // the run changed to one without video while this one was indexed
        index_ = index;
        if (attachPending_) {
            attachPending_ = false;
            storeVideoLink();
        }
        if (const QString said = videoWarnings(); !said.isEmpty())
            showStatus(said);
        if (!notAttached_.isEmpty())
            showStatus(std::exchange(notAttached_, QString()));
        if (run_.size() == 0)
            timeline_->setRange(0.0, index->duration_s());
        if (cursorAwaitingVideo_)
            setCursorTime(*cursorAwaitingVideo_);
        requested_ = -1;
        requestFrameForCursor();
        emit videoOpened();
        trackInBackground();
    });
    connect(decoder_, &video::VideoDecoder::failed, this, [this](const QString& message) {
        video_->setMessage(message);
        if (attachPending_) {
            // Back to the video the run had (or none), which the session still names.
            attachPending_ = false;
            restoreVideoLink();
            notAttached_ = tr("%1 (not attached: the run keeps the video it had)").arg(message);
            showStatus(notAttached_);
            if (!videoPath_.isEmpty() && index_)
                notAttached_.clear();  // the run's video is on screen already: nothing comes to cover it
            return;
        }
        showStatus(message);
    });
    connect(decoder_, &video::VideoDecoder::frameReady, this, [this](int n, double t, const QImage& image) {
        // A frame of the video shown before, decoded while the run or the video changed: the
        // view said "no video" and went on showing it.
        if (!index_)
            return;
        frame_ = n;
        video_->setFrame(image, n, t,
                         index_->decodedAcrossDamage(n) ? tr("decoded across a damaged stretch: partly made up by the decoder") : QString());
        emit frameShown(n);
    });
    connect(model_, &LabelModel::labelsChanged, this, [this] {
        updateShading();
        saveLabels();
        updateLabelCount();
    });
    connect(&syncWatcher_, &QFutureWatcher<video::VideoSync>::finished, this, [this] {
        if (watchedGeneration_ != jobGeneration_)
            return;  // the run or the video changed while it ran
        const bool forOperator = wantPending_;
        wantPending_ = false;
        updateAutoSyncButton();
        if (jobCancel_ && jobCancel_->load()) {
            // Stopped by the operator: what it tracked so far is not a trace, nor a sync.
            tracked_.reset();
            updateTrace();
            emit trackingFinished();
            return;
        }
        try {
            video::VideoSync vs = syncWatcher_.result();
            if (jobOptions_.codedOnce != codedOnceBox_->isChecked())
                vs = video::refitVideoSync(std::move(vs), *index_, run_, syncOptions());  // ticked or cleared meanwhile
            if (forOperator) {
                pendingSync_ = vs.result;
                sayWhatHelps(vs.result);
            }
            tracked_ = std::move(vs);
            trackedMarks_ = jobMarks_;
        } catch (const std::exception& e) {
            tracked_.reset();
            if (forOperator) {
                pendingSync_.reset();
                showStatus(tr("Automatic sync failed: %1").arg(jobFailure(e)));
            }
        }
        if (forOperator) {
            updateSyncUi();
            emit syncFinished();
        }
        updateTrace();
        emit trackingFinished();
    });
    connect(&suggestWatcher_, &QFutureWatcher<video::VideoLabels>::finished, this, [this] {
        suggestButton_->setEnabled(true);
        const video::VideoLabels found = suggestWatcher_.result();
        if (found.cancelled || suggestGeneration_ != jobGeneration_) {
            showStatus(tr("Suggestion stopped: the run or its video changed"));
            emit labelsSuggested();
            return;
        }
        if (!(suggestMapping_ == mapping_)) {
            showStatus(tr("Suggestion dropped: the video's offset changed while it was read; suggest again"));
            emit labelsSuggested();
            return;
        }
        const QString name = QFileInfo(videoPath_).fileName();
        QString from;
        if (!found.videoUsed)
            from = tr("force and position only (%1: %2)").arg(name, found.problem);
        else if (found.phases)
            from = tr("force, position and the tissue's motion in %1").arg(name);
        else if (found.relaxationProblem && !found.relaxationProblem->isEmpty())
            from = tr("force and position; no relaxation from %1: %2").arg(name, *found.relaxationProblem);
        else
            from = tr("force and position, the relaxation from the surface in %1").arg(name);
        applySuggestion(found.labels, from);
    });
}

ReviewWorkspace::~ReviewWorkspace()
{
    if (suggestCancel_)
        suggestCancel_->store(true);
    suggestWatcher_.waitForFinished();
    if (jobCancel_)
        jobCancel_->store(true);
    try {
        syncWatcher_.waitForFinished();
    } catch (const std::exception&) {
        // A cancelled job may end in an exception (too little tracked): nobody needs it now.
    }
}

void ReviewWorkspace::buildUi()
{
    video_ = new VideoView(this);
    video_->setFocusPolicy(Qt::NoFocus);
    connect(video_, &VideoView::openRequested, this, &ReviewWorkspace::chooseVideo);
    connect(video_, &VideoView::videoDropped, this, &ReviewWorkspace::attachVideo);
    // What the operator draws on the video is kept with the run's link to it, for a restart.
    connect(video_, &VideoView::marksChanged, this, &ReviewWorkspace::storeVideoLink);
    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("reviewForcePlot"));
    plot_->setFocusPolicy(Qt::NoFocus);
    // The wheel zooms time; the label timeline below follows (same axis, to the pixel).
    plot_->setInteractions(QCP::iRangeZoom);
    plot_->axisRect()->setRangeZoom(Qt::Horizontal);
    // Room on the left for the timeline's track names, which sit under the plot's margin.
    plot_->axisRect()->setMinimumMargins(QMargins(92, 15, 15, 15));
    plot_->addGraph();
    plot_->graph(0)->setPen(QPen(QColor(30, 30, 30), 1.2));
    plot_->xAxis->setLabel(tr("recording time [s]"));
    plot_->yAxis->setLabel(tr("force [N]"));
    // The recorded position and the needle tracked in the video, on the right axis.
    plot_->graph(0)->setName(tr("force"));
    positionGraph_ = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    positionGraph_->setName(tr("recorded position"));
    positionGraph_->setPen(QPen(QColor(40, 90, 200), 1.0));
    trackedGraph_ = plot_->addGraph(plot_->xAxis, plot_->yAxis2);
    trackedGraph_->setName(tr("needle tracked in the video"));
    trackedGraph_->setPen(QPen(QColor(230, 120, 0), 1.6, Qt::DashLine));
    plot_->yAxis2->setVisible(true);
    plot_->yAxis2->setLabel(tr("position [mm]"));
    plot_->legend->setVisible(true);
    QFont legendFont = font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.85);
    plot_->legend->setFont(legendFont);
    plot_->legend->setBrush(QColor(255, 255, 255, 200));
    // In one row above the plot, not over it: the force and the position reach every corner.
    plot_->axisRect()->insetLayout()->take(plot_->legend);
    plot_->axisRect()->insetLayout()->simplify();
    plot_->plotLayout()->insertRow(0);
    plot_->plotLayout()->addElement(0, 0, plot_->legend);
    plot_->plotLayout()->setRowStretchFactor(0, 0.001);
    plot_->legend->setWrap(2);  // the plot beside the video is narrow: two names a row
    plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    plot_->legend->setBorderPen(Qt::NoPen);
    plot_->legend->setMargins(QMargins(4, 0, 4, 0));
    plotCursor_ = new QCPItemStraightLine(plot_);
    plotCursor_->setPen(QPen(QColor(220, 0, 0), 1.5));
    plotCursor_->point1->setCoords(0, 0);
    plotCursor_->point2->setCoords(0, 1);
    plot_->setMinimumHeight(200);  // the legend's two rows and a force axis that reads
    connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) {
        setCursorTime(plot_->xAxis->pixelToCoord(e->position().x()));
    });

    timeline_ = new Timeline(model_, undo_, this);
    timeline_->setFocusPolicy(Qt::NoFocus);
    connect(timeline_, &Timeline::cursorMoved, this, &ReviewWorkspace::setCursorTime);
    connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this](const QCPRange& r) {
        timeline_->setRange(r.lower, r.upper);
    });
    connect(plot_, &QCustomPlot::afterLayout, this, &ReviewWorkspace::alignTimeline);
    connect(plot_, &QCustomPlot::afterReplot, this, &ReviewWorkspace::alignTimeline);

    // Transport.
    auto* transport = new QHBoxLayout;
    auto button = [&](const QString& text, const QString& tip, auto slot) {
        auto* b = new QPushButton(text, this);
        b->setToolTip(tip);
        b->setFocusPolicy(Qt::NoFocus);
        connect(b, &QPushButton::clicked, this, slot);
        transport->addWidget(b);
        return b;
    };
    button(tr("−10"), tr("ten frames back (Shift+Left)"), [this] { stepFrames(-10); });
    button(tr("−1"), tr("one frame back (Left)"), [this] { stepFrames(-1); });
    playButton_ = button(tr("Play"), tr("play / pause (Space)"), [this] { setPlaying(!isPlaying()); });
    button(tr("+1"), tr("one frame forward (Right)"), [this] { stepFrames(1); });
    button(tr("+10"), tr("ten frames forward (Shift+Right)"), [this] { stepFrames(10); });
    speedBox_ = new QComboBox(this);
    speedBox_->setObjectName(QStringLiteral("reviewSpeed"));
    speedBox_->setFocusPolicy(Qt::NoFocus);
    for (double s : {0.1, 0.25, 0.5, 1.0, 1.5, 2.0})
        speedBox_->addItem(tr("%1×").arg(s), s);
    speedBox_->setCurrentIndex(3);
    connect(speedBox_, &QComboBox::currentIndexChanged, this, [this] { setSpeed(speedBox_->currentData().toDouble()); });
    transport->addWidget(speedBox_);
    auto* jump = new QDoubleSpinBox(this);
    jump->setRange(-1e6, 1e6);
    jump->setDecimals(3);
    jump->setSuffix(tr(" s"));
    jump->setToolTip(tr("jump to a recording time"));
    connect(jump, &QDoubleSpinBox::editingFinished, this, [this, jump] {
        setCursorTime(jump->value());
        // The keyboard back to the hotkeys: the next label key went into the box.
        if (jump->hasFocus())
            setFocus(Qt::OtherFocusReason);
    });
    jumpBox_ = jump;
    jump->setFocusPolicy(Qt::ClickFocus);  // the workspace keeps the keyboard for the hotkeys
    transport->addWidget(new QLabel(tr("go to"), this));
    transport->addWidget(jump);
    transport->addStretch();

    // Synchronisation.
    auto* sync = new QHBoxLayout;
    // Two rows (the offset and drift; finding them) so a laptop screen holds them.
    auto* syncFind = new QHBoxLayout;
    QHBoxLayout* syncRow = sync;
    sync->addWidget(new QLabel(tr("video offset"), this));
    offsetBox_ = new QDoubleSpinBox(this);
    offsetBox_->setFocusPolicy(Qt::ClickFocus);
    offsetBox_->setRange(-3600, 3600);
    offsetBox_->setDecimals(4);
    offsetBox_->setSingleStep(0.001);
    offsetBox_->setSuffix(tr(" s"));
    offsetBox_->setToolTip(tr("video time = recording time + offset"));
    connect(offsetBox_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (std::abs(v - mapping_.offset_s) > 1e-7) {
            SyncState after = syncState();
            after.mapping.offset_s = v;
            after.method = SyncMethod::Manual;
            after.confidence.reset();
            changeSync(after, tr("set the video offset"), OffsetTyped);
        }
    });
    sync->addWidget(offsetBox_);
    driftBox_ = new QDoubleSpinBox(this);
    driftBox_->setFocusPolicy(Qt::ClickFocus);
    driftBox_->setRange(-10000, 10000);
    driftBox_->setDecimals(1);
    driftBox_->setSuffix(tr(" ppm"));
    driftBox_->setToolTip(tr("clock drift of the video against the force record (video runs fast: positive)"));
    connect(driftBox_, &QDoubleSpinBox::valueChanged, this, [this](double ppm) {
        SyncState after = syncState();
        after.mapping.drift = ppm * 1e-6;
        after.method = SyncMethod::Manual;
        after.confidence.reset();
        changeSync(after, tr("set the drift"), DriftTyped);
    });
    sync->addWidget(new QLabel(tr("drift"), this));
    sync->addWidget(driftBox_);
    auto syncButton = [&](const QString& text, const QString& tip, auto slot) {
        auto* b = new QPushButton(text, this);
        b->setToolTip(tip);
        b->setFocusPolicy(Qt::NoFocus);
        connect(b, &QPushButton::clicked, this, slot);
        syncRow->addWidget(b);
        return b;
    };
    auto frameDuration = [this] { return index_ ? index_->frameDuration() : 1.0 / 29.97; };
    syncButton(tr("−1 frame"), tr("nudge the offset by one frame"), [this, frameDuration] {
        SyncState after = syncState();
        after.mapping.nudge(-1, frameDuration());
        after.method = SyncMethod::Manual;
        after.confidence.reset();
        changeSync(after, tr("nudge the offset by a frame"));
    });
    syncButton(tr("+1 frame"), tr("nudge the offset by one frame"), [this, frameDuration] {
        SyncState after = syncState();
        after.mapping.nudge(1, frameDuration());
        after.method = SyncMethod::Manual;
        after.confidence.reset();
        changeSync(after, tr("nudge the offset by a frame"));
    });
    syncRow = syncFind;
    syncButton(tr("Mark event in force"), tr("the event is at the cursor in the force record"), [this] { markEventInRecording(); });
    syncButton(tr("Mark event in video"), tr("the event is in the frame shown"), [this] { markEventInVideo(); });
    autoSyncButton_ = syncButton(tr("Auto sync"), QString(), [this] {
        if (wantPending_)
            stopAutoSync();
        else
            startAutoSync();
    });
    autoSyncButton_->setObjectName(QStringLiteral("autoSync"));
    // Under Auto sync, in the height the result beside it takes anyway: the row has no width to spare.
    syncFind->removeWidget(autoSyncButton_);
    auto* autoSyncColumn = new QVBoxLayout;
    autoSyncColumn->setSpacing(2);
    autoSyncColumn->addWidget(autoSyncButton_);
    codedOnceBox_ = new QCheckBox(tr("coded once"), this);
    codedOnceBox_->setObjectName(QStringLiteral("codedOnce"));
    codedOnceBox_->setFocusPolicy(Qt::NoFocus);
    codedOnceBox_->setToolTip(tr("tick when the video is as its camera or console wrote it, never converted (as a lab converts "
                                 "a console's export to H.264): the coder's lag on a slow needle, and the offset with it, are "
                                 "then known more closely. Kept with the run's video."));
    connect(codedOnceBox_, &QCheckBox::toggled, this, [this] { codedOnceChanged(); });
    autoSyncColumn->addWidget(codedOnceBox_);
    autoSyncColumn->addStretch();
    syncFind->addLayout(autoSyncColumn);
    syncLabel_ = new QLabel(this);
    syncLabel_->setObjectName(QStringLiteral("syncResult"));
    // A long result wraps in the space there is instead of widening the window.
    syncLabel_->setWordWrap(true);
    syncLabel_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    syncLabel_->setMinimumWidth(120);
    syncLabel_->setToolTip(tr("r: correlation of the needle's tracked displacement with the recorded position at the offset found; "
                              "confidence also weighs how unique the peak is, whether both halves of the video agree and the motion onsets"));
    syncFind->addWidget(syncLabel_, 1);
    // Accept/Reject sit with the offset they set (the row below would not fit a laptop in German).
    syncRow = sync;
    acceptButton_ = syncButton(tr("Accept"), tr("use the offset found"), [this] { acceptSync(); });
    overrideBox_ = new QCheckBox(tr("accept a low confidence"), this);
    overrideBox_->setFocusPolicy(Qt::NoFocus);
    overrideBox_->setToolTip(tr("the offset found is below the accept threshold: tick only after checking it on an event in both"));
    connect(overrideBox_, &QCheckBox::toggled, this, [this] { updateSyncUi(); });
    sync->addWidget(overrideBox_);
    rejectButton_ = syncButton(tr("Reject"), tr("keep the current offset"), [this] { rejectSync(); });
    sync->addStretch();
    syncPlot_ = new QCustomPlot(this);
    syncPlot_->setFocusPolicy(Qt::NoFocus);
    syncPlot_->setFixedHeight(86);
    syncPlot_->addGraph();
    syncPlot_->graph(0)->setPen(QPen(QColor(30, 30, 30), 1.2));
    syncPlot_->xAxis->setLabel(tr("video offset [s]"));
    syncPlot_->yAxis->setLabel(QStringLiteral("r"));  // as the result beside it says; "correlation r" ran past the 86 px
    {
        // 0, 0.5 and 1 read in its 86 px; ticks every 0.2 ran into each other.
        QSharedPointer<QCPAxisTickerFixed> ticker(new QCPAxisTickerFixed);
        ticker->setTickStep(0.5);
        syncPlot_->yAxis->setTicker(ticker);
    }
    syncMarker_ = new QCPItemStraightLine(syncPlot_);
    syncMarker_->setPen(QPen(QColor(220, 0, 0), 1.5, Qt::DashLine));

    // Labels.
    auto* labels = new QHBoxLayout;
    suggestButton_ = new QPushButton(tr("Suggest labels"), this);
    suggestButton_->setFocusPolicy(Qt::NoFocus);
    suggestButton_->setToolTip(tr("phases or events from force and position, and from the synchronised video when there is one"));
    connect(suggestButton_, &QPushButton::clicked, this, &ReviewWorkspace::suggestLabels);
    labels->addWidget(suggestButton_);
    auto* editSet = new QPushButton(tr("Edit label set…"), this);
    editSet->setFocusPolicy(Qt::NoFocus);
    editSet->setToolTip(tr("add, rename or remove the labels of this protocol and their hotkeys"));
    connect(editSet, &QPushButton::clicked, this, &ReviewWorkspace::editLabelSet);
    labels->addWidget(editSet);
    labelCount_ = new QLabel(this);
    labelCount_->setObjectName(QStringLiteral("labelCount"));
    labels->addWidget(labelCount_);
    keysHelp_ = new QLabel(this);
    keysHelp_->setObjectName(QStringLiteral("keysHelp"));
    keysHelp_->setWordWrap(true);
    keysHelp_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    labels->addWidget(keysHelp_, 1);
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("reviewStatus"));
    status_->setWordWrap(true);
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    // Two lines kept for it: a status that wrapped to a second line moved the buttons above it
    // down a line, under the pointer of an operator about to click one (and under xdotool's).
    status_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    status_->setMinimumHeight(2 * status_->fontMetrics().lineSpacing());

    auto* top = new QSplitter(Qt::Horizontal, this);
    top->addWidget(video_);
    // The label timeline sits right under the force plot, so both share one time axis.
    auto* forceColumn = new QWidget(top);
    auto* forceLayout = new QVBoxLayout(forceColumn);
    forceLayout->setContentsMargins(0, 0, 0, 0);
    forceLayout->setSpacing(0);
    forceLayout->addWidget(plot_, 1);
    forceLayout->addWidget(timeline_);
    top->addWidget(forceColumn);
    top->setStretchFactor(0, 1);
    top->setStretchFactor(1, 1);
    top->setSizes({1000, 1000});  // half each: the force needs as much width as the picture
    plot_->setMinimumWidth(320);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(top, 1);
    layout->addLayout(transport);
    layout->addLayout(labels);
    layout->addLayout(sync);
    layout->addLayout(syncFind);
    layout->addWidget(syncPlot_);
    layout->addWidget(status_);

    playTimer_ = new QTimer(this);
    playTimer_->setInterval(15);
    connect(playTimer_, &QTimer::timeout, this, [this] {
        setCursorTime(playStartCursor_ + playClock_.elapsed() / 1000.0 * speed_);
        if (cursor_ >= cursorSpan().second)
            setPlaying(false);
    });
    updateSyncUi();
    model_->setDefinitions(savedLabelSet(protocol_));
    updateKeysHelp();
    updateShading();
    updateLabelCount();
}

void ReviewWorkspace::updateKeysHelp()
{
    QStringList keys;
    for (const LabelDef& d : model_->definitions())
        keys << QStringLiteral("%1 %2/%3").arg(QKeySequence(d.key).toString(QKeySequence::NativeText), trackDisplayName(d.track), labelDisplayName(d.label));
    keysHelp_->setText(tr("Keys: %1 · S split · Del delete · Ctrl+Z undo").arg(keys.join(QStringLiteral(", "))));
}

LabelSetDialog* ReviewWorkspace::editLabelSet()
{
    auto* dialog = new LabelSetDialog(protocol_, model_->definitions(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        const QList<LabelDef> defs = dialog->definitions();
        // A phase being marked may belong to a label that is gone.
        for (const auto& [track, p] : pending_)
            timeline_->setPending(track, {}, std::nullopt);
        pending_.clear();
        model_->setDefinitions(defs);
        saveLabelSet(protocol_, defs);
        updateKeysHelp();
        showStatus(tr("Label set of %1 saved: %2 labels").arg(protocol_).arg(defs.size()));
    });
    showModeless(dialog);  // a run may be recording meanwhile (modeless_dialogs.h)
    return dialog;
}

void ReviewWorkspace::showStatus(const QString& text) { status_->setText(text); }
QString ReviewWorkspace::status() const { return status_->text(); }

// Where the labels of `runPath` go when they cannot be written beside it: the user's own data
// folder, by the session's folder name and the labels file's name.
static QString keptLabelsPath(const QString& runPath)
{
    QString name = QFileInfo(labelsPathFor(runPath)).fileName();
    if (name.size() > 200)  // a name the run's own disk refused for its length
        name = name.left(189) + QStringLiteral(".labels.csv");
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("unsaved-labels/%1/%2").arg(QFileInfo(runPath).absoluteDir().dirName(), name));
}

// A labels file with rows that could not be read is copied aside before the next label saved
// over it drops them: what the operator typed stays on disk, beside the run, to mend by hand.
// An identical copy made at an earlier opening is reused.
static QString setLabelsFileAside(const QString& labelsPath)
{
    const QFileInfo fi(labelsPath);
    QString base = fi.fileName();
    base.chop(int(qstrlen(".labels.csv")));
    QFile original(labelsPath);
    if (!original.open(QIODevice::ReadOnly))
        return {};
    const QByteArray bytes = original.readAll();
    for (int k = 1; k < 100; ++k) {
        const QString copy = fi.dir().filePath(base + (k == 1 ? QStringLiteral(".unread") : QStringLiteral(".unread-%1").arg(k)) + QStringLiteral(".labels.csv"));
        QFile existing(copy);
        if (existing.exists()) {
            if (existing.open(QIODevice::ReadOnly) && existing.readAll() == bytes)
                return copy;
            continue;
        }
        return QFile::copy(labelsPath, copy) ? copy : QString();
    }
    return {};
}

bool ReviewWorkspace::openRun(const QString& path)
{
    notAttached_.clear();
    markRecording_.reset();
    markVideo_.reset();
    markedEvent_.reset();
    try {
        // A run cut off mid-row (a crash) is read up to its last whole row, saying so.
        RunReadResult read = readRunFile(path, {.dropTruncatedLastRow = true});
        Run run = std::move(read.run);
        resetTrack();
        Labels labels;
        QStringList labelsNotes;
        const QString lp = labelsPathFor(path);
        if (QFileInfo::exists(lp)) {
            // A labels file with a bad row (edited by hand) or none readable at all does not keep
            // the run from Review; its rows that can be read are shown.
            try {
                LabelsRead read = readLabels(lp);
                labels = std::move(read.labels);
                labelsNotes = read.problems();
            } catch (const RunFileError& e) {
                labelsNotes << e.message();
            }
            if (!labelsNotes.isEmpty()) {
                const QString copy = setLabelsFileAside(lp);
                labelsNotes << (copy.isEmpty() ? tr("the labels file could not be copied aside: the next label saved replaces it")
                                               : tr("the labels file as it was is kept in %1").arg(QDir::toNativeSeparators(copy)));
            }
        }
        run_ = std::move(run);
        runPath_.clear();  // no saving while loading
        const QString protocol = run_.metadata.value(QStringLiteral("protocol"), QString());
        protocol_ = protocol == QLatin1String("friction") ? protocol : QStringLiteral("stiffness");
        model_->setDefinitions(savedLabelSet(protocol_));
        model_->setLabels(labels);
        runPath_ = path;
        undo_->clear();
        // Labels made while they could not be written beside the run (a full disk) are the
        // operator's latest: taken back, and saved beside the run when it can be written. The
        // next label replaced them, and what was kept was lost.
        const QString kept = keptLabelsPath(path);
        QString keptNote;
        if (QFileInfo::exists(kept)) {
            try {
                labels = readLabelsFile(kept);
                model_->setLabels(labels);
                saveLabels();
                keptNote = QFileInfo::exists(kept) ? tr("labels taken from %1 (not yet saved beside the run)").arg(QDir::toNativeSeparators(kept))
                                                   : tr("labels kept in %1 are saved beside the run again").arg(QDir::toNativeSeparators(kept));
            } catch (const RunFileError& e) {
                keptNote = tr("labels kept in %1 cannot be read: %2").arg(QDir::toNativeSeparators(kept), e.message());
            }
        }
        pending_.clear();
        QVector<double> t(run_.time_s.begin(), run_.time_s.end()), f(run_.force_N.begin(), run_.force_N.end());
        plot_->graph(0)->setData(t, f, true);
        positionGraph_->setData(t, QVector<double>(run_.position_mm.begin(), run_.position_mm.end()), true);
        trackedGraph_->data()->clear();
        plot_->rescaleAxes();
        plot_->yAxis->scaleRange(1.1);
        plot_->yAxis2->scaleRange(1.1);
        timeline_->setRange(plot_->xAxis->range().lower, plot_->xAxis->range().upper);
        updateKeysHelp();
        updateShading();
        setCursorTime(run_.time_s.front());
        showStatus(tr("%1 opened: %2 samples, %3 labels read").arg(QFileInfo(path).fileName()).arg(run_.size()).arg(labels.size())
                   + (keptNote.isEmpty() ? QString() : QStringLiteral("; ") + keptNote)
                   + (labelsNotes.isEmpty() ? QString() : QStringLiteral("; ") + labelsNotes.join(QStringLiteral("; ")))
                   + (read.warnings.isEmpty() ? QString() : QStringLiteral("; ") + read.warnings.join(QStringLiteral("; "))));
        restoreVideoLink();
        return true;
    } catch (const RunFileError& e) {
        showStatus(e.message());
        return false;
    }
}

void ReviewWorkspace::closeRun()
{
    setPlaying(false);
    runPath_.clear();  // nothing is saved from here on
    run_ = Run{};
    model_->setLabels({});
    undo_->clear();
    for (const auto& [track, p] : pending_)
        timeline_->setPending(track, {}, std::nullopt);
    pending_.clear();
    plot_->graph(0)->data()->clear();
    positionGraph_->data()->clear();
    trackedGraph_->data()->clear();
    plot_->replot();
    pendingSync_.reset();
    clearVideo();  // the marks and what was tracked go with it
    setCursorTime(0.0);
    setMapping({}, SyncMethod::None);
    updateSyncUi();
    updateShading();
    updateLabelCount();
    showStatus(tr("No run open: double-click one in the session list"));
}

void ReviewWorkspace::openVideo(const QString& path)
{
    // Marks belong to one run and one video, and so do the region and the line drawn on it.
    markRecording_.reset();
    markVideo_.reset();
    markedEvent_.reset();
    if (path != videoPath_) {
        // Kept with the link when the new video is attached, not before (nothing to store yet).
        const QSignalBlocker quiet(video_);
        video_->setMarks({});
        const QSignalBlocker alsoQuiet(codedOnceBox_);
        codedOnceBox_->setChecked(false);  // said of another file
    }
    videoPath_ = path;
    index_.reset();
    resetTrack();
    frame_ = -1;
    video_->openButton()->hide();
    video_->setMessage(tr("Indexing the video…"));
    decoder_->open(path);
}

void ReviewWorkspace::updateLabelCount()
{
    labelCount_->setText(tr("labels: %n", nullptr, int(model_->labels().size())));
}

void ReviewWorkspace::alignTimeline()
{
    const QRect axis = plot_->axisRect()->rect();
    const QPoint left = timeline_->mapFromGlobal(plot_->mapToGlobal(axis.topLeft()));
    timeline_->setAxisPixels(left.x(), axis.width());
}

void ReviewWorkspace::clearVideo()
{
    markRecording_.reset();
    markVideo_.reset();
    markedEvent_.reset();
    videoPath_.clear();
    index_.reset();
    resetTrack();
    frame_ = -1;
    requested_ = -1;
    video_->clearVideo();
    {
        const QSignalBlocker quiet(video_);  // the marks went with the video they were drawn on
        video_->setMarks({});
        const QSignalBlocker alsoQuiet(codedOnceBox_);
        codedOnceBox_->setChecked(false);
    }
    // What the decoder still does for the video gone (indexing it, reading a frame of a file
    // since deleted) is no longer this run's: it said "cannot reopen the video" or "Indexing
    // the video" over a run without one (video probe).
    decoder_->close();
}

bool ReviewWorkspace::attachVideo(const QString& path)
{
    if (runPath_.isEmpty()) {
        showStatus(tr("Open a run first (double-click it in the session list), then attach its video"));
        return false;
    }
    if (!QFileInfo(path).isFile()) {
        showStatus(tr("%1: no such video file").arg(QDir::toNativeSeparators(path)));
        return false;
    }
    // An offset belongs to one video: a new one starts from nothing (kept once it opens; the
    // decoder may say so before open() returns).
    attachPending_ = true;
    pendingSync_.reset();
    updateSyncUi();
    setMapping({}, SyncMethod::None);
    openVideo(QFileInfo(path).absoluteFilePath());
    showStatus(tr("%1 attached to %2; sync it (Auto sync, or mark an event in both)")
                   .arg(QFileInfo(path).fileName(), QFileInfo(runPath_).fileName()));
    return true;
}

void ReviewWorkspace::chooseVideo()
{
    if (runPath_.isEmpty()) {
        showStatus(tr("Open a run first (double-click it in the session list), then attach its video"));
        return;
    }
    // Modeless: a run may be recording meanwhile (modeless_dialogs.h). The video goes to the
    // run the chooser was opened for, even if another is opened in Review before it closes.
    FileChoice choice;
    choice.title = tr("Open the video of %1").arg(QFileInfo(runPath_).fileName());
    choice.dir = QFileInfo(runPath_).absolutePath();
    choice.filter = tr("Videos (%1);;All files (*)").arg(QStringLiteral("*.") + videoSuffixes().join(QStringLiteral(" *.")));
    chooseFileModeless(this, choice, [this, run = runPath_](const QString& path) {
        if (run == runPath_)
            attachVideo(path);
        else
            showStatus(tr("Video not attached: %1 is no longer the run in review").arg(QFileInfo(run).fileName()));
    });
}

void ReviewWorkspace::restoreVideoLink()
{
    attachPending_ = false;
    QString problem;
    std::optional<RunVideoLink> link = readRunVideoLink(runPath_, &problem);
    // The link the run file carries itself (the demo's, an export's), else the run's own video
    // beside it (RUN.mp4), when the session names none. The file's offset was ignored and its
    // video shown at offset 0 (0.6 to 1.3 s off on the demo's runs).
    if (!link)
        link = runVideoLinkFromRun(run_, runPath_);
    QString video = link ? link->video : QString();
    if (!link)
        video = videoBesideRun(runPath_);
    const QString keepPath = runPath_;
    runPath_.clear();  // restoring is no change to store
    pendingSync_.reset();
    updateSyncUi();
    setMapping(link ? link->mapping : TimelineMapping{}, link ? link->method : SyncMethod::None, link ? link->confidence : std::nullopt);
    runPath_ = keepPath;
    if (video.isEmpty()) {
        clearVideo();
    } else if (!QFileInfo::exists(video)) {
        clearVideo();
        video_->setMessage(tr("The video of this run, %1, is missing. Open it again where it now lies.").arg(QDir::toNativeSeparators(video)));
        videoPath_.clear();
    } else if (video != videoPath_ || !index_) {
        openVideo(video);
    } else {
        requested_ = -1;
        requestFrameForCursor();
        trackInBackground();
        // The run opened again with its video still open: the video's warnings (a damaged
        // stretch) were said only when it was opened, and the run's line covered them.
        if (const QString said = videoWarnings(); !said.isEmpty())
            showStatus(status_->text() + QStringLiteral("; ") + said);
    }
    if (!videoPath_.isEmpty()) {
        const QSignalBlocker quiet(video_);  // read from the store, nothing to store
        video_->setMarks(link ? link->marks : PictureMarks{});
        const QSignalBlocker alsoQuiet(codedOnceBox_);
        codedOnceBox_->setChecked(link && link->codedOnce);
    }
    if (!problem.isEmpty())
        showStatus(problem);
}

QString ReviewWorkspace::videoWarnings() const
{
    // All of them: each used to replace the one before, and only the last was read.
    if (!index_ || index_->warnings.isEmpty())
        return {};
    return tr("%1: %2").arg(QFileInfo(videoPath_).fileName(), index_->warnings.join(QStringLiteral("; ")));
}

void ReviewWorkspace::storeVideoLink()
{
    if (runPath_.isEmpty() || attachPending_)
        return;
    try {
        RunVideoLink link{videoPath_, mapping_, syncMethod_, syncConfidence_, video_->marks(), codedOnceBox_->isChecked()};
        const bool empty = videoPath_.isEmpty() && mapping_ == TimelineMapping{} && syncMethod_ == SyncMethod::None;
        writeRunVideoLink(runPath_, empty ? std::nullopt : std::optional(link));
        emit videoLinkChanged();
    } catch (const Error& e) {
        showStatus(tr("Video and sync not kept: %1").arg(e.message()));
    }
}

std::pair<double, double> ReviewWorkspace::cursorSpan() const
{
    double from = std::numeric_limits<double>::infinity(), to = -from;
    if (run_.size()) {
        from = run_.time_s.front();
        to = run_.time_s.back();
    }
    if (index_ && !index_->frames.empty()) {
        from = std::min(from, mapping_.toRecording(index_->frames.front().time_s));
        to = std::max(to, mapping_.toRecording(index_->frames.back().time_s));
    }
    return {from, to};
}

void ReviewWorkspace::setCursorTime(double t)
{
    // Only the run's span at offset 0 was reachable: a video that starts long before the
    // recording showed only its first frames, and the event to mark in it could not be reached
    // (video probe).
    // A place in the video beyond the run asked for while the video is still indexed (a
    // restart's restore) is taken when the index says how far the video reaches: it was clamped
    // to the run.
    cursorAwaitingVideo_.reset();
    if (const auto [from, to] = cursorSpan(); from <= to) {
        if ((t < from || t > to) && !index_ && !videoPath_.isEmpty())
            cursorAwaitingVideo_ = t;
        t = std::clamp(t, from, to);
    }
    cursor_ = t;
    // The plot follows a cursor that leaves it, to a tenth of its width inside (on its edge
    // the cursor hid under the axis).
    if (const QCPRange shown = plot_->xAxis->range(); run_.size() && (t < shown.lower || t > shown.upper)) {
        const double margin = 0.1 * shown.size();
        const double shift = t < shown.lower ? t - shown.lower - margin : t - shown.upper + margin;
        plot_->xAxis->setRange(shown.lower + shift, shown.upper + shift);
    }
    timeline_->setCursorTime(t);
    {
        const QSignalBlocker block(jumpBox_);
        jumpBox_->setValue(t);
    }
    for (auto& [track, p] : pending_)
        timeline_->setPending(track, p.first, p.second);
    plotCursor_->point1->setCoords(t, 0);
    plotCursor_->point2->setCoords(t, 1);
    plot_->replot(QCustomPlot::rpQueuedReplot);
    requestFrameForCursor();
}

void ReviewWorkspace::requestFrameForCursor()
{
    if (!index_)
        return;
    const int n = index_->frameAt(mapping_.toVideo(cursor_));
    if (n != requested_) {
        requested_ = n;
        decoder_->requestFrame(n);
    }
}

void ReviewWorkspace::stepFrames(int n)
{
    if (!index_) {
        setCursorTime(cursor_ + n * 0.002);
        return;
    }
    const int from = requested_ >= 0 ? requested_ : index_->frameAt(mapping_.toVideo(cursor_));
    const int to = std::clamp(from + n, 0, index_->size() - 1);
    // Land the cursor inside the frame (its start), so the frame shown is exactly `to`.
    setCursorTime(mapping_.toRecording(index_->frames[std::size_t(to)].time_s + 1e-6));
}

void ReviewWorkspace::setPlaying(bool on)
{
    if (on) {
        playStartCursor_ = cursor_;
        playClock_.start();
        playTimer_->start();
    } else {
        playTimer_->stop();
    }
    playButton_->setText(on ? tr("Pause") : tr("Play"));
}

bool ReviewWorkspace::isPlaying() const { return playTimer_->isActive(); }

void ReviewWorkspace::setSpeed(double factor)
{
    speed_ = std::clamp(factor, 0.1, 2.0);
    if (speedBox_) {
        int nearest = 0;
        for (int i = 1; i < speedBox_->count(); ++i)
            if (std::abs(speedBox_->itemData(i).toDouble() - speed_) < std::abs(speedBox_->itemData(nearest).toDouble() - speed_))
                nearest = i;
        const QSignalBlocker block(speedBox_);
        speedBox_->setCurrentIndex(nearest);
    }
    playStartCursor_ = cursor_;
    playClock_.restart();
}

bool ReviewWorkspace::cursorInRecording()
{
    // The cursor also goes over the video before and after the recording, where there is no
    // force to mark or label: a label at -20 s and a force mark before the first sample were
    // taken without a word (probe).
    if (run_.size() == 0 || (cursor_ >= run_.time_s.front() && cursor_ <= run_.time_s.back()))
        return true;
    showStatus(tr("The cursor (%1 s) is outside the recording (%2 to %3 s): labels and force marks go on the recording")
                   .arg(localNumber(cursor_, 3), localNumber(run_.time_s.front(), 3), localNumber(run_.time_s.back(), 3)));
    return false;
}

void ReviewWorkspace::markEventInRecording()
{
    if (!cursorInRecording())
        return;
    markRecording_ = cursor_;
    if (markVideo_)
        applyMarkedEvent();
    else
        showStatus(tr("Event marked in the force record at %1 s; now step the video to it and mark it there").arg(localNumber(cursor_, 3)));
}

void ReviewWorkspace::markEventInVideo()
{
    if (!index_ || index_->frames.empty())
        return;
    // The frame at the cursor, not the frame last shown: after a far step the frame on screen
    // may still be the one before while the cursor's is decoded, and the mark took that one
    // (probe: 11 frames off, while the status named the old frame's time).
    const int n = index_->frameAt(mapping_.toVideo(cursor_));
    markVideo_ = index_->frames[std::size_t(n)].time_s;
    if (markRecording_)
        applyMarkedEvent();
    else
        showStatus(tr("Event marked in the video at %1 s; now mark it in the force record").arg(localNumber(*markVideo_, 3)));
}

void ReviewWorkspace::applyMarkedEvent()
{
    const double r = *markRecording_, v = *markVideo_;
    markRecording_.reset();
    markVideo_.reset();
    // Two events at least a second apart give the drift as well; a drift over 1 % is no
    // clock's, but a mark on the wrong frame.
    constexpr double kMinApart_s = 1.0, kMaxDrift = 0.01;
    SyncState after = syncState();
    after.method = SyncMethod::EventMarks;
    after.confidence.reset();
    after.markedEvent = std::pair{r, v};
    const double apart_s = markedEvent_ ? std::abs(r - markedEvent_->first) : 0.0;
    const auto both = markedEvent_ && apart_s >= kMinApart_s ? TimelineMapping::fromEvents(markedEvent_->first, markedEvent_->second, r, v)
                                                            : std::nullopt;
    if (both && std::abs(both->drift) <= kMaxDrift) {
        after.mapping = *both;
        changeSync(after, tr("set the offset and drift from two events"));
        showStatus(tr("Offset and drift set from two events (%1 s apart): drift %2 ppm")
                       .arg(localNumber(apart_s, 2))
                       .arg(localNumber(both->drift * 1e6, 0)));
    } else {
        after.mapping = TimelineMapping::fromEvent(r, v, mapping_.drift);
        changeSync(after, tr("set the offset from an event"));
        if (both)
            showStatus(tr("Offset set. With the event before, it would mean a drift of %1 ppm, which no clock has: "
                          "check both marks; the drift was kept").arg(localNumber(both->drift * 1e6, 0)));
        else
            showStatus(tr("Offset set; mark a second event, a second or more away, in both to set the drift too"));
    }
}

ReviewWorkspace::SyncState ReviewWorkspace::syncState() const { return {mapping_, syncMethod_, syncConfidence_, markedEvent_}; }

void ReviewWorkspace::applySyncState(const SyncState& s)
{
    markedEvent_ = s.markedEvent;
    setMapping(s.mapping, s.method, s.confidence);
}

void ReviewWorkspace::changeSync(const SyncState& after, const QString& text, int mergeId)
{
    undo_->push(new SyncCommand<SyncState>(syncState(), after, [this](const SyncState& s) { applySyncState(s); }, text, mergeId));
}

void ReviewWorkspace::setMapping(const TimelineMapping& m, SyncMethod method, std::optional<double> confidence)
{
    mapping_ = m;
    syncMethod_ = method;
    syncConfidence_ = confidence;
    storeVideoLink();
    // Not over what the operator is typing (the change may be theirs): the box's text would
    // be written anew under the cursor.
    const QSignalBlocker block(offsetBox_), blockDrift(driftBox_);
    if (std::abs(offsetBox_->value() - m.offset_s) > 1e-9)
        offsetBox_->setValue(m.offset_s);
    if (std::abs(driftBox_->value() - m.drift * 1e6) > 1e-6)
        driftBox_->setValue(m.drift * 1e6);
    requested_ = -1;
    requestFrameForCursor();
    updateTrace();
}

void ReviewWorkspace::handleLabelKey(int key)
{
    const LabelDef* def = model_->definitionForKey(key);
    if (!def || !cursorInRecording())
        return;
    timeline_->setCurrentTrack(def->track);
    if (def->point) {
        undo_->push(new AddLabelCommand(model_, Label{def->track, def->label, cursor_, cursor_, {}}));
        return;
    }
    // Insertion and withdrawal phases follow one another: a phase started on one track closes
    // the one still open on another at the cursor (instead of leaving it hanging unseen).
    for (auto other = pending_.begin(); other != pending_.end();) {
        if (other->first == def->track) {
            ++other;
            continue;
        }
        const auto [label, start] = other->second;
        const QString track = other->first;
        other = pending_.erase(other);
        timeline_->setPending(track, {}, std::nullopt);
        const Label l{track, label, std::min(start, cursor_), std::max(start, cursor_), {}};
        if (l.end_s > l.start_s && model_->canPlace(l)) {
            undo_->push(new AddLabelCommand(model_, l));
            showStatus(tr("%1 on %2 closed at %3 s").arg(label, trackDisplayName(track)).arg(localNumber(cursor_, 3)));
        } else {
            showStatus(tr("%1 on %2 was not closed (it would be empty or overlap another phase): not added").arg(label, trackDisplayName(track)));
        }
    }
    const auto it = pending_.find(def->track);
    if (it != pending_.end()) {
        const auto [label, start] = it->second;
        pending_.erase(it);
        timeline_->setPending(def->track, {}, std::nullopt);
        const Label l{def->track, label, std::min(start, cursor_), std::max(start, cursor_), {}};
        if (l.end_s > l.start_s) {
            if (model_->canPlace(l))
                undo_->push(new AddLabelCommand(model_, l));
            else
                showStatus(tr("%1 overlaps another phase on %2: not added").arg(label, trackDisplayName(def->track)));
        }
        if (label == def->label)
            return;  // the same key closes the phase
    }
    pending_[def->track] = {def->label, cursor_};
    timeline_->setPending(def->track, def->label, cursor_);
}

void ReviewWorkspace::keyPressEvent(QKeyEvent* e)
{
    const bool ctrl = e->modifiers() & Qt::ControlModifier;
    const bool shift = e->modifiers() & Qt::ShiftModifier;
    // The status line says what was undone or redone: it kept what the undone step had said
    // ("Offset set; mark a second event…" after the offset went back to 0, probe).
    auto step = [this](bool forward) {
        if (!(forward ? undo_->canRedo() : undo_->canUndo()))
            return;
        const QString what = forward ? undo_->redoText() : undo_->undoText();
        forward ? undo_->redo() : undo_->undo();
        showStatus(forward ? tr("Redone: %1").arg(what) : tr("Undone: %1").arg(what));
    };
    if (ctrl && e->key() == Qt::Key_Z) {
        step(shift);
    } else if (ctrl && e->key() == Qt::Key_Y) {
        step(true);
    } else if (e->key() == Qt::Key_Left || e->key() == Qt::Key_Right) {
        stepFrames((e->key() == Qt::Key_Left ? -1 : 1) * (shift ? 10 : 1));
    } else if (e->key() == Qt::Key_Space) {
        setPlaying(!isPlaying());
    } else if (e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace) {
        const QString track = timeline_->currentTrack();
        const Label* target = model_->intervalAt(track, cursor_);
        if (!target) {  // the nearest point event within a frame
            for (const Label& l : model_->labels())
                if (l.isPoint() && l.track == track && std::abs(l.start_s - cursor_) < 0.02)
                    target = &l;
        }
        if (target)
            undo_->push(new RemoveLabelCommand(model_, *target));
    } else if (e->key() == Qt::Key_S && !ctrl) {
        if (const Label* l = model_->intervalAt(timeline_->currentTrack(), cursor_))
            undo_->push(new SplitLabelCommand(model_, *l, cursor_));
    } else if (!ctrl && model_->definitionForKey(e->key())) {
        handleLabelKey(e->key());
    } else {
        QWidget::keyPressEvent(e);
    }
}

void ReviewWorkspace::updateShading()
{
    // Rectangles behind the force curve, one per labelled phase.
    for (int i = plot_->itemCount() - 1; i >= 0; --i)
        if (auto* r = qobject_cast<QCPItemRect*>(plot_->item(i)))
            plot_->removeItem(r);
    for (const Label& l : model_->labels()) {
        if (l.isPoint())
            continue;
        auto* r = new QCPItemRect(plot_);
        r->setLayer(QStringLiteral("background"));
        r->topLeft->setTypeX(QCPItemPosition::ptPlotCoords);
        r->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
        r->bottomRight->setTypeX(QCPItemPosition::ptPlotCoords);
        r->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
        r->topLeft->setCoords(l.start_s, 0.0);
        r->bottomRight->setCoords(l.end_s, 1.0);
        QColor c = model_->colorOf(l);
        c.setAlpha(l.track == QLatin1String("withdrawal") ? 45 : 70);
        r->setBrush(c);
        r->setPen(Qt::NoPen);
    }
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ReviewWorkspace::saveLabels()
{
    if (runPath_.isEmpty())
        return;
    const QString kept = keptLabelsPath(runPath_);
    try {
        writeLabelsFile(labelsPathFor(runPath_), model_->labels());
        QFile::remove(kept);  // beside the run at last: the copy kept meanwhile is done with
    } catch (const RunFileError& e) {
        // Beside the run they cannot be written (a read-only or full disk): kept in the user's
        // own data folder instead, and said in a box once, where only a status line said it and
        // the labels were gone with the next run opened. Opening the run again takes them back.
        QString where;
        try {
            QDir().mkpath(QFileInfo(kept).absolutePath());
            writeLabelsFile(kept, model_->labels());
            where = tr("They are kept in %1, and saved beside the run when it is opened again and its folder can be written.").arg(QDir::toNativeSeparators(kept));
        } catch (const RunFileError& e2) {
            where = tr("They could not be kept elsewhere either (%1): they are lost when another run is opened.").arg(e2.message());
        }
        showStatus(tr("Labels not saved: %1").arg(e.message()));
        if (labelsWarnedFor_ != runPath_) {
            labelsWarnedFor_ = runPath_;
            warnModeless(this, tr("Labels not saved"), tr("Labels not saved: %1\n\n%2").arg(e.message(), where))
                ->setObjectName(QStringLiteral("labelsNotSaved"));
        }
    }
}

void ReviewWorkspace::suggestLabels()
{
    if (run_.size() == 0 || suggestWatcher_.isRunning())
        return;
    if (!index_ || syncMethod_ == SyncMethod::None) {
        // The picture on an unknown clock would put the phases in the wrong place.
        const QString from = index_                 ? tr("force and position (synchronise the video to have its motion used)")
                             : videoPath_.isEmpty() ? tr("force and position")
                                                    : tr("force and position (the video is still being indexed)");
        applySuggestion(nb::suggestLabels(run_), from);
        return;
    }
    suggestCancel_ = std::make_shared<std::atomic_bool>(false);
    suggestGeneration_ = jobGeneration_;
    suggestMapping_ = mapping_;
    suggestButton_->setEnabled(false);
    const QString name = QFileInfo(videoPath_).fileName();
    showStatus(tr("Reading the motion in %1 for the suggestion…").arg(name));
    const video::FrameIndex index = *index_;
    const Run run = run_;
    const TimelineMapping mapping = mapping_;
    const std::shared_ptr<std::atomic_bool> cancel = suggestCancel_;
    QPointer<ReviewWorkspace> self(this);
    auto progress = [self, name](int done, int total) {
        QMetaObject::invokeMethod(self, [self, name, done, total] {
            if (self && self->suggestWatcher_.isRunning())
                self->showStatus(tr("Reading the motion in %1 for the suggestion: frame %2 of %3").arg(name).arg(done).arg(total));
        }, Qt::QueuedConnection);
    };
    suggestWatcher_.setFuture(QtConcurrent::run([index, run, mapping, name, progress, cancel] {
        return video::suggestLabelsWithVideo(run, index, mapping, name, progress, cancel.get());
    }));
}

void ReviewWorkspace::applySuggestion(const Labels& suggested, const QString& from)
{
    // One undo step for what was placed, and none where nothing was.
    int placed = 0;
    for (const Label& l : suggested)
        if (model_->canPlace(l)) {
            if (placed++ == 0)
                undo_->beginMacro(tr("suggest labels"));
            undo_->push(new AddLabelCommand(model_, l));
        }
    if (placed > 0)
        undo_->endMacro();
    // What was added, not what was found: on a run already labelled it said "45 labels
    // suggested" and added none.
    QString text = tr("%n label(s) suggested from %1: check and correct them", nullptr, placed).arg(from);
    if (placed < int(suggested.size()))
        text += QLatin1Char(' ') + tr("(%n more left out: they overlap labels already there)", nullptr, int(suggested.size()) - placed);
    showStatus(text);
    emit labelsSuggested();
}

video::VideoSyncOptions ReviewWorkspace::syncOptions() const
{
    video::VideoSyncOptions options;
    const PictureMarks marks = video_->marks();
    options.roi = marks.region;
    if (!marks.needle.isNull())
        options.axis = marks.needle;
    options.codedOnce = codedOnceBox_->isChecked();
    return options;
}

void ReviewWorkspace::sayWhatHelps(const SyncResult& r)
{
    if (r.acceptable())
        return;
    // What the operator can do about it: say the file was coded once where only that is in doubt,
    // else check it on an event; and a needle too faint to be found, or a clock on its line, is
    // read where its line and a region around its path are drawn.
    const QString lag = localNumber(1000.0 * r.pictureLag_s, 0), give = localNumber(1000.0 * r.pictureLagUncertainty_s, 0);
    if (r.codedOnceWouldHelp())
        showStatus(tr("Low confidence: the video's coder shows this slow needle late, by %1 ms give or take %2 ms, as it may have "
                      "been converted; if it is as the camera or console coded it, tick “coded once”, else check the offset on an "
                      "event (contact or puncture) before accepting").arg(lag, give));
    else if (r.lagLimitsPrecision())
        showStatus(tr("Low confidence: the video's coder shows this slow needle late, by %1 ms give or take %2 ms; "
                      "check the offset on an event (contact or puncture) before accepting").arg(lag, give));
    else if (video_->needleLine().isNull())
        showStatus(tr("Low confidence: if the needle is faint or burnt-in text lies on its line, draw the line on the "
                      "video with Shift+drag (shaft to tip) and a region around its path with a drag, then Auto sync again"));
}

void ReviewWorkspace::codedOnceChanged()
{
    storeVideoLink();
    // The needle's track does not change with what the operator says of the file, only its fit:
    // the answer waiting for Accept (or the one Auto sync would take) is fitted again at once.
    if (!tracked_ || !index_)
        return;
    tracked_ = video::refitVideoSync(std::move(*tracked_), *index_, run_, syncOptions());
    if (!pendingSync_) {
        // The offset in use stays what the operator accepted or set.
        showStatus(tr("Kept with the video: Auto sync now fits the offset for it at once"));
        return;
    }
    pendingSync_ = tracked_->result;
    updateSyncUi();
    updateTrace();
    if (!pendingSync_->acceptable())
        sayWhatHelps(*pendingSync_);
    else if (codedOnceBox_->isChecked())
        showStatus(tr("Sync fitted again for a video coded once: confidence %1").arg(localNumber(pendingSync_->confidence, 2)));
    else
        showStatus(tr("Sync fitted again for a video that may have been converted: confidence %1").arg(localNumber(pendingSync_->confidence, 2)));
}

void ReviewWorkspace::startAutoSync()
{
    if (!index_ || run_.size() == 0) {
        showStatus(tr("Open a run and a video first"));
        return;
    }
    const PictureMarks marks = video_->marks();
    const bool running = syncWatcher_.isRunning() && watchedGeneration_ == jobGeneration_;
    if (!running && tracked_ && trackedMarks_ == marks) {
        // The background tracking already fitted this run and video with these marks.
        pendingSync_ = tracked_->result;
        updateSyncUi();
        updateTrace();
        QTimer::singleShot(0, this, [this] { emit syncFinished(); });
        return;
    }
    operatorStopped_ = false;
    syncLabel_->setText(tr("correlating…"));
    if (running && jobMarks_ == marks)
        wantPending_ = true;  // the background job is doing just this
    else
        startSyncJob(true);
    updateAutoSyncButton();
}

void ReviewWorkspace::stopAutoSync()
{
    if (!wantPending_)
        return;
    // The tracking stops as well, and is not started again in the background for this run and
    // video: on a long video the operator stops it to have the machine back.
    wantPending_ = false;
    operatorStopped_ = true;
    if (jobCancel_)
        jobCancel_->store(true);
    syncLabel_->setText(tr("Automatic sync stopped"));
    updateAutoSyncButton();
}

void ReviewWorkspace::updateAutoSyncButton()
{
    if (!autoSyncButton_)
        return;
    autoSyncButton_->setText(wantPending_ ? tr("Stop sync") : tr("Auto sync"));
    autoSyncButton_->setToolTip(wantPending_ ? tr("stop the automatic sync (the offset in use stays)")
                                             : tr("track the needle and fit its displacement to the recorded position. Drag on the video to draw a "
                                                  "region: the needle is read in it alone (leave burnt-in clocks and counters out). "
                                                  "Shift+drag from the shaft to the tip to draw the needle's line where it is not found."));
}

void ReviewWorkspace::startSyncJob(bool forOperator)
{
    if (jobCancel_)
        jobCancel_->store(true);
    jobCancel_ = std::make_shared<std::atomic_bool>(false);
    watchedGeneration_ = jobGeneration_;
    wantPending_ = forOperator;
    jobMarks_ = video_->marks();
    jobOptions_ = syncOptions();
    const video::FrameIndex index = *index_;
    const video::VideoSyncOptions options = jobOptions_;
    const Run run = run_;
    const std::shared_ptr<std::atomic_bool> cancel = jobCancel_;
    // How far the tracking is, while the operator waits for it: a long video showed
    // "correlating…" for minutes with nothing moving.
    QPointer<ReviewWorkspace> self(this);
    const int generation = jobGeneration_;
    auto progress = [self, generation](int done, int total) {
        QMetaObject::invokeMethod(self, [self, generation, done, total] {
            if (self && self->wantPending_ && self->watchedGeneration_ == generation && self->jobGeneration_ == generation)
                self->syncLabel_->setText(tr("correlating: frame %1 of %2…").arg(done).arg(total));
        }, Qt::QueuedConnection);
    };
    syncWatcher_.setFuture(QtConcurrent::run([index, run, options, cancel, progress] {
        return video::syncVideoToRun(index, run, options, progress, cancel.get());
    }));
}

void ReviewWorkspace::trackInBackground()
{
    if (!index_ || run_.size() == 0 || tracked_ || operatorStopped_ || (syncWatcher_.isRunning() && watchedGeneration_ == jobGeneration_))
        return;
    startSyncJob(false);
}

void ReviewWorkspace::resetTrack()
{
    ++jobGeneration_;
    if (suggestCancel_)
        suggestCancel_->store(true);
    if (jobCancel_)
        jobCancel_->store(true);
    if (wantPending_) {
        wantPending_ = false;
        syncLabel_->clear();
        updateAutoSyncButton();
    }
    operatorStopped_ = false;
    tracked_.reset();
    updateTrace();
}

void ReviewWorkspace::updateTrace()
{
    // While a sync waits for Accept, the trace shows what accepting it would do.
    const bool pending = pendingSync_.has_value();
    TimeSignal s;
    if (tracked_ && !tracked_->track.time_s.empty())
        s = trackedPosition({tracked_->track.time_s, tracked_->track.displacement_px}, tracked_->result,
                            pending ? pendingSync_->mapping() : mapping_);
    QVector<double> t(s.time_s.begin(), s.time_s.end()), x(s.value.begin(), s.value.end());
    trackedGraph_->setData(t, x, true);
    // Two names a row, pending or not: one a row took a third of the plot's height on a laptop
    // while the sync's curve took its place below, and the force was left 60 px.
    trackedGraph_->setName(pending ? tr("needle tracked (offset found)") : tr("needle tracked in the video"));
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void ReviewWorkspace::updateSyncUi()
{
    const bool low = pendingSync_ && !pendingSync_->acceptable();
    // Below the threshold Accept is a deliberate act: the operator ticks the override first.
    acceptButton_->setEnabled(pendingSync_.has_value() && (!low || overrideBox_->isChecked()));
    rejectButton_->setEnabled(pendingSync_.has_value());
    overrideBox_->setVisible(low);
    if (!low && overrideBox_->isChecked()) {
        const QSignalBlocker block(overrideBox_);
        overrideBox_->setChecked(false);
    }
    syncPlot_->setVisible(pendingSync_.has_value());
    if (!pendingSync_) {
        syncLabel_->clear();
        syncLabel_->setStyleSheet(QString());
        if (trackedGraph_)
            updateTrace();
        return;
    }
    QString text = tr("found %1 s (confidence %2, r = %3)")
                       .arg(localNumber(pendingSync_->offset_s, 3))
                       .arg(localNumber(pendingSync_->confidence, 2))
                       .arg(localNumber(std::abs(pendingSync_->correlation), 2));
    if (pendingSync_->drift != 0.0)
        text += tr(", drift %1 %").arg(localNumber(100.0 * pendingSync_->drift, 3));
    if (pendingSync_->pictureLag_s >= 0.0005)
        text += tr(", coded pictures %1 ms late (allowed for)").arg(localNumber(1000.0 * pendingSync_->pictureLag_s, 0));
    if (low)
        text = tr("LOW CONFIDENCE: %1; check it on an event before accepting").arg(text);
    syncLabel_->setText(text);
    syncLabel_->setStyleSheet(low ? QStringLiteral("QLabel { color: #b00000; font-weight: bold; }") : QString());
    QVector<double> offsets, r;
    for (const auto& [o, c] : pendingSync_->curve) {
        offsets << o;
        r << c;
    }
    syncPlot_->graph(0)->setData(offsets, r, true);
    syncPlot_->rescaleAxes();
    syncPlot_->yAxis->scaleRange(1.1);
    syncMarker_->point1->setCoords(pendingSync_->offset_s, 0);
    syncMarker_->point2->setCoords(pendingSync_->offset_s, 1);
    syncPlot_->replot(QCustomPlot::rpQueuedReplot);
    updateTrace();
}

void ReviewWorkspace::acceptSync()
{
    if (!pendingSync_ || (!pendingSync_->acceptable() && !overrideBox_->isChecked()))
        return;
    // The displacement sync measures the drift too; the speed fallback leaves it alone.
    const bool measuredDrift = pendingSync_->scale_px_per_mm != 0.0;
    SyncState after = syncState();
    after.mapping = {pendingSync_->offset_s, measuredDrift ? pendingSync_->drift : mapping_.drift};
    after.method = SyncMethod::Automatic;
    after.confidence = pendingSync_->confidence;
    changeSync(after, tr("accept the sync found"));
    pendingSync_.reset();
    updateSyncUi();
}

void ReviewWorkspace::rejectSync()
{
    pendingSync_.reset();
    overrideBox_->setChecked(false);
    updateSyncUi();
}

}  // namespace nb
