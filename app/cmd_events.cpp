// `needlebench events RUN.csv`: contact, puncture, internal punctures and relaxation of a
// constant-velocity insertion.

#include "cli_support.h"
#include "core/model_json.h"
#include "core/tr.h"

#include "core/events.h"
#include "core/fit_error.h"
#include "core/run_file.h"
#include "core/stiffness_fit.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <cmath>
#include <optional>

namespace nb::cli {

namespace {

QJsonObject eventJson(const RunEvent& e)
{
    return {{QStringLiteral("time_s"), e.time_s},
            {QStringLiteral("position_mm"), e.position_mm},
            {QStringLiteral("force_N"), e.force_N}};
}

// Fixed decimals in the columns; a value no rig gives (a corrupt sample, said when the file was
// read) in exponent form, not as three hundred digits.
QString column(double v, int width, int decimals)
{
    return std::abs(v) < 1e6 ? QStringLiteral("%1").arg(v, width, 'f', decimals) : QStringLiteral("%1").arg(v, width, 'g', 4);
}

QString eventLine(const QString& name, const RunEvent& e)
{
    return QStringLiteral("%1 %2 %3 %4\n")
        .arg(name.leftJustified(18), column(e.time_s, 9, 3), column(e.position_mm, 11, 3), column(e.force_N, 9, 4));
}

}  // namespace

int cmdEvents(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("RUN.csv"), nb::TrCli::tr("a constant-velocity insertion run"));
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("events"), args, io, 1, 1, &code))
        return code;
    const QString path = parser.positionalArguments().first();
    InsertionEvents ev;
    // The stiffness as `fit stiffness` gives it for this run (through the origin at the contact,
    // on the zeroed force). The contact's own search fits a line with a free offset over the
    // whole stroke, whose a1 and a2 differed from fit stiffness's by several per cent unsaid.
    std::optional<StiffnessFit> stiffness;
    QString noStiffness;
    try {
        const RunReadResult r = readRunFile(path, {.dropTruncatedLastRow = true});
        for (const QString& w : r.warnings)
            io.err << nb::TrCli::tr("warning: %1\n").arg(w);
        if (const QString w = notAnInsertionRun(r.run, path); !w.isEmpty())
            io.err << w << '\n';
        ev = detectEvents(r.run);
        try {
            stiffness = fitStiffness(stiffnessSegment(r.run, ev));
        } catch (const FitError& e) {
            noStiffness = e.message();
        }
    } catch (const RunFileError& e) {
        io.err << "needlebench events: " << e.message() << '\n';
        return Failure;
    } catch (const FitError& e) {
        io.err << "needlebench events: " << path << ": " << e.message() << '\n';
        return Failure;
    }
    if (parser.isSet(json)) {
        QJsonArray internal;
        for (const RunEvent& e : ev.internalPunctures)
            internal.append(eventJson(e));
        printJson(io, {{QStringLiteral("file"), path},
                       {QStringLiteral("contact"), eventJson(ev.contact)},
                       {QStringLiteral("puncture"), eventJson(ev.puncture)},
                       {QStringLiteral("puncture_depth_mm"), ev.punctureDepth_mm()},
                       {QStringLiteral("internal_punctures"), internal},
                       {QStringLiteral("relaxation"), ev.relaxation ? QJsonValue(eventJson(*ev.relaxation)) : QJsonValue()},
                       {QStringLiteral("zero_offset_N"), ev.zeroOffset_N},
                       {QStringLiteral("noise_N"), ev.noise_N},
                       {QStringLiteral("stiffness"), stiffness ? [&] {
                            QJsonObject s = toJson(stiffness->quadratic.model);
                            s.insert(QStringLiteral("rms_N"), stiffness->quadratic.rms_N);
                            return QJsonValue(s);
                        }() : QJsonValue()}});
        return Ok;
    }
    io.out << nb::TrCli::tr("events of %1 (force zeroed by %2 N, noise %3 N)\n")
                  .arg(path)
                  .arg(ev.zeroOffset_N, 0, 'g', 4)
                  .arg(ev.noise_N, 0, 'g', 3);
    io.out << nb::TrCli::tr("event                 time_s position_mm   force_N\n");
    io.out << eventLine(nb::TrCli::tr("contact"), ev.contact);
    io.out << eventLine(nb::TrCli::tr("puncture"), ev.puncture);
    if (ev.relaxation)
        io.out << eventLine(nb::TrCli::tr("relaxation"), *ev.relaxation);
    for (const RunEvent& e : ev.internalPunctures)
        io.out << eventLine(nb::TrCli::tr("internal puncture"), e);
    if (stiffness)
        io.out << nb::TrCli::tr("puncture depth %1 mm; stiffness a1 = %2 N/mm, a2 = %3 N/mm² (as fit stiffness gives it)\n")
                      .arg(ev.punctureDepth_mm(), 0, 'f', 3)
                      .arg(stiffness->quadratic.model.a1_N_per_mm, 0, 'g', 4)
                      .arg(stiffness->quadratic.model.a2_N_per_mm2, 0, 'g', 4);
    else
        io.out << nb::TrCli::tr("puncture depth %1 mm; no stiffness fit (%2)\n").arg(ev.punctureDepth_mm(), 0, 'f', 3).arg(noStiffness);
    return Ok;
}

}  // namespace nb::cli
