#include "rig_friction_matrix.h"

#include "support/truth_columns.h"

#include "core/fit_error.h"
#include "core/friction_fit.h"
#include "core/friction_peak_line.h"
#include "core/run_file.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#include <algorithm>
#include <cmath>

namespace nb::accuracy {

QString RigFrictionSet::describe() const
{
    return QStringLiteral("%1 %2/%3/%4 Hz ±%5 mm, band ±%6 mm/s, gap %7 mm, noise %8 N")
        .arg(tissue)
        .arg(frequencies_hz[0], 0, 'f', 2)
        .arg(frequencies_hz[1], 0, 'f', 2)
        .arg(frequencies_hz[2], 0, 'f', 2)
        .arg(amplitude_mm, 0, 'f', 1)
        .arg(stickBand_mm_s, 0, 'f', 1)
        .arg(plateGap_mm, 0, 'f', 2)
        .arg(forceNoise_N, 0, 'f', 4);
}

std::vector<RigFrictionSet> drawRigFrictionSets(std::mt19937& rng, int count)
{
    const QStringList tissues{QStringLiteral("liver1"), QStringLiteral("liver2"), QStringLiteral("liver3"),
                              QStringLiteral("liver5"), QStringLiteral("liver7")};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<RigFrictionSet> sets;
    for (int i = 0; i < count; ++i) {
        RigFrictionSet s;
        s.tissue = tissues[qsizetype(std::min<double>(tissues.size() - 1, std::floor(u(rng) * tissues.size())))];
        s.stickBand_mm_s = 1.0 + 5.0 * u(rng);
        s.plateGap_mm = 0.5 + 2.5 * u(rng);
        s.forceNoise_N = 0.0005 * std::pow(20.0, u(rng));  // 0.5 to 10 mN, log-uniform
        s.amplitude_mm = 5.0 + 5.0 * u(rng);
        // One of each: slow, middle, fast, around the thesis's three frequencies.
        s.frequencies_hz = {0.2 + 0.1 * u(rng), 0.4 + 0.15 * u(rng), 0.65 + 0.15 * u(rng)};
        s.seed = unsigned(rng() % 100000u) + 1u;
        sets.push_back(s);
    }
    return sets;
}

RigFrictionOutcome runRigFrictionSet(const RigFrictionSet& set, const QString& executable, const QString& workDir, bool withTruePhases)
{
    RigFrictionOutcome out;
    QDir().mkpath(workDir);
    std::vector<FrictionFit> fits;
    KarnoppPerLength truth;
    double thickness_m = 0.03;
    try {
        for (std::size_t k = 0; k < set.frequencies_hz.size(); ++k) {
            const QString runPath = QDir(workDir).filePath(QStringLiteral("run%1.csv").arg(k));
            const QString truthPath = QDir(workDir).filePath(QStringLiteral("truth%1.json").arg(k));
            QProcess p;
            p.start(executable, {QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("friction"),
                                 QStringLiteral("--tissue"), set.tissue, QStringLiteral("--frequency-hz"),
                                 QString::number(set.frequencies_hz[k], 'f', 4), QStringLiteral("--amplitude-mm"),
                                 QString::number(set.amplitude_mm, 'f', 3), QStringLiteral("--stick-band-mm-s"),
                                 QString::number(set.stickBand_mm_s, 'f', 3), QStringLiteral("--plate-gap-mm"),
                                 QString::number(set.plateGap_mm, 'f', 3), QStringLiteral("--force-noise-n"),
                                 QString::number(set.forceNoise_N, 'f', 5), QStringLiteral("--cycles"), QString::number(set.cycles),
                                 QStringLiteral("--seed"), QString::number(set.seed + unsigned(k)), QStringLiteral("--truth"), truthPath,
                                 QStringLiteral("--out"), runPath});
            if (!p.waitForFinished(180000) || p.exitCode() != 0) {
                out.problem = QStringLiteral("simulate failed: ") + QString::fromUtf8(p.readAllStandardError());
                return out;
            }
            QFile tf(truthPath);
            if (!tf.open(QIODevice::ReadOnly)) {
                out.problem = QStringLiteral("no truth file ") + truthPath;
                return out;
            }
            const QJsonObject model = QJsonDocument::fromJson(tf.readAll()).object().value(QStringLiteral("model")).toObject();
            const QJsonObject f = model.value(QStringLiteral("friction_per_length")).toObject();
            truth = {f.value(QStringLiteral("Cp_N_per_m")).toDouble(), f.value(QStringLiteral("Cn_N_per_m")).toDouble(),
                     f.value(QStringLiteral("bp_Ns_per_m2")).toDouble(), f.value(QStringLiteral("bn_Ns_per_m2")).toDouble(),
                     f.value(QStringLiteral("Dp_N_per_m")).toDouble(), f.value(QStringLiteral("Dn_N_per_m")).toDouble()};
            // fitFriction takes C and b from phase c of a run's own `phase` column.
            const Run recorded = readRunFile(runPath).run;
            const Run seen = withTruePhases ? recorded : nbtest::withoutTruthColumns(recorded);
            FrictionOptions o;
            o.thickness_mm = model.value(QStringLiteral("thickness_mm")).toDouble(30.0);
            thickness_m = o.thickness_mm / 1000.0;
            o.estimateBand = true;
            fits.push_back(fitFriction(seen, o));
        }
    } catch (const FitError& e) {
        out.problem = e.message();
        return out;
    } catch (const RunFileError& e) {
        out.problem = e.message();
        return out;
    }
    auto rel = [](double got, double want) { return std::fabs(got - want) / std::fabs(want); };
    std::vector<RunPeaks> peaks;
    for (const FrictionFit& f : fits)
        peaks.push_back(f.peaks);
    const std::optional<PeakSpeedLine> line = peakSpeedLine(peaks);
    for (std::size_t k = 0; k < fits.size(); ++k) {
        const KarnoppPerLength& p = fits[k].perLength;
        out.runErrC[k] = std::max(rel(p.Cp_N_per_m, truth.Cp_N_per_m), rel(p.Cn_N_per_m, truth.Cn_N_per_m));
        out.runErrB[k] = std::max(rel(p.bp_Ns_per_m2, truth.bp_Ns_per_m2), rel(p.bn_Ns_per_m2, truth.bn_Ns_per_m2));
        out.runDeparts[k] = line && departureFromLine(fits[k], *line).significant;
        for (const char* name : {"Cp", "Cn", "bp", "bn"})
            out.runFlagged[k] = out.runFlagged[k] || fits[k].notPhysicalValues.contains(QLatin1String(name));
    }
    if (line) {
        // The line is in N; the truth per metre of needle in tissue (one slab, one thickness).
        const double L = thickness_m;
        out.line = true;
        out.lineErrC = std::max(rel(line->model.Cp_N / L, truth.Cp_N_per_m), rel(line->model.Cn_N / L, truth.Cn_N_per_m));
        out.lineErrB = std::max(rel(line->model.bp_Ns_per_m / L, truth.bp_Ns_per_m2), rel(line->model.bn_Ns_per_m / L, truth.bn_Ns_per_m2));
    }
    out.fits = fits;
    out.truth = truth;
    out.ok = true;
    return out;
}

}  // namespace nb::accuracy
