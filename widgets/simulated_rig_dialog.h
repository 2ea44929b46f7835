#pragma once
// Devices ▸ Simulated rig…: the simulated rig's tissue preset, tip, seed and the sampling
// rate, checked before the dialog accepts them (devices::checkSimulatedRig).

#include "devices/device_spec.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace nb {

class SimulatedRigDialog : public QDialog {
    Q_OBJECT
public:
    SimulatedRigDialog(const devices::SimulatedRigSpec& spec, double rateHz, QWidget* parent = nullptr);

    devices::SimulatedRigSpec spec() const;
    double rateHz() const;

public slots:
    void accept() override;

private:
    devices::SimulatedRigSpec base_;
    QComboBox* tissue_ = nullptr;
    QComboBox* tip_ = nullptr;
    QSpinBox* seed_ = nullptr;
    QDoubleSpinBox* rate_ = nullptr;
    QLabel* problem_ = nullptr;
};

}  // namespace nb
