#include "commands.h"
#include "core/tr.h"

#include "cli_support.h"

#include <QCoreApplication>

namespace nb::cli {

// Each command's entry point, defined in its cmd_*.cpp file.
int cmdVersion(const QStringList& args, Io io);
int cmdFit(const QStringList& args, Io io);
int cmdEvents(const QStringList& args, Io io);
int cmdDevices(const QStringList& args, Io io);
int cmdAcquire(const QStringList& args, Io io);
int cmdExport(const QStringList& args, Io io);
int cmdDemo(const QStringList& args, Io io);
int cmdSimulate(const QStringList& args, Io io);
int cmdVideoInfo(const QStringList& args, Io io);
int cmdFrame(const QStringList& args, Io io);
int cmdSync(const QStringList& args, Io io);
int cmdLabels(const QStringList& args, Io io);
int cmdPlan(const QStringList& args, Io io);

const std::vector<Command>& commands()
{
    static const std::vector<Command> all{
        {QStringLiteral("version"), nb::TrCli::tr("print the version"), cmdVersion},
        {QStringLiteral("fit"), nb::TrCli::tr("fit calibration, stiffness or friction models"), cmdFit},
        {QStringLiteral("events"), nb::TrCli::tr("find contact, punctures and relaxation in a run"), cmdEvents},
        {QStringLiteral("devices"), nb::TrCli::tr("list connected DAQs and serial ports"), cmdDevices},
        {QStringLiteral("acquire"), nb::TrCli::tr("record one run on real (or simulated) devices"), cmdAcquire},
        {QStringLiteral("export"), nb::TrCli::tr("export a session as CSV, HDF5 or ELAN files"), cmdExport},
        {QStringLiteral("demo"), nb::TrCli::tr("simulate, label, fit and export a short session"), cmdDemo, true},
        {QStringLiteral("simulate"), nb::TrCli::tr("record one run on the simulated rig"), cmdSimulate},
        {QStringLiteral("video-info"), nb::TrCli::tr("index a video: frames, rate, duplicates"), cmdVideoInfo},
        {QStringLiteral("frame"), nb::TrCli::tr("write one exact video frame as an image"), cmdFrame},
        {QStringLiteral("sync"), nb::TrCli::tr("find the video's offset to a run (motion vs needle speed)"), cmdSync},
        {QStringLiteral("labels"), nb::TrCli::tr("suggest phase and event labels for a run"), cmdLabels},
        {QStringLiteral("plan"), nb::TrCli::tr("experiment plans: templates, new, run (resumes), report by factor"), cmdPlan},
    };
    return all;
}

bool needsWidgets(const QStringList& arguments)
{
    if (arguments.isEmpty())
        return false;
    for (const Command& c : commands())
        if (c.name == arguments.first())
            return c.rendersWidgets;
    return false;
}

static void printUsage(QTextStream& s)
{
    s << nb::TrCli::tr("Usage: needlebench                 open the workbench (GUI, simulated rig)\n"
                                     "       needlebench COMMAND [options]  run headless\n\n"
                                     "Commands:\n");
    for (const Command& c : commands())
        s << "  " << c.name.leftJustified(16) << ' ' << c.summary << '\n';
    s << nb::TrCli::tr("\n'needlebench COMMAND --help' describes a command.\n");
    // What scripts test for: the numbers are promises, as the commands' options are.
    s << nb::TrCli::tr("\nExit status: 0 done; 1 failed (the message says why, naming the file or device); 2 the command "
                       "was given wrongly; 128+N ended by signal N (130 Ctrl+C, 143 SIGTERM), what was recorded closed.\n");
}

int run(const QStringList& arguments, Io io)
{
    if (arguments.isEmpty() || arguments.first() == QLatin1String("help") ||
        arguments.first() == QLatin1String("--help") || arguments.first() == QLatin1String("-h")) {
        printUsage(arguments.isEmpty() ? io.err : io.out);
        return arguments.isEmpty() ? Usage : Ok;
    }
    const QString word = arguments.first();
    for (const Command& c : commands()) {
        if (c.name == word) {
            try {
                return c.run(arguments.mid(1), io);
            } catch (const std::exception& e) {
                io.err << "needlebench " << word << ": " << QString::fromStdString(e.what()) << '\n';
                return Failure;
            }
        }
    }
    io.err << nb::TrCli::tr("needlebench: unknown command '%1'\n\n").arg(word);
    printUsage(io.err);
    return Usage;
}

}  // namespace nb::cli
