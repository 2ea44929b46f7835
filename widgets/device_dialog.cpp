#include "device_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace nb {

namespace {
// Item data of the "type it in" entries: they take their spec from the line edit beside.
const QString kOtherU6 = QStringLiteral("u6:?");
const QString kOtherPort = QStringLiteral("zaber:?");
}  // namespace

DeviceDialog::DeviceDialog(const devices::DeviceSpec& spec, Lister lister, QWidget* parent)
    : QDialog(parent), lister_(std::move(lister)), spec_(spec), daq_(new QComboBox(this)), daqSerial_(new QLineEdit(this)),
      channel_(new QSpinBox(this)), gain_(new QComboBox(this)), stage_(new QComboBox(this)), port_(new QLineEdit(this)),
      microsteps_(new QDoubleSpinBox(this)), found_(new QLabel(this)), error_(new QLabel(this))
{
    setWindowTitle(tr("Devices"));
    daq_->setObjectName(QStringLiteral("daq"));
    daqSerial_->setObjectName(QStringLiteral("daqSerial"));
    daqSerial_->setPlaceholderText(tr("serial number, e.g. 360012345"));
    channel_->setObjectName(QStringLiteral("u6Channel"));
    channel_->setRange(0, 13);
    channel_->setValue(spec.u6Channel);
    channel_->setToolTip(tr("Analog input (differential with the next one)"));
    gain_->setObjectName(QStringLiteral("u6Gain"));
    gain_->addItem(tr("×1 (±10 V)"));
    gain_->addItem(tr("×10 (±1 V)"));
    gain_->addItem(tr("×100 (±100 mV)"));
    gain_->addItem(tr("×1000 (±10 mV)"));
    gain_->setCurrentIndex(std::clamp(spec.u6GainIndex, 0, 3));
    stage_->setObjectName(QStringLiteral("stage"));
    port_->setObjectName(QStringLiteral("stagePort"));
    port_->setPlaceholderText(tr("serial port, e.g. /dev/ttyUSB0"));
    microsteps_->setObjectName(QStringLiteral("zaberMicrosteps"));
    microsteps_->setRange(1.0, 1.0e8);
    microsteps_->setDecimals(3);
    microsteps_->setValue(spec.zaberMicrostepsPerMm);
    microsteps_->setToolTip(tr("The axis's micro-steps per millimetre (from its data sheet)"));

    auto* daqBox = new QGroupBox(tr("Force sensor (DAQ)"), this);
    auto* daqForm = new QFormLayout(daqBox);
    daqForm->addRow(tr("Device"), daq_);
    daqForm->addRow(tr("Serial number"), daqSerial_);
    daqForm->addRow(tr("Input"), channel_);
    daqForm->addRow(tr("Range"), gain_);
    auto* stageBox = new QGroupBox(tr("Insertion stage"), this);
    auto* stageForm = new QFormLayout(stageBox);
    stageForm->addRow(tr("Device"), stage_);
    stageForm->addRow(tr("Port"), port_);
    stageForm->addRow(tr("Micro-steps per mm"), microsteps_);

    auto* scan = new QPushButton(tr("&Rescan"), this);
    scan->setObjectName(QStringLiteral("rescan"));
    connect(scan, &QPushButton::clicked, this, &DeviceDialog::rescan);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->addButton(scan, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &DeviceDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &DeviceDialog::reject);

    found_->setObjectName(QStringLiteral("found"));
    found_->setWordWrap(true);
    error_->setObjectName(QStringLiteral("error"));
    error_->setWordWrap(true);
    error_->setStyleSheet(QStringLiteral("color: #c62828"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(daqBox);
    layout->addWidget(stageBox);
    layout->addWidget(found_);
    layout->addWidget(error_);
    layout->addWidget(buttons);

    connect(daq_, &QComboBox::currentIndexChanged, this, &DeviceDialog::updateEnabled);
    connect(stage_, &QComboBox::currentIndexChanged, this, &DeviceDialog::updateEnabled);
    fill(spec.daq, spec.stage);
}

void DeviceDialog::rescan()
{
    const devices::DeviceSpec chosen = spec();
    fill(chosen.daq, chosen.stage);
}

void DeviceDialog::fill(const QString& daq, const QString& stage)
{
    const std::vector<devices::ConnectedDevice> found = lister_ ? lister_() : std::vector<devices::ConnectedDevice>{};
    daq_->clear();
    daq_->addItem(tr("Simulated rig"), QStringLiteral("sim"));
    daq_->addItem(tr("LabJack U6, the first found"), QStringLiteral("u6"));
    stage_->clear();
    stage_->addItem(tr("Simulated stage"), QStringLiteral("sim"));
    QStringList problems;
    int daqs = 0, ports = 0;
    for (const devices::ConnectedDevice& d : found) {
        if (d.spec.isEmpty()) {
            problems << tr("%1: %2").arg(d.description, d.problem);
            continue;
        }
        QString text = d.kind == QLatin1String("daq") ? d.description : tr("Zaber on %1").arg(d.spec.mid(6));
        if (d.spec.startsWith(QLatin1String("u6:")))
            text += QStringLiteral(" #") + d.spec.mid(3);
        if (d.kind != QLatin1String("daq") && !d.description.isEmpty())
            text += QStringLiteral(" (%1)").arg(d.description);
        if (!d.problem.isEmpty())
            text += QStringLiteral(" – %1").arg(d.problem);
        (d.kind == QLatin1String("daq") ? daq_ : stage_)->addItem(text, d.spec);
        (d.kind == QLatin1String("daq") ? daqs : ports) += 1;
    }
    daq_->addItem(tr("LabJack U6 by serial number…"), kOtherU6);
    stage_->addItem(tr("Zaber on another port…"), kOtherPort);
    found_->setText(tr("Found %n LabJack U6(s)", nullptr, daqs) + QStringLiteral(", ") + tr("%n serial port(s)", nullptr, ports) +
                    (problems.isEmpty() ? QString() : QStringLiteral("; ") + problems.join(QStringLiteral("; "))));

    // Put back what was chosen, typing it in when it is not connected now.
    int i = daq_->findData(daq);
    if (i < 0 && daq.startsWith(QLatin1String("u6:"))) {
        daqSerial_->setText(daq.mid(3));
        i = daq_->findData(kOtherU6);
    }
    daq_->setCurrentIndex(std::max(0, i));
    int j = stage_->findData(stage);
    if (j < 0 && stage.startsWith(QLatin1String("zaber:"))) {
        port_->setText(stage.mid(6));
        j = stage_->findData(kOtherPort);
    }
    stage_->setCurrentIndex(std::max(0, j));
    updateEnabled();
}

void DeviceDialog::updateEnabled()
{
    const QString daq = daq_->currentData().toString();
    const QString stage = stage_->currentData().toString();
    daqSerial_->setEnabled(daq == kOtherU6);
    channel_->setEnabled(daq != QLatin1String("sim"));
    gain_->setEnabled(daq != QLatin1String("sim"));
    port_->setEnabled(stage == kOtherPort);
    microsteps_->setEnabled(stage != QLatin1String("sim"));
}

devices::DeviceSpec DeviceDialog::spec() const
{
    devices::DeviceSpec s = spec_;
    s.daq = daq_->currentData().toString();
    if (s.daq == kOtherU6)
        s.daq = QStringLiteral("u6:") + daqSerial_->text().trimmed();
    s.stage = stage_->currentData().toString();
    if (s.stage == kOtherPort)
        s.stage = QStringLiteral("zaber:") + port_->text().trimmed();
    s.u6Channel = channel_->value();
    s.u6GainIndex = gain_->currentIndex();
    s.zaberMicrostepsPerMm = microsteps_->value();
    return s;
}

QString DeviceDialog::problem() const
{
    return error_->text();
}

void DeviceDialog::accept()
{
    const devices::DeviceSpec s = spec();
    QString why;
    if (s.daq == QLatin1String("u6:"))
        why = tr("Type the U6's serial number, or choose a listed one.");
    else if (s.stage == QLatin1String("zaber:"))
        why = tr("Type the stage's serial port (zaber:PORT), or choose a listed one.");
    if (why.isEmpty())
        why = devices::checkDaqSpec(s.daq);
    if (why.isEmpty())
        why = devices::checkStageSpec(s.stage);
    error_->setText(why);
    if (why.isEmpty())
        QDialog::accept();
}

}  // namespace nb
