#pragma once

#include "core/session.h"
#include "devices/device_set.h"

#include "devices/interlocks.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QPointer>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QMessageBox;
class QTimer;
class QDockWidget;
class QTabWidget;
class QMenu;
class QLockFile;
class QSettings;

namespace nb {

namespace devices {
class AcquisitionEngine;
struct DeviceSpec;
struct RunPlan;
struct EngineStatus;
struct RunSummary;
struct Sample;
class LiveRun;
}  // namespace devices
class ControlPanel;
class ForcePlots;
class SessionView;
class CalibrationWizard;
class ReviewWorkspace;
class AnalysisWorkspace;
class ExportDialog;
class WelcomeDialog;
class PlanPanel;
class PlanWalker;
struct Plan;

struct WorkbenchOptions {
    bool realtime = true;             // false: the simulated rig runs as fast as it can (tests)
    double rateHz = 1000.0;
    QString sessionDir;               // open (or create) this session; empty: the last one, else a new one
    double calibrationDwell_s = 2.0;  // averaging per mass in the calibration wizard
    bool persistSettings = true;      // restore and save window layout and settings
    // Devices from the settings (devices/daq, devices/stage: see devices/device_spec.h); off in
    // tests, which always run on the simulated rig.
    bool devicesFromSettings = true;
    // Makes the devices instead of the settings (tests: one helper connects the simulated rig
    // and keeps a hand on it, as QGroundControl's MockLink does).
    std::function<devices::DeviceSet()> deviceFactory;
    // With no session given or last used: show the welcome (new / open / recent) instead of
    // creating an empty session folder.
    bool welcome = true;
};

// The workbench window: the control panel and status (left), the live plots (centre), the
// session's runs (right), on the simulated rig. Drains the engine's live ring on a timer.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    explicit MainWindow(const WorkbenchOptions& options, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Closes without the quit question (a signal: the system is going down, or the operator's
    // kill): what moves is stopped and what records is saved, as on a confirmed quit. After a
    // SIGTERM the question stood unanswered and the process never went.
    void closeWithoutAsking();

    ControlPanel* controlPanel() const { return panel_; }
    ForcePlots* plots() const { return plots_; }
    SessionView* sessionView() const { return sessionView_; }
    ReviewWorkspace* reviewWorkspace() const { return review_; }
    AnalysisWorkspace* analysisWorkspace() const { return analysis_; }
    QTabWidget* workspaces() const { return tabs_; }
    // Opens a recorded run in the review workspace (with its video, when one lies beside it).
    void reviewRun(const QString& path);
    devices::AcquisitionEngine* engine() const { return engine_.get(); }
    const Session* session() const { return session_ ? &*session_ : nullptr; }
    // Runs recovered when the session was opened (file names).
    const QStringList& recoveredRuns() const { return recovered_; }
    QString lastRunPath() const { return lastRunPath_; }
    QString lastEndReason() const { return lastEndReason_; }
    int runsEnded() const { return runsEnded_; }

    // Opens a session folder (recovering interrupted runs); false with a message on error.
    bool openSession(const QString& dir);
    bool createSession(const QString& dir, const SessionInfo& info);
    // Session ▸ Details…: the dialog, then setSessionInfo() with what was entered.
    void editSessionDetails();
    // Saves the open session's details (false with a message when it cannot).
    bool setSessionInfo(const SessionInfo& info);
    // The non-modal calibration wizard, fed from the live stream.
    CalibrationWizard* openCalibrationWizard();
    void useCalibration(const StoredCalibration& calibration);
    // Devices ▸ Choose devices…: the dialog, then switchDevices() with the choice.
    void chooseDevices();
    // Replaces the engine with one on `spec`'s devices (the simulated rig for any that cannot be
    // opened, with a message). Refused while a run records or the calibration wizard is open.
    // True when every chosen device opened.
    bool switchDevices(const devices::DeviceSpec& spec);
    // Devices ▸ Simulated rig…: the dialog, then the engine rebuilt on the chosen rig.
    void chooseSimulatedRig();
    // The simulated rig kept with the open session, if it differs from the one running.
    void restoreSimulatedRig();
    // Whether the stage moves or a run records now (Esc is then the emergency stop).
    bool motionOrRecording() const;
    // The emergency stop, from the panel button or Esc anywhere.
    void emergencyStopNow();
    // Reads NEEDLEBENCH_SESSION_DIR (a fresh or given session, no saved settings, the default
    // simulated rig) and NEEDLEBENCH_FAST_SIM=1 (simulated clock): scenario tests under X.
    static WorkbenchOptions optionsFromEnvironment();
    // Session ▸ Export session…: the export dialog (non-modal; null without a session).
    ExportDialog* exportSession();
    // The welcome: new session, open one, or a recent one.
    WelcomeDialog* showWelcome();
    // The experiment plan walked in this window (issue 16; main_window_plan.cpp).
    PlanWalker* planWalker() const { return planWalker_; }
    PlanPanel* planPanel() const { return planPanel_; }
    // Session ▸ New plan from template…: the dialog, then startPlan() with the plan made.
    void newPlanDialog();
    // Makes `plan` the session's plan.json and walks it (false with a message when refused).
    bool startPlan(const Plan& plan);

protected:
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void buildMenus();
    // Startup, welcome, recent sessions, video and export actions (issue 14).
    // A warning box named `name` (modeless: the E-stop stays at hand), or that box again with `text`.
    void sayInABox(const QString& name, const QString& title, const QString& text);
    // What the quit question asks in state `st` (a run to stop, a needle left in tissue); empty
    // when quitting needs no question.
    static QString quitQuestionText(const devices::EngineStatus& s);
    // Deeper than this past the start, quitting asks first (1 mm: a needle at its start rests
    // clear of the tissue; the stage's own settling is far less).
    static constexpr double kAwayFromStart_mm = 1.0;
    void openStartupSession();
    // What the operator was looking at when the window closed: the tab, and Review's run and
    // cursor (a run of the session opened at start only).
    void saveWorkspace(QSettings& settings) const;
    void restoreWorkspace();
    QStringList recentSessions() const;
    void rememberRecentSession(const QString& dir);
    void addDayActions(QMenu* sessionMenu);
    // A new engine on `spec` (nullopt: the simulated rig); `problem` says why it fell back.
    std::unique_ptr<devices::AcquisitionEngine> makeEngine(const std::optional<devices::DeviceSpec>& spec, QString* problem,
                                                           std::optional<double> forceLimit_N = std::nullopt);
    std::unique_ptr<devices::AcquisitionEngine> engineOn(devices::DeviceSet devices, std::optional<double> forceLimit_N = std::nullopt);
    // Connects the engine's signals to the window (the force limit and calibration are the caller's).
    void attachEngine();
    void onStatus(const devices::EngineStatus& status);
    void onRunEnded(const devices::RunSummary& summary);
    void startRun();
    void newSessionDialog();
    void openSessionDialog();
    void showMessage(const QString& text, bool alarm = false);
    void refitMessage();
    QString shownMessage_;  // the status line's text whole, shortened again when the window is resized
    bool shownAlarm_ = false;
    // `text` with the open session's folder left out of the paths it names.
    QString withinSession(QString text) const;

    // Operator safety (issue 12), in main_window_safety.cpp.
    void installSafety();
    // Refuses `control` with the reason in the status bar when the interlocks forbid it now.
    bool refused(Control control);
    // Bias or zero: when the interlocks advise against it, asks before insisting.
    void biasOrInsist();
    void zeroOrInsist();
    void noteMotionCommand() { motionCommand_.start(); }
    devices::DeviceSpec currentSpec() const;
    // The plan walker's part (main_window_plan.cpp): its dock and menu entries, the session's
    // plan on opening, the next run's settings set and locked, each plan run's attempt.
    void buildPlanDock();
    void addPlanActions(QMenu* sessionMenu);
    void openSessionPlan();
    void armPlanRun();
    void showPlan();
    // At Start: the plan run's file and metadata into `plan`; false when refused (message shown).
    bool beginPlanRun(devices::RunPlan& plan);
    void endPlanRun(const QString& endReason);
    void planStatus(const devices::EngineStatus& status);
    // The simulated rig the next plan run asks for, once the rig is at rest.
    void applyPlanRig();
    // The simulated rig's preset, tip and seed in the run's metadata (sim_tissue, sim_tip, sim_seed).
    void addRigMetadata(devices::RunPlan& plan) const;

    WorkbenchOptions options_;
    std::unique_ptr<devices::AcquisitionEngine> engine_;
    std::optional<Session> session_;
    std::unique_ptr<QLockFile> sessionLock_;  // the open session's, while this window has it
    ControlPanel* panel_ = nullptr;
    ForcePlots* plots_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    ReviewWorkspace* review_ = nullptr;
    AnalysisWorkspace* analysis_ = nullptr;
    SessionView* sessionView_ = nullptr;
    QDockWidget* panelDock_ = nullptr;
    QDockWidget* sessionDock_ = nullptr;
    QPointer<CalibrationWizard> wizard_;
    QPointer<QMessageBox> quitQuestion_;  // asked while the stage moves; modeless
    bool quitConfirmed_ = false;
    QTimer* drainTimer_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QString summaryDevicesWhole_, summaryDevices_;  // the devices' description, and as the summary shows it
    devices::LiveRun* liveRun_ = nullptr;  // what the plots and the calibration wizard observe
    bool runIsLinear_ = false;
    QString lastRunPath_, lastEndReason_;
    int runsEnded_ = 0;
    QStringList recovered_;
    QString nominalSensor_;
    QElapsedTimer motionCommand_;  // since the last motion the window asked for (status lags)
    std::shared_ptr<devices::DeviceSpec> spec_;  // the devices the engine runs on (null: the factory's)
    PlanWalker* planWalker_ = nullptr;
    PlanPanel* planPanel_ = nullptr;
    QDockWidget* planDock_ = nullptr;
    bool planRigPending_ = false;
    bool planPanelBusy_ = false;  // what the Plan dock last showed: the rig moving or recording
};

}  // namespace nb
