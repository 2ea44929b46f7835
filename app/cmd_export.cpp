// `needlebench export SESSION_DIR --format csv|hdf5|eaf --out PATH`: a session's runs as
// plain CSV + JSON sidecars (and label interval tables), one HDF5 file, or ELAN documents.
// Ctrl-C cancels between chunks and leaves no half-written file behind.

#include "cli_support.h"
#include "core/tr.h"

#include "core/export/dataset_loader.h"
#include "core/export/eaf_export.h"
#include "core/export/earlier_export.h"
#include "core/export/kept_export.h"
#include "core/export/label_intervals.h"
#include "core/export/made_folders.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_hdf5.h"
#include "core/export/stale_parts.h"
#include "video/frame_index_store.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QScopeGuard>
#include <csignal>
#include <optional>
#include <unistd.h>

namespace nb::cli {

namespace {

volatile std::sig_atomic_t interrupted = 0;
void onInterrupt(int) { interrupted = 1; }

// The first three of `paths`, and "…" when there are more: a message names what it is about
// without filling the terminal.
QString firstFew(const QStringList& paths)
{
    return QStringList(paths.mid(0, 3)).join(QStringLiteral(", ")) + (paths.size() > 3 ? QStringLiteral(", …") : QString());
}

// --copy-video: the video beside the export (a hard link when the file system allows, else a
// copy), so that the export folder carries it. Returns the path linked to (the original when
// it could not be placed).
QString placeVideo(const QString& video, const QDir& outDir, QStringList* written, QTextStream& err)
{
    if (video.isEmpty())
        return video;
    const QString target = outDir.absoluteFilePath(QFileInfo(video).fileName());
    if (QFileInfo(target).absoluteFilePath() == QFileInfo(video).absoluteFilePath())
        return video;
    QFile::remove(target);
    if (::link(QFile::encodeName(video).constData(), QFile::encodeName(target).constData()) != 0 && !QFile::copy(video, target)) {
        err << nb::TrCli::tr("warning: %1: could not copy the video beside the export; linked where it is").arg(target) << '\n';
        return video;
    }
    *written << target;
    return target;
}

}  // namespace

int cmdExport(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(nb::TrCli::tr("Export a session's runs, labels and metadata."));
    parser.addPositionalArgument(QStringLiteral("SESSION_DIR"), nb::TrCli::tr("a session folder (or any folder of run files)"));
    const QCommandLineOption format(QStringLiteral("format"),
                                    nb::TrCli::tr("csv: a CSV + JSON sidecar + label interval table per run (OUT is a folder); "
                                       "hdf5: one HDF5 file (OUT is the file); eaf: an ELAN document per run with its "
                                       "force CSV linked (OUT is a folder)"),
                                    QStringLiteral("csv|hdf5|eaf"));
    const QCommandLineOption out(QStringLiteral("out"), nb::TrCli::tr("where to write"), QStringLiteral("PATH"));
    const QCommandLineOption copyVideo(QStringLiteral("copy-video"),
                                       nb::TrCli::tr("put each run's video beside the export (hard link, else copy) and link "
                                                     "that, so the export folder can be moved or shared on its own"));
    parser.addOption(format);
    parser.addOption(out);
    const QCommandLineOption overwrite(QStringLiteral("overwrite"),
                                       nb::TrCli::tr("replace files in OUT that are not an earlier export's (a run file, a table "
                                                     "made by hand); an earlier export's files are replaced without it"));
    parser.addOption(copyVideo);
    parser.addOption(overwrite);
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("export"), args, io, 1, 1, &code))
        return code;
    const QString fmt = parser.value(format);
    if (fmt != QLatin1String("csv") && fmt != QLatin1String("hdf5") && fmt != QLatin1String("eaf")) {
        io.err << "needlebench export: "
               << (fmt.isEmpty() ? nb::TrCli::tr("--format is required (csv|hdf5|eaf)") : nb::TrCli::tr("unknown format '%1' (csv|hdf5|eaf)").arg(fmt))
               << "\n\n" << nb::TrCli::tr("Run 'needlebench export --help' for the options.") << '\n';
        return Usage;
    }
    if (parser.value(out).isEmpty()) {
        io.err << "needlebench export: " << nb::TrCli::tr("--out PATH is required") << "\n\n"
               << nb::TrCli::tr("Run 'needlebench export --help' for the options.") << '\n';
        return Usage;
    }
    const QString dir = parser.positionalArguments().first();
    const QString target = parser.value(out);
    // The export's files carry the runs' names: written into the session they read, they
    // replace its run files (the calibration header and the raw columns gone).
    if (fmt != QLatin1String("hdf5") && samePath(target, dir)) {
        io.err << "needlebench export: " << nb::TrCli::tr("--out %1 is the session folder itself; its run files would be replaced. Name another folder.").arg(target) << '\n';
        return Usage;
    }
    if (fmt == QLatin1String("hdf5") && QFileInfo(target).isFile()) {
        if (!isHdf5File(target)) {
            io.err << "needlebench export: " << nb::TrCli::tr("--out %1 exists and is not an HDF5 file (a run file?); it is kept. Name another file.").arg(target) << '\n';
            return Usage;
        }
    }

    LoadedDataset loaded;
    try {
        loaded = loadDataset(dir);
    } catch (const ExportError& e) {
        io.err << "needlebench export: " << e.message() << '\n';
        return Failure;
    }
    Dataset& d = loaded.dataset;
    addVideoFrameTimes(d, video::frameTimesOf, &loaded.warnings);
    for (const QString& w : loaded.warnings)
        io.err << nb::TrCli::tr("warning: %1").arg(w) << '\n';
    if (d.runs.empty()) {
        io.err << "needlebench export: " << nb::TrCli::tr("%1: no run files (*.csv with time_s,position_mm,force_N)").arg(dir) << '\n';
        return Failure;
    }

    // An earlier export's files are the export's to replace; a recorded run or a hand-made table
    // of the same name in OUT (another session's folder, say) is kept unless --overwrite.
    QStringList names;
    for (const DatasetRun& r : d.runs)
        names << r.name;
    const FilesInTheWay inTheWay = filesInTheWay(fmt == QLatin1String("hdf5") ? QStringList{target}
                                                                               : runExportPaths(target, names, fmt == QLatin1String("eaf")));
    if (!inTheWay.other.isEmpty() && !parser.isSet(overwrite)) {
        io.err << "needlebench export: "
               << nb::TrCli::tr("%n file(s) in %1 would be replaced that are not an earlier export's (%2); they are kept. "
                                "Name another folder, or give --overwrite.", nullptr, int(inTheWay.other.size()))
                      .arg(target, firstFew(inTheWay.other))
               << '\n';
        return Usage;
    }
    if (!inTheWay.earlierExport.isEmpty())
        io.err << nb::TrCli::tr("note: replacing %n file(s) of an earlier export in %1", nullptr, int(inTheWay.earlierExport.size())).arg(target)
               << '\n';

    // Ctrl+C, `kill` and a closed terminal alike cancel between files and say so: SIGTERM ended
    // the export silently, half of it looking complete.
    interrupted = 0;
    const auto previousInt = std::signal(SIGINT, onInterrupt), previousTerm = std::signal(SIGTERM, onInterrupt),
               previousHup = std::signal(SIGHUP, onInterrupt);
    auto restore = qScopeGuard([&] {
        std::signal(SIGINT, previousInt);
        std::signal(SIGTERM, previousTerm);
        std::signal(SIGHUP, previousHup);
    });
    const ExportProgress progress = [](qint64, qint64) { return interrupted == 0; };
    QStringList written;
    // Folders made for an export that then fails are taken away when left empty.
    QStringList made;
    bool finished = false;
    // The earlier export's files stay whole until this one is: a failure half-way puts them
    // back, where it left half of each export (probe, a full disk).
    std::optional<KeptExport> kept;
    if (!inTheWay.earlierExport.isEmpty()) {
        try {
            kept.emplace(inTheWay.earlierExport);
        } catch (const ExportError& e) {
            io.err << "needlebench export: " << e.message() << '\n';
            return Failure;
        }
    }
    auto tidy = qScopeGuard([&] {
        if (kept && finished)
            kept->release();
        else if (kept && kept->restore(written))
            io.err << nb::TrCli::tr("the earlier export in %1 is as it was").arg(target) << '\n';
        // A fresh export that fails half-way takes its files away: the runs written before a full
        // disk stopped it looked like a whole export of fewer runs. Files of the user's that
        // --overwrite replaced are not ours to take.
        if (!finished && !kept) {
            int removed = 0;
            for (const QString& f : written)
                if (!inTheWay.other.contains(f) && QFile::remove(f))
                    ++removed;
            if (removed > 0)
                io.err << nb::TrCli::tr("the %n file(s) this export had written are removed", nullptr, removed) << '\n';
        }
        if (!finished)
            removeEmptyFolders(made);
    });
    bool madeOk = true;
    try {
        const QString outFolder = fmt == QLatin1String("hdf5") ? QFileInfo(target).absolutePath() : target;
        for (const QString& p : removeStaleParts(outFolder))
            io.err << nb::TrCli::tr("warning: removed %1, left by an export that did not finish").arg(p) << '\n';
        if (parser.isSet(copyVideo)) {
            made << makeFolders(outFolder, &madeOk);
            if (!madeOk) {
                io.err << "needlebench export: " << nb::TrCli::tr("%1: cannot create the folder").arg(outFolder) << '\n';
                return Failure;
            }
            for (DatasetRun& r : d.runs)
                r.videoPath = placeVideo(r.videoPath, QDir(outFolder), &written, io.err);
        }
        if (fmt == QLatin1String("hdf5")) {
            // Its folder made as the CSV export makes its own (it said "cannot create the file
            // (is the folder writable?)" of a folder not there).
            made << makeFolders(outFolder, &madeOk);
            if (!madeOk) {
                io.err << "needlebench export: " << nb::TrCli::tr("%1: cannot create the folder").arg(outFolder) << '\n';
                return Failure;
            }
            io.out << nb::TrCli::tr("writing %1 runs to %2").arg(d.runs.size()).arg(target) << '\n';
            io.out.flush();
            if (!writeSessionHdf5(target, d, [&](qint64 done, qint64 total) {
                    if (done > 0) {
                        io.out << QStringLiteral("[%1/%2] %3\n").arg(done).arg(total).arg(d.runs[std::size_t(done - 1)].name);
                        io.out.flush();
                    }
                    return progress(done, total);
                })) {
                io.err << "needlebench export: " << nb::TrCli::tr("cancelled; %1 was not written").arg(target) << '\n';
                return Failure;
            }
            written << target;
        } else {
            made << makeFolders(target, &madeOk);
            if (!madeOk) {
                io.err << "needlebench export: " << nb::TrCli::tr("%1: cannot create the folder").arg(target) << '\n';
                return Failure;
            }
            const QDir outDir(target);
            for (std::size_t i = 0; i < d.runs.size(); ++i) {
                const DatasetRun& r = d.runs[i];
                io.out << QStringLiteral("[%1/%2] %3\n").arg(i + 1).arg(d.runs.size()).arg(r.name);
                io.out.flush();
                const QString csv = outDir.filePath(r.name + QStringLiteral(".csv"));
                if (!writeRunCsv(csv, r, progress)) {
                    io.err << "needlebench export: " << nb::TrCli::tr("cancelled after %1 of %2 runs; %3 was not written")
                                                            .arg(i).arg(d.runs.size()).arg(csv) << '\n';
                    return Failure;
                }
                written << csv << sidecarPath(csv);
                if (fmt == QLatin1String("csv")) {
                    const QString intervals = outDir.filePath(r.name + QStringLiteral(".intervals.csv"));
                    writeLabelIntervalsCsv(intervals, labelIntervals(r.run, r.labels, frameClockFor(r)));
                    written << intervals;
                } else {
                    const QString eaf = outDir.filePath(r.name + QStringLiteral(".eaf"));
                    writeEaf(eaf, r, {csv, r.videoPath, {}});
                    written << eaf;
                }
            }
        }
    } catch (const ExportError& e) {
        io.err << "needlebench export: " << e.message() << '\n';
        return Failure;
    }
    finished = true;
    io.out << nb::TrCli::tr("exported %1 runs from %2 as %3: %4 files").arg(d.runs.size()).arg(dir, fmt).arg(written.size()) << '\n';
    // A run the session lists and the export lacks fails the command, whatever it wrote: a
    // script exporting a day's session went on with most runs skipped, on exit status 0.
    if (!loaded.runsLeftOut.isEmpty()) {
        io.err << "needlebench export: "
               << nb::TrCli::tr("%n run(s) of the session left out (named above): %1", nullptr, int(loaded.runsLeftOut.size()))
                      .arg(firstFew(loaded.runsLeftOut))
               << '\n';
        return Failure;
    }
    return Ok;
}

}  // namespace nb::cli
