#pragma once
#include <QMainWindow>

namespace nb {

// The workbench window: wires the reusable views in widgets/ to the device layer.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
};

}  // namespace nb
