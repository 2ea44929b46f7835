#pragma once
// The friction-phase part of issue 13's accuracy matrix: runs of the simulated friction
// platform (`needlebench simulate`, so the public flags are what is exercised) drawn at random
// over frequency, amplitude, stick band, plate gap, tissue and force noise; the imaging view
// of each rendered, given a look (noise and low contrast, burnt-in clock, turned picture,
// blurred texture, dropped and repeated frames) and encoded (MJPEG, H.264 with B-frames, DV).
// The suggestion sees neither the simulator's phase column nor its tissue position; its
// phases are compared sample by sample with the simulator's. Shared by bench/bench_accuracy
// (the table) and tests/video/test_phase_accuracy (the targets, on a smaller draw).

#include "accuracy_matrix.h"

#include <QString>

#include <random>
#include <vector>

namespace nb::accuracy {

struct PhaseMatrixCase {
    double frequency_hz = 0.5;
    double amplitude_mm = 10.0;
    double stickBand_mm_s = 2.5;   // ± of the zero band
    double plateGap_mm = 1.5;
    double forceNoise_N = 0.0012;
    double thickness_mm = 30.0;    // the slab (not drawn by drawPhaseMatrix: the simulator's default)
    QString tissue = QStringLiteral("liver7");
    int cycles = 3;
    Look look = Look::Rendered;
    Codec codec = Codec::Mjpeg;
    int width = 640, height = 480;
    double offset_s = 1.0;         // the video starts this long before the recording
    double drift = 0.0;            // the video clock's rate error
    unsigned seed = 1;

    QString describe() const;
};

struct PhaseMatrixOutcome {
    bool ok = false;
    QString problem;
    double withoutVideo = 0.0;     // fraction of samples whose suggested phase is the true one
    double withVideo = 0.0;
    bool videoUsed = false;        // false: the picture could not be read (withVideo is force only)
    QString videoSource;           // what the suggestion says it came from
    // Of the suggested phase labels, the fraction the picture placed (their comment says they
    // came from the tissue's motion); 0 where it was judged too unclear and the force decided.
    double fromPicture = 0.0;
};

// `small`: smaller pictures (for the ctest).
std::vector<PhaseMatrixCase> drawPhaseMatrix(std::mt19937& rng, int count, bool small);
// Each case's slab thickness drawn from [lo_mm, hi_mm] with a generator of its own (from the
// matrix's seed), so that the rest of every case is the draw without it
// (bench_accuracy --phase-thickness-mm).
void drawSlabThicknesses(std::vector<PhaseMatrixCase>& cases, unsigned seed, double lo_mm, double hi_mm);
PhaseMatrixOutcome runPhaseMatrixCase(const PhaseMatrixCase& c, const QString& executable, const QString& workDir);

}  // namespace nb::accuracy

namespace nb::accuracy {
// One of the looks above applied to a rendered picture (8-bit grey), noise seeded by `seed`
// and the frame (for the other matrices that draw the same looks).
void applyMatrixLook(Look look, unsigned seed, int frameNumber, double videoTime_s, cv::Mat& m);
QString matrixLookName(Look look);
}  // namespace nb::accuracy
