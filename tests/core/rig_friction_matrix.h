#pragma once
// Friction fits on the simulated rig's own runs (`needlebench simulate --protocol friction`,
// so the public flags are exercised), not on runs generated from the fitted model: the slab
// sits against compliant plates, is carried in phase a, meets the plate in b1/b2 and springs
// back as the needle slows. Each set is one slab at three frequencies drawn around the thesis's
// 0.2 / 0.5 / 0.8 Hz, over tissue, stick band, plate gap, force noise and amplitude. The fit
// sees force and position only (the simulator's phase and tissue columns are removed).

#include "core/friction_fit.h"

#include <QString>

#include <array>
#include <random>
#include <vector>

namespace nb::accuracy {

struct RigFrictionSet {
    QString tissue = QStringLiteral("liver7");
    double stickBand_mm_s = 2.5;    // ± of the zero band
    double plateGap_mm = 1.5;
    double forceNoise_N = 0.0012;
    double amplitude_mm = 10.0;
    std::array<double, 3> frequencies_hz{0.2, 0.5, 0.8};
    int cycles = 7;
    unsigned seed = 1;

    QString describe() const;
};

struct RigFrictionOutcome {
    bool ok = false;
    QString problem;
    // Largest relative error of the two directions (fractions), per run and for the line.
    std::array<double, 3> runErrC{}, runErrB{};
    std::array<bool, 3> runDeparts{};   // the fit said this run's C departs from the line
    std::array<bool, 3> runFlagged{};   // the fit flagged its C or b (not physical, not determined)
    bool line = false;
    double lineErrC = 0.0, lineErrB = 0.0;
    std::vector<FrictionFit> fits;      // the three runs' fits, for a closer look
    KarnoppPerLength truth;             // the slab's own values, per metre
};

std::vector<RigFrictionSet> drawRigFrictionSets(std::mt19937& rng, int count);
// withTruePhases: the fit is given the simulator's own phases (C and b from phase c as the thesis
// labelled it from the video), to see what perfect labels change; otherwise force and position only.
RigFrictionOutcome runRigFrictionSet(const RigFrictionSet& set, const QString& executable, const QString& workDir,
                                     bool withTruePhases = false);

}  // namespace nb::accuracy
