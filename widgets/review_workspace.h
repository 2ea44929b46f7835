#pragma once
// Video review: the video, the force plot and the label timeline on one cursor in recording
// time (video time = recording time + offset, sync.h). Step, play at 0.1x-2x, scrub; set the
// offset by hand (nudge by a frame), by marking one event in both, or automatically; label
// phases and events with one hotkey each, undo/redo without limit. Labels are saved with the
// run (RUN.labels.csv beside RUN.csv) after every change.
//
// Keys: 1-4 / 5-8 insertion / withdrawal a, b1, b2, c (friction; press to start a phase,
// the next key closes it and starts the next, the same key closes it); C P R I events
// (stiffness); Left/Right one frame (Shift: ten); Space play/pause; S split; Delete delete;
// Ctrl+Z undo; Ctrl+Shift+Z or Ctrl+Y redo.

#include "core/run.h"
#include "core/run_video_link.h"
#include "core/sync.h"
#include "video/labels_from_video.h"
#include "video/video_decoder.h"
#include "video/video_sync.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QWidget>

#include <atomic>
#include <map>
#include <memory>
#include <optional>

class QCPGraph;
class QCPItemStraightLine;
class QCustomPlot;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;
class QUndoStack;

namespace nb {

class LabelModel;
class LabelSetDialog;
class Timeline;
class VideoView;

class ReviewWorkspace : public QWidget {
    Q_OBJECT
public:
    explicit ReviewWorkspace(QWidget* parent = nullptr);
    ~ReviewWorkspace() override;

    // Both report problems in the workspace (status line) and return false.
    bool openRun(const QString& path);
    // Shows no run (another session was opened: its runs are not this one's).
    void closeRun();
    void openVideo(const QString& path);  // asynchronous: indexing, then the first frame
    // Attaches a video to the run in review and keeps it with the run in the session
    // (videos.json); the offset starts again from 0. False with a message when no run is open.
    bool attachVideo(const QString& path);
    // Open video…: the file dialog, then attachVideo().
    void chooseVideo();
    QString videoPath() const { return videoPath_; }
    QString runPath() const { return runPath_; }
    // How the current offset was found and with what confidence (kept with the run).
    SyncMethod syncMethod() const { return syncMethod_; }
    std::optional<double> syncConfidence() const { return syncConfidence_; }

    double cursorTime() const { return cursor_; }
    void setCursorTime(double recording_s);
    void stepFrames(int n);
    void setPlaying(bool on);
    bool isPlaying() const;
    void setSpeed(double factor);  // 0.1 .. 2; the speed box shows the nearest it offers
    double speed() const { return speed_; }
    TimelineMapping mapping() const { return mapping_; }
    // `method` and `confidence` say how it was found; stored with the run when one is open.
    void setMapping(const TimelineMapping& m, SyncMethod method = SyncMethod::Manual, std::optional<double> confidence = std::nullopt);
    // Marking one event in both sets the offset; a second one, a second or more away, sets the
    // drift too (the two buttons of the sync bar).
    void markEventInRecording();  // at the cursor
    void markEventInVideo();      // the frame shown
    int currentFrame() const { return frame_; }
    QString status() const;
    // Review's own status line, kept until the next thing Review says.
    void showStatus(const QString& text);

    LabelModel* labelModel() const { return model_; }
    QUndoStack* undoStack() const { return undo_; }
    Timeline* timeline() const { return timeline_; }
    VideoView* videoView() const { return video_; }
    video::VideoDecoder* decoder() const { return decoder_; }

    // Applies the labels suggested from the data (one undoable step). With a synchronised
    // video the tissue's motion in it (friction phases) or the surface's spring-back
    // (relaxation) is read first, in the background: the labels come with labelsSuggested().
    // Without a video, or before it is synchronised, from force and position at once.
    void suggestLabels();
    bool isSuggesting() const { return suggestWatcher_.isRunning(); }
    QPushButton* suggestButton() const { return suggestButton_; }
    // Opens the label-set editor for the run's protocol (not blocking); accepting it changes
    // the hotkeys at once and keeps the set in QSettings for the protocol.
    LabelSetDialog* editLabelSet();
    // Runs automatic synchronisation in the background; the result waits for accept/reject.
    void startAutoSync();
    // While Auto sync runs, its button stops it (and the tracking under it).
    void stopAutoSync();
    std::optional<SyncResult> pendingSync() const { return pendingSync_; }
    // Takes the pending offset (and drift); refused below kSyncAcceptConfidence unless the
    // operator ticked the override.
    void acceptSync();
    QPushButton* acceptButton() const { return acceptButton_; }
    QCheckBox* acceptOverride() const { return overrideBox_; }
    // "coded once": the operator says the video was never converted (RunVideoLink::codedOnce).
    QCheckBox* codedOnceBox() const { return codedOnceBox_; }
    void rejectSync();
    // Correlation against offset of the pending automatic sync, the offset found marked;
    // visible from the end of Auto sync until Accept/Reject.
    QCustomPlot* syncPlot() const { return syncPlot_; }
    // The recorded position (mm, right axis of the force plot) and, over it, the needle's
    // displacement tracked in the video, in recording time through the pending sync (while one
    // waits) or the offset and drift in use, and in mm through the sync's fit: where the two
    // part, the sync is wrong. The tracking runs in the background once a run and its video
    // are open (the same tracking Auto sync fits, which then takes its result); empty until then
    // or when no needle was found.
    QCPGraph* positionGraph() const { return positionGraph_; }
    QCPGraph* trackedGraph() const { return trackedGraph_; }
    bool isTracking() const { return syncWatcher_.isRunning(); }

signals:
    void frameShown(int index);
    void videoOpened();
    void syncFinished();
    void videoLinkChanged();  // the video or the sync kept with the run changed
    void trackingFinished();  // the background tracking ended (the trace may have changed)
    void labelsSuggested();   // suggestLabels() has applied its labels (or found none to add)

protected:
    void keyPressEvent(QKeyEvent* e) override;

private:
    // Video link kept per run (core/run_video_link.h).
    void restoreVideoLink();
    QString videoWarnings() const;  // the open video's warnings in one line (empty when none)
    void storeVideoLink();
    void clearVideo();
    void alignTimeline();
    void updateLabelCount();
    QLabel* labelCount_ = nullptr;  // the timeline's time axis under the plot's, to the pixel
    SyncMethod syncMethod_ = SyncMethod::None;
    std::optional<double> syncConfidence_;

    void buildUi();
    void handleLabelKey(int key);
    void updateShading();
    void saveLabels();
    void requestFrameForCursor();
    // Where the cursor can go (recording time): the run, and the whole video through the
    // mapping, so that a frame outside the run can be reached to mark an event in it.
    std::pair<double, double> cursorSpan() const;
    // Whether the cursor lies in the recording; says so in the status line when it does not.
    bool cursorInRecording();
    void updateSyncUi();
    void updateKeysHelp();
    // The one background job that tracks the needle and fits it (video::syncVideoToRun);
    // `forOperator`: Auto sync asked, its result becomes the pending sync.
    void startSyncJob(bool forOperator);
    void trackInBackground();
    void resetTrack();  // the run or the video changed: what was tracked no longer applies
    void updateTrace();
    void applySuggestion(const Labels& suggested, const QString& from);

    Run run_;
    QString runPath_;
    QString protocol_ = QStringLiteral("friction");
    TimelineMapping mapping_;
    double cursor_ = 0.0;
    std::optional<double> cursorAwaitingVideo_;  // beyond the run, until the video's index says how far it reaches
    int frame_ = -1, requested_ = -1;
    video::FrameIndexPtr index_;
    QString videoPath_;
    // A video the operator chose, not yet opened: the run's link keeps the one before until
    // it opens (a file that fails to open replaced it).
    bool attachPending_ = false;
    // Why the video last chosen was not attached: said again once the run's own video is back,
    // whose warnings (a rotation tag) took its place in the status line.
    QString notAttached_;
    QString labelsWarnedFor_;  // the run whose labels could not be saved beside it, said once
    std::map<QString, std::pair<QString, double>> pending_;  // track -> (label, start)
    std::optional<double> markRecording_, markVideo_;
    std::optional<std::pair<double, double>> markedEvent_;  // the last event marked in both (recording, video)
    void applyMarkedEvent();
    // What the operator changes of the sync, undoable with the labels (Ctrl+Z): a mark on the
    // wrong frame or a nudge too many took the offset before it away for good. Edits of one
    // box in a row (`mergeId`, the spin boxes' typing) are one step.
    struct SyncState {
        TimelineMapping mapping;
        SyncMethod method = SyncMethod::None;
        std::optional<double> confidence;
        std::optional<std::pair<double, double>> markedEvent;
    };
    SyncState syncState() const;
    void applySyncState(const SyncState& s);
    void changeSync(const SyncState& after, const QString& text, int mergeId = -1);
    std::optional<SyncResult> pendingSync_;
    double speed_ = 1.0;
    double playStartCursor_ = 0.0;
    QElapsedTimer playClock_;
    bool loadingLabels_ = false;

    LabelModel* model_;
    QUndoStack* undo_;
    video::VideoDecoder* decoder_;
    VideoView* video_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    QCPItemStraightLine* plotCursor_ = nullptr;
    Timeline* timeline_ = nullptr;
    QTimer* playTimer_ = nullptr;
    QPushButton* playButton_ = nullptr;
    QComboBox* speedBox_ = nullptr;
    QDoubleSpinBox* offsetBox_ = nullptr;
    QDoubleSpinBox* driftBox_ = nullptr;
    QDoubleSpinBox* jumpBox_ = nullptr;
    QLabel* syncLabel_ = nullptr;
    QCustomPlot* syncPlot_ = nullptr;
    QCPItemStraightLine* syncMarker_ = nullptr;
    QPushButton* acceptButton_ = nullptr;
    QPushButton* autoSyncButton_ = nullptr;
    bool operatorStopped_ = false;  // the operator stopped Auto sync: no tracking in the background
    void updateAutoSyncButton();
    QCheckBox* overrideBox_ = nullptr;
    QCheckBox* codedOnceBox_ = nullptr;
    video::VideoSyncOptions syncOptions() const;  // for the marks drawn and what is said of the file
    void codedOnceChanged();
    void sayWhatHelps(const SyncResult& r);  // in the status line, for a result below the threshold
    QPushButton* rejectButton_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* keysHelp_ = nullptr;
    QFutureWatcher<video::VideoSync> syncWatcher_;
    std::shared_ptr<std::atomic_bool> jobCancel_;
    PictureMarks jobMarks_;  // what the operator had drawn on the video when the job began
    video::VideoSyncOptions jobOptions_;  // and what it was told
    int jobGeneration_ = 0, watchedGeneration_ = -1;
    bool wantPending_ = false;
    std::optional<video::VideoSync> tracked_;  // the last job's answer for this run and video
    PictureMarks trackedMarks_;
    // Suggest labels with the video: one job at a time, for the run, video and offset it began with.
    QFutureWatcher<video::VideoLabels> suggestWatcher_;
    std::shared_ptr<std::atomic_bool> suggestCancel_;
    int suggestGeneration_ = -1;
    TimelineMapping suggestMapping_;
    QPushButton* suggestButton_ = nullptr;
    QCPGraph* positionGraph_ = nullptr;
    QCPGraph* trackedGraph_ = nullptr;
};

}  // namespace nb
