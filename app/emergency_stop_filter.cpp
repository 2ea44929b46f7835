#include "emergency_stop_filter.h"

#include <QCoreApplication>
#include <QKeyEvent>

namespace nb {

EmergencyStopFilter::EmergencyStopFilter(std::function<bool()> busy, std::function<void()> stop, QObject* parent)
    : QObject(parent), busy_(std::move(busy)), stop_(std::move(stop))
{
}

void EmergencyStopFilter::install()
{
    if (installed_ || !QCoreApplication::instance())
        return;
    QCoreApplication::instance()->installEventFilter(this);
    installed_ = true;
}

bool EmergencyStopFilter::eventFilter(QObject* watched, QEvent* event)
{
    // A widget that wants Esc for itself (a line edit's completer, a menu) asks first with a
    // ShortcutOverride; while busy the stop wins, so that is taken too.
    const QEvent::Type type = event->type();
    if (type != QEvent::KeyPress && type != QEvent::ShortcutOverride)
        return QObject::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() != Qt::Key_Escape || !busy_())
        return QObject::eventFilter(watched, event);
    // The key press stops; its ShortcutOverride only keeps the focus widget from claiming it.
    if (type == QEvent::KeyPress)
        stop_();
    event->accept();
    return true;
}

}  // namespace nb
