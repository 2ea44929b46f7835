#include "session_info_dialog.h"

#include "core/data_names.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>

namespace nb {

SessionInfoDialog::SessionInfoDialog(Mode mode, const SessionInfo& info, const QString& parentFolder, QWidget* parent)
    : QDialog(parent), original_(info), organ_(new QLineEdit(info.organ, this)), specimen_(new QLineEdit(info.specimen, this)),
      tip_(new QComboBox(this)), thickness_(new QDoubleSpinBox(this)), operator_(new QLineEdit(info.operatorName, this)),
      protocol_(new QLineEdit(info.protocol, this)), notes_(new QPlainTextEdit(info.notes, this))
{
    setWindowTitle(mode == Mode::New ? tr("New session") : tr("Session details"));
    organ_->setObjectName(QStringLiteral("organ"));
    specimen_->setObjectName(QStringLiteral("specimen"));
    tip_->setObjectName(QStringLiteral("tip"));
    tip_->setEditable(true);
    // Tip names are data (run metadata, fits group by them): shown translated, stored as they are.
    tip_->addItem(QString(), QString());
    for (const QString& tip : {QStringLiteral("beveled"), QStringLiteral("diamond"), QStringLiteral("blunt")})
        tip_->addItem(tipDisplayName(tip), tip);
    if (const int known = tip_->findData(info.tip); known >= 0)
        tip_->setCurrentIndex(known);
    else
        tip_->setCurrentText(info.tip);
    thickness_->setObjectName(QStringLiteral("thickness"));
    thickness_->setRange(0, 500);
    thickness_->setSuffix(tr(" mm"));
    thickness_->setValue(info.thickness_mm);
    thickness_->setToolTip(tr("Slab thickness on the friction platform; 0 for a whole organ"));
    operator_->setObjectName(QStringLiteral("operator"));
    protocol_->setObjectName(QStringLiteral("protocol"));
    protocol_->setPlaceholderText(tr("overall stiffness, friction, …"));
    notes_->setObjectName(QStringLiteral("notes"));
    notes_->setTabChangesFocus(true);  // Tab moves on, as in every other field; a keyboard-only operator was trapped here

    auto* form = new QFormLayout(this);
    form->addRow(tr("Organ"), organ_);
    form->addRow(tr("Specimen number"), specimen_);
    form->addRow(tr("Needle tip"), tip_);
    form->addRow(tr("Thickness"), thickness_);
    form->addRow(tr("Operator"), operator_);
    form->addRow(tr("Protocol"), protocol_);
    form->addRow(tr("Notes"), notes_);
    if (mode == Mode::New) {
        folder_ = new QLineEdit(parentFolder, this);
        folder_->setObjectName(QStringLiteral("parentFolder"));
        auto* browse = new QPushButton(tr("Browse…"), this);
        connect(browse, &QPushButton::clicked, this, [this] {
            // Qt's own chooser, never the desktop's: Esc must reach the emergency stop's filter.
            const QString d = QFileDialog::getExistingDirectory(this, tr("Parent folder"), folder_->text(),
                                                                QFileDialog::ShowDirsOnly | QFileDialog::DontUseNativeDialog);
            if (!d.isEmpty())
                folder_->setText(d);
        });
        auto* row = new QHBoxLayout;
        row->addWidget(folder_, 1);
        row->addWidget(browse);
        form->addRow(tr("Parent folder"), row);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

SessionInfo SessionInfoDialog::info() const
{
    SessionInfo i = original_;
    i.organ = organ_->text().trimmed();
    i.specimen = specimen_->text().trimmed();
    // A known tip by its shown name gives its stored name; anything typed is kept as typed.
    const QString tip = tip_->currentText().trimmed();
    const int known = tip_->findText(tip);
    i.tip = known >= 0 ? tip_->itemData(known).toString() : tip;
    i.thickness_mm = thickness_->value();
    i.operatorName = operator_->text().trimmed();
    i.protocol = protocol_->text().trimmed();
    i.notes = notes_->toPlainText();
    return i;
}

QString SessionInfoDialog::parentFolder() const
{
    return folder_ ? folder_->text().trimmed() : QString();
}

}  // namespace nb
