#include "modeless_dialogs.h"

#include <QDialog>
#include <QMessageBox>
#include <QRegularExpression>

namespace nb {

void showModeless(QDialog* dialog)
{
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::NonModal);
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

QFileDialog* chooseFileModeless(QWidget* parent, const FileChoice& choice, std::function<void(const QString&)> chosen)
{
    auto* dialog = new QFileDialog(parent, choice.title, choice.dir, choice.filter);
    dialog->setOption(QFileDialog::DontUseNativeDialog);
    dialog->setFileMode(choice.mode);
    dialog->setAcceptMode(choice.accept);
    if (choice.mode == QFileDialog::Directory)
        dialog->setOption(QFileDialog::ShowDirsOnly);
    if (!choice.name.isEmpty())
        dialog->selectFile(choice.name);
    if (choice.accept == QFileDialog::AcceptSave && !choice.filter.isEmpty()) {
        // A name typed without a suffix takes the chosen type's ("a1_by_motion" saved as
        // "a1_by_motion.png"), as desktop programs do.
        auto suffixOf = [](const QString& filter) {
            static const QRegularExpression glob(QStringLiteral("\\*\\.(\\w+)"));
            const QRegularExpressionMatch m = glob.match(filter);
            return m.hasMatch() ? m.captured(1) : QString();
        };
        dialog->setDefaultSuffix(suffixOf(dialog->selectedNameFilter()));
        QObject::connect(dialog, &QFileDialog::filterSelected, dialog,
                         [dialog, suffixOf](const QString& filter) { dialog->setDefaultSuffix(suffixOf(filter)); });
    }
    QObject::connect(dialog, &QFileDialog::fileSelected, dialog, [chosen = std::move(chosen)](const QString& path) {
        if (!path.isEmpty())
            chosen(path);
    });
    showModeless(dialog);
    return dialog;
}

QMessageBox* warnModeless(QWidget* parent, const QString& title, const QString& text)
{
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, parent);
    showModeless(box);
    return box;
}

}  // namespace nb
