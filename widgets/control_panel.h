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

class QAbstractButton;
class QButtonGroup;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QStackedWidget;

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

private:
    void updateControls();
    QString motionProblem() const;
    QPushButton* addButton(Control control, const QString& text, const QString& help);

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
    std::map<QString, QLabel*> status_labels_;
    QString calibrationName_;
};

}  // namespace nb
