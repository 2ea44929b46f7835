#include "display_guard.h"

#include <QByteArray>
#include <QtGlobal>

#include <cstdio>
#include <cstdlib>

namespace nb {

namespace {
QString startupExplanation;
QtMessageHandler qtHandler = nullptr;

void explainingHandler(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtFatalMsg) {
        // Qt's warnings before it (the display it tried) have been printed; its fatal message
        // advises a reinstall, which would not help.
        std::fprintf(stderr, "%s\n", qPrintable(startupExplanation));
        std::fflush(stderr);
        std::_Exit(2);
    }
    if (qtHandler)
        qtHandler(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(message));
}
}  // namespace

bool haveDisplay(int argc, char** argv)
{
#if defined(Q_OS_LINUX) || defined(Q_OS_FREEBSD)
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") || !qEnvironmentVariableIsEmpty("DISPLAY")
        || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        return true;
    for (int i = 1; i < argc; ++i)
        if (QByteArray(argv[i]) == "-platform")
            return true;
    return false;
#else
    Q_UNUSED(argc);
    Q_UNUSED(argv);
    return true;
#endif
}

void explainFatalStartup(const QString& explanation)
{
    startupExplanation = explanation;
    qtHandler = qInstallMessageHandler(explainingHandler);
}

void endStartupExplanation()
{
    qInstallMessageHandler(qtHandler);
    qtHandler = nullptr;
}

}  // namespace nb
