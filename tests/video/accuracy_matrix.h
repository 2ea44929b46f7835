#pragma once
// The accuracy matrix of issue 13: runs from the simulated rig (`needlebench simulate`),
// videos of them in many looks and codecs with a known offset and drift, and what the
// sync pipeline, the phase suggestion and the friction fit make of them. Every case is
// drawn at random from a printed seed; nothing here knows the answer it is checked against
// except the comparison at the end. Shared by bench/bench_accuracy (the table) and
// tests/video/test_accuracy (the targets, on a smaller draw).

#include <QString>
#include <QStringList>

#include <functional>
#include <random>
#include <vector>

namespace cv {
class Mat;
}

namespace nb::accuracy {

// The matrix draws the first seven; Speckle (a faint thin needle on grainy tissue, the grain
// as strong as the needle) is asked for by name, so that adding it left every drawn case alone.
enum class Look { Rendered, Plain, NoisyLowContrast, Overlays, Angle30, Angle90, VariableRate, Speckle };
enum class Codec { Mjpeg, H264, Dv };

QString lookName(Look l);
QString codecName(Codec c);
// The ffmpeg encoder arguments of a codec.
QStringList codecArguments(Codec c);
// Grey frames encoded at a constant rate with the ffmpeg tool (DV at NTSC's 30000/1001);
// returns what went wrong, empty when the file is written.
QString encodeConstantRate(const std::vector<cv::Mat>& frames, Codec codec, double fps, const QString& path);

struct SyncCase {
    bool sine = true;
    double frequency_hz = 0.5;    // sine
    double amplitude_mm = 8.0;    // sine
    int cycles = 3;               // sine
    double velocity_mm_s = 4.0;   // linear
    double depth_mm = 30.0;       // linear
    double offset_s = 0.0;        // true video time at recording time 0
    double drift = 0.0;           // true video clock rate error
    Look look = Look::Plain;
    Codec codec = Codec::Mjpeg;
    int width = 640, height = 480;
    unsigned seed = 1;
    // VariableRate: the clock the file's timestamps are written on. A writer with a coarse
    // clock rounds them (frames a frame apart may land 1 ms apart); the truth stays the
    // time each picture was taken.
    int timestampClock_hz = 1000;
    // The clock and frame counter centred on the needle's line, the clock on the shaft behind
    // the tip's travel and the counter beyond it, in any look (the matrix draws them at fixed
    // places in the Overlays look only, crossed by the line at some angles).
    bool overlaysOnNeedleLine = false;

    QString describe() const;
};

struct SyncOutcome {
    SyncCase c;
    bool ok = false;              // false: the pipeline threw (problem says why)
    QString problem;
    double errorFrames = 0.0;     // largest mapping error over the recording, in frames
    double confidence = 0.0;
    bool acceptable = false;
    double seconds = 0.0;         // time the pipeline took (index, track, fit)
    double maskedFraction = 0.0;  // frames of the chosen needle line without a tip
};

// Draws `count` cases. `small` shrinks videos and runs (for the ctest).
std::vector<SyncCase> drawSyncCases(std::mt19937& rng, int count, bool small);

// Simulates, renders, encodes, synchronises one case inside `workDir`. `executable` is the
// needlebench program (for `simulate`).
SyncOutcome runSyncCase(const SyncCase& c, const QString& executable, const QString& workDir);

struct FrictionCase {
    double frequency_hz = 0.5;
    double band_mm_s = 2.5;       // the true stick band (half-width)
    double amplitude_mm = 10.0;
    unsigned seed = 1;
};

struct FrictionOutcome {
    FrictionCase c;
    bool ok = false;
    QString problem;
    double errC = 0.0, errB = 0.0;  // worst relative error of C (Cp, Cn) and b (bp, bn)
    double bandFound_mm_s = 0.0;
    bool flagged = false;           // the fit flagged a value as not physical
};

std::vector<FrictionCase> drawFrictionCases(std::mt19937& rng, int count);
FrictionOutcome runFrictionCase(const FrictionCase& c);

// p-quantile (0..1) of v (empty: 0).
double quantile(std::vector<double> v, double p);

}  // namespace nb::accuracy
