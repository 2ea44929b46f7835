#pragma once
// Checks shared by the phase accuracy tests: a case of bench_accuracy's phase matrix, drawn
// again from its seed and index, run with its imaging video against issue 13's 90 %.
#include "support/case_share.h"
#include "video/phase_matrix.h"
#include "video/video_fixtures.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <optional>
#include <random>

namespace nb::accuracy {

// Case `index` of bench_accuracy's phase matrix for `seed`, drawn as the bench draws it
// (with `slabs_mm`, as --phase-thickness-mm LO:HI draws it), into `c`; false when it is no
// longer the case a test describes (the draw has changed).
inline bool drawnCase(unsigned seed, int index, const std::function<bool(const PhaseMatrixCase&)>& stillTheCase, PhaseMatrixCase& c,
                      std::optional<std::pair<double, double>> slabs_mm = {})
{
    std::mt19937 rng(seed ^ 0x9e3779b9u);
    std::vector<PhaseMatrixCase> cases = drawPhaseMatrix(rng, 24, false);
    if (cases.size() != 24)
        return false;
    if (slabs_mm)
        drawSlabThicknesses(cases, seed, slabs_mm->first, slabs_mm->second);
    c = cases[std::size_t(index)];
    return stillTheCase(c);
}

// Runs a drawn case with its video: the labels' source must say `source` (the video decided,
// or was left aside), and agreement reach issue 13's 90 %, and be no more than
// `belowForceAtMost` under the force's alone.
inline void checkWithVideo(const PhaseMatrixCase& c, const QString& source = QStringLiteral("suggested from the tissue's motion"),
                           double belowForceAtMost = 1.0)
{
    QTemporaryDir dir;
    const PhaseMatrixOutcome o = runPhaseMatrixCase(c, QStringLiteral(NB_EXECUTABLE), dir.path());
    QVERIFY2(o.ok, qPrintable(o.problem));
    qInfo("%s: without video %.1f %%, with video %.1f %% (%s)", qPrintable(c.describe()), 100 * o.withoutVideo, 100 * o.withVideo,
          qPrintable(o.videoSource));
    QVERIFY2(o.videoSource.contains(source), qPrintable(o.videoSource));
    QVERIFY2(o.withVideo >= std::max(0.9, o.withoutVideo - belowForceAtMost),
             qPrintable(QStringLiteral("with video %1, without %2").arg(o.withVideo).arg(o.withoutVideo)));
}

// Case `index` of the draw for `seed`, checked with its video. The videos are encoded with the
// ffmpeg tool, which the README's test command installs; without it there is nothing to check.
inline void checkDrawnCase(unsigned seed, int index, const std::function<bool(const PhaseMatrixCase&)>& stillTheCase,
                           const QString& source = QStringLiteral("suggested from the tissue's motion"),
                           std::optional<std::pair<double, double>> slabs_mm = {}, double belowForceAtMost = 1.0)
{
    if (!nb::test::haveFfmpeg())
        QSKIP("the ffmpeg tool is needed to encode the videos");
    PhaseMatrixCase c;
    QVERIFY2(drawnCase(seed, index, stillTheCase, c, slabs_mm), qPrintable(c.describe()));
    NB_SKIP_OUTSIDE_CASE_SHARE();
    checkWithVideo(c, source, belowForceAtMost);
}

// The current row's drawn case (columns `seed` and `index`), checked with its video.
inline void checkDrawnRow(const std::function<bool(const PhaseMatrixCase&)>& stillTheCase,
                          const QString& source = QStringLiteral("suggested from the tissue's motion"),
                          std::optional<std::pair<double, double>> slabs_mm = {})
{
    QFETCH(unsigned, seed);
    QFETCH(int, index);
    checkDrawnCase(seed, index, stillTheCase, source, slabs_mm);
}

}  // namespace nb::accuracy
