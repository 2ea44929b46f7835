#pragma once
// Relaxation read off the imaging video (issue 13), over a matrix drawn at random: insertion
// runs of the simulated organ (`needlebench simulate --protocol stiffness`) over tissue,
// velocity and seed; their imaging view rendered, given one of the accuracy matrix's looks
// (tests/video/phase_matrix.h) and encoded (MJPEG or H.264 with B-frames) on a video clock
// with an offset and drift. The suggestion sees neither the simulator's tissue position nor
// its phase; its relaxation is compared with the simulator's `relaxed_s`. Shared by
// bench/bench_accuracy (--relax-cases) and tests/video/test_relax_accuracy.

#include "accuracy_matrix.h"

#include <QString>

#include <random>
#include <vector>

namespace nb::accuracy {

struct RelaxMatrixCase {
    QString tissue = QStringLiteral("liver1");
    double velocity_mm_s = 4.0;
    Look look = Look::Rendered;
    Codec codec = Codec::Mjpeg;
    int width = 640, height = 480;
    double fps = 30000.0 / 1001.0;
    double offset_s = 1.0;   // the video starts this long before the recording
    double drift = 0.0;
    unsigned seed = 1;

    QString describe() const;
};

struct RelaxMatrixOutcome {
    bool ok = false;              // false: the case could not be made (problem says why)
    QString problem;
    bool suggested = false;       // a relaxation was suggested from the video
    QString why;                  // its comment, or why none was
    double errorFrames = 0.0;     // suggested minus true, in the video's frames
    double truth_s = 0.0, suggested_s = 0.0;
    bool suggestedWithoutVideo = false;  // must stay false: the force cannot show it
};

std::vector<RelaxMatrixCase> drawRelaxMatrix(std::mt19937& rng, int count, bool small);
RelaxMatrixOutcome runRelaxMatrixCase(const RelaxMatrixCase& c, const QString& executable, const QString& workDir);

}  // namespace nb::accuracy
