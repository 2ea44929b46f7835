// `needlebench demo --out DIR [--short]`: a whole session headless, as fast as the machine
// allows. Simulates stiffness runs on two liver presets and friction runs at 0.2/0.5/0.8 Hz
// with rendered imaging video, synchronises each video from its motion, suggests labels,
// fits every model, and writes the run CSVs, the HDF5 file, the fit tables and the figures.
// Everything runs in-process, as function calls.

#include "cli_support.h"
#include "simulated_run.h"
#include "core/tr.h"

#include "core/export/dataset_loader.h"
#include "core/export/label_intervals.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_analysis.h"
#include "core/export/session_hdf5.h"
#include "core/label_suggest.h"
#include "core/run_file.h"
#include "core/session.h"
#include "core/sync.h"
#include "video/frame_index.h"
#include "video/labels_from_video.h"
#include "video/video_error.h"
#include "video/video_sync.h"
#include "widgets/analysis/analysis_plots.h"
#include "widgets/analysis/figure_export.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <optional>
#include <qcustomplot.h>

namespace nb::cli {

namespace {

// Seven cycles as in the thesis; the slowest (0.2 Hz) then lasts 35 s.
constexpr int kFrictionCycles = 7;

// Smaller than the console's 720x480 and MJPEG: the demo renders, writes and reads back
// about 1800 frames of incompressible noise, which H.264 at full size takes minutes for.
constexpr int kVideoWidth = 360, kVideoHeight = 240;
constexpr double kVideoFps = 30000.0 / 1001.0;

struct Step {
    QString protocol, tissue;
    double frequency_hz = 0.0;
    int seed = 1;
};

}  // namespace

int cmdDemo(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Simulate, label, fit and export a short session in one go."));
    const QCommandLineOption out(QStringLiteral("out"), nb::TrCli::tr("the folder to write everything into"), QStringLiteral("DIR"));
    const QCommandLineOption shortOpt(QStringLiteral("short"), nb::TrCli::tr("a shorter session (one run per condition, fewer cycles)"));
    parser.addOption(out);
    parser.addOption(shortOpt);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("demo"), args, io, 0, 0, &code))
        return code;
    if (parser.value(out).isEmpty()) {
        io.err << "needlebench demo: " << nb::TrCli::tr("--out DIR is required") << "\n\n" << nb::TrCli::tr("Run 'needlebench demo --help' for the options.") << '\n';
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

    // Everything a demo writes (session/, session.h5, tables/, figures) goes into --out: a folder
    // already holding anything is refused, as a session.h5 or tables there were replaced.
    if (QFileInfo(root.path()).isDir() && !root.isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)) {
        io.err << "needlebench demo: "
               << nb::TrCli::tr("%1 is not empty; a demo writes a session and its exports into --out: choose an empty or new folder")
                      .arg(root.path())
               << '\n';
        return Failure;
    }
    if (!QDir().mkpath(root.path())) {
        io.err << "needlebench demo: " << nb::TrCli::tr("%1: cannot create the folder").arg(root.path()) << '\n';
        return Failure;
    }
    const QString sessionDir = root.filePath(QStringLiteral("session"));
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
    step(nb::TrCli::tr("session folder %1").arg(sessionDir));

    // Two liver presets for stiffness (beveled, 4 mm/s), the friction slab at three frequencies.
    std::vector<Step> plan;
    const int perTissue = shortRun ? 1 : 3;
    for (const char* tissue : {"liver1", "liver2"})
        for (int k = 0; k < perTissue; ++k)
            plan.push_back({QStringLiteral("stiffness"), QString::fromLatin1(tissue), 0.0, k + 1});
    for (double f : shortRun ? std::vector<double>{0.5} : std::vector<double>{0.2, 0.5, 0.8})
        plan.push_back({QStringLiteral("friction"), QStringLiteral("liver7"), f, 1});

    struct VideoReport {
        QString run, video;
        int frames = 0;
        double trueOffset_s = 0.0;
        std::optional<SyncResult> sync;
        QString syncProblem;
        std::optional<video::FrameIndex> index;
    };
    std::vector<VideoReport> videos;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        const Step& s = plan[i];
        const bool friction = s.protocol == QLatin1String("friction");
        const QString runPath = session.nextRunPath(friction ? QStringLiteral("sine") : QStringLiteral("linear"));
        const QFileInfo fi(runPath);
        const QString truth = root.filePath(QStringLiteral("truth/%1.truth.json").arg(fi.completeBaseName()));
        QDir().mkpath(QFileInfo(truth).path());
        SimulatedRunRequest request;
        request.protocol = s.protocol;
        request.rig.tissue = s.tissue;
        request.rig.tip = devices::sim::usualTip(s.tissue, false);
        request.rig.setup = friction ? devices::sim::Setup::Platform : devices::sim::Setup::Organ;
        request.rig.seed = std::uint64_t(s.seed);
        request.rig.realtime = false;
        request.out = runPath;
        request.truth = truth;
        if (friction) {
            request.sine = {10.0, s.frequency_hz, shortRun ? 3 : kFrictionCycles};
            // The imaging console is started by hand a little before the recording: a lead-in
            // that differs per run, so that the synchronisation has something to find.
            request.video = fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".avi"));
            request.videoOffset_s = 0.6 + 0.35 * double(videos.size());
            request.videoWidth = kVideoWidth;
            request.videoHeight = kVideoHeight;
            request.videoSeed = unsigned(s.seed + int(i));
        }
        const SimulatedRunResult simulated = simulateRun(request);
        if (!simulated.error.isEmpty()) {
            io.err << "needlebench demo: " << nb::TrCli::tr("simulating %1 failed: %2").arg(runPath, simulated.error) << '\n';
            return Failure;
        }
        step(nb::TrCli::tr("simulated %1 (%2, %3)")
                 .arg(fi.fileName(), s.tissue,
                      friction ? nb::TrCli::tr("sine %1 Hz").arg(s.frequency_hz) : nb::TrCli::tr("insertion 4 mm/s")));

        Run run;
        try {
            run = readRunFile(runPath).run;
        } catch (const RunFileError& e) {
            io.err << "needlebench demo: " << e.message() << '\n';
            return Failure;
        }

        if (friction) {
            // The imaging console is started by hand a little before the recording: a lead-in
            // that differs per run, so that the synchronisation has something to find.
            VideoReport v;
            v.run = fi.fileName();
            v.video = QFileInfo(request.video).fileName();
            const QString videoPath = request.video;
            v.frames = simulated.videoFrames;
            v.trueOffset_s = simulated.videoOffset_s;
            step(nb::TrCli::tr("rendered imaging video %1 (%2 frames at 29.97/s, started %3 s before the recording)")
                     .arg(v.video).arg(v.frames).arg(request.videoOffset_s, 0, 'f', 2));

            // Found the way a user would: the needle tracked in the video against its position.
            try {
                video::VideoSyncOptions so;
                so.sync.maxOffset_s = 5.0;
                v.index = video::buildFrameIndex(videoPath);
                v.sync = video::syncVideoToRun(*v.index, run, so).result;
            } catch (const video::VideoError& e) {
                v.syncProblem = e.message();
            } catch (const std::invalid_argument& e) {
                v.syncProblem = QString::fromUtf8(e.what());
            }
            run.metadata.set(QStringLiteral("video_file"), v.video);
            run.metadata.set(QStringLiteral("video_fps"), kVideoFps);
            if (v.sync) {
                run.metadata.set(QStringLiteral("sync_offset_s"), v.sync->offset_s);
                run.metadata.set(QStringLiteral("sync_confidence"), v.sync->confidence);
                run.metadata.set(QStringLiteral("sync_method"), v.sync->method + QStringLiteral(" (needlebench demo)"));
                if (v.sync->drift != 0.0)
                    run.metadata.set(QStringLiteral("sync_drift"), v.sync->drift);
                step(nb::TrCli::tr("synchronised %1: offset %2 s found, %3 s true (%4 frames off), confidence %5")
                         .arg(v.video)
                         .arg(v.sync->offset_s, 0, 'f', 3)
                         .arg(v.trueOffset_s, 0, 'f', 3)
                         .arg((v.sync->offset_s - v.trueOffset_s) * kVideoFps, 0, 'f', 1)
                         .arg(v.sync->confidence, 0, 'f', 2));
            } else {
                step(nb::TrCli::tr("note: could not synchronise %1 (%2); its frames are numbered without an offset")
                         .arg(v.video, v.syncProblem));
            }
            try {
                writeRunFile(runPath, run);
            } catch (const RunFileError& e) {
                io.err << "needlebench demo: " << e.message() << '\n';
                return Failure;
            }
            videos.push_back(v);
        }

        // As labels suggest --video and Review do: the friction phases checked against the
        // tissue's motion in the run's video, on the clock the sync found.
        Labels labels;
        QString from;
        if (friction && !videos.empty() && videos.back().sync && videos.back().index) {
            const VideoReport& v = videos.back();
            const video::VideoLabels found = video::suggestLabelsWithVideo(run, *v.index, v.sync->mapping(), v.video);
            labels = found.labels;
            from = found.videoUsed ? nb::TrCli::tr("phases a, b1, b2, c per half-cycle, checked against the tissue's motion in %1").arg(v.video)
                                   : nb::TrCli::tr("phases a, b1, b2, c per half-cycle from force and position (%1: %2)").arg(v.video, found.problem);
        } else {
            labels = suggestLabels(run);
            from = friction ? nb::TrCli::tr("phases a, b1, b2, c per half-cycle")
                            : nb::TrCli::tr("contact and puncture events; no imaging video to read the relaxation off");
        }
        const QString labelsPath = labelsPathFor(runPath);
        try {
            writeLabelsFile(labelsPath, labels);
        } catch (const RunFileError& e) {
            io.err << "needlebench demo: " << e.message() << '\n';
            return Failure;
        }
        step(nb::TrCli::tr("labelled %1: %2 suggested labels (%3)").arg(fi.fileName()).arg(labels.size()).arg(from));
    }

    LoadedDataset loaded = loadDataset(sessionDir);
    for (const QString& w : loaded.warnings)
        io.err << nb::TrCli::tr("warning: %1").arg(w) << '\n';
    const Dataset& d = loaded.dataset;
    const SessionAnalysis a = analyseDataset(d);
    for (const QString& w : a.warnings)
        io.err << nb::TrCli::tr("warning: %1").arg(w) << '\n';
    step(nb::TrCli::tr("fitted %1 stiffness runs in %2 groups, %3 friction runs, %4 validations")
             .arg(a.stiffness.size()).arg(a.stiffnessGroups.size()).arg(a.friction.size()).arg(a.validation.size()));

    const QString csvDir = root.filePath(QStringLiteral("csv"));
    QDir().mkpath(csvDir);
    for (const DatasetRun& r : d.runs) {
        const QString csv = QDir(csvDir).filePath(r.name + QStringLiteral(".csv"));
        writeRunCsv(csv, r);
        writeLabelIntervalsCsv(QDir(csvDir).filePath(r.name + QStringLiteral(".intervals.csv")),
                               labelIntervals(r.run, r.labels, frameClockFor(r.run)));
    }
    step(nb::TrCli::tr("wrote %1 run CSVs with JSON sidecars and label interval tables").arg(d.runs.size()));

    const QString h5 = root.filePath(QStringLiteral("session.h5"));
    writeSessionHdf5(h5, d);
    step(nb::TrCli::tr("wrote %1").arg(h5));

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
    step(nb::TrCli::tr("wrote %1 fit tables (CSV and LaTeX)").arg(tables.size()));

    const QString figDir = root.filePath(QStringLiteral("figures"));
    QDir().mkpath(figDir);
    QCustomPlot plot;
    int figures = 0;
    for (const StiffnessGroupResult& g : a.stiffnessGroups) {
        plotStiffness(&plot, a, g.group);
        saveJournalFigures(&plot, QDir(figDir).filePath(QStringLiteral("stiffness_%1.png").arg(g.group)));
        ++figures;
    }
    for (const FrictionRunResult& f : a.friction) {
        const auto run = std::find_if(d.runs.begin(), d.runs.end(), [&](const DatasetRun& r) { return r.name == f.run; });
        if (run == d.runs.end())
            continue;
        plotFrictionVelocity(&plot, *run, f);
        saveJournalFigures(&plot, QDir(figDir).filePath(QStringLiteral("friction_velocity_%1.png").arg(f.run)));
        plotPhases(&plot, *run);
        saveJournalFigures(&plot, QDir(figDir).filePath(QStringLiteral("phases_%1.png").arg(f.run)));
        figures += 2;
    }
    for (const ValidationResult& v : a.validation) {
        plotValidation(&plot, v);
        saveJournalFigures(&plot, QDir(figDir).filePath(QStringLiteral("validation_%1.png").arg(v.run)));
        ++figures;
    }
    step(nb::TrCli::tr("wrote %1 figures").arg(figures));

    io.out << '\n' << nb::TrCli::tr("Demo finished in %1 s. Where everything went:").arg(clock.elapsed() / 1000.0, 0, 'f', 1) << '\n'
           << nb::TrCli::tr("  session (run files + labels): %1").arg(sessionDir) << '\n'
           << nb::TrCli::tr("  run CSVs + JSON sidecars:     %1").arg(csvDir) << '\n'
           << nb::TrCli::tr("  HDF5 (all runs):              %1").arg(h5) << '\n'
           << nb::TrCli::tr("  fit tables (CSV, LaTeX):      %1").arg(tablesDir) << '\n'
           << nb::TrCli::tr("  figures (PNG, PDF, SVG):      %1").arg(figDir) << '\n'
           << nb::TrCli::tr("  simulator ground truth:       %1").arg(root.filePath(QStringLiteral("truth"))) << '\n';
    for (const VideoReport& v : videos) {
        if (v.sync)
            io.out << nb::TrCli::tr("  video %1 (%2 frames): sync offset %3 s found, %4 s true, %5 ms off, confidence %6")
                          .arg(QDir(sessionDir).filePath(v.video))
                          .arg(v.frames)
                          .arg(v.sync->offset_s, 0, 'f', 3)
                          .arg(v.trueOffset_s, 0, 'f', 3)
                          .arg((v.sync->offset_s - v.trueOffset_s) * 1000.0, 0, 'f', 0)
                          .arg(v.sync->confidence, 0, 'f', 2)
                   << '\n';
        else
            io.out << nb::TrCli::tr("  video %1 (%2 frames): not synchronised (%3); true offset %4 s")
                          .arg(QDir(sessionDir).filePath(v.video))
                          .arg(v.frames)
                          .arg(v.syncProblem)
                          .arg(v.trueOffset_s, 0, 'f', 3)
                   << '\n';
    }
    for (const StiffnessGroupResult& g : a.stiffnessGroups)
        io.out << nb::TrCli::tr("  stiffness %1: a1 = %2 N/mm, a2 = %3 N/mm², puncture at %4 mm, %5 N")
                      .arg(g.group)
                      .arg(g.summary.pooled.quadratic.model.a1_N_per_mm, 0, 'f', 4)
                      .arg(g.summary.pooled.quadratic.model.a2_N_per_mm2, 0, 'f', 4)
                      .arg(g.meanPunctureDepth_mm, 0, 'f', 2)
                      .arg(g.meanPunctureForce_N, 0, 'f', 3)
               << '\n';
    if (a.frictionOverall)
        io.out << nb::TrCli::tr("  friction overall: Cp = %1 N/m, Cn = %2 N/m, bp = %3 N s/m², bn = %4 N s/m²")
                      .arg(a.frictionOverall->mean.Cp_N_per_m, 0, 'f', 2)
                      .arg(a.frictionOverall->mean.Cn_N_per_m, 0, 'f', 2)
                      .arg(a.frictionOverall->mean.bp_Ns_per_m2, 0, 'f', 1)
                      .arg(a.frictionOverall->mean.bn_Ns_per_m2, 0, 'f', 1)
               << '\n';
    return a.stiffnessGroups.empty() && !a.frictionOverall ? Failure : Ok;
}

}  // namespace nb::cli
