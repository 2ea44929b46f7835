#pragma once
// The operator's controls (thesis section 2.6, redone): enable, bias, zero, motion choice,
// start insertion (moves AND records), withdraw, stop motion (keeps recording), end run
// (closes the file), the force limit and an emergency stop that is always enabled. Each
// control is enabled only when interlocks.h allows it and says why not in its tooltip.
// The panel only asks: the main window forwards its requests to the engine.

#include "devices/acquisition_engine.h"
#include "devices/interlocks.h"

#include <QWidget>
#include <map>
#include <optional>

class QAbstractButton;
class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QStackedWidget;

class QSettings;

namespace nb {

class ControlPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlPanel(QWidget* parent = nullptr);

    // The motion part of the next run (linear or sine, with its parameters).
    devices::RunPlan motionPlan() const;
    QString motionName() const;  // "linear" | "sine"
    double withdrawVelocity() const;
    double forceLimit() const;
    void setForceLimit(double newtons);
    // The operator's fields kept between sessions: the force limit under run/forceLimit_N, the
    // motion and jog fields under motion/NAME (the mode as motion/sine, the cycles, the jog
    // step). The panel knows its fields; callers don't. While a plan holds the motion, the
    // operator's own motion is what is kept. settingsChanged() says when one of them changed,
    // so that they can be written at once: written only at quit, a crash brought back an older,
    // higher force limit.
    void saveSettings(QSettings& settings) const;
    void restoreSettings(const QSettings& settings);
    double withdrawForceLimit() const;
    void setWithdrawForceLimit(double newtons);
    // The sine's centre depth (where the run moves first, unrecorded).
    double sineCentre() const;
    void setSineCentre(double mm);

    // A plan sets the next run's motion: the fields show `plan`'s and stay locked, with `why` in
    // their tooltip, until unlockMotion(); motionPlan() then carries its stop at puncture too.
    // Returns what the fields cannot hold (a value out of their range; nothing is locked then).
    // Leaving the plan gives the operator back the motion the panel had before it (the plan's
    // 4 mm/s and 40 mm stayed, deeper than the specimen, and were kept over a restart).
    QString lockMotion(const devices::RunPlan& plan, const QString& why);
    void unlockMotion();
    bool motionLocked() const { return locked_.has_value(); }
    // What must be done before Start besides the interlocks' own rules (a plan's checklist);
    // empty: nothing. Start stays disabled with it in its tooltip.
    void setStartHold(const QString& reason);
    // Whether the calibration wizard is open (no run starts while it is).
    void setCalibrating(bool open);

    void setStatus(const devices::EngineStatus& status);
    void setSessionOpen(bool open);
    // Set by the main window from the session's active calibration.
    void setCalibrationName(const QString& name);

    const InterlockState& interlockState() const { return state_; }
    QAbstractButton* button(Control control) const;

signals:
    void enableRequested(bool on);
    void biasRequested();
    void zeroRequested();
    void startRequested();
    void withdrawRequested(double velocity_mm_s);
    void stopMotionRequested();
    void endRunRequested();
    void forceLimitChanged(double newtons);
    void emergencyStopRequested();
    void calibrateRequested();
    void withdrawForceLimitChanged(double newtons);
    // Out to where the last run began (after a force-limit or emergency stop).
    void withdrawToRequested(double velocity_mm_s, double target_mm);
    // Unrecorded moves: a step (negative = out) or to a position.
    void jogRequested(double delta_mm, double velocity_mm_s);
    void moveToRequested(double position_mm, double velocity_mm_s);
    // The emergency stop latch's reset: enables the stage again on purpose.
    void resetEmergencyStopRequested();
    // A field saveSettings() keeps changed.
    void settingsChanged();

private:
    void updateControls();
    QString motionProblem() const;
    QPushButton* addButton(Control control, const QString& text, const QString& help);
    QWidget* buildLatchBanner();
    QWidget* buildJogBox();
    void updateSafetyControls();
    void setEnabledKeepingFocusSafe(QWidget* w, bool enabled);

    InterlockState state_;
    devices::EngineStatus status_;
    std::map<Control, QPushButton*> buttons_;
    std::map<Control, QString> help_;
    QGroupBox* motionBox_ = nullptr;
    QRadioButton* linear_ = nullptr;
    QRadioButton* sine_ = nullptr;
    QStackedWidget* motionPages_ = nullptr;
    QDoubleSpinBox* velocity_ = nullptr;
    QDoubleSpinBox* depth_ = nullptr;
    QDoubleSpinBox* amplitude_ = nullptr;
    QDoubleSpinBox* frequency_ = nullptr;
    QSpinBox* cycles_ = nullptr;
    QDoubleSpinBox* limit_ = nullptr;
    QDoubleSpinBox* withdrawLimit_ = nullptr;
    QDoubleSpinBox* centre_ = nullptr;
    QWidget* latchBanner_ = nullptr;
    QPushButton* withdrawToStart_ = nullptr;
    QPushButton* jogOut_ = nullptr;
    QPushButton* jogIn_ = nullptr;
    QPushButton* goTo_ = nullptr;
    QComboBox* jogStep_ = nullptr;
    QDoubleSpinBox* goToPosition_ = nullptr;
    QWidget* jogBox_ = nullptr;
    std::map<QString, QLabel*> status_labels_;
    QString calibrationName_;
    std::optional<devices::RunPlan> locked_;
    // The operator's motion fields, as they were before a plan set its own.
    struct MotionFields {
        bool sine = false;
        double velocity = 0, depth = 0, amplitude = 0, frequency = 0;
        int cycles = 1;
    };
    MotionFields motionFields() const;
    void setMotionFields(const MotionFields& m);
    std::optional<MotionFields> operatorMotion_;
    QString lockReason_, startHold_;
    bool calibrating_ = false;
};

}  // namespace nb
