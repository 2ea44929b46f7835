#include "main_window.h"
#include "core/local_number.h"

#include "widgets/modeless_dialogs.h"
#include "core/run_file.h"
#include "core/run_keys.h"

#include "translation.h"

#include "core/events.h"
#include "core/fit_error.h"
#include "devices/acquisition_engine.h"
#include "devices/device_error.h"
#include "devices/device_set.h"
#include "devices/device_spec.h"
#include "devices/live_run.h"
#include "widgets/calibration_wizard.h"
#include "widgets/control_panel.h"
#include "widgets/device_dialog.h"
#include "widgets/export_dialog.h"
#include "widgets/welcome_dialog.h"
#include "widgets/force_plots.h"
#include "widgets/analysis/analysis_workspace.h"
#include "widgets/review_workspace.h"
#include "widgets/session_info_dialog.h"
#include "widgets/session_view.h"

#include <QAbstractButton>
#include <QLocale>
#include <QActionGroup>
#include <QRegularExpression>
#include <algorithm>
#include <QCloseEvent>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QLockFile>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QGuiApplication>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

namespace nb {

namespace {

QString defaultSessionRoot()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).filePath(QStringLiteral("sessions"));
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : MainWindow(optionsFromEnvironment(), parent) {}

MainWindow::MainWindow(const WorkbenchOptions& options, QWidget* parent) : QMainWindow(parent), options_(options)
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(tr("NeedleBench"));

    QString deviceProblem;
    engine_ = options_.deviceFactory
                  ? engineOn(options_.deviceFactory())
                  : makeEngine(options_.devicesFromSettings ? std::optional(devices::specFromSettings(QSettings())) : std::nullopt,
                               &deviceProblem);

    // Record live, review video against the force, analyse the session: one window, three tabs.
    liveRun_ = new devices::LiveRun(60.0, this);
    plots_ = new ForcePlots(this);
    plots_->observe(liveRun_);
    review_ = new ReviewWorkspace(this);
    analysis_ = new AnalysisWorkspace(this);
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName(QStringLiteral("workspaces"));
    tabs_->setDocumentMode(true);
    tabs_->addTab(plots_, tr("&Record"));
    tabs_->addTab(review_, tr("Revie&w"));  // Alt+V is the View menu
    tabs_->addTab(analysis_, tr("&Analysis"));
    // Review's keys (Space plays, digits label) act on the review: the keyboard goes there with
    // the tab. It stayed on the control panel's last button, and Space pressed it (the stage
    // was disabled and its zero lost).
    connect(tabs_, &QTabWidget::currentChanged, this, [this] {
        if (tabs_->currentWidget() == review_)
            review_->setFocus(Qt::TabFocusReason);
    });
    setCentralWidget(tabs_);

    panel_ = new ControlPanel(this);
    setWindowIcon(QIcon(QStringLiteral(":/icons/needlebench.svg")));  // after the panel registered the icons
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(panel_);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    // Its minimum, not its preferred width: the window must fit a 1366 px laptop. Room for the
    // scroll bar, which shows only when the jog fields or the latch banner are open on a low screen.
    scroll->setMinimumWidth(panel_->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    panelDock_ = new QDockWidget(tr("Control panel"), this);
    panelDock_->setObjectName(QStringLiteral("controlDock"));
    panelDock_->setWidget(scroll);
    panelDock_->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);  // never closed: E-stop lives here
    addDockWidget(Qt::LeftDockWidgetArea, panelDock_);

    sessionView_ = new SessionView(this);
    sessionDock_ = new QDockWidget(tr("Session"), this);
    sessionDock_->setObjectName(QStringLiteral("sessionDock"));
    sessionDock_->setWidget(sessionView_);
    addDockWidget(Qt::BottomDockWidgetArea, sessionDock_);
    // The control panel (with the E-stop and the status) gets the full height of the window.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    resizeDocks({sessionDock_}, {190}, Qt::Vertical);
    buildPlanDock();

    statusLabel_ = new QLabel(this);
    statusBar()->addPermanentWidget(statusLabel_);
    connect(sessionView_, &SessionView::runActivated, this, &MainWindow::reviewRun);
    if (!deviceProblem.isEmpty())
        showMessage(tr("Could not open the configured devices (%1); using the simulated rig.").arg(deviceProblem), true);

    installSafety();

    // Through engine_ each time: the operator may switch devices, and so the engine.
    connect(panel_, &ControlPanel::enableRequested, this, [this](bool on) { engine_->enableStage(on); });
    connect(panel_, &ControlPanel::biasRequested, this, &MainWindow::biasOrInsist);
    connect(panel_, &ControlPanel::zeroRequested, this, &MainWindow::zeroOrInsist);
    connect(panel_, &ControlPanel::forceLimitChanged, this, [this](double limit) { engine_->setForceLimit(limit, !isVisible()); });
    connect(panel_, &ControlPanel::forceLimitChanged, plots_, &ForcePlots::setForceLimit);
    connect(panel_, &ControlPanel::startRequested, this, &MainWindow::startRun);
    connect(panel_, &ControlPanel::withdrawRequested, this, [this](double v) {
        noteMotionCommand();
        engine_->withdraw(v);
        liveRun_->mark(devices::LiveMarkKind::Withdraw);
    });
    connect(panel_, &ControlPanel::stopMotionRequested, this, [this] {
        engine_->stopMotion();
        liveRun_->mark(devices::LiveMarkKind::Stop);
    });
    connect(panel_, &ControlPanel::endRunRequested, this, [this] { engine_->endRun(); });
    connect(panel_, &ControlPanel::emergencyStopRequested, this, &MainWindow::emergencyStopNow);
    connect(panel_, &ControlPanel::calibrateRequested, this, &MainWindow::openCalibrationWizard);

    attachEngine();
    buildMenus();

    QSettings settings;
    const bool restored = options_.persistSettings && restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    // A window closed maximised comes back so, whatever the window manager made of the
    // geometry's own flag (it came back at its minimum size after the first session).
    if (restored && settings.value(QStringLiteral("window/maximized")).toBool())
        setWindowState(windowState() | Qt::WindowMaximized);
    if (options_.persistSettings) {
        restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
        panel_->restoreSettings(settings);
        // Written as they change, not only at quit: a crash brought back an older, higher force
        // limit (and the mode, cycles and jog step were not kept at all).
        connect(panel_, &ControlPanel::settingsChanged, this, [this] {
            QSettings settings;
            panel_->saveSettings(settings);
        });
    }
    if (!options_.persistSettings) {
        resize(1400, 860);
    } else if (!restored) {
        // The first start: the layout wants 1400x860; on a smaller screen (a laptop's 1366x768)
        // the whole screen, where Qt's own guess cut off the panel's controls.
        const QScreen* screen = QGuiApplication::primaryScreen();
        const QSize room = screen ? screen->availableGeometry().size() : QSize(1400, 860);
        // The size it takes when the operator leaves maximised: without one, a window that was
        // only ever maximised came back at its minimum size (1087x598).
        resize(std::min(room.width(), 1400), std::min(room.height(), 860));
        if (room.width() < 1400 || room.height() < 860)
            setWindowState(windowState() | Qt::WindowMaximized);
    }
    engine_->setForceLimit(panel_->forceLimit(), true);
    engine_->setWithdrawForceLimit(panel_->withdrawForceLimit(), true);
    plots_->setForceLimit(panel_->forceLimit());

    openStartupSession();
    if (options_.persistSettings) {
        restoreWorkspace();
        // Kept as they change, as the panel's fields are: a crash loses none of them. Connected
        // after the restore, which the opening session's defaults would otherwise overwrite.
        connect(analysis_, &AnalysisWorkspace::choicesChanged, this, [this] {
            QSettings settings;
            analysis_->saveChoices(settings);
        });
    }

    drainTimer_ = new QTimer(this);
    drainTimer_->setInterval(25);  // 40 frames/s at most
    connect(drainTimer_, &QTimer::timeout, liveRun_, &devices::LiveRun::pull);
    drainTimer_->start();
    engine_->start();
}

std::unique_ptr<devices::AcquisitionEngine> MainWindow::makeEngine(const std::optional<devices::DeviceSpec>& spec,
                                                                   QString* problem, std::optional<double> forceLimit_N)
{
    devices::DeviceSpec chosen = spec.value_or(devices::DeviceSpec{});
    chosen.simulated.realtime = options_.realtime;
    spec_ = std::make_shared<devices::DeviceSpec>(chosen);
    return engineOn(devices::openDevicesOrSimulated(chosen, problem), forceLimit_N);
}

std::unique_ptr<devices::AcquisitionEngine> MainWindow::engineOn(devices::DeviceSet devices, std::optional<double> forceLimit_N)
{
    nominalSensor_ = devices.description;
    devices::EngineConfig config;
    config.rateHz = options_.rateHz;
    config.realtimeScheduling = options_.realtime;
    if (forceLimit_N)
        config.forceLimit_N = *forceLimit_N;
    return std::make_unique<devices::AcquisitionEngine>(std::move(devices), config);
}

void MainWindow::attachEngine()
{
    devices::AcquisitionEngine* e = engine_.get();
    connect(e, &devices::AcquisitionEngine::statusChanged, this, &MainWindow::onStatus);
    liveRun_->setSource(&e->liveRing());
    connect(e, &devices::AcquisitionEngine::runStarted, this, [this](const QString& path) {
        lastRunPath_ = path;
        liveRun_->beginRun(runIsLinear_);
        sessionView_->setBusyPath(path);
        showMessage(tr("Recording %1").arg(QDir::toNativeSeparators(path)));
        sessionView_->refresh();
    });
    connect(e, &devices::AcquisitionEngine::runEnded, this, &MainWindow::onRunEnded);
    connect(e, &devices::AcquisitionEngine::runRefused, this, [this](const QString& why) {
        showMessage(withinSession(why), true);
        // Start was pressed and nothing moved: the reason in a box (modeless: the E-stop stays
        // at hand), where a status line alone went by unread in a few seconds.
        sayInABox(QStringLiteral("runNotStarted"), tr("Run not started"), withinSession(why));
        if (!engine_->status().recording)
            endPlanRun(QStringLiteral("not started"));
    });
    connect(e, &devices::AcquisitionEngine::faultOccurred, this, [this](const QString& device, const QString& reason) {
        showMessage(tr("Fault: %1: %2").arg(device, reason), true);
        liveRun_->mark(devices::LiveMarkKind::Fault);
    });
    connect(e, &devices::AcquisitionEngine::forceLimitTripped, this, [this](double force, double position) {
        showMessage(tr("Force limit tripped at %1 N, %2 mm: the stage was stopped").arg(localNumber(force, 2)).arg(localNumber(position, 2)), true);
        liveRun_->mark(devices::LiveMarkKind::ForceLimit);
    });
    connect(e, &devices::AcquisitionEngine::message, this, [this](const QString& text) {
        statusBar()->setStyleSheet(QString());  // a plain note is not shown in the last alarm's red
        // Files in the session by their names, and elided in the middle where the rest would
        // run under the rig's summary on the right: a file name, at the end, is what the
        // operator looks for.
        const int room = statusBar()->width() - statusLabel_->width() - 12 * statusBar()->fontMetrics().averageCharWidth();
        statusBar()->showMessage(statusBar()->fontMetrics().elidedText(withinSession(text), Qt::ElideMiddle, std::max(room, 120)), 8000);
    });
}

void MainWindow::chooseDevices()
{
    if (refused(Control::ChangeSetup))
        return;
    DeviceDialog dialog(devices::specFromSettings(QSettings()), [] { return devices::listDevices(); }, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    {
        QSettings settings;
        devices::saveSpec(settings, dialog.spec());
    }
    switchDevices(dialog.spec());
}

bool MainWindow::switchDevices(const devices::DeviceSpec& spec)
{
    if (refused(Control::ChangeSetup))
        return false;
    if (wizard_) {
        showMessage(tr("Devices not changed: close the calibration wizard first."), true);
        return false;
    }
    engine_->shutdown();  // stops the axis and the stream, and lets go of the hardware
    QString problem;
    engine_ = makeEngine(spec, &problem, panel_->forceLimit());
    attachEngine();
    engine_->setWithdrawForceLimit(panel_->withdrawForceLimit(), true);
    if (const auto centre = devices::suggestedSineCentre_mm(currentSpec()))
        panel_->setSineCentre(*centre);
    if (session_)
        if (const auto cal = session_->activeCalibration())
            engine_->setCalibration(cal->fit.slope_V_per_g, cal->name);
    engine_->start();
    if (!problem.isEmpty()) {
        showMessage(tr("Could not open the chosen devices (%1); using the simulated rig.").arg(problem), true);
        return false;
    }
    showMessage(tr("Devices: %1").arg(engine_->deviceDescription()));
    return true;
}

MainWindow::~MainWindow()
{
    drainTimer_->stop();
    if (wizard_)
        delete wizard_.data();
    engine_->shutdown();
}

void MainWindow::buildMenus()
{
    auto* sessionMenu = menuBar()->addMenu(tr("&Session"));
    sessionMenu->addAction(tr("&New session…"), QKeySequence::New, this, &MainWindow::newSessionDialog);
    sessionMenu->addAction(tr("&Open session…"), QKeySequence::Open, this, &MainWindow::openSessionDialog);
    sessionMenu->addAction(tr("Session &details…"), this, &MainWindow::editSessionDetails);
    addDayActions(sessionMenu);
    addPlanActions(sessionMenu);
    sessionMenu->addSeparator();
    sessionMenu->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    auto* devicesMenu = menuBar()->addMenu(tr("&Devices"));
    devicesMenu->addAction(tr("&Choose devices…"), this, &MainWindow::chooseDevices);
    devicesMenu->addAction(tr("&Simulated rig…"), this, &MainWindow::chooseSimulatedRig);

    auto* calibration = menuBar()->addMenu(tr("&Calibration"));
    calibration->addAction(tr("&Calibrate force sensor…"), this, &MainWindow::openCalibrationWizard);
    calibration->addAction(tr("Use the sensor's &nominal calibration"), this, [this] {
        if (refused(Control::Calibrate))  // not while a run records: its forces would change scale
            return;
        StoredCalibration c;
        c.sensor = nominalSensor_;
        c.nominal = true;
        // The chain the devices were opened with: a bridge on a U6 is 100x weaker than the
        // simulated amplified chain.
        c.fit.slope_V_per_g = engine_->nominalSlope_V_per_g();
        if (!(c.fit.slope_V_per_g > 0.0)) {
            showMessage(tr("These devices do not state a nominal calibration: calibrate the sensor."), true);
            return;
        }
        c.fit.r2 = 1.0;
        c.name = QStringLiteral("nominal_") + QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd_HHmmss"));
        useCalibration(c);
    });

    auto* view = menuBar()->addMenu(tr("&View"));
    view->addAction(panelDock_->toggleViewAction());
    view->addAction(sessionDock_->toggleViewAction());
    view->addAction(planDock_->toggleViewAction());
    view->addSeparator();
    auto* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(this);
    const std::pair<QString, QString> names[] = {{QStringLiteral("en"), QStringLiteral("English")},
                                                 {QStringLiteral("de"), QStringLiteral("Deutsch")}};
    for (const auto& [code, name] : names) {
        QAction* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(preferredLanguage() == code);
        a->setData(code);
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code, a] {
            if (refused(Control::ChangeSetup)) {
                for (QAction* other : a->actionGroup()->actions())
                    other->setChecked(other->data().toString() == preferredLanguage());
                return;
            }
            setPreferredLanguage(code);
            QMessageBox::information(this, tr("Language"), tr("The language changes when NeedleBench is started again."));
        });
    }
}

bool MainWindow::openSession(const QString& dir)
{
    // One program a session (lockSession says why).
    const bool same = session_ && QDir(session_->dir()) == QDir(dir);  // this window has it already
    SessionLock lock = same ? SessionLock{} : lockSession(dir);
    if (lock.refused()) {
        sayInABox(QStringLiteral("sessionInUse"), tr("Open session"),
                  tr("%1 is open in another NeedleBench (%2). Close it there first, or open another session.")
                      .arg(QDir::toNativeSeparators(dir), lock.heldBy));
        return false;
    }
    try {
        Session s = Session::open(dir);
        QStringList problems;
        recovered_ = s.recoverInterrupted(engine_->status().runPath, &problems);
        session_ = std::move(s);
        if (!same)
            sessionLock_ = std::move(lock.file);  // the last session's is released
        // Said in a box, not only in the status bar, which the devices' first messages overwrote
        // at once: a run cut short by a crash is news the operator must not miss. Modeless, and
        // shown once: the recovered files are closed now.
        QStringList news;
        if (!recovered_.isEmpty())
            news << tr("Recovered %n interrupted run(s): %1. Each ends where its recording stopped; its file says "
                       "'end_reason: recovered'.", nullptr, int(recovered_.size()))
                        .arg(recovered_.join(QStringLiteral(", ")));
        if (!problems.isEmpty())
            news << tr("Could not recover:\n%1").arg(problems.join(QLatin1Char('\n')));
        if (!news.isEmpty()) {
            showMessage(news.join(QLatin1Char(' ')), true);
            warnModeless(this, tr("Interrupted runs"), news.join(QStringLiteral("\n\n")))->setObjectName(QStringLiteral("interruptedRuns"));
        } else {
            // "No session open" stood below the session opened from the welcome.
            showMessage(tr("Session %1 open").arg(QDir::toNativeSeparators(session_->dir())));
        }
    } catch (const SessionError& e) {
        QMessageBox::warning(this, tr("Open session"), e.message());
        return false;
    }
    if (const auto cal = session_->activeCalibration())
        engine_->setCalibration(cal->fit.slope_V_per_g, cal->name);
    else
        engine_->useNominalCalibration();
    // Review showed the last session's run, and edits went to its files.
    if (!review_->runPath().isEmpty() && QFileInfo(review_->runPath()).absoluteDir() != QDir(session_->dir()))
        review_->closeRun();
    restoreSimulatedRig();
    panel_->setSessionOpen(true);
    sessionView_->setSession(&*session_);
    if (options_.persistSettings)
        analysis_->restoreChoices(QSettings());
    analysis_->openSession(session_->dir());
    setWindowTitle(tr("NeedleBench – %1").arg(QDir::toNativeSeparators(session_->dir())));
    if (options_.persistSettings) {
        QSettings().setValue(QStringLiteral("session/last"), session_->dir());
        rememberRecentSession(session_->dir());
    }
    openSessionPlan();
    return true;
}

void MainWindow::reviewRun(const QString& path)
{
    // The workspace restores the run's video and sync kept in the session (or clears them).
    if (!review_->openRun(path))
        return;
    sessionView_->selectRun(path);
    tabs_->setCurrentWidget(review_);
    // Also when Review was already the tab: a run opened from the session list left the keyboard
    // there, and the arrows moved through the list instead of the frames.
    review_->setFocus(Qt::OtherFocusReason);
}

bool MainWindow::createSession(const QString& dir, const SessionInfo& info)
{
    try {
        Session::create(dir, info);
    } catch (const SessionError& e) {
        QMessageBox::warning(this, tr("New session"), e.message());
        return false;
    }
    return openSession(dir);
}

// ---- Startup, welcome, recent sessions, video and export actions (issue 14) ----

void MainWindow::openStartupSession()
{
    // The session given (created when it is not one yet: tests and `--session DIR`), else the
    // last one; else nothing is created: the welcome asks what to do.
    QString dir = options_.sessionDir;
    if (dir.isEmpty() && options_.persistSettings && Session::isSession(QSettings().value(QStringLiteral("session/last")).toString()))
        dir = QSettings().value(QStringLiteral("session/last")).toString();
    // One that cannot be opened (another window has it) leaves the operator at the welcome.
    if (!dir.isEmpty() && (Session::isSession(dir) ? openSession(dir) : createSession(dir, {})))
        return;
    panel_->setSessionOpen(false);
    const QString last = options_.persistSettings ? QSettings().value(QStringLiteral("session/last")).toString() : QString();
    if (options_.sessionDir.isEmpty() && !last.isEmpty() && !Session::isSession(last))
        showMessage(tr("The last session, %1, is not there any more (moved or renamed?): open it where it is now, or start a new one.")
                        .arg(QDir::toNativeSeparators(last)));
    else
        showMessage(tr("No session open: start a new one or open one (Session menu)."));
    // The welcome would hide the box that says why the last session did not open, and block it.
    if (options_.welcome && !findChild<QMessageBox*>(QStringLiteral("sessionInUse")))
        QTimer::singleShot(0, this, &MainWindow::showWelcome);
}

void MainWindow::saveWorkspace(QSettings& settings) const
{
    settings.setValue(QStringLiteral("workspace/tab"), tabs_->currentIndex());
    settings.setValue(QStringLiteral("review/run"), review_->runPath());
    settings.setValue(QStringLiteral("review/cursor_s"), review_->cursorTime());
    settings.setValue(QStringLiteral("review/speed"), review_->speed());
    analysis_->saveChoices(settings);
}

void MainWindow::restoreWorkspace()
{
    const QSettings settings;
    // The playback speed the operator labels at (a slow 0.25× for the phases' edges).
    review_->setSpeed(settings.value(QStringLiteral("review/speed"), 1.0).toDouble());
    const QString run = settings.value(QStringLiteral("review/run")).toString();
    // A run of another session is not this one's to show (reviewBelongsToTheOpenSession).
    const bool ours = session_ && !run.isEmpty() && QFileInfo(run).absoluteDir() == QDir(session_->dir());
    if (ours && QFileInfo::exists(run) && review_->openRun(run)) {
        review_->setCursorTime(settings.value(QStringLiteral("review/cursor_s")).toDouble());
        sessionView_->selectRun(run);
    }
    else if (ours) {
        // Said in Review too, where it stays until a run is opened: the status line's next
        // message took it away before the operator looked.
        const QString gone = tr("The run in review when NeedleBench closed is gone: %1").arg(QDir::toNativeSeparators(run));
        showMessage(gone);
        review_->showStatus(gone);
    }
    const int tab = settings.value(QStringLiteral("workspace/tab"), 0).toInt();
    if (tab > 0 && tab < tabs_->count() && (tabs_->widget(tab) != review_ || !review_->runPath().isEmpty()))
        tabs_->setCurrentIndex(tab);
}

QStringList MainWindow::recentSessions() const
{
    return QSettings().value(QStringLiteral("session/recent")).toStringList();
}

void MainWindow::rememberRecentSession(const QString& dir)
{
    QStringList recent = recentSessions();
    recent.removeAll(dir);
    recent.prepend(dir);
    while (recent.size() > 8)
        recent.removeLast();
    QSettings().setValue(QStringLiteral("session/recent"), recent);
}

WelcomeDialog* MainWindow::showWelcome()
{
    auto* welcome = new WelcomeDialog(options_.persistSettings ? recentSessions() : QStringList(), this);
    welcome->setAttribute(Qt::WA_DeleteOnClose);
    connect(welcome, &WelcomeDialog::newSessionRequested, this, &MainWindow::newSessionDialog);
    connect(welcome, &WelcomeDialog::openSessionRequested, this, &MainWindow::openSessionDialog);
    connect(welcome, &WelcomeDialog::recentSessionChosen, this, &MainWindow::openSession);
    welcome->open();
    return welcome;
}

void MainWindow::addDayActions(QMenu* sessionMenu)
{
    QAction* video = sessionMenu->addAction(tr("Open &video for the run in review…"), this, [this] {
        tabs_->setCurrentWidget(review_);
        review_->chooseVideo();
    });
    video->setObjectName(QStringLiteral("actionOpenVideo"));
    QAction* exportAction = sessionMenu->addAction(tr("&Export session…"), this, [this] { exportSession(); });
    exportAction->setObjectName(QStringLiteral("actionExportSession"));
    exportAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
}

ExportDialog* MainWindow::exportSession()
{
    if (!session_) {
        showMessage(tr("Open a session to export it."), true);
        return nullptr;
    }
    auto* dialog = new ExportDialog(session_->dir(), analysis_, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // The last export's folder (of this session) and formats: the dialog went back to
    // SESSION/export and its defaults, and Export again wrote elsewhere than the operator had.
    if (options_.persistSettings) {
        const QSettings settings;
        if (settings.value(QStringLiteral("export/session")).toString() == session_->dir()
            && !settings.value(QStringLiteral("export/target")).toString().isEmpty())
            dialog->setTargetDir(settings.value(QStringLiteral("export/target")).toString());
        if (const QVariantList c = settings.value(QStringLiteral("export/choice")).toList(); c.size() == 5)
            dialog->setChoice({c[0].toBool(), c[1].toBool(), c[2].toBool(), c[3].toBool(), c[4].toBool()});
        connect(dialog, &ExportDialog::exportFinished, this, [this, dialog](bool ok) {
            if (!ok || !session_)
                return;
            QSettings settings;
            settings.setValue(QStringLiteral("export/session"), session_->dir());
            settings.setValue(QStringLiteral("export/target"), dialog->targetDir());
            const ExportDialog::Choice c = dialog->choice();
            settings.setValue(QStringLiteral("export/choice"), QVariantList{c.csv, c.hdf5, c.eaf, c.figures, c.tables});
        });
    }
    connect(dialog, &ExportDialog::exportFinished, this, [this, dialog](bool ok) {
        // A failure replaces an earlier export's "exported", which stood beside it.
        showMessage(ok ? tr("Session exported into %1").arg(QDir::toNativeSeparators(dialog->targetDir()))
                       : tr("Export not finished: %1").arg(dialog->resultText().section(QLatin1Char('\n'), 0, 0)));
    });
    showModeless(dialog);  // the stage may be moving meanwhile (modeless_dialogs.h)
    return dialog;
}

void MainWindow::newSessionDialog()
{
    if (refused(Control::ChangeSetup))
        return;
    // A day of specimens: the next session starts from the open one's details, in the folder
    // beside it; only the specimen and the notes are new. With none open, the last session made
    // gives its operator and folder.
    SessionInfo start;
    QString parent = defaultSessionRoot();
    if (session_) {
        start = session_->info();
        parent = QFileInfo(session_->dir()).absolutePath();
    } else if (options_.persistSettings) {
        start.operatorName = QSettings().value(QStringLiteral("session/operator")).toString();
        parent = QSettings().value(QStringLiteral("session/parent"), parent).toString();
    }
    start.specimen.clear();
    start.notes.clear();
    start.created = {};
    SessionInfoDialog dialog(SessionInfoDialog::Mode::New, start, parent, this);
    if (dialog.exec() != QDialog::Accepted || refused(Control::ChangeSetup))
        return;
    const SessionInfo info = dialog.info();
    if (!createSession(QDir(dialog.parentFolder()).filePath(sessionFolderName(info, QDateTime::currentDateTime())), info))
        return;
    if (options_.persistSettings) {
        QSettings().setValue(QStringLiteral("session/operator"), info.operatorName);
        QSettings().setValue(QStringLiteral("session/parent"), dialog.parentFolder());
    }
}

void MainWindow::editSessionDetails()
{
    if (!session_ || refused(Control::ChangeSetup))
        return;
    SessionInfoDialog dialog(SessionInfoDialog::Mode::Edit, session_->info(), {}, this);
    if (dialog.exec() == QDialog::Accepted && !refused(Control::ChangeSetup))
        setSessionInfo(dialog.info());
}

bool MainWindow::setSessionInfo(const SessionInfo& info)
{
    if (!session_)
        return false;
    try {
        session_->setInfo(info);
    } catch (const SessionError& e) {
        QMessageBox::warning(this, tr("Session details"), e.message());
        return false;
    }
    showMessage(tr("Session details saved; the next runs carry them."));
    sessionView_->refresh();
    return true;
}

void MainWindow::openSessionDialog()
{
    if (refused(Control::ChangeSetup))
        return;
    // Beside the open session, else where the last one was made (it opened in the working
    // folder when the default one did not exist).
    QString start = session_ ? QFileInfo(session_->dir()).absolutePath() : QString();
    if (start.isEmpty() && options_.persistSettings)
        start = QSettings().value(QStringLiteral("session/parent")).toString();
    if (start.isEmpty() || !QFileInfo(start).isDir())
        start = defaultSessionRoot();
    // Qt's own chooser, never the desktop's: Esc must reach the emergency stop's filter.
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open session folder"), start,
                                                          QFileDialog::ShowDirsOnly | QFileDialog::DontUseNativeDialog);
    if (!dir.isEmpty() && !refused(Control::ChangeSetup))
        openSession(dir);
}

CalibrationWizard* MainWindow::openCalibrationWizard()
{
    if (!wizard_ && refused(Control::Calibrate))
        return nullptr;
    if (!wizard_) {
        wizard_ = new CalibrationWizard(nominalSensor_, this);
        wizard_->setAttribute(Qt::WA_DeleteOnClose);
        wizard_->setDwell(options_.calibrationDwell_s);
        if (auto load = engine_->calibrationLoad())
            wizard_->setLoadMassHook([load](double grams) { return std::optional(load->setLoadMass_g(grams)); });
        // Both the U6's widest input range and the simulated ADC are ±10 V.
        constexpr double kInputRange_V = 10.0;
        wizard_->setSensorRange(kInputRange_V, engine_->nominalSlope_V_per_g());
        connect(wizard_, &CalibrationWizard::calibrationAccepted, this, &MainWindow::useCalibration);
        connect(liveRun_, &devices::LiveRun::samplesAppended, wizard_, [this](std::size_t first) {
            const devices::LiveSeries& live = liveRun_->series();
            for (std::size_t i = first; i < live.size(); ++i)
                wizard_->addSample(liveRun_->clockOrigin_s() + live.time_s[i], live.volts[i]);
        });
        connect(wizard_, &QDialog::finished, this, [this] {
            if (auto load = engine_->calibrationLoad())
                load->setLoadMass_g(0.0);
        });
        connect(wizard_, &QObject::destroyed, panel_, [this] { panel_->setCalibrating(false); });
        panel_->setCalibrating(true);
    }
    wizard_->show();
    wizard_->raise();
    return wizard_;
}

void MainWindow::useCalibration(const StoredCalibration& calibration)
{
    if (!session_)
        return;
    try {
        const QString name = session_->saveCalibration(calibration);
        engine_->setCalibration(calibration.fit.slope_V_per_g, name);
        showMessage(tr("Calibration %1 saved in the session and used for every following run (d = %2 mV/g, r² = %3)")
                        .arg(name)
                        .arg(QLocale().toString(calibration.fit.slope_V_per_g * 1000.0, 'f', 4))
                        .arg(QLocale().toString(calibration.fit.r2, 'f', 6)));
    } catch (const SessionError& e) {
        QMessageBox::warning(this, tr("Calibration"), e.message());
    }
    sessionView_->refresh();
}

void MainWindow::startRun()
{
    if (!session_)
        return;
    if (wizard_) {  // Start is off in the panel then; a plan's next run comes this way too
        InterlockState state = panel_->interlockState();
        state.calibrating = true;
        showMessage(tr("Not now: %1").arg(permission(Control::StartInsertion, state).reason), true);
        return;
    }
    devices::RunPlan plan = panel_->motionPlan();
    plan.outPath = session_->nextRunPath(panel_->motionName());
    plan.endWhenMotionDone = true;
    const Metadata sm = sessionMetadata(session_->info());
    for (const auto& [k, v] : sm.entries())
        plan.metadata.set(k, v);
    plan.metadata.set(key::session, QDir(session_->dir()).dirName());
    if (!beginPlanRun(plan))
        return;
    runIsLinear_ = plan.motion == devices::RunPlan::Motion::Linear;
    addRigMetadata(plan);
    noteMotionCommand();
    engine_->startRun(plan);
}

void MainWindow::onStatus(const devices::EngineStatus& s)
{
    panel_->setStatus(s);
    plots_->setForceMargin(s.running ? std::optional(s.forceMargin_N) : std::nullopt);
    planStatus(s);
    if (wizard_)
        wizard_->setDeviceTime(s.deviceTime_s);
    // The devices' description (a simulated rig's tissue, tip and seed; a real device's serial
    // and port) is shortened here and whole in the tooltip: the messages beside it need room.
    const QString devices = engine_->deviceDescription();
    const auto summary = [this](double rateHz, qint64 samples, qint64 dropped) {
        return tr("%1 · %2 Hz · %3 samples · dropped %4").arg(summaryDevices_).arg(localNumber(rateHz, 0)).arg(samples).arg(dropped);
    };
    // Measured when the devices change, not at every status (25 a second).
    if (devices != summaryDevicesWhole_) {
        const QFontMetrics metrics = statusLabel_->fontMetrics();
        summaryDevicesWhole_ = devices;
        summaryDevices_ = metrics.elidedText(devices, Qt::ElideRight, 28 * metrics.averageCharWidth());
        // As wide as a day's counts from the start, so that the summary does not grow under the
        // message beside it (elided to the room left when it was shown) as the samples add up.
        statusLabel_->setMinimumWidth(metrics.horizontalAdvance(summary(10000.0, 99999999, 99999)) + 2 * statusLabel_->margin() + 4);
        refitMessage();  // to the room the summary leaves now
    }
    statusLabel_->setText(summary(s.rateHz, qint64(s.samples), qint64(s.dropped + s.overruns)));
    QString tip = tr("%1\n%n plot frame(s) drawn", nullptr, plots_->framesDrawn()).arg(devices);
    if (!s.realtimeWarning.isEmpty())
        tip += QLatin1Char('\n') + s.realtimeWarning;
    statusLabel_->setToolTip(tip);
    // The quit question follows what happens while it is open (an emergency stop ended the
    // run and the motion it spoke of).
    if (quitQuestion_ && quitQuestion_->isVisible()) {
        QString text = quitQuestionText(s);
        if (text.isEmpty())
            text = tr("Nothing moves or records now. Quit?");
        if (quitQuestion_->text() != text)
            quitQuestion_->setText(text);
    }
}

void MainWindow::onRunEnded(const devices::RunSummary& summary)
{
    sessionView_->setBusyPath({});
    lastRunPath_ = summary.path;
    lastEndReason_ = fileName(summary.endReason);
    endPlanRun(lastEndReason_);
    ++runsEnded_;
    // The file's name: the session's folder is on screen, and a whole path pushed the run's
    // end reason out of the status bar at 1366 px.
    const QString file = QFileInfo(summary.path).fileName();
    const bool normal = endedNormally(summary.endReason);
    const bool unwritten = summary.endReason == EndReason::WriteError;
    QString text = (unwritten ? tr("Run stopped, file incomplete: %1 (%2, %3 samples, %4 dropped)") : tr("Run saved: %1 (%2, %3 samples, %4 dropped)"))
                       .arg(file, displayName(summary.endReason))
                       .arg(summary.samples)
                       .arg(summary.dropped);
    if (!summary.fault.isEmpty())
        text += QStringLiteral(" – ") + withinSession(summary.fault);
    // Red is for what cut the run short; a few dropped samples are a note, not an alarm.
    showMessage(text, !normal);
    // A disk that filled (or media removed) mid-run is said in a box: one status line, cut in
    // the middle and beginning "Run saved", was all the operator got.
    if (unwritten)
        sayInABox(QStringLiteral("runNotWritten"), tr("Run file incomplete"),
                  tr("%1 could not be written to the end, and the stage was stopped: %2\n\nThe rows written before are kept in the "
                     "file. Free space on the disk (or choose another session folder) before the next run.")
                      .arg(file, withinSession(summary.fault)));
    if (const QString problem = liveRun_->endRun(summary.path); !problem.isEmpty())
        showMessage(tr("Could not read the run back to mark its events: %1").arg(problem), true);
    sessionView_->refresh();
    if (session_)
        analysis_->openSession(session_->dir());
}

QString MainWindow::withinSession(QString text) const
{
    // The session's folder is in the title bar: files in it by their names, so that what went
    // wrong ("No space left on device", "only 12 kB free") is not cut off at the status bar's end.
    if (session_) {
        const QString dir = QDir(session_->dir()).absolutePath();
        text.replace(dir + QLatin1Char('/'), QString()).replace(QDir::toNativeSeparators(dir) + QDir::separator(), QString());
    }
    return text;
}

void MainWindow::sayInABox(const QString& name, const QString& title, const QString& text)
{
    // One box of a kind: a second refusal replaces the first's text.
    if (auto* box = findChild<QMessageBox*>(name); box && box->isVisible()) {
        box->setText(text);
        box->raise();
        return;
    }
    QMessageBox* box = warnModeless(this, title, text);
    box->setObjectName(name);
    if (!isVisible()) {
        // Said at start (another window has the last session): over the window once it shows.
        box->hide();
        QTimer::singleShot(0, box, [box] {
            box->show();
            box->raise();
        });
    }
}

void MainWindow::showMessage(const QString& text, bool alarm)
{
    statusBar()->setStyleSheet(alarm ? QStringLiteral("QStatusBar { color: #c62828; font-weight: bold; }") : QString());
    // Shortened in the middle where it would run under the summary on the right (the start
    // says what happened, the end names the file or the reason); whole in the tooltip.
    QFont font = statusBar()->font();
    font.setBold(alarm);
    const QFontMetrics metrics(font);
    // Before the window is shown (a device that failed at start) the bar has no width yet.
    const int room = statusBar()->isVisible()
                         ? statusBar()->width() - std::max(statusLabel_->width(), statusLabel_->minimumWidth()) - 4 * metrics.averageCharWidth()
                         : QWIDGETSIZE_MAX;
    statusBar()->showMessage(metrics.elidedText(text, Qt::ElideMiddle, std::max(room, 160)));
    statusBar()->setToolTip(text);  // whole, where the bar is too narrow for it
    shownMessage_ = text;
    shownAlarm_ = alarm;
}

// A message said before the window had its width (at start) ran under the summary on the right,
// cut off: it is shortened again to the room there is now.
void MainWindow::refitMessage()
{
    if (!statusBar()->currentMessage().isEmpty() && !shownMessage_.isEmpty())
        showMessage(shownMessage_, shownAlarm_);
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    QTimer::singleShot(0, this, &MainWindow::refitMessage);  // once the status bar has its new width
}

QString MainWindow::quitQuestionText(const devices::EngineStatus& s)
{
    const InterlockState st = s.interlocks();
    const Permission quit = permission(Control::Quit, st);
    if (!quit.enabled)
        return (s.recording ? tr("%1\nStop the stage now (emergency stop; the run is saved as such) and quit?")
                            : tr("%1\nStop the stage now (emergency stop) and quit?"))
            .arg(quit.reason);
    // Withdraw, not To start: in a sine "the start" is its centre, inside the tissue, and the
    // question pointed at a button that was off or would leave the needle in.
    // Nothing moves, but the needle was left in the tissue (a run ended at depth, an emergency
    // stop): the window went at once and the operator lost the panel that withdraws it.
    if (st.inTissue)
        return tr("The needle is still in the tissue. Withdraw it first, or quit and leave it there?");
    // Jogged in (never recorded, so no contact was marked) or stopped short of the start: the
    // needle may be in tissue all the same.
    if (st.startKnown && s.position_mm > kAwayFromStart_mm)
        return tr("The needle is %1 mm from its start. Withdraw it first, or quit and leave it there?")
            .arg(QLocale().toString(s.position_mm, 'f', 1));
    // The force says so where the position cannot (zeroed in the tissue: "Zero anyway").
    if (s.loaded)
        return tr("A force of %1 N is on the needle: it may be in the tissue. Withdraw it first, or quit and leave it there?")
            .arg(QLocale().toString(s.force_N, 'f', 2));
    return {};
}

void MainWindow::closeWithoutAsking()
{
    quitConfirmed_ = true;
    close();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    const Permission quit = permission(Control::Quit, engine_->status().interlocks());
    const QString question = quitQuestionText(engine_->status());
    if (!question.isEmpty() && !quitConfirmed_) {
        // The offer to end the run first, modeless: the stage moves while it is asked, and the
        // EMERGENCY STOP button must stay clickable (Esc in the question stops it as well).
        event->ignore();
        if (quitQuestion_) {
            quitQuestion_->raise();
            quitQuestion_->activateWindow();
            return;
        }
        quitQuestion_ = new QMessageBox(QMessageBox::Question, tr("Quit"), question, QMessageBox::Yes | QMessageBox::No, this);
        quitQuestion_->setObjectName(QStringLiteral("quitQuestion"));
        // Said, not Yes and No: "Withdraw it first, or quit and leave it there?" has no yes.
        quitQuestion_->button(QMessageBox::Yes)->setText(tr("Quit"));
        quitQuestion_->button(QMessageBox::No)->setText(tr("Don't quit"));
        quitQuestion_->setDefaultButton(QMessageBox::No);
        connect(quitQuestion_, &QMessageBox::finished, this, [this](int answer) {
            if (answer != QMessageBox::Yes)
                return;
            quitConfirmed_ = true;
            QTimer::singleShot(0, this, &QWidget::close);
        });
        showModeless(quitQuestion_);
        return;
    }
    if (!quit.enabled) {
        engine_->emergencyStop();
        // The run's end comes back from the engine after the window has gone: a plan's run would
        // stay "running" in plan.json, and be called interrupted at the next start while its
        // file says emergency stop.
        endPlanRun(fileName(EndReason::EmergencyStop));
    }
    if (options_.persistSettings) {
        QSettings settings;
        settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
        settings.setValue(QStringLiteral("window/maximized"), isMaximized());
        settings.setValue(QStringLiteral("window/state"), saveState());
        panel_->saveSettings(settings);
        saveWorkspace(settings);
    }
    QMainWindow::closeEvent(event);
}

}  // namespace nb
