// `needlebench demo --out DIR [--short]`: a whole session headless, as fast as the machine
// allows. Simulates stiffness runs on two liver presets and friction runs at 0.2/0.5/0.8 Hz
// (with rendered imaging video when the simulator offers it), suggests labels, fits every
// model, and writes the run CSVs, the HDF5 file, the fit tables and the figures.
// The other commands are called in-process through the registry, as a user would chain them.

#include "cli_support.h"

#include "core/export/dataset_loader.h"
#include "core/export/label_intervals.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_analysis.h"
#include "core/export/session_hdf5.h"
#include "core/session.h"
#include "widgets/analysis/analysis_plots.h"
#include "widgets/analysis/figure_export.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <qcustomplot.h>

namespace nb::cli {

namespace {

QString tr(const char* s) { return QCoreApplication::translate("cli", s); }

const Command* findCommand(const QString& name)
{
    for (const Command& c : commands())
        if (c.name == name)
            return &c;
    return nullptr;
}

// Runs another command with its output captured (shown only when it fails).
int runQuiet(const QString& name, const QStringList& args, QString* output)
{
    const Command* c = findCommand(name);
    if (!c)
        return -1;
    QString out, err;
    QTextStream o(&out), e(&err);
    int code = Failure;
    try {
        code = c->run(args, {o, e});
    } catch (const std::exception& ex) {
        e << QString::fromStdString(ex.what());
    }
    o.flush();
    e.flush();
    *output = (out + err).trimmed();
    return code;
}

// The simulator's own record of what happened, as labels: what `labels suggest` would give
// on a perfect day. Used only when that command is not available.
Labels labelsFromTruth(const QString& truthPath)
{
    Labels labels;
    QFile f(truthPath);
    if (!f.open(QIODevice::ReadOnly))
        return labels;
    const QJsonObject t = QJsonDocument::fromJson(f.readAll()).object();
    for (const QJsonValue& v : t.value(QStringLiteral("phases")).toArray()) {
        const QJsonObject p = v.toObject();
        const double a = std::max(0.0, p.value(QStringLiteral("start_s")).toDouble());
        const double b = p.value(QStringLiteral("end_s")).toDouble();
        if (b > a)
            labels.push_back({p.value(QStringLiteral("track")).toString(QStringLiteral("phase")), p.value(QStringLiteral("label")).toString(), a, b, {}});
    }
    for (const QJsonValue& v : t.value(QStringLiteral("events")).toArray()) {
        const QJsonObject e = v.toObject();
        const double time = e.value(QStringLiteral("time_s")).toDouble();
        QString name = e.value(QStringLiteral("name")).toString();
        if (name == QLatin1String("relaxed"))
            name = QStringLiteral("relaxation");
        if (time >= 0.0 && !name.isEmpty())
            labels.push_back({QStringLiteral("events"), name, time, time, {}});
    }
    return labels;
}

struct Step {
    QString protocol, tissue;
    double frequency_hz = 0.0;
    int seed = 1;
};

}  // namespace

int cmdDemo(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(tr("Simulate, label, fit and export a short session in one go."));
    const QCommandLineOption out(QStringLiteral("out"), tr("the folder to write everything into"), QStringLiteral("DIR"));
    const QCommandLineOption shortOpt(QStringLiteral("short"), tr("a shorter session (one run per condition, fewer cycles)"));
    parser.addOption(out);
    parser.addOption(shortOpt);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("demo"), args, io, 0, 0, &code))
        return code;
    if (parser.value(out).isEmpty()) {
        io.err << "needlebench demo: " << tr("--out DIR is required") << "\n\n" << tr("Run 'needlebench demo --help' for the options.") << '\n';
        return Usage;
    }
    const bool shortRun = parser.isSet(shortOpt);
    const QDir root(parser.value(out));
    QElapsedTimer clock;
    clock.start();
    auto step = [&](const QString& what) {
        io.out << QStringLiteral("[%1 s] ").arg(clock.elapsed() / 1000.0, 5, 'f', 1) << what << '\n';
        io.out.flush();
    };

    if (!QDir().mkpath(root.path())) {
        io.err << "needlebench demo: " << tr("%1: cannot create the folder").arg(root.path()) << '\n';
        return Failure;
    }
    const QString sessionDir = root.filePath(QStringLiteral("session"));
    if (QFileInfo::exists(sessionDir) && !QDir(sessionDir).isEmpty()) {
        io.err << "needlebench demo: " << tr("%1 already holds a session; choose an empty --out folder").arg(sessionDir) << '\n';
        return Failure;
    }
    SessionInfo info;
    info.organ = QStringLiteral("bovine liver (simulated)");
    info.specimen = QStringLiteral("demo");
    info.tip = QStringLiteral("beveled/diamond");
    info.thickness_mm = 30.0;
    info.operatorName = QStringLiteral("needlebench demo");
    info.protocol = QStringLiteral("stiffness + friction");
    info.created = QDateTime::currentDateTime();
    Session session = [&] {
        try {
            return Session::create(sessionDir, info);
        } catch (const SessionError& e) {
            throw std::runtime_error(e.message().toStdString());
        }
    }();
    step(tr("session folder %1").arg(sessionDir));

    // Two liver presets for stiffness (beveled, 4 mm/s), the friction slab at three frequencies.
    std::vector<Step> plan;
    const int perTissue = shortRun ? 1 : 3;
    for (const char* tissue : {"liver1", "liver2"})
        for (int k = 0; k < perTissue; ++k)
            plan.push_back({QStringLiteral("stiffness"), QString::fromLatin1(tissue), 0.0, k + 1});
    for (double f : shortRun ? std::vector<double>{0.5} : std::vector<double>{0.2, 0.5, 0.8})
        plan.push_back({QStringLiteral("friction"), QStringLiteral("liver7"), f, 1});

    bool videoSupported = true;
    QStringList labelSources;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        const Step& s = plan[i];
        const bool friction = s.protocol == QLatin1String("friction");
        const QString runPath = session.nextRunPath(friction ? QStringLiteral("sine") : QStringLiteral("linear"));
        const QFileInfo fi(runPath);
        const QString truth = root.filePath(QStringLiteral("truth/%1.truth.json").arg(fi.completeBaseName()));
        QDir().mkpath(QFileInfo(truth).path());
        QStringList simArgs{QStringLiteral("--protocol"), s.protocol, QStringLiteral("--tissue"), s.tissue,
                            QStringLiteral("--seed"), QString::number(s.seed), QStringLiteral("--out"), runPath,
                            QStringLiteral("--truth"), truth};
        if (friction)
            simArgs << QStringLiteral("--frequency-hz") << QString::number(s.frequency_hz) << QStringLiteral("--cycles")
                    << QString::number(shortRun ? 3 : 7);
        QString output;
        int rc = Failure;
        if (friction && videoSupported) {
            rc = runQuiet(QStringLiteral("simulate"),
                          simArgs + QStringList{QStringLiteral("--video"), fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".mp4"))},
                          &output);
            if (rc == Usage) {
                videoSupported = false;  // this build's simulator renders no video: record without
                step(tr("note: the simulator offers no --video here; friction runs are recorded without imaging video"));
            }
        }
        if (!friction || !videoSupported)
            rc = runQuiet(QStringLiteral("simulate"), simArgs, &output);
        if (rc != Ok) {
            io.err << "needlebench demo: " << tr("simulating %1 failed:\n%2").arg(runPath, output) << '\n';
            return Failure;
        }
        step(tr("simulated %1 (%2, %3)")
                 .arg(fi.fileName(), s.tissue,
                      friction ? tr("sine %1 Hz").arg(s.frequency_hz) : tr("insertion 4 mm/s")));

        // Labels: the labelling command when this build has it, else the simulator's record.
        const QString labelsPath = labelsPathFor(runPath);
        QString how;
        if (findCommand(QStringLiteral("labels"))) {
            QString lout;
            const int lrc = runQuiet(QStringLiteral("labels"),
                                     {QStringLiteral("suggest"), runPath, QStringLiteral("--out"), labelsPath}, &lout);
            if (lrc == Ok && QFileInfo::exists(labelsPath))
                how = tr("labels suggest");
            else
                step(tr("note: labels suggest failed for %1: %2").arg(fi.fileName(), lout.section(QLatin1Char('\n'), 0, 0)));
        }
        if (how.isEmpty()) {
            writeLabelsFile(labelsPath, labelsFromTruth(truth));
            how = tr("the simulator's record (no labels suggest in this build)");
        }
        labelSources << how;
        step(tr("labelled %1 from %2").arg(fi.fileName(), how));
    }

    LoadedDataset loaded = loadDataset(sessionDir);
    for (const QString& w : loaded.warnings)
        io.err << tr("warning: %1").arg(w) << '\n';
    const Dataset& d = loaded.dataset;
    const SessionAnalysis a = analyseDataset(d);
    for (const QString& w : a.warnings)
        io.err << tr("warning: %1").arg(w) << '\n';
    step(tr("fitted %1 stiffness runs in %2 groups, %3 friction runs, %4 validations")
             .arg(a.stiffness.size()).arg(a.stiffnessGroups.size()).arg(a.friction.size()).arg(a.validation.size()));

    const QString csvDir = root.filePath(QStringLiteral("csv"));
    QDir().mkpath(csvDir);
    for (const DatasetRun& r : d.runs) {
        const QString csv = QDir(csvDir).filePath(r.name + QStringLiteral(".csv"));
        writeRunCsv(csv, r);
        writeLabelIntervalsCsv(QDir(csvDir).filePath(r.name + QStringLiteral(".intervals.csv")),
                               labelIntervals(r.run, r.labels, frameClockFor(r.run)));
    }
    step(tr("wrote %1 run CSVs with JSON sidecars and label interval tables").arg(d.runs.size()));

    const QString h5 = root.filePath(QStringLiteral("session.h5"));
    writeSessionHdf5(h5, d);
    step(tr("wrote %1").arg(h5));

    const QString tablesDir = root.filePath(QStringLiteral("tables"));
    QDir().mkpath(tablesDir);
    const std::vector<std::pair<QString, FitTable>> tables{
        {QStringLiteral("stiffness_runs"), stiffnessRunsTable(a)},   {QStringLiteral("stiffness_pooled"), stiffnessPooledTable(a)},
        {QStringLiteral("friction_runs"), frictionRunsTable(a)},     {QStringLiteral("friction_summary"), frictionSummaryTable(a)},
        {QStringLiteral("validation"), validationTable(a)},
    };
    for (const auto& [name, table] : tables) {
        writeFitTableCsv(QDir(tablesDir).filePath(name + QStringLiteral(".csv")), table);
        writeFitTableLatex(QDir(tablesDir).filePath(name + QStringLiteral(".tex")), table);
    }
    step(tr("wrote %1 fit tables (CSV and LaTeX)").arg(tables.size()));

    const QString figDir = root.filePath(QStringLiteral("figures"));
    QDir().mkpath(figDir);
    QCustomPlot plot;
    int figures = 0;
    for (const StiffnessGroupResult& g : a.stiffnessGroups) {
        plotStiffness(&plot, a, g.group);
        saveFigure(&plot, QDir(figDir).filePath(QStringLiteral("stiffness_%1.png").arg(g.group)));
        ++figures;
    }
    for (const FrictionRunResult& f : a.friction) {
        const auto run = std::find_if(d.runs.begin(), d.runs.end(), [&](const DatasetRun& r) { return r.name == f.run; });
        if (run == d.runs.end())
            continue;
        plotFrictionVelocity(&plot, *run, f);
        saveFigure(&plot, QDir(figDir).filePath(QStringLiteral("friction_velocity_%1.png").arg(f.run)));
        plotPhases(&plot, *run);
        saveFigure(&plot, QDir(figDir).filePath(QStringLiteral("phases_%1.png").arg(f.run)));
        figures += 2;
    }
    for (const ValidationResult& v : a.validation) {
        plotValidation(&plot, v);
        saveFigure(&plot, QDir(figDir).filePath(QStringLiteral("validation_%1.png").arg(v.run)));
        ++figures;
    }
    step(tr("wrote %1 figures").arg(figures));

    io.out << '\n' << tr("Demo finished in %1 s. Where everything went:").arg(clock.elapsed() / 1000.0, 0, 'f', 1) << '\n'
           << tr("  session (run files + labels): %1").arg(sessionDir) << '\n'
           << tr("  run CSVs + JSON sidecars:     %1").arg(csvDir) << '\n'
           << tr("  HDF5 (all runs):              %1").arg(h5) << '\n'
           << tr("  fit tables (CSV, LaTeX):      %1").arg(tablesDir) << '\n'
           << tr("  figures (PNG):                %1").arg(figDir) << '\n'
           << tr("  simulator ground truth:       %1").arg(root.filePath(QStringLiteral("truth"))) << '\n';
    for (const StiffnessGroupResult& g : a.stiffnessGroups)
        io.out << tr("  stiffness %1: a1 = %2 N/mm, a2 = %3 N/mm², puncture at %4 mm, %5 N")
                      .arg(g.group)
                      .arg(g.summary.pooled.quadratic.model.a1_N_per_mm, 0, 'f', 4)
                      .arg(g.summary.pooled.quadratic.model.a2_N_per_mm2, 0, 'f', 4)
                      .arg(g.meanPunctureDepth_mm, 0, 'f', 2)
                      .arg(g.meanPunctureForce_N, 0, 'f', 3)
               << '\n';
    if (a.frictionOverall)
        io.out << tr("  friction overall: Cp = %1 N/m, Cn = %2 N/m, bp = %3 N s/m², bn = %4 N s/m²")
                      .arg(a.frictionOverall->mean.Cp_N_per_m, 0, 'f', 2)
                      .arg(a.frictionOverall->mean.Cn_N_per_m, 0, 'f', 2)
                      .arg(a.frictionOverall->mean.bp_Ns_per_m2, 0, 'f', 1)
                      .arg(a.frictionOverall->mean.bn_Ns_per_m2, 0, 'f', 1)
               << '\n';
    return a.stiffnessGroups.empty() && !a.frictionOverall ? Failure : Ok;
}

}  // namespace nb::cli
