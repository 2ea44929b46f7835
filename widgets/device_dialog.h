#pragma once
// Chooses the devices a session drives: the DAQ (the simulated rig, or a LabJack U6, by
// serial number or the first found) and the stage (simulated, or a Zaber controller on a
// serial port), with the settings each needs. Lists what is connected and rescans on demand;
// the result is a devices::DeviceSpec, checked before the dialog accepts it.

#include "devices/device_spec.h"

#include <QDialog>
#include <functional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace nb {

class DeviceDialog : public QDialog {
    Q_OBJECT
public:
    using Lister = std::function<std::vector<devices::ConnectedDevice>()>;
    DeviceDialog(const devices::DeviceSpec& spec, Lister lister, QWidget* parent = nullptr);

    devices::DeviceSpec spec() const;
    QString problem() const;  // why the last OK was refused, empty if it was not

public slots:
    void rescan();
    void accept() override;

private:
    void fill(const QString& daq, const QString& stage);
    void updateEnabled();

    Lister lister_;
    devices::DeviceSpec spec_;
    QComboBox* daq_;
    QLineEdit* daqSerial_;
    QSpinBox* channel_;
    QComboBox* gain_;
    QComboBox* stage_;
    QLineEdit* port_;
    QDoubleSpinBox* microsteps_;
    QLabel* found_;
    QLabel* error_;
};

}  // namespace nb
