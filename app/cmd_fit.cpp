// `needlebench fit calibration|stiffness|friction`: the thesis's identifications, headless.
// The JSON keys are a contract with users' scripts; the tables are for reading.

#include "cli_support.h"
#include "core/model_json.h"
#include "core/tr.h"

#include "core/calibration.h"
#include "core/events.h"
#include "core/fit_error.h"
#include "core/friction_fit.h"
#include "core/friction_peak_line.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "core/stiffness_fit.h"
#include "core/tissue_trace.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace nb::cli {

namespace {

// A failure of one input file: printed as one line naming the file, exit 1.
struct FileFailure {
    QString message;
};

Run loadRun(const QString& path, Io io)
{
    try {
        RunReadResult r = readRunFile(path, {.dropTruncatedLastRow = true});
        for (const QString& w : r.warnings)
            io.err << nb::TrCli::tr("warning: %1\n").arg(w);
        return std::move(r.run);
    } catch (const RunFileError& e) {
        throw FileFailure{e.message()};
    }
}

// A labels file given to a fit: a row it cannot take, labels that overlap, and a label of the
// fit's kind (intervals or points) that is none of the names it knows are said on stderr, so
// that a typo ("C", "punct") is seen instead of silently fitted around. `reads` are the names
// the fit uses, `known` every name of that kind the window labels with.
Labels readLabelsForFit(const QString& path, const QStringList& reads, const QStringList& known, bool intervals, Io io)
{
    LabelsRead read;
    try {
        read = readLabels(path);
    } catch (const RunFileError& e) {
        throw FileFailure{e.message()};
    }
    for (const QString& p : read.problems())
        io.err << nb::TrCli::tr("warning: %1\n").arg(p);
    for (const QString& o : overlappingLabels(read.labels))
        io.err << nb::TrCli::tr("warning: %1: %2\n").arg(path, o);
    QStringList unknown;
    for (const Label& l : read.labels)
        if (l.isPoint() != intervals && !known.contains(l.label, intervals ? Qt::CaseSensitive : Qt::CaseInsensitive) && !unknown.contains(l.label))
            unknown << l.label;
    if (!unknown.isEmpty())
        io.err << nb::TrCli::tr("warning: %1: %2 not used by this fit (it reads %3)\n")
                      .arg(path, QLatin1Char('\'') + unknown.join(QStringLiteral("', '")) + QLatin1Char('\''), reads.join(QStringLiteral(", ")));
    return std::move(read.labels);
}

// A run named twice (a shell glob, and the file again) was fitted twice, and the pooled fit and
// the mean of runs counted it so (one run three times: "± 0"). Each file is fitted once, saying
// so; returns the places of the files kept, the first of each.
QList<qsizetype> eachRunOnce(const QStringList& files, Io io)
{
    QList<qsizetype> kept;
    QStringList seen;
    for (qsizetype i = 0; i < files.size(); ++i) {
        const QFileInfo fi(files[i]);
        const QString key = fi.exists() ? fi.canonicalFilePath() : fi.absoluteFilePath();
        if (seen.contains(key)) {
            io.err << nb::TrCli::tr("warning: %1 is given more than once; it is fitted once").arg(files[i]) << '\n';
            continue;
        }
        seen << key;
        kept << i;
    }
    return kept;
}

QStringList pick(const QStringList& list, const QList<qsizetype>& at)
{
    QStringList out;
    for (qsizetype i : at)
        out << list[i];
    return out;
}

template <typename F>
auto onFile(const QString& path, F&& f)
{
    try {
        return f();
    } catch (const FitError& e) {
        throw FileFailure{QStringLiteral("%1: %2").arg(path, e.message())};
    }
}

QString num(double v, int precision = 5) { return QString::number(v, 'g', precision); }

// [issue 15] A fit whose values are not finite is no result: the file is refused, named.
void requireFinite(const QString& path, std::initializer_list<double> values)
{
    for (double v : values)
        if (!std::isfinite(v))
            throw FileFailure{nb::TrCli::tr("%1: the fit gave no finite result (forces or positions out of any measurable range?)").arg(path)};
}

// A statistic undefined for one run (a standard deviation) is left empty, not reported as 0.
QJsonValue statistic(double v, std::size_t runs) { return runs < 2 || !std::isfinite(v) ? QJsonValue() : QJsonValue(v); }

QJsonObject alternativesJson(const StiffnessFit& f)
{
    return {{QStringLiteral("cubic"),
             QJsonObject{{QStringLiteral("a1_N_per_mm"), f.cubic.a1_N_per_mm},
                         {QStringLiteral("a2_N_per_mm2"), f.cubic.a2_N_per_mm2},
                         {QStringLiteral("a3_N_per_mm3"), f.cubic.a3_N_per_mm3},
                         {QStringLiteral("rms_N"), f.cubic.rms_N},
                         {QStringLiteral("r2"), f.cubic.r2}}},
            {QStringLiteral("spring"),
             QJsonObject{{QStringLiteral("a_per_N"), f.spring.a_per_N},
                         {QStringLiteral("b_mm_per_N"), f.spring.b_mm_per_N},
                         {QStringLiteral("rms_N"), f.spring.rms_N},
                         {QStringLiteral("r2"), f.spring.r2},
                         {QStringLiteral("converged"), f.spring.converged}}}};
}

int fitCalibrationCommand(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("FILE.csv"), nb::TrCli::tr("calibration points: columns mass_g, voltage_V"));
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("fit calibration"), args, io, 1, 1, &code))
        return code;
    const QString path = parser.positionalArguments().first();
    std::vector<CalibrationPoint> points;
    try {
        points = readCalibrationFile(path);
    } catch (const RunFileError& e) {
        throw FileFailure{e.message()};
    }
    const CalibrationFit fit = onFile(path, [&] { return fitCalibration(points); });
    if (parser.isSet(json)) {
        QJsonArray residuals;
        for (double r : fit.residuals_V)
            residuals.append(r);
        printJson(io, {{QStringLiteral("file"), path},
                       {QStringLiteral("slope_V_per_g"), fit.slope_V_per_g},
                       {QStringLiteral("intercept_V"), fit.intercept_V},
                       {QStringLiteral("r2"), fit.r2},
                       {QStringLiteral("rms_V"), fit.rms_V},
                       {QStringLiteral("residuals_V"), residuals}});
        return Ok;
    }
    io.out << nb::TrCli::tr("calibration %1: V = %2 V/g * m + %3 V   r2 = %4   rms = %5 V\n")
                  .arg(path, num(fit.slope_V_per_g, 7), num(fit.intercept_V, 7), num(fit.r2, 7), num(fit.rms_V, 3));
    io.out << nb::TrCli::tr("    mass_g   voltage_V  residual_V\n");
    std::size_t worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (std::fabs(fit.residuals_V[i]) > std::fabs(fit.residuals_V[worst]))
            worst = i;
    for (std::size_t i = 0; i < points.size(); ++i) {
        io.out << QStringLiteral("%1 %2 %3")
                      .arg(points[i].mass_g, 10, 'f', 2)
                      .arg(points[i].voltage_V, 11, 'f', 6)
                      .arg(fit.residuals_V[i], 11, 'e', 2);
        // Three rms is where a point stops looking like noise.
        if (i == worst && fit.rms_V > 0.0 && std::fabs(fit.residuals_V[i]) > 3.0 * fit.rms_V)
            io.out << nb::TrCli::tr("  <- largest residual, check this point");
        io.out << '\n';
    }
    return Ok;
}

int fitStiffnessCommand(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    const QCommandLineOption labels(QStringLiteral("labels"),
                                    nb::TrCli::tr("a run's labels (track,label,start_s,end_s,comment); its 'contact' and "
                                       "'puncture' points replace the detected ones. Give it once per run, in the "
                                       "runs' order."),
                                    QStringLiteral("FILE"));
    parser.addOption(json);
    parser.addOption(labels);
    parser.addPositionalArgument(QStringLiteral("RUN.csv..."), nb::TrCli::tr("constant-velocity insertion runs"));
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("fit stiffness"), args, io, 1, -1, &code))
        return code;
    QStringList files = parser.positionalArguments();
    QStringList labelFiles = parser.values(labels);
    if (!labelFiles.isEmpty() && labelFiles.size() != files.size()) {
        io.err << "needlebench fit stiffness: "
               << nb::TrCli::tr("%1 label files for %2 runs; give --labels once per run, in the runs' order\n")
                      .arg(labelFiles.size())
                      .arg(files.size())
               << nb::TrCli::tr("Usage: needlebench fit stiffness RUN.csv... [--labels FILE]... [--json]\n");
        return Usage;
    }
    const QList<qsizetype> once = eachRunOnce(files, io);
    files = pick(files, once);
    if (!labelFiles.isEmpty())
        labelFiles = pick(labelFiles, once);
    std::vector<InsertionEvents> events;
    std::vector<StiffnessSegment> segments;
    for (qsizetype f = 0; f < files.size(); ++f) {
        const QString& path = files[f];
        const Run run = loadRun(path, io);
        if (const QString w = notAnInsertionRun(run, path); !w.isEmpty())
            io.err << w << '\n';
        if (!labelFiles.isEmpty()) {
            const QStringList reads{QStringLiteral("contact"), QStringLiteral("puncture")};
            const Labels marks = readLabelsForFit(labelFiles[f], reads, reads + QStringList{QStringLiteral("relaxation"), QStringLiteral("internal puncture")}, false, io);
            // An event the file does not mark is detected in the force, as without it: said, so that
            // a labels file of another run (or one without events) is not taken for the operator's.
            QStringList unmarked;
            for (const QString& name : reads)
                if (!marksEvent(marks, name))
                    unmarked << name;
            if (!unmarked.isEmpty())
                io.err << nb::TrCli::tr("warning: %1 marks no %2 for %3: found in the force instead")
                              .arg(labelFiles[f], unmarked.join(nb::TrCli::tr(" or ")), path)
                       << '\n';
            // Detection's error names the run, a label's the labels file.
            try {
                events.push_back(eventsWithLabels(run, marks));
            } catch (const FitError&) {
                events.push_back(onFile(path, [&] { return detectEvents(run); }));
                onFile(labelFiles[f], [&] {
                    applyEventLabels(events.back(), run, marks);
                    return 0;
                });
            }
        } else {
            events.push_back(onFile(path, [&] { return detectEvents(run); }));
        }
        segments.push_back(stiffnessSegment(run, events.back()));
        const StiffnessFit one = onFile(path, [&] { return fitStiffness(segments.back()); });  // names the file if a run is unusable
        requireFinite(path, {one.quadratic.model.a1_N_per_mm, one.quadratic.model.a2_N_per_mm2, one.quadratic.rms_N});
    }
    const StiffnessSummary sum = fitStiffnessRuns(segments);

    if (parser.isSet(json)) {
        QJsonArray runs;
        for (std::size_t i = 0; i < events.size(); ++i) {
            const auto& ev = events[i];
            const auto& f = sum.runs[i];
            QJsonObject o = toJson(f.quadratic);
            o.insert(QStringLiteral("file"), files[qsizetype(i)]);
            o.insert(QStringLiteral("contact_mm"), ev.contact.position_mm);
            o.insert(QStringLiteral("puncture_mm"), ev.puncture.position_mm);
            o.insert(QStringLiteral("puncture_depth_mm"), ev.punctureDepth_mm());
            o.insert(QStringLiteral("puncture_force_N"), ev.puncture.force_N);
            o.insert(QStringLiteral("zero_offset_N"), ev.zeroOffset_N);
            o.insert(QStringLiteral("samples"), qint64(f.samples));
            o.insert(QStringLiteral("alternatives"), alternativesJson(f));
            runs.append(o);
        }
        QJsonObject pooled = toJson(sum.pooled.quadratic);
        pooled.insert(QStringLiteral("samples"), qint64(sum.pooled.samples));
        pooled.insert(QStringLiteral("alternatives"), alternativesJson(sum.pooled));
        printJson(io, {{QStringLiteral("runs"), runs},
                       {QStringLiteral("pooled"), pooled},
                       {QStringLiteral("mean_of_runs"),
                        [&] {
                            QJsonObject mean = toJson(sum.meanOfRuns);
                            mean.insert(QStringLiteral("a1_std_N_per_mm"), statistic(sum.stdDevOfRuns.a1_N_per_mm, sum.runs.size()));
                            mean.insert(QStringLiteral("a2_std_N_per_mm2"), statistic(sum.stdDevOfRuns.a2_N_per_mm2, sum.runs.size()));
                            return mean;
                        }()}});
        return Ok;
    }
    io.out << nb::TrCli::tr("stiffness f = a1*x + a2*x^2, x = depth past contact [mm]\n");
    io.out << nb::TrCli::tr("run                       contact_mm puncture_mm depth_mm  force_N  a1_N/mm   a2_N/mm2  rms_N    r2\n");
    auto row = [&](const QString& name, const QString& c, const QString& p, const QString& d, const QString& fN,
                   const QuadraticStiffnessFit& q) {
        io.out << name.left(25).leftJustified(25) << ' ' << c.rightJustified(10) << ' ' << p.rightJustified(11) << ' '
               << d.rightJustified(8) << ' ' << fN.rightJustified(8) << ' ' << num(q.model.a1_N_per_mm, 4).rightJustified(9)
               << ' ' << num(q.model.a2_N_per_mm2, 4).rightJustified(9) << ' ' << num(q.rms_N, 3).rightJustified(8) << ' '
               << num(q.r2, 4) << '\n';
    };
    for (std::size_t i = 0; i < events.size(); ++i) {
        const auto& ev = events[i];
        row(QFileInfo(files[qsizetype(i)]).fileName(), num(ev.contact.position_mm, 4), num(ev.puncture.position_mm, 4),
            num(ev.punctureDepth_mm(), 4), num(ev.puncture.force_N, 4), sum.runs[i].quadratic);
    }
    row(nb::TrCli::tr("pooled"), QString(), QString(), QString(), QString(), sum.pooled.quadratic);
    io.out << nb::TrCli::tr("mean of runs: a1 = %1 ± %2 N/mm, a2 = %3 ± %4 N/mm²\n")
                  .arg(num(sum.meanOfRuns.a1_N_per_mm, 4), num(sum.stdDevOfRuns.a1_N_per_mm, 2),
                       num(sum.meanOfRuns.a2_N_per_mm2, 4), num(sum.stdDevOfRuns.a2_N_per_mm2, 2));
    io.out << nb::TrCli::tr("alternatives (pooled): cubic rms %1 N r2 %2 (a3 = %3 N/mm³); spring x/(a x + b) rms %4 N r2 %5\n")
                  .arg(num(sum.pooled.cubic.rms_N, 3), num(sum.pooled.cubic.r2, 4), num(sum.pooled.cubic.a3_N_per_mm3, 3),
                       num(sum.pooled.spring.rms_N, 3), num(sum.pooled.spring.r2, 4));
    return Ok;
}

QJsonObject groupJson(const FrictionGroup& g, bool withFrequency)
{
    QJsonObject mean = toJson(g.mean), sd = toJson(g.stdDev);
    if (g.massEstimateMean_kg) {
        mean.insert(QStringLiteral("m_est_kg"), *g.massEstimateMean_kg);
        sd.insert(QStringLiteral("m_est_kg"), *g.massEstimateStdDev_kg);
    }
    if (g.runs < 2)  // [issue 15] a standard deviation of one run is undefined: left empty
        for (const QString& k : sd.keys())
            sd.insert(k, QJsonValue());
    // A value no run of the group determines (all flagged it) is null, not NaN.
    for (QJsonObject* o : {&mean, &sd})
        for (const QString& k : o->keys())
            if (o->value(k).isDouble() && !std::isfinite(o->value(k).toDouble()))
                o->insert(k, QJsonValue());
    QJsonObject o{{QStringLiteral("runs"), qint64(g.runs)}, {QStringLiteral("mean"), mean}, {QStringLiteral("std"), sd}};
    if (withFrequency)
        o.insert(QStringLiteral("frequency_hz"), g.frequency_hz);
    return o;
}

std::optional<double> positiveNumber(const QString& text)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok && std::isfinite(v) && v > 0.0 ? std::optional<double>(v) : std::nullopt;
}

int fitFrictionCommand(const QStringList& args, Io io)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), nb::TrCli::tr("print JSON"));
    const QCommandLineOption thickness(QStringLiteral("thickness-mm"),
                                       nb::TrCli::tr("length of needle in tissue (slab thickness), required"), QStringLiteral("T"));
    const QCommandLineOption mass(QStringLiteral("mass-kg"),
                                  nb::TrCli::tr("needle holder mass removed from the force (eq. 21, default 0.087)"), QStringLiteral("M"));
    const QCommandLineOption estimate(QStringLiteral("estimate-mass"), nb::TrCli::tr("estimate the mass with the friction (eq. 19)"));
    const QCommandLineOption band(QStringLiteral("band-m-s"),
                                  nb::TrCli::tr("zero-velocity band width, e.g. 0.005 = ±2.5 mm/s (default: found in each run's data)"),
                                  QStringLiteral("B"));
    const QCommandLineOption labels(QStringLiteral("labels"),
                                    nb::TrCli::tr("phase labels (track,label,start_s,end_s,comment) for a single run; "
                                       "C and b then come from phase c, D from phase a. Runs may carry a 'phase' "
                                       "column instead. Without phases the velocity band decides."),
                                    QStringLiteral("FILE"));
    const QCommandLineOption tissueTrace(QStringLiteral("tissue-trace"),
                                         nb::TrCli::tr("the tissue's velocity over the run (time_s,tissue_velocity_mm_s, as labels suggest "
                                                       "--tissue-trace writes it from the video) for a single run: C and b are then fitted "
                                                       "against the needle's velocity relative to the tissue"),
                                         QStringLiteral("FILE.csv"));
    for (const auto* o : {&json, &thickness, &mass, &estimate, &band, &labels, &tissueTrace})
        parser.addOption(*o);
    parser.addPositionalArgument(QStringLiteral("RUN.csv..."), nb::TrCli::tr("sinusoidal runs through a tissue slab"));
    int code = Ok;
    if (!parseArgs(parser, QStringLiteral("fit friction"), args, io, 1, -1, &code))
        return code;
    auto usage = [&](const QString& why) {
        io.err << "needlebench fit friction: " << why << '\n'
               << nb::TrCli::tr("Usage: needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass] "
                     "[--band-m-s B] [--labels FILE] [--tissue-trace FILE.csv] [--json]\n");
        return int(Usage);
    };
    FrictionOptions options;
    if (!parser.isSet(thickness))
        return usage(nb::TrCli::tr("--thickness-mm is required"));
    // Per length of tissue: a slab of 1e9 mm gave coefficients a million times too small, as results.
    constexpr double kThickestSlab_mm = 1000.0;
    if (const auto t = positiveNumber(parser.value(thickness)); t && *t <= kThickestSlab_mm)
        options.thickness_mm = *t;
    else if (t)
        return usage(nb::TrCli::tr("--thickness-mm: %1 mm is no slab (at most %2 mm)").arg(parser.value(thickness)).arg(kThickestSlab_mm));
    else
        return usage(nb::TrCli::tr("--thickness-mm: '%1' is not a positive number").arg(parser.value(thickness)));
    if (parser.isSet(mass) && parser.isSet(estimate))
        return usage(nb::TrCli::tr("--mass-kg and --estimate-mass exclude each other"));
    if (parser.isSet(mass)) {
        bool ok = false;
        options.mass_kg = parser.value(mass).toDouble(&ok);
        if (!ok || !std::isfinite(options.mass_kg) || options.mass_kg < 0.0)
            return usage(nb::TrCli::tr("--mass-kg: '%1' is not a mass").arg(parser.value(mass)));
    }
    options.estimateMass = parser.isSet(estimate);
    options.estimateBand = !parser.isSet(band);
    if (parser.isSet(band)) {
        if (const auto b = positiveNumber(parser.value(band)))
            options.band_m_s = *b;
        else
            return usage(nb::TrCli::tr("--band-m-s: '%1' is not a positive number").arg(parser.value(band)));
    }
    const QStringList named = parser.positionalArguments();
    if (parser.isSet(labels) && named.size() != 1)
        return usage(nb::TrCli::tr("--labels applies to a single run; give one run per call"));
    if (parser.isSet(tissueTrace) && named.size() != 1)
        return usage(nb::TrCli::tr("--tissue-trace applies to a single run; give one run per call"));
    const QStringList files = pick(named, eachRunOnce(named, io));
    std::optional<TissueMotion> trace;
    if (parser.isSet(tissueTrace)) {
        try {
            trace = readTissueTrace(parser.value(tissueTrace));
        } catch (const TissueTraceError& e) {
            io.err << "needlebench fit friction: " << e.message() << '\n';
            return Failure;
        }
    }

    std::vector<FrictionFit> fits;
    for (const QString& path : files) {
        const Run run = loadRun(path, io);
        QStringList phases;
        if (parser.isSet(labels)) {
            const QStringList friction{QStringLiteral("a"), QStringLiteral("b1"), QStringLiteral("b2"), QStringLiteral("c")};
            phases = phasePerSample(readLabelsForFit(parser.value(labels), friction, friction, true, io), run.time_s);
            // A labels file without phases (an insertion run's, say) would silently set the
            // run's own phase column aside.
            if (std::all_of(phases.begin(), phases.end(), [](const QString& p) { return p.isEmpty(); })) {
                io.err << nb::TrCli::tr("warning: %1 holds no friction phase over %2 (a, b1, b2, c); the run's own phase column "
                                        "is used, else the velocity band")
                              .arg(parser.value(labels), path)
                       << '\n';
                phases.clear();
            }
        }
        FrictionOptions runOptions = options;
        if (trace) {
            runOptions.tissueVelocity_m_s = tissueVelocityAt(*trace, run.time_s);
            for (double& v : runOptions.tissueVelocity_m_s)
                v /= 1000.0;  // mm/s -> m/s
            runOptions.tissueStep_s = (trace->time_s.back() - trace->time_s.front()) / double(trace->time_s.size() - 1);
        }
        fits.push_back(onFile(path, [&] { return fitFriction(run, runOptions, phases); }));
        const KarnoppModel& k = fits.back().model;
        requireFinite(path, {k.Cp_N, k.Cn_N, k.bp_Ns_per_m, k.bn_Ns_per_m, k.Dp_N, k.Dn_N, fits.back().rms_N});
    }
    const auto groups = groupByFrequency(fits);
    const FrictionGroup all = overall(fits);
    std::vector<RunPeaks> peaks;
    for (const FrictionFit& f : fits)
        peaks.push_back(f.peaks);
    const std::optional<PeakSpeedLine> peakLine = peakSpeedLine(peaks);
    const double L = options.thickness_mm / 1000.0;
    auto linePerLength = [&](const PeakSpeedLine& l) {
        return KarnoppPerLength{l.model.Cp_N / L, l.model.Cn_N / L, l.model.bp_Ns_per_m / L, l.model.bn_Ns_per_m / L, 0.0, 0.0};
    };

    if (parser.isSet(json)) {
        QJsonArray runs;
        for (std::size_t i = 0; i < fits.size(); ++i) {
            const FrictionFit& f = fits[i];
            // No phase a and no band to read the static friction from: not determined, null as
            // per_length has it (it said 0).
            const bool staticRead = f.staticSource != QLatin1String("none");
            QJsonObject perLength = toJson(f.perLength);
            if (!staticRead) {
                perLength[QStringLiteral("Dp_N_per_m")] = QJsonValue();
                perLength[QStringLiteral("Dn_N_per_m")] = QJsonValue();
            }
            QJsonObject o{{QStringLiteral("file"), files[qsizetype(i)]},
                          {QStringLiteral("frequency_hz"), f.frequency_hz},
                          {QStringLiteral("Cp_N"), f.model.Cp_N},
                          {QStringLiteral("Cn_N"), f.model.Cn_N},
                          {QStringLiteral("bp_Ns_per_m"), f.model.bp_Ns_per_m},
                          {QStringLiteral("bn_Ns_per_m"), f.model.bn_Ns_per_m},
                          {QStringLiteral("Dp_N"), staticRead ? QJsonValue(f.model.Dp_N) : QJsonValue()},
                          {QStringLiteral("Dn_N"), staticRead ? QJsonValue(f.model.Dn_N) : QJsonValue()},
                          {QStringLiteral("rms_N"), f.rms_N},
                          {QStringLiteral("static_source"), f.staticSource},
                          {QStringLiteral("samples_positive"), qint64(f.positiveSamples)},
                          {QStringLiteral("samples_negative"), qint64(f.negativeSamples)},
                          {QStringLiteral("per_length"), perLength},
                          {QStringLiteral("band_m_s"), f.band_m_s},
                          {QStringLiteral("band_estimated"), f.bandEstimated},
                          // C and b against the needle's velocity relative to the tissue's (--tissue-trace), else the needle's.
                          {QStringLiteral("tissue_trace"), f.relativeVelocity ? QJsonValue(parser.value(tissueTrace)) : QJsonValue()},
                          {QStringLiteral("band_slowing_down_m_s"), f.bandEstimated ? f.bandSlowingDown_m_s : f.band_m_s},
                          {QStringLiteral("standard_errors"), QJsonObject{{QStringLiteral("Cp_N"), f.seCp_N},
                                                                          {QStringLiteral("Cn_N"), f.seCn_N},
                                                                          {QStringLiteral("bp_Ns_per_m"), f.seBp_Ns_per_m},
                                                                          {QStringLiteral("bn_Ns_per_m"), f.seBn_Ns_per_m},
                                                                          {QStringLiteral("Dp_N"), std::isfinite(f.seDp_N) ? QJsonValue(f.seDp_N) : QJsonValue()},
                                                                          {QStringLiteral("Dn_N"), std::isfinite(f.seDn_N) ? QJsonValue(f.seDn_N) : QJsonValue()}}},
                          {QStringLiteral("physical"), f.notPhysical.isEmpty()},
                          {QStringLiteral("not_physical"), QJsonArray::fromStringList(f.notPhysical)},
                          {QStringLiteral("not_physical_values"), QJsonArray::fromStringList(f.notPhysicalValues)}};
            if (f.massEstimate_kg)
                o.insert(QStringLiteral("m_est_kg"), *f.massEstimate_kg);
            // b/k of a slab that springs back off the plate (0: the run shows none), and k.
            QJsonObject springBack{{QStringLiteral("positive_s"), f.springBackP_s}, {QStringLiteral("negative_s"), f.springBackN_s}};
            if (f.springBackP_s > 0.0)
                springBack.insert(QStringLiteral("slab_stiffness_positive_N_per_m"), f.model.bp_Ns_per_m / f.springBackP_s);
            if (f.springBackN_s > 0.0)
                springBack.insert(QStringLiteral("slab_stiffness_negative_N_per_m"), f.model.bn_Ns_per_m / f.springBackN_s);
            o.insert(QStringLiteral("spring_back"), springBack);
            // The slab's give against its plate, read where it was carried into it (null: not shown).
            auto give = [](const std::optional<nb::PlateGive>& g) {
                if (!g)
                    return QJsonValue();
                return QJsonValue(QJsonObject{{QStringLiteral("stiffness_N_per_m"), g->stiffness_N_per_m},
                                              {QStringLiteral("up_to_N"), g->upTo_N},
                                              {QStringLiteral("losses_Ns_per_m"), g->losses_Ns_per_m},
                                              {QStringLiteral("rises"), qint64(g->rises)}});
            };
            o.insert(QStringLiteral("plate_give"),
                     QJsonObject{{QStringLiteral("positive"), give(f.plateGiveP)}, {QStringLiteral("negative"), give(f.plateGiveN)}});
            o.insert(QStringLiteral("residual_to_noise"),
                     QJsonObject{{QStringLiteral("positive"), f.residualToNoiseP}, {QStringLiteral("negative"), f.residualToNoiseN}});
            // How far C moves (a fraction of it) when the sliding line may bend.
            o.insert(QStringLiteral("c_shift_if_bent"),
                     QJsonObject{{QStringLiteral("positive"), f.bendShiftCp}, {QStringLiteral("negative"), f.bendShiftCn}});
            // Where the tissue was still arriving at the plate past the top speed (null: not seen).
            auto speedOrNull = [](double speed_m_s) { return std::isfinite(speed_m_s) ? QJsonValue(speed_m_s) : QJsonValue(); };
            o.insert(QStringLiteral("arriving_above_m_s"), QJsonObject{{QStringLiteral("positive"), speedOrNull(f.arrivingAboveP_m_s)},
                                                                      {QStringLiteral("negative"), speedOrNull(f.arrivingAboveN_m_s)}});
            o.insert(QStringLiteral("sliding_speed_m_s"),
                     QJsonObject{{QStringLiteral("positive"), QJsonArray{f.slidingFromP_m_s, f.slidingToP_m_s}},
                                 {QStringLiteral("negative"), QJsonArray{f.slidingFromN_m_s, f.slidingToN_m_s}}});
            QJsonObject top;
            auto peakJson = [](const PeakPoint& p) {
                return QJsonObject{{QStringLiteral("speed_m_s"), p.speed_m_s}, {QStringLiteral("force_N"), p.force_N},
                                   {QStringLiteral("settled"), p.settled}};
            };
            if (f.peaks.positive)
                top.insert(QStringLiteral("positive"), peakJson(*f.peaks.positive));
            if (f.peaks.negative)
                top.insert(QStringLiteral("negative"), peakJson(*f.peaks.negative));
            o.insert(QStringLiteral("peak"), top);
            if (peakLine) {
                const LineDeparture d = departureFromLine(f, *peakLine);
                o.insert(QStringLiteral("C_from_peak_line_percent"),
                         QJsonObject{{QStringLiteral("Cp"), d.Cp_percent}, {QStringLiteral("Cn"), d.Cn_percent}});
                o.insert(QStringLiteral("departs_from_peak_line"), d.significant);
            }
            runs.append(o);
        }
        QJsonArray byFrequency;
        for (const FrictionGroup& g : groups)
            byFrequency.append(groupJson(g, true));
        QJsonObject doc{{QStringLiteral("runs"), runs},
                        {QStringLiteral("by_frequency"), byFrequency},
                        {QStringLiteral("overall"), groupJson(all, false)},
                        {QStringLiteral("thickness_mm"), options.thickness_mm},
                        {QStringLiteral("band_m_s"), options.estimateBand && !fits.empty() ? fits.front().band_m_s : options.band_m_s},
                        {QStringLiteral("band_estimated"), options.estimateBand}};
        if (peakLine) {
            const KarnoppPerLength pl = linePerLength(*peakLine);
            doc.insert(QStringLiteral("peak_speed_line"),
                       QJsonObject{{QStringLiteral("Cp_N"), peakLine->model.Cp_N},
                                   {QStringLiteral("Cn_N"), peakLine->model.Cn_N},
                                   {QStringLiteral("bp_Ns_per_m"), peakLine->model.bp_Ns_per_m},
                                   {QStringLiteral("bn_Ns_per_m"), peakLine->model.bn_Ns_per_m},
                                   {QStringLiteral("per_length"), QJsonObject{{QStringLiteral("Cp_N_per_m"), pl.Cp_N_per_m},
                                                                              {QStringLiteral("Cn_N_per_m"), pl.Cn_N_per_m},
                                                                              {QStringLiteral("bp_Ns_per_m2"), pl.bp_Ns_per_m2},
                                                                              {QStringLiteral("bn_Ns_per_m2"), pl.bn_Ns_per_m2}}},
                                   {QStringLiteral("standard_errors"), QJsonObject{{QStringLiteral("Cp_N"), peakLine->seCp_N},
                                                                                   {QStringLiteral("Cn_N"), peakLine->seCn_N},
                                                                                   {QStringLiteral("bp_Ns_per_m"), peakLine->seBp_Ns_per_m},
                                                                                   {QStringLiteral("bn_Ns_per_m"), peakLine->seBn_Ns_per_m}}},
                                   {QStringLiteral("runs"), qint64(peakLine->runs)},
                                   {QStringLiteral("slowest_m_s"), peakLine->slowest_m_s},
                                   {QStringLiteral("fastest_m_s"), peakLine->fastest_m_s}});
        }
        printJson(io, doc);
        return Ok;
    }
    io.out << nb::TrCli::tr("friction per unit length of needle in tissue (thickness %1 mm): C, D in N/m, b in N·s/m²\n")
                  .arg(num(options.thickness_mm));
    const bool m = options.estimateMass;
    io.out << nb::TrCli::tr("group             statistic freq_Hz ") << (m ? nb::TrCli::tr("  m_est_kg ") : QString())
           << nb::TrCli::tr("       Cp        Bp        Cn        Bn        Dp        Dn\n");
    auto line = [&](const QString& group, const QString& stat, const QString& freq, std::optional<double> mass,
                    const KarnoppPerLength& p, bool defined = true, const QStringList& notPhysical = {}) {
        io.out << group.left(17).leftJustified(17) << ' ' << stat.leftJustified(9) << ' ' << freq.rightJustified(7) << ' ';
        if (m)
            io.out << (mass && defined ? num(*mass, 4) : QString()).rightJustified(10) << ' ';
        // A value flagged as not physical is not printed as a result; an undefined statistic is left empty.
        const char* names[] = {"Cp", "bp", "Cn", "bn", "Dp", "Dn"};
        int k = 0;
        for (double v : {p.Cp_N_per_m, p.bp_Ns_per_m2, p.Cn_N_per_m, p.bn_Ns_per_m2, p.Dp_N_per_m, p.Dn_N_per_m}) {
            const QString name = QString::fromLatin1(names[k++]);
            const bool bad = notPhysical.contains(name);
            io.out << (!defined || !std::isfinite(v) ? QString() : bad ? nb::TrCli::tr("no result") : num(v, 5)).rightJustified(9) << ' ';
        }
        io.out << '\n';
    };
    for (std::size_t i = 0; i < fits.size(); ++i)
        line(QFileInfo(files[qsizetype(i)]).fileName(), nb::TrCli::tr("run"), num(fits[i].frequency_hz, 3), fits[i].massEstimate_kg,
             fits[i].perLength, true, fits[i].notPhysicalValues);
    for (const FrictionGroup& g : groups) {
        const QString name = nb::TrCli::tr("%1Hz (%2 runs)").arg(num(g.frequency_hz, 3)).arg(g.runs);
        line(name, nb::TrCli::tr("mean"), num(g.frequency_hz, 3), g.massEstimateMean_kg, g.mean);
        line(name, nb::TrCli::tr("std"), num(g.frequency_hz, 3), g.massEstimateStdDev_kg, g.stdDev, g.runs > 1);
    }
    line(nb::TrCli::tr("all (%1 runs)").arg(all.runs), nb::TrCli::tr("mean"), QString(), all.massEstimateMean_kg, all.mean);
    line(nb::TrCli::tr("all (%1 runs)").arg(all.runs), nb::TrCli::tr("std"), QString(), all.massEstimateStdDev_kg, all.stdDev, all.runs > 1);
    if (peakLine) {
        // D is not defined by the line: printed empty (the line() columns are all or nothing).
        io.out << nb::TrCli::tr("peak speeds").leftJustified(17) << ' ' << nb::TrCli::tr("line").leftJustified(9) << ' '
               << QString().rightJustified(7) << ' ' << (m ? QString().rightJustified(10) + QLatin1Char(' ') : QString());
        const KarnoppPerLength pl = linePerLength(*peakLine);
        for (double v : {pl.Cp_N_per_m, pl.bp_Ns_per_m2, pl.Cn_N_per_m, pl.bn_Ns_per_m2})
            io.out << num(v, 5).rightJustified(9) << ' ';
        io.out << '\n';
    }
    for (std::size_t i = 0; i < fits.size(); ++i) {
        const FrictionFit& f = fits[i];
        const QString name = QFileInfo(files[qsizetype(i)]).fileName();
        io.out << nb::TrCli::tr("%1: D from %2, rms %3 N\n").arg(name, f.staticSource, num(f.rms_N, 3));
        if (f.bandEstimated)
            io.out << nb::TrCli::tr("%1: zero-velocity band found in the data: ±%2 mm/s after turning points, ±%3 mm/s before them\n")
                          .arg(name, num(f.band_m_s * 500.0, 3), num(f.bandSlowingDown_m_s * 500.0, 3));
        else
            io.out << nb::TrCli::tr("%1: zero-velocity band ±%2 mm/s (given)\n").arg(name, num(f.band_m_s * 500.0, 3));
        if (f.relativeVelocity)
            io.out << nb::TrCli::tr("%1: C and b fitted against the needle's velocity relative to the tissue's (%2)\n")
                          .arg(name, parser.value(tissueTrace));
        io.out << nb::TrCli::tr("%1: standard errors per length: Cp ±%2, bp ±%3, Cn ±%4, bn ±%5\n")
                      .arg(name, num(f.seCp_N / L, 3), num(f.seBp_Ns_per_m / L, 3), num(f.seCn_N / L, 3), num(f.seBn_Ns_per_m / L, 3));
        if (std::isfinite(f.seDp_N) && std::isfinite(f.seDn_N))
            io.out << nb::TrCli::tr("%1: standard errors of D per length: Dp ±%2, Dn ±%3 (the spread of %4 and %5 break-aways)\n")
                          .arg(name, num(f.seDp_N / L, 3), num(f.seDn_N / L, 3))
                          .arg(f.breakawaysP)
                          .arg(f.breakawaysN);
        if (std::isfinite(f.arrivingAboveP_m_s) || std::isfinite(f.arrivingAboveN_m_s)) {
            auto above = [&](double speed_m_s) {
                return std::isfinite(speed_m_s) ? nb::TrCli::tr("above %1 mm/s").arg(num(speed_m_s * 1000.0, 3)) : nb::TrCli::tr("not seen");
            };
            io.out << nb::TrCli::tr("%1: the tissue was still arriving at the plate as the needle passed its top speed (+ motion: %2, "
                                    "- motion: %3); those samples are left out of the sliding line and the peak point\n")
                          .arg(name, above(f.arrivingAboveP_m_s), above(f.arrivingAboveN_m_s));
        }
        if (f.springBackP_s > 0.0 || f.springBackN_s > 0.0) {
            auto stiffness = [&](double b, double lag) {
                return lag > 0.0 ? nb::TrCli::tr("%1 N/m").arg(num(b / lag, 3)) : nb::TrCli::tr("no give seen");
            };
            io.out << nb::TrCli::tr("%1: the slab springs back off the plate as the needle slows (its stiffness against the plate: "
                                    "%2 in + motion, %3 in - motion); C and b are taken against the tissue's motion\n")
                          .arg(name, stiffness(f.model.bp_Ns_per_m, f.springBackP_s), stiffness(f.model.bn_Ns_per_m, f.springBackN_s));
        }
        for (const auto& [give, direction] : {std::pair{&f.plateGiveP, nb::TrCli::tr("+ motion")}, std::pair{&f.plateGiveN, nb::TrCli::tr("- motion")}})
            if (*give)
                io.out << nb::TrCli::tr("%1: in %2 the slab gives against the plate by %3 N/m up to %4 N (read where the needle carries it in, "
                                        "%5 times); C and b are taken against the tissue's motion where it rests on that give\n")
                              .arg(name, direction, num((*give)->stiffness_N_per_m, 3), num((*give)->upTo_N, 3))
                              .arg((*give)->rises);
        for (const QString& why : f.notPhysical)
            io.out << nb::TrCli::tr("%1: NOT A RESULT (not physical, or not determined by this run): %2\n").arg(name, why);
        if (peakLine) {
            const LineDeparture d = departureFromLine(f, *peakLine);
            if (d.significant)
                io.out << nb::TrCli::tr("%1: C departs from the peak-speed line (Cp %2 %, Cn %3 %): the tissue moves while the "
                                        "needle slows, so this run's sliding line is tilted; prefer the peak-speed line\n")
                              .arg(name, num(d.Cp_percent, 2), num(d.Cn_percent, 2));
        }
    }
    if (peakLine) {
        io.out << nb::TrCli::tr("peak-speed line: C and b through the top speeds of %1 runs (%2 to %3 mm/s), where the needle "
                                "does not accelerate and the tissue rests against the plate; standard errors per length: "
                                "Cp ±%4, bp ±%5, Cn ±%6, bn ±%7\n")
                      .arg(peakLine->runs)
                      .arg(num(peakLine->slowest_m_s * 1000.0, 3), num(peakLine->fastest_m_s * 1000.0, 3), num(peakLine->seCp_N / L, 3),
                           num(peakLine->seBp_Ns_per_m / L, 3), num(peakLine->seCn_N / L, 3), num(peakLine->seBn_Ns_per_m / L, 3));
    } else if (fits.size() > 1) {
        io.out << nb::TrCli::tr("no peak-speed line: it needs three runs or more whose tissue settled at the top and whose top "
                                "speeds differ by a fifth or more (e.g. the same slab at 0.2, 0.5 and 0.8 Hz)\n");
    }
    return Ok;
}

void printFitUsage(QTextStream& s)
{
    s << nb::TrCli::tr("Usage: needlebench fit calibration FILE.csv [--json]\n"
            "       needlebench fit stiffness RUN.csv... [--json]\n"
            "       needlebench fit friction RUN.csv... --thickness-mm T [--mass-kg M | --estimate-mass]\n"
            "                                [--band-m-s B] [--labels FILE] [--json]\n"
            "'needlebench fit WHAT --help' describes each.\n");
}

}  // namespace

int cmdFit(const QStringList& args, Io io)
{
    const QString what = args.value(0);
    if (what == QLatin1String("--help") || what == QLatin1String("-h")) {
        printFitUsage(io.out);
        return Ok;
    }
    try {
        if (what == QLatin1String("calibration"))
            return fitCalibrationCommand(args.mid(1), io);
        if (what == QLatin1String("stiffness"))
            return fitStiffnessCommand(args.mid(1), io);
        if (what == QLatin1String("friction"))
            return fitFrictionCommand(args.mid(1), io);
    } catch (const FileFailure& f) {
        io.err << "needlebench fit " << what << ": " << f.message << '\n';
        return Failure;
    } catch (const FitError& e) {
        io.err << "needlebench fit " << what << ": " << e.message() << '\n';
        return Failure;
    }
    io.err << (what.isEmpty() ? nb::TrCli::tr("needlebench fit: say what to fit\n")
                              : nb::TrCli::tr("needlebench fit: unknown fit '%1'\n").arg(what));
    printFitUsage(io.err);
    return Usage;
}

}  // namespace nb::cli
