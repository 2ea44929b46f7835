#pragma once
// Dialogs that leave the main window usable. What the window offers while the stage moves or
// a run records opens this way: a modal dialog blocks every click on the window behind it, the
// EMERGENCY STOP button included, and on X11 a click there takes the keyboard from the dialog
// as well, so that Esc went nowhere either.

#include <QFileDialog>
#include <QString>

#include <functional>

class QDialog;
class QMessageBox;
class QWidget;

namespace nb {

// Shows `dialog` above its parent without blocking any window; it is deleted when closed.
void showModeless(QDialog* dialog);

struct FileChoice {
    QString title;
    QString dir;
    QString filter;  // empty: any file
    QFileDialog::FileMode mode = QFileDialog::ExistingFile;
    QFileDialog::AcceptMode accept = QFileDialog::AcceptOpen;
    QString name;  // the file name offered (saving); without a suffix, the chosen type's is added

    // A folder to choose, starting in `dir`.
    static FileChoice folder(const QString& title, const QString& dir)
    {
        FileChoice c;
        c.title = title;
        c.dir = dir;
        c.mode = QFileDialog::Directory;
        return c;
    }
};

// Qt's own file chooser (never the desktop's: Esc must reach the emergency stop's filter),
// modeless; `chosen` is called with the path the operator picks, not when they cancel.
QFileDialog* chooseFileModeless(QWidget* parent, const FileChoice& choice, std::function<void(const QString&)> chosen);

// A warning the operator may read while the stage moves.
QMessageBox* warnModeless(QWidget* parent, const QString& title, const QString& text);

}  // namespace nb
