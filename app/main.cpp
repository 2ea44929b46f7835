// needlebench: with no command word the workbench GUI on the simulated rig; with one, a
// headless command on QCoreApplication (no display needed).

#include "commands.h"
#include "main_window.h"
#include "translation.h"

#include <QApplication>
#include <QCoreApplication>
#include <QTextStream>
#include <cstdio>
#include <memory>

static bool isHeadless(int argc, char** argv)
{
    // Qt's own GUI options (-platform, -style, ...) start with '-'; a command word does not.
    return argc > 1 && argv[1][0] != '-';
}

int main(int argc, char** argv)
{
    QCoreApplication::setOrganizationName(QStringLiteral("NeedleBench"));
    QCoreApplication::setApplicationName(QStringLiteral("needlebench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEEDLEBENCH_VERSION));

    if (isHeadless(argc, argv) || (argc > 1 && (QByteArray(argv[1]) == "--help" || QByteArray(argv[1]) == "-h"))) {
        QStringList words;
        for (int i = 1; i < argc; ++i)
            words << QString::fromLocal8Bit(argv[i]);
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
        QTextStream err(stderr);
        const int code = nb::cli::run(app.arguments().mid(1), {out, err});
        out.flush();
        err.flush();
        return code;
    }

    QApplication app(argc, argv);
    nb::installTranslation(app);
    nb::MainWindow window;
    window.show();
    return app.exec();
}
