#include "main_window.h"

#include <QLabel>
#include <QMenuBar>
#include <QStatusBar>

namespace nb {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setWindowTitle(tr("NeedleBench"));
    auto* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    setCentralWidget(new QLabel(tr("Simulated rig"), this));
    statusBar()->showMessage(tr("Ready"));
    resize(1280, 800);
}

}  // namespace nb
