// `needlebench devices`: what is connected (USB DAQs through libusb, serial ports) and the
// --daq/--stage string that selects each.

#include "cli_support.h"
#include "core/tr.h"

#include "devices/device_spec.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace nb::cli {

int cmdDevices(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOption(json);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("devices"), args, io, 0, 0, &code))
        return code;
    const auto found = devices::listDevices();
    if (parser.isSet(json)) {
        QJsonArray daqs, ports;
        for (const auto& d : found) {
            QJsonObject o{{QStringLiteral("spec"), d.spec}, {QStringLiteral("description"), d.description}};
            if (!d.problem.isEmpty())
                o.insert(QStringLiteral("problem"), d.problem);
            (d.kind == QLatin1String("daq") ? daqs : ports).append(o);
        }
        daqs.prepend(QJsonObject{{QStringLiteral("spec"), QStringLiteral("sim")},
                                 {QStringLiteral("description"), nb::TrCli::tr("simulated load cell (default)")}});
        ports.prepend(QJsonObject{{QStringLiteral("spec"), QStringLiteral("sim")},
                                  {QStringLiteral("description"), nb::TrCli::tr("simulated stage (default)")}});
        printJson(io, QJsonObject{{QStringLiteral("daqs"), daqs}, {QStringLiteral("stages"), ports}});
        return Ok;
    }
    io.out << nb::TrCli::tr("DAQs (--daq):\n");
    io.out << "  sim                      " << nb::TrCli::tr("simulated load cell (default)") << '\n';
    for (const auto& d : found)
        if (d.kind == QLatin1String("daq"))
            io.out << "  " << d.spec.leftJustified(24) << ' ' << d.description
                   << (d.problem.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(d.problem)) << '\n';
    io.out << nb::TrCli::tr("Stages (--stage):\n");
    io.out << "  sim                      " << nb::TrCli::tr("simulated stage (default)") << '\n';
    for (const auto& d : found)
        if (d.kind == QLatin1String("serial"))
            io.out << "  " << d.spec.leftJustified(24) << ' ' << d.description << '\n';
    return Ok;
}

}  // namespace nb::cli
