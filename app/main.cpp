// needlebench: with no command word the workbench GUI on the simulated rig; with one, a
// headless command on QCoreApplication (no display needed).

#include "commands.h"
#include "display_guard.h"
#include "guarded_main.h"
#include "interrupt_watcher.h"
#include "main_window.h"
#include "translation.h"

#include "core/tr.h"
#include "devices/acquisition_engine.h"

#include <QApplication>
#include <QCoreApplication>
#include <QStringDecoder>
#include <QTextStream>
#include <QTimer>
#include <cstdio>
#include <malloc.h>
#include <memory>
#include <cstring>
#include <cerrno>

// OpenCV allocates its images and spectra afresh at every call (the tissue tracker's phase
// correlation: hundreds of kB a frame, in several threads), and glibc gave each back to the
// system when freed and faulted it in again at the next call: `labels suggest` on a video spent
// half its time in the kernel (5.1 s against 2.7 s kept). Freed memory is kept for reuse. ctest
// gives the test programs, which have their own main, the same through GLIBC_TUNABLES
// (tests/CMakeLists.txt); both settings are needed (one alone was slower than neither).
static void keepFreedMemory()
{
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

static bool isHeadless(int argc, char** argv)
{
    // Qt's own GUI options (-platform, -style, ...) start with '-'; a command word does not.
    return argc > 1 && argv[1][0] != '-';
}

// The options a user types by habit to ask what a program is, answered as their commands are.
static bool asksForHelpOrVersion(int argc, char** argv)
{
    if (argc < 2)
        return false;
    const QByteArray first(argv[1]);
    return first == "--help" || first == "-h" || first == "--version" || first == "-v";
}

// The window on the workbench: a signal (SIGTERM, SIGINT, SIGHUP) stops the stage and closes
// an open run with end reason "interrupted" before the window goes.
static int runWindow(QApplication& app)
{
    nb::MainWindow window;
    nb::InterruptWatcher interrupts;
    // Quitting goes without the quit question (QCoreApplication::quit() asked the window, whose
    // question then waited for an operator who was not there), with status 128 + the signal.
    const auto leave = [&window](int signo) {
        window.closeWithoutAsking();
        QCoreApplication::exit(128 + signo);
    };
    QObject::connect(&interrupts, &nb::InterruptWatcher::interrupted, &app, [&](int signo) {
        nb::devices::AcquisitionEngine* engine = window.engine();
        if (interrupts.signalNumber() != signo || !engine || !engine->status().recording) {
            leave(signo);  // nothing to close, or a second signal: go now
            return;
        }
        QObject::connect(engine, &nb::devices::AcquisitionEngine::runEnded, &app, [leave, signo] { leave(signo); });
        nb::Metadata extra;
        extra.set(QStringLiteral("signal"), nb::InterruptWatcher::signalName(signo));
        engine->interrupt(extra);
        QTimer::singleShot(5000, &app, [leave, signo] { leave(signo); });
    });
    window.show();
    return app.exec();
}

int main(int argc, char** argv)
{
    keepFreedMemory();
    nb::installTerminateHandler();
    // FFmpeg's own log lines ("[mov,mp4,… @ 0x…] moov atom not found") duplicate what NeedleBench
    // says about a video, by name; OPENCV_FFMPEG_LOGLEVEL=16 brings them back for a diagnosis.
    if (qEnvironmentVariableIsEmpty("OPENCV_FFMPEG_LOGLEVEL"))
        qputenv("OPENCV_FFMPEG_LOGLEVEL", "-8");
    QCoreApplication::setOrganizationName(QStringLiteral("NeedleBench"));
    QCoreApplication::setApplicationName(QStringLiteral("needlebench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEEDLEBENCH_VERSION));

    QTextStream err(stderr);
    if (isHeadless(argc, argv) || asksForHelpOrVersion(argc, argv)) {
        QStringList words;
        for (int i = 1; i < argc; ++i)
            words << QString::fromLocal8Bit(argv[i]);
        if (words.value(0) == QLatin1String("--version") || words.value(0) == QLatin1String("-v"))
            words[0] = QStringLiteral("version");
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
            QStringList arguments = app.arguments().mid(1);
            if (!arguments.isEmpty())
                arguments[0] = words.value(0);  // --version asked as the command it is
            // A file name in another encoding (Latin-1 from an old instrument PC) cannot be
            // given back to the file system once read as text: it was "cannot open: no such
            // file", naming a file with a '?' the operator could not find.
            for (int i = 1; i < argc; ++i) {
                QStringDecoder utf8(QStringDecoder::Utf8);
                (void)QString(utf8.decode(QByteArrayView(argv[i])));
                if (utf8.hasError()) {
                    err << nb::TrCli::tr("needlebench %1: '%2' is not UTF-8, so it cannot be opened by name here: rename it "
                                         "(for example with convmv -f latin1 -t utf8 --notest)")
                               .arg(what, QString::fromLatin1(argv[i]))
                        << '\n';
                    err.flush();
                    return int(nb::cli::Usage);
                }
            }
            int code = nb::runGuarded(what, [&] { return nb::cli::run(arguments, {out, err}); }, err);
            out.flush();
            // What a script reads from the output is the result: an output that could not be
            // written (a full disk behind `> out.json`) is a failure, not exit 0 and an empty file.
            errno = 0;
            if ((out.status() == QTextStream::WriteFailed || std::fflush(stdout) != 0 || std::ferror(stdout)) && code == 0) {
                err << nb::TrCli::tr("needlebench %1: the output could not be written (%2)")
                           .arg(what, errno ? QString::fromLocal8Bit(std::strerror(errno)) : nb::TrCli::tr("write error"))
                    << '\n';
                code = 1;
            }
            err.flush();
            return code;
        }, err);
    }

    // What to say if there is no display to open the window on, in the operator's language
    // (the translation needs an application; the window's own needs the display).
    QString cannotOpen;
    {
        QCoreApplication probe(argc, argv);
        nb::installTranslation(probe);
        const QString commands = nb::TrCli::tr("Run a command without the window, such as 'needlebench demo'; "
                                               "'needlebench --help' lists them.");
        if (!nb::haveDisplay(argc, argv)) {
            err << nb::TrCli::tr("needlebench: no display to open the workbench on (neither DISPLAY nor "
                                 "WAYLAND_DISPLAY is set). Log in to a desktop or use ssh -X.")
                << ' ' << commands << '\n';
            return 2;
        }
        cannotOpen = nb::TrCli::tr("needlebench: the workbench cannot open on the display '%1' (see above): is "
                                   "the desktop still running, or the SSH session still forwarding X?")
                         .arg(qEnvironmentVariable("DISPLAY", qEnvironmentVariable("WAYLAND_DISPLAY")))
                     + QLatin1Char(' ') + commands;
    }

    // A signal while the window starts up is kept and handled once it is up.
    nb::InterruptWatcher::catchEarly();
    return nb::runGuarded(QStringLiteral("(window)"), [&] {
        nb::explainFatalStartup(cannotOpen);
        QApplication app(argc, argv);
        nb::endStartupExplanation();
        nb::installTranslation(app);
        // Qt takes its own options (-platform, -style, …) out of argv: what is left is a typo,
        // which opened the window (restoring the last session) instead of saying so.
        if (argc > 1) {
            err << nb::TrCli::tr("needlebench: unknown option '%1'; 'needlebench --help' lists the commands and their options")
                       .arg(QString::fromLocal8Bit(argv[1]))
                << '\n';
            return 2;
        }
        return nb::runGuarded(QStringLiteral("(window)"), [&] { return runWindow(app); }, err);
    }, err);
}
