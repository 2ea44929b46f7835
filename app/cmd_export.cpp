// `needlebench export SESSION_DIR --format csv|hdf5|eaf --out PATH`: a session's runs as
// plain CSV + JSON sidecars (and label interval tables), one HDF5 file, or ELAN documents.
// Ctrl-C cancels between chunks and leaves no half-written file behind.

#include "cli_support.h"
#include "core/tr.h"

#include "core/export/dataset_loader.h"
#include "core/export/eaf_export.h"
#include "core/export/label_intervals.h"
#include "core/export/run_csv_export.h"
#include "core/export/session_hdf5.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QScopeGuard>
#include <csignal>

namespace nb::cli {

namespace {

volatile std::sig_atomic_t interrupted = 0;
void onInterrupt(int) { interrupted = 1; }

// The video beside a run: named in its metadata (`video`, relative to the run file) or
// sharing its base name.
QString videoFor(const DatasetRun& r)
{
    if (r.sourcePath.isEmpty())
        return {};
    const QFileInfo fi(r.sourcePath);
    for (const char* key : {"video", "video_file", "video_path"}) {
        if (const auto v = r.run.meta(QString::fromLatin1(key)); v && !v->trimmed().isEmpty()) {
            const QString p = QFileInfo(v->trimmed()).isAbsolute() ? v->trimmed() : fi.dir().filePath(v->trimmed());
            if (QFileInfo::exists(p))
                return p;
        }
    }
    for (const char* ext : {"mp4", "avi", "mkv", "mov"}) {
        const QString p = fi.dir().filePath(fi.completeBaseName() + QLatin1Char('.') + QLatin1String(ext));
        if (QFileInfo::exists(p))
            return p;
    }
    return {};
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
    parser.addOption(format);
    parser.addOption(out);
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

    LoadedDataset loaded;
    try {
        loaded = loadDataset(dir);
    } catch (const ExportError& e) {
        io.err << "needlebench export: " << e.message() << '\n';
        return Failure;
    }
    for (const QString& w : loaded.warnings)
        io.err << nb::TrCli::tr("warning: %1").arg(w) << '\n';
    const Dataset& d = loaded.dataset;
    if (d.runs.empty()) {
        io.err << "needlebench export: " << nb::TrCli::tr("%1: no run files (*.csv with time_s,position_mm,force_N)").arg(dir) << '\n';
        return Failure;
    }

    interrupted = 0;
    const auto previous = std::signal(SIGINT, onInterrupt);
    auto restore = qScopeGuard([&] { std::signal(SIGINT, previous); });
    const ExportProgress progress = [](qint64, qint64) { return interrupted == 0; };
    QStringList written;
    try {
        if (fmt == QLatin1String("hdf5")) {
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
            if (!QDir().mkpath(target)) {
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
                    writeLabelIntervalsCsv(intervals, labelIntervals(r.run, r.labels, frameClockFor(r.run)));
                    written << intervals;
                } else {
                    const QString eaf = outDir.filePath(r.name + QStringLiteral(".eaf"));
                    writeEaf(eaf, r, {csv, videoFor(r)});
                    written << eaf;
                }
            }
        }
    } catch (const ExportError& e) {
        io.err << "needlebench export: " << e.message() << '\n';
        return Failure;
    }
    io.out << nb::TrCli::tr("exported %1 runs from %2 as %3: %4 files").arg(d.runs.size()).arg(dir, fmt).arg(written.size()) << '\n';
    return Ok;
}

}  // namespace nb::cli
