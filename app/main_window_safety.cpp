// The main window's part of operator safety (issue 12): the emergency stop from everywhere,
// one mode at a time, bias and zero only on purpose under load, jog, and the simulated rig's
// settings. Kept apart from main_window.cpp so the rules stay in one place.
#include "main_window.h"
#include "core/local_number.h"

#include "emergency_stop_filter.h"

#include "devices/acquisition_engine.h"
#include "devices/device_spec.h"
#include "widgets/control_panel.h"
#include "widgets/force_plots.h"
#include "widgets/simulated_rig_dialog.h"

#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QLabel>
#include <QStatusBar>
#include <QTimer>

namespace nb {

WorkbenchOptions MainWindow::optionsFromEnvironment()
{
    WorkbenchOptions o;
    const QString dir = qEnvironmentVariable("NEEDLEBENCH_SESSION_DIR");
    if (!dir.isEmpty()) {
        o.sessionDir = dir;
        o.persistSettings = false;
        o.devicesFromSettings = false;
    }
    else if (QSettings().contains(QStringLiteral("sim/rateHz")))
        o.rateHz = qBound(100.0, QSettings().value(QStringLiteral("sim/rateHz")).toDouble(), 10000.0);  // Devices ▸ Simulated rig…
    if (qEnvironmentVariable("NEEDLEBENCH_FAST_SIM") == QLatin1String("1"))
        o.realtime = false;
    return o;
}

void MainWindow::installSafety()
{
    auto* filter = new EmergencyStopFilter([this] { return motionOrRecording(); }, [this] { emergencyStopNow(); }, this);
    filter->install();

    connect(panel_, &ControlPanel::resetEmergencyStopRequested, this, [this] {
        engine_->enableStage(true);
        showMessage(tr("Emergency stop reset: the stage is enabled again."));
    });
    // Before the window shows, a change is the settings' being restored, not the operator's: no
    // echo ("withdrawal force limit 6 N" stood in the status line at start).
    connect(panel_, &ControlPanel::withdrawForceLimitChanged, this, [this](double n) { engine_->setWithdrawForceLimit(n, !isVisible()); });
    connect(panel_, &ControlPanel::withdrawToRequested, this, [this](double v, double target_mm) {
        if (refused(Control::Withdraw))
            return;
        noteMotionCommand();
        engine_->withdraw(v, target_mm);
        showMessage(tr("Withdrawing to the start position, %1 mm (not recorded)").arg(localNumber(target_mm, 2)));
    });
    connect(panel_, &ControlPanel::jogRequested, this, [this](double delta_mm, double v) {
        if (refused(Control::Jog))
            return;
        noteMotionCommand();
        engine_->jog(delta_mm, v);
    });
    connect(panel_, &ControlPanel::moveToRequested, this, [this](double position_mm, double v) {
        if (refused(Control::Jog))
            return;
        noteMotionCommand();
        engine_->moveTo(position_mm, v);
    });
    if (const auto centre = devices::suggestedSineCentre_mm(currentSpec()))
        panel_->setSineCentre(*centre);
}

devices::DeviceSpec MainWindow::currentSpec() const
{
    // The test factory's rig is the default simulated one.
    return spec_ ? *spec_ : devices::DeviceSpec{};
}

void MainWindow::addRigMetadata(devices::RunPlan& plan) const
{
    if (!spec_ || spec_->stage != QLatin1String("sim"))
        return;
    plan.metadata.set(QStringLiteral("sim_tissue"), spec_->simulated.tissue);
    // The tip the rig runs with (an empty choice is the preset's usual one, as the device line says).
    plan.metadata.set(QStringLiteral("sim_tip"), devices::simulatedTip(spec_->simulated));
    plan.metadata.set(QStringLiteral("sim_seed"), QString::number(spec_->simulated.seed));
}

bool MainWindow::motionOrRecording() const
{
    if (!engine_)
        return false;
    const devices::EngineStatus s = engine_->status();
    // The status trails a command by up to one period: a motion just asked for counts.
    const bool justAsked = motionCommand_.isValid() && motionCommand_.elapsed() < 300;
    return escapeStops(s.interlocks()) || s.jogging || justAsked;
}

void MainWindow::emergencyStopNow()
{
    engine_->emergencyStop();  // first: everything else can wait
    motionCommand_.invalidate();
    liveRun_->mark(devices::LiveMarkKind::EmergencyStop);
    showMessage(tr("Emergency stop: the stage is disabled until you reset it in the control panel."), true);
    // A menu or list open when Esc stopped the stage covered the latched panel that says what
    // happened: the operator sees the stop, not the menu.
    for (int guard = 0; QApplication::activePopupWidget() && guard < 8; ++guard)
        QApplication::activePopupWidget()->close();
}

bool MainWindow::refused(Control control)
{
    InterlockState state = engine_->status().interlocks();
    if (motionCommand_.isValid() && motionCommand_.elapsed() < 300)
        state.moving = true;  // asked for, not yet reported
    const Permission p = permission(control, state);
    if (p.enabled)
        return false;
    showMessage(tr("Not now: %1").arg(p.reason), true);
    // The reason must be read whole: the device line on the right gives way for a while.
    statusLabel_->hide();
    QTimer::singleShot(10000, statusLabel_, &QWidget::show);
    return true;
}

namespace {

// Asks before insisting on what the interlocks advised against; true to go ahead.
bool confirmInsist(QWidget* parent, const QString& title, const QString& reason, const QString& action)
{
    QMessageBox box(QMessageBox::Warning, title, reason, QMessageBox::NoButton, parent);
    box.setInformativeText(MainWindow::tr("Do it anyway only if you are sure the needle is free and at rest."));
    QPushButton* insist = box.addButton(action, QMessageBox::DestructiveRole);
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.exec();
    return box.clickedButton() == static_cast<QAbstractButton*>(insist);
}

}  // namespace

void MainWindow::biasOrInsist()
{
    const Permission p = permission(Control::Bias, engine_->status().interlocks());
    if (p.enabled) {
        engine_->biasSensor();
        return;
    }
    if (!p.overridable) {
        showMessage(tr("Not now: %1").arg(p.reason), true);
        return;
    }
    if (confirmInsist(this, tr("Bias force sensor"), p.reason, tr("Bias &anyway"))) {
        engine_->biasSensor(true);
        showMessage(tr("Bias taken under load on purpose: %1").arg(p.reason), true);
    } else {
        showMessage(tr("Bias not taken: %1").arg(p.reason), true);
    }
}

void MainWindow::zeroOrInsist()
{
    const Permission p = permission(Control::Zero, engine_->status().interlocks());
    if (p.enabled) {
        engine_->zeroStage();
        return;
    }
    if (!p.overridable) {
        showMessage(tr("Not now: %1").arg(p.reason), true);
        return;
    }
    if (confirmInsist(this, tr("Zero position"), p.reason, tr("Zero &anyway"))) {
        engine_->zeroStage(true);
        showMessage(tr("Position zeroed in tissue on purpose: %1").arg(p.reason), true);
    } else {
        showMessage(tr("Position not zeroed: %1").arg(p.reason), true);
    }
}

void MainWindow::restoreSimulatedRig()
{
    const QJsonObject kept = session_ ? session_->simulatedRig() : QJsonObject();
    const std::optional<devices::SimulatedRigSpec> rig = devices::simulatedRigFromJson(kept);
    if (kept.isEmpty() || !rig || engine_->status().recording)
        return;
    devices::DeviceSpec spec = currentSpec();
    const double rate = kept.value(QStringLiteral("rate_hz")).toDouble(options_.rateHz);
    const bool same = devices::toJson(spec.simulated) == devices::toJson(*rig) && rate == options_.rateHz;
    if (same || (spec.daq != QLatin1String("sim") && spec.stage != QLatin1String("sim")))
        return;
    spec.simulated = *rig;
    if (rate >= 100.0 && rate <= 10000.0)
        options_.rateHz = rate;
    if (switchDevices(spec))
        showMessage(tr("Simulated rig of this session: %1, seed %2").arg(rig->tissue).arg(rig->seed));
}

void MainWindow::chooseSimulatedRig()
{
    if (refused(Control::ChangeSetup))
        return;
    devices::DeviceSpec spec = currentSpec();
    SimulatedRigDialog dialog(spec.simulated, options_.rateHz, this);
    if (dialog.exec() != QDialog::Accepted || refused(Control::ChangeSetup))
        return;
    spec.simulated = dialog.spec();
    options_.rateHz = dialog.rateHz();
    if (options_.persistSettings) {
        QSettings settings;
        devices::saveSpec(settings, spec);
        settings.setValue(QStringLiteral("sim/rateHz"), options_.rateHz);
    }
    if (session_) {
        // Kept with the session, so that reopening it runs on the same specimen.
        QJsonObject kept = devices::toJson(spec.simulated);
        kept.insert(QStringLiteral("rate_hz"), options_.rateHz);
        try {
            session_->setSimulatedRig(kept);
        } catch (const SessionError& e) {
            showMessage(e.message(), true);
        }
    }
    if (switchDevices(spec))
        showMessage(tr("Simulated rig: %1, seed %2, %3 Hz")
                        .arg(spec.simulated.tissue)
                        .arg(spec.simulated.seed)
                        .arg(localNumber(options_.rateHz, 0)));
}

}  // namespace nb
