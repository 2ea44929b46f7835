#include "control_panel.h"

#include "core/local_number.h"

#include "core/data_names.h"

#include <QSettings>

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

// The icons live in a static library: their resource must be registered by hand.
static void initResources() { Q_INIT_RESOURCE(resources); }

namespace nb {

namespace {

QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, double value, int decimals, const QString& suffix)
{
    auto* s = new QDoubleSpinBox(parent);
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setValue(value);
    s->setSuffix(suffix);
    s->setKeyboardTracking(false);
    return s;
}

QString yesNo(bool on) { return on ? QObject::tr("yes") : QObject::tr("no"); }

// The panel must fit a 1366x768 laptop without scrolling: group boxes with tight margins.
template <typename Layout>
Layout* compact(Layout* l)
{
    l->setContentsMargins(6, 4, 6, 6);
    l->setSpacing(4);
    return l;
}

}  // namespace

ControlPanel::ControlPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("controlPanel"));
    static const bool resourcesReady = (initResources(), true);
    Q_UNUSED(resourcesReady);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(6);

    // Emergency stop first, big and always enabled.
    auto* estop = addButton(Control::EmergencyStop, tr("EMERGENCY STOP (Esc)"),
                            tr("Stops the stage at once and ends the run (always available; key: Esc)"));
    estop->setMinimumHeight(44);
    estop->setIcon(QIcon(QStringLiteral(":/icons/estop.svg")));
    estop->setIconSize(QSize(28, 28));
    estop->setStyleSheet(QStringLiteral("QPushButton { background: #c62828; color: white; font-weight: bold; }"));
    layout->addWidget(estop);
    connect(estop, &QPushButton::clicked, this, &ControlPanel::emergencyStopRequested);
    layout->addWidget(buildLatchBanner());

    auto* prep = new QGroupBox(tr("1. Prepare"), this);
    auto* prepLayout = compact(new QGridLayout(prep));
    auto* enable = addButton(Control::Enable, tr("&Enable stage"), tr("Powers the stage drive"));
    enable->setCheckable(true);
    connect(enable, &QPushButton::clicked, this, [this, enable] { emit enableRequested(enable->isChecked()); });
    auto* bias = addButton(Control::Bias, tr("&Bias force sensor"),
                           tr("Takes the present force as zero (needle free of tissue)"));
    connect(bias, &QPushButton::clicked, this, &ControlPanel::biasRequested);
    auto* zero = addButton(Control::Zero, tr("&Zero position"), tr("Makes the present stage position 0 mm"));
    connect(zero, &QPushButton::clicked, this, &ControlPanel::zeroRequested);
    auto* calibrate = addButton(Control::Calibrate, tr("Calibrate sensor…"),
                                tr("Known masses on the load cell, fit V = d·m + c"));
    calibrate->setIcon(QIcon(QStringLiteral(":/icons/calibrate.svg")));
    connect(calibrate, &QPushButton::clicked, this, &ControlPanel::calibrateRequested);
    prepLayout->addWidget(enable, 0, 0);
    prepLayout->addWidget(bias, 0, 1);
    prepLayout->addWidget(zero, 1, 0);
    prepLayout->addWidget(calibrate, 1, 1);
    layout->addWidget(prep);

    motionBox_ = new QGroupBox(tr("2. Motion"), this);
    auto* motionLayout = compact(new QVBoxLayout(motionBox_));
    auto* kinds = new QHBoxLayout;
    linear_ = new QRadioButton(tr("Linear"), motionBox_);
    sine_ = new QRadioButton(tr("Sinusoidal"), motionBox_);
    linear_->setChecked(true);
    kinds->addWidget(linear_);
    kinds->addWidget(sine_);
    motionLayout->addLayout(kinds);
    motionPages_ = new QStackedWidget(motionBox_);
    auto* linearPage = new QWidget(motionPages_);
    // Label, field, label, field: two fields a row, only the chosen motion's fields shown.
    auto* linearForm = new QGridLayout(linearPage);
    linearForm->setContentsMargins(0, 0, 0, 0);
    linearForm->setVerticalSpacing(4);
    velocity_ = spin(linearPage, 0.1, 50.0, 4.0, 2, tr(" mm/s"));
    depth_ = spin(linearPage, 0.5, 150.0, 30.0, 1, tr(" mm"));
    const auto addField = [](QGridLayout* grid, int row, int column, const QString& label, QWidget* field) {
        auto* l = new QLabel(label, field->parentWidget());
        l->setBuddy(field);
        grid->addWidget(l, row, 2 * column);
        grid->addWidget(field, row, 2 * column + 1);
        grid->setColumnStretch(2 * column + 1, 1);
    };
    addField(linearForm, 0, 0, tr("Velocity"), velocity_);
    addField(linearForm, 0, 1, tr("Depth"), depth_);
    auto* sinePage = new QWidget(motionPages_);
    auto* sineForm = new QGridLayout(sinePage);
    sineForm->setContentsMargins(0, 0, 0, 0);
    sineForm->setVerticalSpacing(4);
    amplitude_ = spin(sinePage, 0.1, 50.0, 10.0, 1, tr(" mm"));
    frequency_ = spin(sinePage, 0.01, 5.0, 0.5, 2, tr(" Hz"));
    cycles_ = new QSpinBox(sinePage);
    cycles_->setRange(1, 100);
    cycles_->setValue(7);
    velocity_->setObjectName(QStringLiteral("velocity"));
    depth_->setObjectName(QStringLiteral("depth"));
    amplitude_->setObjectName(QStringLiteral("amplitude"));
    frequency_->setObjectName(QStringLiteral("frequency"));
    cycles_->setObjectName(QStringLiteral("cycles"));
    linear_->setObjectName(QStringLiteral("linear"));
    sine_->setObjectName(QStringLiteral("sine"));
    centre_ = spin(sinePage, 0.0, 150.0, 15.0, 1, tr(" mm"));
    centre_->setObjectName(QStringLiteral("centre"));
    centre_->setToolTip(tr("The sine oscillates about this depth; the needle moves there first (not recorded)"));
    addField(sineForm, 0, 0, tr("Centre depth"), centre_);
    addField(sineForm, 0, 1, tr("Amplitude"), amplitude_);
    addField(sineForm, 1, 0, tr("Frequency"), frequency_);
    addField(sineForm, 1, 1, tr("Cycles"), cycles_);
    motionPages_->addWidget(linearPage);
    motionPages_->addWidget(sinePage);
    motionLayout->addWidget(motionPages_);
    // The stack is as tall as the page shown, not as its tallest page (room for the status).
    const auto sizeToPage = [this] {
        for (int i = 0; i < motionPages_->count(); ++i)
            motionPages_->widget(i)->setSizePolicy(QSizePolicy::Preferred,
                                                   i == motionPages_->currentIndex() ? QSizePolicy::Preferred : QSizePolicy::Ignored);
        motionPages_->adjustSize();
    };
    sizeToPage();
    connect(sine_, &QRadioButton::toggled, this, [this, sizeToPage](bool on) {
        motionPages_->setCurrentIndex(on ? 1 : 0);
        sizeToPage();
        updateControls();
    });
    for (QDoubleSpinBox* s : {velocity_, depth_, amplitude_, frequency_, centre_})
        connect(s, &QDoubleSpinBox::valueChanged, this, &ControlPanel::updateControls);
    connect(cycles_, &QSpinBox::valueChanged, this, &ControlPanel::updateControls);
    layout->addWidget(motionBox_);

    auto* runBox = new QGroupBox(tr("3. Run"), this);
    auto* runLayout = compact(new QGridLayout(runBox));
    auto* start = addButton(Control::StartInsertion, tr("Start &insertion (moves + records)"),
                            tr("Starts recording a new run file, then moves the needle in"));
    start->setStyleSheet(QStringLiteral("QPushButton:enabled { font-weight: bold; }"));
    start->setIcon(QIcon(QStringLiteral(":/icons/record.svg")));
    connect(start, &QPushButton::clicked, this, &ControlPanel::startRequested);
    auto* withdraw = addButton(Control::Withdraw, tr("Withdraw"), tr("Moves the needle back to 0 mm"));
    withdraw->setIcon(QIcon(QStringLiteral(":/icons/withdraw.svg")));
    connect(withdraw, &QPushButton::clicked, this, [this] { emit withdrawRequested(withdrawVelocity()); });
    auto* stop = addButton(Control::StopMotion, tr("Stop (keeps recording)"),
                           tr("Decelerates the stage; the run keeps recording until End run"));
    stop->setIcon(QIcon(QStringLiteral(":/icons/stop.svg")));
    connect(stop, &QPushButton::clicked, this, &ControlPanel::stopMotionRequested);
    auto* end = addButton(Control::EndRun, tr("End run (closes file)"),
                          tr("Stops recording and closes the run file"));
    end->setIcon(QIcon(QStringLiteral(":/icons/end_run.svg")));
    connect(end, &QPushButton::clicked, this, &ControlPanel::endRunRequested);
    runLayout->addWidget(start, 0, 0, 1, 2);
    runLayout->addWidget(stop, 1, 0);
    runLayout->addWidget(end, 1, 1);
    runLayout->addWidget(withdraw, 2, 0);
    auto* limitRow = new QHBoxLayout;
    auto* limitLabel = new QLabel(tr("Max. force"), runBox);
    limitLabel->setToolTip(tr("Maximum force"));
    limitRow->addWidget(limitLabel);
    limit_ = spin(runBox, 0.0, 20.0, 8.0, 2, tr(" N"));
    limit_->setToolTip(tr("The stage stops at once when the force reaches this (0 = no limit: runs refused)"));
    limit_->setObjectName(QStringLiteral("forceLimit"));
    connect(limit_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        state_.forceLimit_N = v;
        emit forceLimitChanged(v);
        updateControls();
    });
    limitRow->addWidget(limit_, 1);
    // Both limits on one row: the status below must stay in sight at 1366x768.
    limitRow->addWidget(new QLabel(tr("Withdrawal"), runBox));
    withdrawLimit_ = spin(runBox, 0.1, 20.0, 9.5, 2, tr(" N"));
    withdrawLimit_->setObjectName(QStringLiteral("withdrawForceLimit"));
    withdrawLimit_->setToolTip(tr("|F| that stops the needle coming out (never below the maximum force, so a limit stop never traps the needle)"));
    connect(withdrawLimit_, &QDoubleSpinBox::valueChanged, this, &ControlPanel::withdrawForceLimitChanged);
    limitRow->addWidget(withdrawLimit_, 1);
    runLayout->addLayout(limitRow, 3, 0, 1, 2);
    withdrawToStart_ = new QPushButton(tr("To start"), runBox);
    withdrawToStart_->setObjectName(QStringLiteral("withdrawToStart"));
    withdrawToStart_->setIcon(QIcon(QStringLiteral(":/icons/withdraw.svg")));
    connect(withdrawToStart_, &QPushButton::clicked, this, [this] {
        if (status_.lastRunStart_mm)
            emit withdrawToRequested(withdrawVelocity(), *status_.lastRunStart_mm);
    });
    runLayout->addWidget(withdrawToStart_, 2, 1);
    // Two equal columns: the button texts, not the longer of each pair, set the width.
    runLayout->setColumnStretch(0, 1);
    runLayout->setColumnStretch(1, 1);
    prepLayout->setColumnStretch(0, 1);
    prepLayout->setColumnStretch(1, 1);
    layout->addWidget(runBox);

    auto* statusBox = new QGroupBox(tr("Status"), this);
    auto* grid = compact(new QGridLayout(statusBox));
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(3);
    // The time in run is said on the recording row and the devices' state by their sample rate:
    // fewer rows to fit a laptop.
    const std::pair<const char*, QString> rows[] = {
        {"devices", tr("Sampling")},    {"stage", tr("Stage")},           {"bias", tr("Bias done")},
        {"zero", tr("Zero done")},      {"force", tr("Force")},           {"position", tr("Position")},
        {"motion", tr("Moving")},       {"margin", tr("Margin")},         {"dropped", tr("Dropped")},
        {"recording", tr("Recording")}, {"calibration", tr("Calibration")}, {"fault", tr("Fault")},
    };
    int index = 0;
    for (const auto& [key, title] : rows) {
        auto* value = new QLabel(QStringLiteral("–"), statusBox);
        value->setObjectName(QStringLiteral("status_") + QLatin1String(key));
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        auto* name = new QLabel(title + QLatin1Char(':'), statusBox);
        name->setStyleSheet(QStringLiteral("color: palette(mid);"));
        if (QByteArray(key) == "margin")
            name->setToolTip(tr("Force left before the maximum force stops the stage"));
        // Long values (file, calibration, fault) get a whole row; the rest share rows in pairs.
        const bool wide = QByteArray(key) == "recording" || QByteArray(key) == "calibration" || QByteArray(key) == "fault" ||
                          QByteArray(key) == "dropped";
        const int row = index / 2;
        if (wide) {
            if (index % 2)
                ++index;
            grid->addWidget(name, index / 2, 0);
            grid->addWidget(value, index / 2, 1, 1, 3);
            index += 2;
        } else {
            // Values come and go at run time: they must not widen the panel (full text in the tip).
            value->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
            value->setMinimumWidth(40);
            grid->addWidget(name, row, (index % 2) * 2);
            grid->addWidget(value, row, (index % 2) * 2 + 1);
            ++index;
        }
        status_labels_[QString::fromLatin1(key)] = value;
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(3, 1);
    // Room for what a busy rig shows (values never widen the panel by themselves).
    int valueWidth = 0;
    for (const QString& busy : {tr("%1 Hz").arg(10000), tr("yes (%1 V)").arg(localNumber(-1.2345, 4)), tr("%1 N").arg(localNumber(-12.345, 3)),
                                tr("%1 mm").arg(localNumber(123.456, 3)), tr("%1 mm/s").arg(localNumber(12.5, 2)),
                                tr("%1 N (%2 %)").arg(localNumber(-0.25, 2)).arg(-3), tr("enabled"), tr("disabled"), tr("at rest")})
        valueWidth = std::max(valueWidth, statusBox->fontMetrics().horizontalAdvance(busy) + 2);
    grid->setColumnMinimumWidth(1, valueWidth);
    grid->setColumnMinimumWidth(3, valueWidth);
    status_labels_[QStringLiteral("fault")]->setWordWrap(true);
    status_labels_[QStringLiteral("recording")]->setWordWrap(true);
    status_labels_[QStringLiteral("calibration")]->setWordWrap(true);
    grid->setRowStretch(grid->rowCount(), 1);
    // The status takes what height remains.
    layout->addWidget(statusBox, 1);
    // Jog is for after a stop: below the status, which must stay in sight, and folded away
    // until asked for.
    auto* jogToggle = new QToolButton(this);
    jogToggle->setObjectName(QStringLiteral("jogToggle"));
    jogToggle->setText(tr("Jog (never recorded)"));
    jogToggle->setCheckable(true);
    jogToggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    jogToggle->setArrowType(Qt::RightArrow);
    jogToggle->setAutoRaise(true);
    jogToggle->setToolTip(tr("Unrecorded moves of the needle: steps in and out, or to a position"));
    layout->addWidget(jogToggle);
    layout->addWidget(buildJogBox());
    jogBox_->setVisible(false);
    connect(jogToggle, &QToolButton::toggled, this, [this, jogToggle](bool open) {
        jogToggle->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
        jogBox_->setVisible(open);
    });

    state_.forceLimit_N = limit_->value();
    updateControls();

    for (QDoubleSpinBox* box : findChildren<QDoubleSpinBox*>())
        connect(box, &QDoubleSpinBox::valueChanged, this, &ControlPanel::settingsChanged);
    connect(cycles_, &QSpinBox::valueChanged, this, &ControlPanel::settingsChanged);
    connect(sine_, &QRadioButton::toggled, this, &ControlPanel::settingsChanged);
    connect(jogStep_, &QComboBox::currentIndexChanged, this, &ControlPanel::settingsChanged);
}

QPushButton* ControlPanel::addButton(Control control, const QString& text, const QString& help)
{
    auto* b = new QPushButton(text, this);
    buttons_[control] = b;
    help_[control] = help;
    return b;
}

QAbstractButton* ControlPanel::button(Control control) const
{
    const auto it = buttons_.find(control);
    return it == buttons_.end() ? nullptr : it->second;
}

devices::RunPlan ControlPanel::motionPlan() const
{
    devices::RunPlan plan;
    plan.motion = sine_->isChecked() ? devices::RunPlan::Motion::Sine : devices::RunPlan::Motion::Linear;
    plan.linear.velocity_mm_s = velocity_->value();
    plan.linear.target_mm = depth_->value();
    plan.sine.amplitude_mm = amplitude_->value();
    plan.sine.frequency_hz = frequency_->value();
    plan.sine.cycles = cycles_->value();
    if (sine_->isChecked())
        plan.startAt_mm = centre_->value();
    plan.metadata.set(QStringLiteral("motion"), motionName());
    if (sine_->isChecked()) {
        plan.metadata.set(QStringLiteral("amplitude_mm"), amplitude_->value());
        plan.metadata.set(QStringLiteral("frequency_hz"), frequency_->value());
        plan.metadata.set(QStringLiteral("cycles"), double(cycles_->value()));

    } else {
        plan.metadata.set(QStringLiteral("velocity_mm_s"), velocity_->value());
        plan.metadata.set(QStringLiteral("depth_mm"), depth_->value());
    }
    if (locked_) {
        plan.stopAtPuncture = locked_->stopAtPuncture;
        plan.slowAfterPuncture_mm_s = locked_->slowAfterPuncture_mm_s;
    }
    return plan;
}

QString ControlPanel::lockMotion(const devices::RunPlan& plan, const QString& why)
{
    const bool sine = plan.motion == devices::RunPlan::Motion::Sine;
    const std::pair<QDoubleSpinBox*, double> values[] = {{velocity_, plan.linear.velocity_mm_s}, {depth_, plan.linear.target_mm},
                                                         {amplitude_, plan.sine.amplitude_mm},   {frequency_, plan.sine.frequency_hz}};
    for (const auto& [box, v] : values)
        if (v < box->minimum() || v > box->maximum() || std::abs(std::round(v * std::pow(10.0, box->decimals())) / std::pow(10.0, box->decimals()) - v) > 1e-9)
            return tr("%1 %2 cannot be set here (%3 to %4 in steps of %5)")
                .arg(box->objectName())
                .arg(v)
                .arg(box->minimum())
                .arg(box->maximum())
                .arg(std::pow(10.0, -box->decimals()));
    if (plan.sine.cycles < cycles_->minimum() || plan.sine.cycles > cycles_->maximum())
        return tr("%1 cycles cannot be set here (%2 to %3)").arg(plan.sine.cycles).arg(cycles_->minimum()).arg(cycles_->maximum());
    if (!locked_)
        operatorMotion_ = motionFields();
    locked_ = plan;  // first: the fields' changes below are the plan's, not the operator's
    (sine ? sine_ : linear_)->setChecked(true);
    for (const auto& [box, v] : values)
        box->setValue(v);
    cycles_->setValue(plan.sine.cycles);
    lockReason_ = why;
    motionBox_->setTitle(tr("2. Motion (set by the plan)"));
    updateControls();
    return {};
}

void ControlPanel::unlockMotion()
{
    locked_.reset();
    if (operatorMotion_)
        setMotionFields(*operatorMotion_);
    operatorMotion_.reset();
    lockReason_.clear();
    motionBox_->setTitle(tr("2. Motion"));
    updateControls();
}

void ControlPanel::setStartHold(const QString& reason)
{
    startHold_ = reason;
    updateControls();
}

void ControlPanel::setCalibrating(bool open)
{
    calibrating_ = open;
    updateControls();
}

QString ControlPanel::motionName() const
{
    return sine_->isChecked() ? QStringLiteral("sine") : QStringLiteral("linear");
}

double ControlPanel::withdrawVelocity() const { return velocity_->value(); }
double ControlPanel::withdrawForceLimit() const { return withdrawLimit_->value(); }

void ControlPanel::saveSettings(QSettings& settings) const
{
    settings.setValue(QStringLiteral("run/forceLimit_N"), forceLimit());
    for (const QDoubleSpinBox* box : findChildren<QDoubleSpinBox*>())
        if (box->objectName() != QLatin1String("forceLimit") && !box->objectName().isEmpty())
            settings.setValue(QStringLiteral("motion/") + box->objectName(), box->value());
    const MotionFields m = operatorMotion_ ? *operatorMotion_ : motionFields();
    settings.setValue(QStringLiteral("motion/sine"), m.sine);
    settings.setValue(QStringLiteral("motion/velocity"), m.velocity);
    settings.setValue(QStringLiteral("motion/depth"), m.depth);
    settings.setValue(QStringLiteral("motion/amplitude"), m.amplitude);
    settings.setValue(QStringLiteral("motion/frequency"), m.frequency);
    settings.setValue(QStringLiteral("motion/cycles"), m.cycles);
    settings.setValue(QStringLiteral("motion/jogStep_mm"), jogStep_->currentData().toDouble());
}

void ControlPanel::restoreSettings(const QSettings& settings)
{
    if (settings.contains(QStringLiteral("run/forceLimit_N")))
        setForceLimit(settings.value(QStringLiteral("run/forceLimit_N")).toDouble());
    for (QDoubleSpinBox* box : findChildren<QDoubleSpinBox*>()) {
        const QString key = QStringLiteral("motion/") + box->objectName();
        if (box->objectName() != QLatin1String("forceLimit") && !box->objectName().isEmpty() && settings.contains(key))
            box->setValue(settings.value(key).toDouble());
    }
    if (settings.contains(QStringLiteral("motion/sine")))
        (settings.value(QStringLiteral("motion/sine")).toBool() ? sine_ : linear_)->setChecked(true);
    if (settings.contains(QStringLiteral("motion/cycles")))
        cycles_->setValue(settings.value(QStringLiteral("motion/cycles")).toInt());
    if (settings.contains(QStringLiteral("motion/jogStep_mm")))
        if (const int i = jogStep_->findData(settings.value(QStringLiteral("motion/jogStep_mm")).toDouble()); i >= 0)
            jogStep_->setCurrentIndex(i);
}

ControlPanel::MotionFields ControlPanel::motionFields() const
{
    return {sine_->isChecked(), velocity_->value(), depth_->value(), amplitude_->value(), frequency_->value(), cycles_->value()};
}

void ControlPanel::setMotionFields(const MotionFields& m)
{
    (m.sine ? sine_ : linear_)->setChecked(true);
    velocity_->setValue(m.velocity);
    depth_->setValue(m.depth);
    amplitude_->setValue(m.amplitude);
    frequency_->setValue(m.frequency);
    cycles_->setValue(m.cycles);
}

void ControlPanel::setWithdrawForceLimit(double newtons) { withdrawLimit_->setValue(newtons); }
double ControlPanel::sineCentre() const { return centre_->value(); }
void ControlPanel::setSineCentre(double mm) { centre_->setValue(mm); }
double ControlPanel::forceLimit() const { return limit_->value(); }
void ControlPanel::setForceLimit(double newtons) { limit_->setValue(newtons); }

QString ControlPanel::motionProblem() const
{
    if (sine_->isChecked()) {
        const double peak = centre_->value() + amplitude_->value();
        if (peak > 150.0)
            return tr("The sine would reach %1 mm, past the stage's travel.").arg(localNumber(peak, 1));
        if (centre_->value() - amplitude_->value() < 0.0)
            return tr("The sine would go above 0 mm: make the centre at least the amplitude.");
        return {};
    }
    if (depth_->value() <= status_.position_mm + 0.01)
        return tr("The depth (%1 mm) is not deeper than the needle is now (%2 mm).")
            .arg(localNumber(depth_->value(), 1))
            .arg(localNumber(status_.position_mm, 1));
    return {};
}

void ControlPanel::setSessionOpen(bool open)
{
    state_.sessionOpen = open;
    updateControls();
}

void ControlPanel::setCalibrationName(const QString& name)
{
    calibrationName_ = name;
    updateControls();
}

void ControlPanel::setStatus(const devices::EngineStatus& s)
{
    status_ = s;
    // The engine's own view of the interlocks, and what only the window knows on top.
    const bool sessionOpen = state_.sessionOpen;
    const double forceLimit = state_.forceLimit_N;
    state_ = s.interlocks();
    state_.sessionOpen = sessionOpen;
    state_.forceLimit_N = forceLimit;
    state_.calibrated = s.slope_V_per_g > 0.0 && !s.calibrationName.isEmpty();
    updateControls();
}

void ControlPanel::updateControls()
{
    state_.motionProblem = motionProblem();
    state_.planHold = startHold_;
    state_.calibrating = calibrating_;
    for (auto& [control, b] : buttons_) {
        const Permission p = permission(control, state_);
        // Refused but insistable (bias or zero under load): clickable, the window asks first.
        setEnabledKeepingFocusSafe(b, p.enabled || p.overridable);
        b->setToolTip(p.enabled ? help_[control] : help_[control] + QStringLiteral("\n") + tr("Not now: %1").arg(p.reason));
    }
    const Permission motion = permission(Control::MotionSettings, state_);
    setEnabledKeepingFocusSafe(motionBox_, motion.enabled && !locked_);
    motionBox_->setToolTip(!motion.enabled ? motion.reason : lockReason_);
    auto* enable = buttons_[Control::Enable];
    enable->setChecked(state_.stageEnabled);
    enable->setText(state_.stageEnabled ? tr("Disable stage") : tr("&Enable stage"));
    // Whether a withdrawal lands in a file is never left to memory.
    buttons_[Control::Withdraw]->setText(state_.recording ? tr("Withdraw (recorded)") : tr("Withdraw (not recorded)"));
    // Nor whether stopping leaves a run open: a jog or a withdrawal outside a run has none.
    buttons_[Control::StopMotion]->setText(state_.recording ? tr("Stop (keeps recording)") : tr("Stop"));

    const auto set = [this](const char* key, const QString& text, bool alarm = false) {
        QLabel* l = status_labels_[QString::fromLatin1(key)];
        if (l->text() == text)
            return;
        l->setText(text);
        if (l->sizePolicy().horizontalPolicy() == QSizePolicy::Ignored)
            l->setToolTip(text);
        // Re-polishing a style sheet is not free and this runs at the status rate (25 Hz).
        if (l->property("alarm").toBool() != alarm || !l->property("alarm").isValid()) {
            l->setProperty("alarm", alarm);
            l->setStyleSheet(alarm ? QStringLiteral("color: #c62828; font-weight: bold;") : QString());
        }
    };
    const devices::EngineStatus& s = status_;
    set("devices", s.running ? tr("%1 Hz").arg(localNumber(s.rateHz, 0)) : tr("stopped"), !s.running);
    set("stage", s.stageEnabled ? tr("enabled") : tr("disabled"));
    set("bias", s.biased ? tr("yes (%1 V)").arg(localNumber(s.bias_V, 4)) : yesNo(false), !s.biased);
    set("zero", yesNo(s.zeroed), !s.zeroed);
    set("motion", s.moving ? tr("%1 mm/s").arg(localNumber(s.velocity_mm_s, 2)) : tr("at rest"));
    set("recording", s.recording ? tr("RECORDING %1, %2 s").arg(s.runPath.section(QLatin1Char('/'), -1)).arg(localNumber(s.runTime_s, 1))
                                 : tr("not recording"));
    set("dropped", tr("%1 (overruns %2)").arg(s.dropped).arg(s.overruns), s.dropped + s.overruns > 0);
    set("force", tr("%1 N").arg(localNumber(s.force_N, 3)));
    set("position", tr("%1 mm").arg(localNumber(s.position_mm, 3)));
    // Against the limit the engine applies now (the withdrawal one while the needle comes out).
    const double limit = s.running ? s.forceMarginOf_N : state_.forceLimit_N;
    const double margin = s.running ? s.forceMargin_N : state_.forceLimit_N - std::abs(s.force_N);
    set("margin",
        limit > 0 ? tr("%1 N (%2 %)").arg(localNumber(margin, 2)).arg(localNumber(std::clamp(100.0 * margin / limit, 0.0, 100.0), 0)) : tr("no limit"),
        limit <= 0 || margin < 0.2 * limit || s.forceLimitTripped);
    set("calibration", s.calibrationName.isEmpty() ? tr("none") : calibrationDisplayName(s.calibrationName),
        s.calibrationName.isEmpty());
    updateSafetyControls();
    set("fault", s.fault.isEmpty() ? (s.forceLimitTripped ? tr("force limit tripped") : tr("none")) : s.fault,
        !s.fault.isEmpty() || s.forceLimitTripped);
}

QWidget* ControlPanel::buildLatchBanner()
{
    latchBanner_ = new QWidget(this);
    latchBanner_->setObjectName(QStringLiteral("latchBanner"));
    latchBanner_->setAttribute(Qt::WA_StyledBackground);
    latchBanner_->setStyleSheet(QStringLiteral("#latchBanner { background: #fff3cd; border: 2px solid #c62828; border-radius: 4px; }"));
    auto* l = new QVBoxLayout(latchBanner_);
    auto* text = new QLabel(tr("<b>EMERGENCY STOP — latched.</b><br>The stage is disabled. Check the rig, then reset: "
                               "this enables the stage again."),
                            latchBanner_);
    text->setWordWrap(true);
    text->setObjectName(QStringLiteral("latchText"));
    auto* reset = new QPushButton(tr("Reset emergency stop (enable stage)"), latchBanner_);
    reset->setObjectName(QStringLiteral("resetEmergencyStop"));
    connect(reset, &QPushButton::clicked, this, &ControlPanel::resetEmergencyStopRequested);
    l->addWidget(text);
    l->addWidget(reset);
    latchBanner_->setVisible(false);
    return latchBanner_;
}

QWidget* ControlPanel::buildJogBox()
{
    auto* box = new QWidget(this);
    jogBox_ = box;
    auto* grid = new QGridLayout(box);
    grid->setContentsMargins(6, 0, 6, 0);
    // Three steps an operator needs: fine, normal, coarse.
    jogStep_ = new QComboBox(box);
    jogStep_->setObjectName(QStringLiteral("jogStep"));
    for (double mm : {0.1, 1.0, 5.0})
        jogStep_->addItem(tr("%1 mm").arg(mm, 0, 'g', 2), mm);
    jogStep_->setCurrentIndex(1);
    jogStep_->setToolTip(tr("Step of one jog"));
    const auto step = [this] { return jogStep_->currentData().toDouble(); };
    jogOut_ = new QPushButton(tr("▲ Out"), box);
    jogOut_->setObjectName(QStringLiteral("jogOut"));
    jogIn_ = new QPushButton(tr("▼ In"), box);
    jogIn_->setObjectName(QStringLiteral("jogIn"));
    connect(jogOut_, &QPushButton::clicked, this, [this, step] { emit jogRequested(-step(), withdrawVelocity()); });
    connect(jogIn_, &QPushButton::clicked, this, [this, step] { emit jogRequested(step(), withdrawVelocity()); });
    goToPosition_ = spin(box, 0.0, 150.0, 0.0, 2, tr(" mm"));
    goToPosition_->setObjectName(QStringLiteral("goToPosition"));
    goTo_ = new QPushButton(tr("Go to position"), box);
    goTo_->setObjectName(QStringLiteral("goTo"));
    connect(goTo_, &QPushButton::clicked, this, [this] { emit moveToRequested(goToPosition_->value(), withdrawVelocity()); });
    grid->addWidget(jogStep_, 0, 0);
    grid->addWidget(jogOut_, 0, 1);
    grid->addWidget(jogIn_, 0, 2);
    grid->addWidget(goToPosition_, 1, 0);
    grid->addWidget(goTo_, 1, 1, 1, 2);
    return box;
}

void ControlPanel::updateSafetyControls()
{
    latchBanner_->setVisible(state_.latched);
    const Permission jog = permission(Control::Jog, state_);
    for (QPushButton* b : {jogOut_, jogIn_, goTo_}) {
        setEnabledKeepingFocusSafe(b, jog.enabled);
        b->setToolTip(jog.enabled ? tr("Moves the needle without recording") : tr("Not now: %1").arg(jog.reason));
    }
    // Out to the last run's start: offered when the needle is deeper than that.
    const Permission out = permission(Control::Withdraw, state_);
    const bool deeper = status_.lastRunStart_mm && status_.position_mm > *status_.lastRunStart_mm + 0.05;
    setEnabledKeepingFocusSafe(withdrawToStart_, out.enabled && deeper);
    withdrawToStart_->setText(status_.lastRunStart_mm
                                  ? tr("To start (%1 mm)").arg(localNumber(*status_.lastRunStart_mm, 1))
                                  : tr("To start"));
    withdrawToStart_->setToolTip(!out.enabled ? tr("Not now: %1").arg(out.reason)
                                 : deeper     ? tr("Moves the needle out to where the last run began (not recorded)")
                                              : tr("The needle is not deeper than where the last run began."));
    // The limits of a run are fixed while it records (and Start never leaves the focus there).
    for (QWidget* field : std::initializer_list<QWidget*>{limit_, withdrawLimit_, jogStep_, goToPosition_})
        setEnabledKeepingFocusSafe(field, !state_.recording);
}

// A widget disabled while it holds the focus hands it on along the focus chain: from Withdraw,
// out of the needle's way, to the next control or the Max. force field with its value
// selected, where digits typed change the run's limit; from Start to a parameter field. The
// emergency stop takes it instead: the one safe place.
void ControlPanel::setEnabledKeepingFocusSafe(QWidget* w, bool enabled)
{
    QWidget* focus = window()->focusWidget();
    if (!enabled && w->isEnabled() && focus && (focus == w || w->isAncestorOf(focus)))
        buttons_[Control::EmergencyStop]->setFocus(Qt::OtherFocusReason);
    w->setEnabled(enabled);
}

}  // namespace nb
