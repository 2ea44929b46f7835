// Accuracy of video sync (and, as they land, phases and friction fits) over a matrix drawn
// at random from a printed seed: `bench_accuracy [--seed N] [--sync-cases N] [--small]
// [--relax-cases N] [--case N] [--phase-case N] [--phase-thickness-mm LO:HI] [--keep DIR] [--rig-friction-details FILE] [--rig-friction-true-phases]`
// (--case, --phase-case: only sync or phase case N of the draw, to look at one again; --keep leaves each case's run,
// video and suggested labels there; --rig-friction-true-phases gives the rig's friction fits the simulator's own phases,
// to see what perfect labels would change; --phase-thickness-mm draws each phase case's slab thickness, 30 mm
// without it). Prints one line per case and the summary against issue 13's targets.
#include "video/accuracy_matrix.h"
#include "video/phase_matrix.h"
#include "video/relax_matrix.h"
#include "core/rig_friction_matrix.h"

#include "core/sync.h"

#include <QCoreApplication>
#include <QDir>
#include <QMap>
#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

using namespace nb::accuracy;

namespace {

// Phase agreement per case, without and with the video (tests/video/phase_matrix.h). Its own
// generator (from the same seed), so that its draw does not depend on the other sections'.
// `thickness_mm`: when set, each slab's thickness is drawn from [first, second]
// (drawSlabThicknesses).
void printPhaseMatrix(QTextStream& out, unsigned seed, int count, const QString& root, int onlyCase,
                      std::optional<std::pair<double, double>> thickness_mm)
{
    out << "\n== phases: simulated friction runs, truth hidden from the suggestion (agreement per sample, without / with video)\n";
    std::mt19937 rng(seed ^ 0x9e3779b9u);
    std::vector<double> without, with;
    int failed = 0, unread = 0, placedByPicture = 0;
    std::vector<PhaseMatrixCase> cases = drawPhaseMatrix(rng, count, false);
    if (thickness_mm)
        drawSlabThicknesses(cases, seed, thickness_mm->first, thickness_mm->second);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (onlyCase >= 0 && int(i) != onlyCase)
            continue;  // the same draw: one case of it again
        const PhaseMatrixOutcome o = runPhaseMatrixCase(cases[i], QStringLiteral(NB_EXECUTABLE), QDir(root).filePath(QStringLiteral("phase%1").arg(i)));
        if (!o.ok) {
            ++failed;
            out << QStringLiteral("%1  FAILED %2: %3\n").arg(i, 3).arg(cases[i].describe(), o.problem);
            out.flush();
            continue;
        }
        without.push_back(100 * o.withoutVideo);
        with.push_back(100 * o.withVideo);
        unread += !o.videoUsed;
        placedByPicture += o.fromPicture > 0.0;
        out << QStringLiteral("%1  without %2 %  with %3 %  picture placed %4 %%5  %6\n")
                   .arg(i, 3)
                   .arg(100 * o.withoutVideo, 5, 'f', 1)
                   .arg(100 * o.withVideo, 5, 'f', 1)
                   .arg(100 * o.fromPicture, 3, 'f', 0)
                   .arg(o.videoUsed ? QString() : QStringLiteral(" (video unread: ") + o.videoSource + QStringLiteral(")"))
                   .arg(cases[i].describe());
        out.flush();
    }
    out << QStringLiteral("phases: %1 runs (%2 failed, %3 videos unread): without video p50 %4 %, min %5 %; with video p50 %6 %, min %7 %\n")
               .arg(without.size() + std::size_t(failed)).arg(failed).arg(unread)
               .arg(quantile(without, 0.5), 0, 'f', 1).arg(quantile(without, 0.0), 0, 'f', 1)
               .arg(quantile(with, 0.5), 0, 'f', 1).arg(quantile(with, 0.0), 0, 'f', 1);
    // How much of "with video" the picture decided: where it is judged too unclear (or agrees
    // with the force everywhere) the figure is the force's own.
    out << QStringLiteral("phases: the picture placed phase labels in %1 of %2 runs; elsewhere it was judged too unclear "
                          "and force and position decided\n")
               .arg(placedByPicture).arg(without.size());
    out << "targets: >= 80 % without video and >= 90 % with video, in every case\n";
}

// Relaxation read off the imaging video of insertion runs (tests/video/relax_matrix.h), its own
// generator so that the other draws stay as they were.
void printRelaxMatrix(QTextStream& out, unsigned seed, int count, bool small, const QString& root)
{
    if (count <= 0)
        return;
    out << "\n== relaxation: simulated insertions, suggested from the surface in the video (truth hidden), error in frames\n";
    std::mt19937 rng(seed ^ 0x5bd1e995u);
    std::vector<double> errors;
    int failed = 0, none = 0, withoutVideo = 0;
    const std::vector<RelaxMatrixCase> cases = drawRelaxMatrix(rng, count, small);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const RelaxMatrixOutcome o = runRelaxMatrixCase(cases[i], QStringLiteral(NB_EXECUTABLE), QDir(root).filePath(QStringLiteral("relax%1").arg(i)));
        if (!o.ok) {
            ++failed;
            out << QStringLiteral("%1  FAILED %2: %3\n").arg(i, 3).arg(cases[i].describe(), o.problem);
            out.flush();
            continue;
        }
        withoutVideo += o.suggestedWithoutVideo;
        if (o.suggested)
            errors.push_back(std::abs(o.errorFrames));
        else
            ++none;
        out << QStringLiteral("%1  %2  true %3 s  %4  %5\n")
                   .arg(i, 3)
                   .arg(o.suggested ? QStringLiteral("err %1 fr").arg(o.errorFrames, 6, 'f', 2) : QStringLiteral("none       "))
                   .arg(o.truth_s, 0, 'f', 3)
                   .arg(cases[i].describe(), o.why);
        out.flush();
    }
    const int made = int(cases.size()) - failed;
    out << QStringLiteral("relaxation: %1 runs (%2 failed to run): suggested in %3 % (%4 none); |error| p50 %5, p95 %6, max %7 frames; "
                          "suggested without video: %8\n")
               .arg(cases.size()).arg(failed)
               .arg(made ? 100.0 * errors.size() / made : 0.0, 0, 'f', 1).arg(none)
               .arg(quantile(errors, 0.5), 0, 'f', 2).arg(quantile(errors, 0.95), 0, 'f', 2).arg(quantile(errors, 1.0), 0, 'f', 2)
               .arg(withoutVideo);
}

double relativeError(double got, double want) { return std::fabs(got - want) / std::fabs(want); }

// The simulated rig's own friction runs (its own generator, so the draws above stay as they were).
// One row per run and direction: the fit's own figures beside its errors against the slab's truth,
// to see which of them tell a wrong C or b (--rig-friction-details FILE).
void writeRigFrictionDetails(QTextStream& t, unsigned seed, std::size_t set, const nb::accuracy::RigFrictionSet& s,
                             const nb::accuracy::RigFrictionOutcome& o)
{
    for (std::size_t k = 0; k < o.fits.size(); ++k) {
        const nb::FrictionFit& f = o.fits[k];
        for (int d : {0, 1}) {
            const bool p = d == 0;
            const char* c = p ? "Cp" : "Cn";
            const char* b = p ? "bp" : "bn";
            t << seed << '\t' << set << '\t' << k << '\t' << (p ? "+" : "-") << '\t' << s.tissue << '\t'
              << s.frequencies_hz[k] << '\t' << s.amplitude_mm << '\t' << s.stickBand_mm_s << '\t' << s.plateGap_mm << '\t'
              << s.forceNoise_N << '\t'
              << relativeError(p ? f.perLength.Cp_N_per_m : f.perLength.Cn_N_per_m, p ? o.truth.Cp_N_per_m : o.truth.Cn_N_per_m) << '\t'
              << relativeError(p ? f.perLength.bp_Ns_per_m2 : f.perLength.bn_Ns_per_m2, p ? o.truth.bp_Ns_per_m2 : o.truth.bn_Ns_per_m2) << '\t'
              << (f.notPhysicalValues.contains(QLatin1String(c)) || f.notPhysicalValues.contains(QLatin1String(b))) << '\t'
              << (p ? f.slidingFromP_m_s : f.slidingFromN_m_s) << '\t' << (p ? f.slidingToP_m_s : f.slidingToN_m_s) << '\t'
              << (p ? f.springBackP_s : f.springBackN_s) << '\t' << (p ? f.residualToNoiseP : f.residualToNoiseN) << '\t'
              << (p ? f.seBp_Ns_per_m / f.model.bp_Ns_per_m : f.seBn_Ns_per_m / f.model.bn_Ns_per_m) << '\t'
              << (p ? f.seCp_N / f.model.Cp_N : f.seCn_N / f.model.Cn_N) << '\t'
              << f.band_m_s << '\t' << f.bandSlowingDown_m_s << '\t' << (p ? f.positiveSamples : f.negativeSamples) << '\t'
              << (p ? f.model.Cp_N : f.model.Cn_N) << '\t' << (p ? f.model.bp_Ns_per_m : f.model.bn_Ns_per_m) << '\t'
              << (p ? f.bendShiftCp : f.bendShiftCn) << '\t';
            const std::optional<nb::PeakPoint>& peak = p ? f.peaks.positive : f.peaks.negative;
            t << (peak ? (peak->settled ? "settled" : "unsettled") : "none") << '\t' << o.runDeparts[k] << '\n';
        }
    }
}

void printRigFriction(QTextStream& out, unsigned seed, int count, const QString& root, QTextStream* details, bool truePhases)
{
    out << (truePhases ? "\n== friction on the simulated rig: one slab at three frequencies, with the simulator's own phases (perfect labels)\n"
                       : "\n== friction on the simulated rig: one slab at three frequencies, force and position only\n");
    std::mt19937 rng(seed + 1u);
    std::vector<double> runC, runB, lineC, lineB;
    int failed = 0, offRuns = 0, offFlagged = 0, noLine = 0;
    // Which slab and direction the misses nobody flagged come from (a pattern there is a limit
    // of the method, scattered misses a defect).
    QMap<QString, int> unflaggedBy;
    const auto sets = nb::accuracy::drawRigFrictionSets(rng, count);
    for (std::size_t i = 0; i < sets.size(); ++i) {
        const auto o = nb::accuracy::runRigFrictionSet(sets[i], QStringLiteral(NB_EXECUTABLE), QDir(root).filePath(QStringLiteral("rigfriction%1").arg(i)),
                                                       truePhases);
        if (!o.ok) {
            ++failed;
            out << QStringLiteral("  %1  FAILED %2: %3\n").arg(i, 2).arg(sets[i].describe(), o.problem);
            continue;
        }
        if (details)
            writeRigFrictionDetails(*details, seed, i, sets[i], o);
        QString runs;
        for (std::size_t k = 0; k < 3; ++k) {
            runC.push_back(100 * o.runErrC[k]);
            runB.push_back(100 * o.runErrB[k]);
            if (o.runErrC[k] > 0.05 || o.runErrB[k] > 0.15) {
                ++offRuns;
                offFlagged += o.runDeparts[k] || o.runFlagged[k];
                if (!o.runDeparts[k] && !o.runFlagged[k]) {
                    const nb::KarnoppPerLength& f = o.fits[k].perLength;
                    const bool plus = relativeError(f.Cp_N_per_m, o.truth.Cp_N_per_m) > 0.05 || relativeError(f.bp_Ns_per_m2, o.truth.bp_Ns_per_m2) > 0.15;
                    const bool minus = relativeError(f.Cn_N_per_m, o.truth.Cn_N_per_m) > 0.05 || relativeError(f.bn_Ns_per_m2, o.truth.bn_Ns_per_m2) > 0.15;
                    ++unflaggedBy[sets[i].tissue + (plus && minus ? QStringLiteral(" +/-") : plus ? QStringLiteral(" +") : QStringLiteral(" -"))];
                }
            }
            runs += QStringLiteral(" %1/%2%3%4").arg(100 * o.runErrC[k], 0, 'f', 1).arg(100 * o.runErrB[k], 0, 'f', 1)
                        .arg(o.runDeparts[k] ? QStringLiteral("*") : QString(), o.runFlagged[k] ? QStringLiteral("!") : QString());
        }
        if (o.line) {
            lineC.push_back(100 * o.lineErrC);
            lineB.push_back(100 * o.lineErrB);
        } else {
            ++noLine;
        }
        out << QStringLiteral("  %1  line C %2 % b %3 %   runs C/b %:%4   %5\n")
                   .arg(i, 2)
                   .arg(o.line ? QString::number(100 * o.lineErrC, 'f', 2) : QStringLiteral("-"))
                   .arg(o.line ? QString::number(100 * o.lineErrB, 'f', 2) : QStringLiteral("-"))
                   .arg(runs, sets[i].describe());
    }
    out << QStringLiteral("rig friction: %1 sets (%2 failed, %3 without a line): peak-speed line C error p50 %4 %, max %5 %; "
                          "b error p50 %6 %, max %7 %\n")
               .arg(sets.size()).arg(failed).arg(noLine)
               .arg(quantile(lineC, 0.5), 0, 'f', 2).arg(quantile(lineC, 1.0), 0, 'f', 2)
               .arg(quantile(lineB, 0.5), 0, 'f', 2).arg(quantile(lineB, 1.0), 0, 'f', 2);
    out << QStringLiteral("  single runs: C error p50 %1 %, max %2 %; b error p50 %3 %, max %4 %; %5 runs off by more than 5 % in C "
                          "or 15 % in b, %6 of them flagged (* departs from the line, ! not physical or not determined)\n")
               .arg(quantile(runC, 0.5), 0, 'f', 2).arg(quantile(runC, 1.0), 0, 'f', 2)
               .arg(quantile(runB, 0.5), 0, 'f', 2).arg(quantile(runB, 1.0), 0, 'f', 2)
               .arg(offRuns).arg(offFlagged);
    if (!unflaggedBy.isEmpty()) {
        QStringList by;
        for (auto it = unflaggedBy.cbegin(); it != unflaggedBy.cend(); ++it)
            by << QStringLiteral("%1 in %2").arg(it.value()).arg(it.key());
        out << QStringLiteral("  not flagged, by slab and direction of motion: %1\n").arg(by.join(QStringLiteral(", ")));
    }
    out << "targets: C within 5 %, b within 15 %\n";
}

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const QStringList a = app.arguments();
    unsigned seed = unsigned(std::chrono::system_clock::now().time_since_epoch().count() % 1000000);
    int syncCases = 20, frictionCases = 24, phaseCases = 24, rigFrictionSets = 8, relaxCases = 12;
    bool small = false, rigTruePhases = false;
    int onlyCase = -1, onlyPhaseCase = -1;
    std::optional<std::pair<double, double>> phaseThickness;
    QString keep, details;
    for (int i = 1; i < a.size(); ++i) {
        if (a[i] == QLatin1String("--seed") && i + 1 < a.size())
            seed = a[++i].toUInt();
        else if (a[i] == QLatin1String("--sync-cases") && i + 1 < a.size())
            syncCases = a[++i].toInt();
        else if (a[i] == QLatin1String("--friction-cases") && i + 1 < a.size())
            frictionCases = a[++i].toInt();
        else if (a[i] == QLatin1String("--rig-friction-sets") && i + 1 < a.size())
            rigFrictionSets = a[++i].toInt();
        else if (a[i] == QLatin1String("--phase-cases") && i + 1 < a.size())
            phaseCases = a[++i].toInt();
        else if (a[i] == QLatin1String("--relax-cases") && i + 1 < a.size())
            relaxCases = a[++i].toInt();
        else if (a[i] == QLatin1String("--case") && i + 1 < a.size())
            onlyCase = a[++i].toInt();
        else if (a[i] == QLatin1String("--phase-case") && i + 1 < a.size())
            onlyPhaseCase = a[++i].toInt();
        else if (a[i] == QLatin1String("--phase-thickness-mm") && i + 1 < a.size()) {
            const QStringList range = a[++i].split(QLatin1Char(':'));
            bool okLo = false, okHi = false;
            const double lo = range.value(0).toDouble(&okLo), hi = range.value(1).toDouble(&okHi);
            if (range.size() != 2 || !okLo || !okHi || !(lo > 0.0) || !(hi >= lo)) {
                std::fprintf(stderr, "bench_accuracy: --phase-thickness-mm wants LO:HI in mm, e.g. 10:30\n");
                return 2;
            }
            phaseThickness = std::pair{lo, hi};
        } else if (a[i] == QLatin1String("--rig-friction-true-phases"))
            rigTruePhases = true;
        else if (a[i] == QLatin1String("--small"))
            small = true;
        else if (a[i] == QLatin1String("--keep") && i + 1 < a.size())
            keep = a[++i];
        else if (a[i] == QLatin1String("--rig-friction-details") && i + 1 < a.size())
            details = a[++i];
        else {
            std::fprintf(stderr, "usage: bench_accuracy [--seed N] [--sync-cases N] [--friction-cases N] [--rig-friction-sets N] [--phase-cases N] [--relax-cases N] [--small] [--case N] [--phase-case N] [--phase-thickness-mm LO:HI] [--keep DIR] [--rig-friction-details FILE] [--rig-friction-true-phases]\n");
            return 2;
        }
    }
    QTextStream out(stdout);
    out << "bench_accuracy: seed " << seed << " (rerun with --seed " << seed << ")\n";
    std::mt19937 rng(seed);
    QTemporaryDir tmp;
    const QString root = keep.isEmpty() ? tmp.path() : keep;

    out << "\n== sync: error over the recording in frames (accept threshold " << nb::kSyncAcceptConfidence << ")\n";
    std::vector<double> errors;
    int within1 = 0, within2 = 0, failed = 0, honestMisses = 0, misses = 0;
    const std::vector<SyncCase> cases = drawSyncCases(rng, syncCases, small);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (onlyCase >= 0 && int(i) != onlyCase)
            continue;  // the draw stays the same: one case of it again
        const SyncOutcome o = runSyncCase(cases[i], QStringLiteral(NB_EXECUTABLE), QDir(root).filePath(QStringLiteral("sync%1").arg(i)));
        if (!o.ok) {
            ++failed;
            out << QStringLiteral("%1  FAILED %2: %3\n").arg(i, 3).arg(cases[i].describe(), o.problem);
            out.flush();
            continue;
        }
        errors.push_back(o.errorFrames);
        within1 += o.errorFrames <= 1.0;
        within2 += o.errorFrames <= 2.0;
        if (o.errorFrames > 1.0) {
            ++misses;
            honestMisses += !o.acceptable;
        }
        out << QStringLiteral("%1  err %2 fr  conf %3%4  %5 s  %6  (%7 % of frames without a tip)\n")
                   .arg(i, 3)
                   .arg(o.errorFrames, 6, 'f', 2)
                   .arg(o.confidence, 4, 'f', 2)
                   .arg(o.errorFrames > 1.0 ? (o.acceptable ? QStringLiteral(" MISS!") : QStringLiteral(" miss ")) : QStringLiteral("      "))
                   .arg(o.seconds, 5, 'f', 1)
                   .arg(cases[i].describe())
                   .arg(100 * o.maskedFraction, 0, 'f', 1);
        out.flush();
    }
    // A case the pipeline could not finish counts as a miss (with no offset to accept).
    const int n = int(errors.size()) + failed;
    misses += failed;
    honestMisses += failed;
    out << QStringLiteral("sync: %1 cases (%2 failed to run, counted as misses): p50 %3, p95 %4, max %5 frames; within 1 frame %6 %, within 2 %7 %; "
                          "misses %8, of which below the accept threshold %9\n")
               .arg(cases.size()).arg(failed)
               .arg(quantile(errors, 0.5), 0, 'f', 2).arg(quantile(errors, 0.95), 0, 'f', 2).arg(quantile(errors, 1.0), 0, 'f', 2)
               .arg(n ? 100.0 * within1 / n : 0.0, 0, 'f', 1).arg(n ? 100.0 * within2 / n : 0.0, 0, 'f', 1)
               .arg(misses).arg(honestMisses);
    out << "targets: within 1 frame >= 95 %, within 2 frames 100 %, every miss below the threshold\n";

    printPhaseMatrix(out, seed, phaseCases, root, onlyPhaseCase, phaseThickness);

    out << "\n== friction: synthetic Karnopp runs, band found by the fit (no phases given)\n";
    std::vector<double> errC, errB;
    int frictionFailed = 0, flagged = 0;
    for (const FrictionCase& c : drawFrictionCases(rng, frictionCases)) {
        const FrictionOutcome o = runFrictionCase(c);
        if (!o.ok) {
            ++frictionFailed;
            out << QStringLiteral("  FAILED %1 Hz, band ±%2 mm/s: %3\n").arg(c.frequency_hz, 0, 'f', 2).arg(c.band_mm_s, 0, 'f', 2).arg(o.problem);
            continue;
        }
        errC.push_back(100 * o.errC);
        errB.push_back(100 * o.errB);
        flagged += o.flagged;
        out << QStringLiteral("  %1 Hz, band ±%2 mm/s: found ±%3, C err %4 %, b err %5 %%6\n")
                   .arg(c.frequency_hz, 0, 'f', 2).arg(c.band_mm_s, 0, 'f', 2).arg(o.bandFound_mm_s, 0, 'f', 2)
                   .arg(100 * o.errC, 0, 'f', 2).arg(100 * o.errB, 0, 'f', 2).arg(o.flagged ? QStringLiteral(" (flagged)") : QString());
    }
    out << QStringLiteral("friction: %1 runs (%2 failed, %3 flagged): C error p50 %4 %, max %5 %; b error p50 %6 %, max %7 %\n")
               .arg(errC.size() + frictionFailed).arg(frictionFailed).arg(flagged)
               .arg(quantile(errC, 0.5), 0, 'f', 2).arg(quantile(errC, 1.0), 0, 'f', 2)
               .arg(quantile(errB, 0.5), 0, 'f', 2).arg(quantile(errB, 1.0), 0, 'f', 2);
    out << "targets: C within 5 %, b within 15 %\n";

    QFile detailsFile(details);
    std::optional<QTextStream> detailsOut;
    if (!details.isEmpty()) {
        if (!detailsFile.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text)) {
            std::fprintf(stderr, "bench_accuracy: cannot write %s: %s\n", qPrintable(details), qPrintable(detailsFile.errorString()));
            return 1;
        }
        detailsOut.emplace(&detailsFile);
        if (detailsFile.size() == 0)
            *detailsOut << "seed\tset\trun\tdirection\ttissue\tfrequency_hz\tamplitude_mm\tstick_band_mm_s\tplate_gap_mm\tforce_noise_N\t"
                           "C_error\tb_error\tflagged\tsliding_from_m_s\tsliding_to_m_s\tspring_back_s\tresidual_to_noise\tse_b_over_b\t"
                           "se_C_over_C\tband_m_s\tband_slowing_down_m_s\tsamples\tC_N\tb_Ns_per_m\tC_shift_if_bent\t"
                           "peak\tdeparts_from_line\n";
    }
    printRigFriction(out, seed, rigFrictionSets, root, detailsOut ? &*detailsOut : nullptr, rigTruePhases);
    printRelaxMatrix(out, seed, relaxCases, small, root);
    return 0;
}
