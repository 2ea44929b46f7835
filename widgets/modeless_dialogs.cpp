#include "modeless_dialogs.h"

#include <QDialog>
#include <QMessageBox>

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
