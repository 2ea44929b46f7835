// needlebench: with no command word the workbench GUI on the simulated rig; with one, a
// headless command on QCoreApplication (no display needed).

#include "commands.h"
#include "guarded_main.h"
#include "interrupt_watcher.h"
#include "main_window.h"
#include "translation.h"

#include "devices/acquisition_engine.h"

#include <QApplication>
#include <QCoreApplication>
#include <QTextStream>
#include <QTimer>
#include <cstdio>
#include <memory>

static bool isHeadless(int argc, char** argv)
{
    // Qt's own GUI options (-platform, -style, ...) start with '-'; a command word does not.
    return argc > 1 && argv[1][0] != '-';
}

// The window on the workbench: a signal (SIGTERM, SIGINT, SIGHUP) stops the stage and closes
// an open run with end reason "interrupted" before the window goes.
static int runWindow(QApplication& app)
{
    nb::MainWindow window;
    nb::InterruptWatcher interrupts;
    QObject::connect(&interrupts, &nb::InterruptWatcher::interrupted, &app, [&](int signo) {
        nb::devices::AcquisitionEngine* engine = window.engine();
        if (interrupts.signalNumber() != signo || !engine || !engine->status().recording) {
            QCoreApplication::quit();  // nothing to close, or a second signal: go now
            return;
        }
        QObject::connect(engine, &nb::devices::AcquisitionEngine::runEnded, &app, [] { QCoreApplication::quit(); });
        nb::Metadata extra;
        extra.set(QStringLiteral("signal"), nb::InterruptWatcher::signalName(signo));
        engine->interrupt(extra);
        QTimer::singleShot(5000, &app, [] { QCoreApplication::quit(); });
    });
    window.show();
    return app.exec();
}

int main(int argc, char** argv)
{
    nb::installTerminateHandler();
    QCoreApplication::setOrganizationName(QStringLiteral("NeedleBench"));
    QCoreApplication::setApplicationName(QStringLiteral("needlebench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEEDLEBENCH_VERSION));

    QTextStream err(stderr);
    if (isHeadless(argc, argv) || (argc > 1 && (QByteArray(argv[1]) == "--help" || QByteArray(argv[1]) == "-h"))) {
        QStringList words;
        for (int i = 1; i < argc; ++i)
            words << QString::fromLocal8Bit(argv[i]);
        const QString what = words.value(0);
        return nb::runGuarded(what, [&] {
            std::unique_ptr<QCoreApplication> holder;
            if (nb::cli::needsWidgets(words)) {
                if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
                    qputenv("QT_QPA_PLATFORM", "offscreen");
                holder = std::make_unique<QApplication>(argc, argv);
            } else {
                holder = std::make_unique<QCoreApplication>(argc, argv);
            }
            QCoreApplication& app = *holder;
            nb::installTranslation(app);
            QTextStream out(stdout);
            const int code = nb::runGuarded(what, [&] { return nb::cli::run(app.arguments().mid(1), {out, err}); }, err);
            out.flush();
            err.flush();
            return code;
        }, err);
    }

    // A signal while the window starts up is kept and handled once it is up.
    nb::InterruptWatcher::catchEarly();
    return nb::runGuarded(QStringLiteral("(window)"), [&] {
        QApplication app(argc, argv);
        nb::installTranslation(app);
        return nb::runGuarded(QStringLiteral("(window)"), [&] { return runWindow(app); }, err);
    }, err);
}
