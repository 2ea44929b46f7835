#pragma once
// Esc is the emergency stop wherever the keyboard focus is: in the main window, a modal
// dialog, an open menu or the file chooser. A window shortcut cannot promise that (a modal
// dialog takes Esc first and closes, and the stage keeps moving), so this filter sits on the
// application and sees every key before any widget does.
//
// While something moves or records, Esc stops it and is consumed: the dialog the operator was
// typing in stays open. At rest Esc does its usual job (closes a dialog or menu).

#include <QObject>
#include <functional>

namespace nb {

class EmergencyStopFilter : public QObject {
    Q_OBJECT
public:
    // `busy`: whether the stage moves or a run records now; `stop`: the emergency stop.
    EmergencyStopFilter(std::function<bool()> busy, std::function<void()> stop, QObject* parent = nullptr);

    // Installs this filter on the application (idempotent).
    void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    std::function<bool()> busy_;
    std::function<void()> stop_;
    bool installed_ = false;
};

}  // namespace nb
