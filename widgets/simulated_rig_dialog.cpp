#include "simulated_rig_dialog.h"

#include "core/data_names.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace nb {

SimulatedRigDialog::SimulatedRigDialog(const devices::SimulatedRigSpec& spec, double rateHz, QWidget* parent)
    : QDialog(parent), base_(spec)
{
    setObjectName(QStringLiteral("simulatedRigDialog"));
    setWindowTitle(tr("Simulated rig"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    tissue_ = new QComboBox(this);
    tissue_->setObjectName(QStringLiteral("tissue"));
    for (const QString& t : devices::simulatedTissues())
        tissue_->addItem(tissueDisplayName(t), t);
    tissue_->setCurrentIndex(std::max(0, tissue_->findData(spec.tissue)));
    tip_ = new QComboBox(this);
    tip_->setObjectName(QStringLiteral("tip"));
    tip_->addItem(tr("the preset's usual tip"), QString());
    for (const QString& t : devices::tipNames())
        tip_->addItem(tipDisplayName(t), t);
    tip_->setCurrentIndex(std::max(0, tip_->findData(spec.tip)));
    seed_ = new QSpinBox(this);
    seed_->setObjectName(QStringLiteral("seed"));
    seed_->setRange(0, 1000000000);
    seed_->setValue(int(std::min<quint64>(spec.seed, 1000000000)));
    rate_ = new QDoubleSpinBox(this);
    rate_->setObjectName(QStringLiteral("rate"));
    rate_->setRange(100.0, 10000.0);
    rate_->setDecimals(0);
    rate_->setSuffix(tr(" Hz"));
    rate_->setValue(rateHz);
    form->addRow(tr("Tissue preset"), tissue_);
    form->addRow(tr("Needle tip"), tip_);
    form->addRow(tr("Random seed"), seed_);
    form->addRow(tr("Sample rate"), rate_);
    layout->addLayout(form);
    auto* note = new QLabel(tr("The rig is rebuilt when you press OK; each run's file records these settings."), this);
    note->setWordWrap(true);
    layout->addWidget(note);
    problem_ = new QLabel(this);
    problem_->setStyleSheet(QStringLiteral("color: #c62828;"));
    problem_->setWordWrap(true);
    layout->addWidget(problem_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &SimulatedRigDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

devices::SimulatedRigSpec SimulatedRigDialog::spec() const
{
    devices::SimulatedRigSpec s = base_;
    s.tissue = tissue_->currentData().toString();
    s.tip = tip_->currentData().toString();
    s.seed = quint64(seed_->value());
    return s;
}

double SimulatedRigDialog::rateHz() const { return rate_->value(); }

void SimulatedRigDialog::accept()
{
    const QString problem = devices::checkSimulatedRig(spec());
    problem_->setText(problem);
    if (problem.isEmpty())
        QDialog::accept();
}

}  // namespace nb
