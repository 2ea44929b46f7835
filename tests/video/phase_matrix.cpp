#include "phase_matrix.h"

#include "support/truth_columns.h"

#include "core/label_suggest.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "devices/sim/imaging_render.h"
#include "video/frame_index.h"
#include "video/frame_reader.h"
#include "video/labels_from_video.h"
#include "video/video_error.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace nb::accuracy {

namespace {

QString phaseLookName(Look l)
{
    switch (l) {
    case Look::Rendered: return QStringLiteral("rendered imaging view");
    case Look::Plain: return QStringLiteral("blurred, little texture");
    case Look::NoisyLowContrast: return QStringLiteral("heavy noise, low contrast");
    case Look::Overlays: return QStringLiteral("burnt-in clock and frame counter");
    case Look::Angle30: return QStringLiteral("needle at 30 deg");
    case Look::Angle90: return QStringLiteral("picture turned 90 deg");
    case Look::VariableRate: return QStringLiteral("dropped/repeated frames");
    case Look::Speckle: return {};  // a sync look; the phase matrix does not draw it
    }
    return {};
}

QString runSimulate(const QStringList& args, const QString& executable, const QString& out)
{
    QProcess p;
    p.start(executable, QStringList{QStringLiteral("simulate")} << args << QStringLiteral("--out") << out);
    if (!p.waitForFinished(180000) || p.exitCode() != 0)
        return QStringLiteral("simulate failed: ") + QString::fromUtf8(p.readAllStandardError());
    return {};
}

// The look applied to one rendered picture (8-bit grey).
void applyLook(const PhaseMatrixCase& c, int frameNumber, double videoTime_s, cv::Mat& m)
{
    cv::RNG rng(std::uint64_t(c.seed) * 104729u + std::uint64_t(frameNumber));
    auto addNoise = [&](double sigma) {
        cv::Mat f, n(m.size(), CV_32F);
        m.convertTo(f, CV_32F);
        rng.fill(n, cv::RNG::NORMAL, 0.0, sigma);
        f += n;
        f.convertTo(m, CV_8U);
    };
    auto turn = [&](double degrees) {
        const cv::Mat r = cv::getRotationMatrix2D(cv::Point2f(m.cols / 2.0f, m.rows / 2.0f), degrees, 1.0);
        cv::Mat out;
        cv::warpAffine(m, out, r, m.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(35));
        m = out;
    };
    switch (c.look) {
    case Look::Rendered: break;
    case Look::Plain:
        cv::GaussianBlur(m, m, cv::Size(0, 0), 2.5);
        addNoise(3.0);
        break;
    case Look::NoisyLowContrast: {
        cv::Mat f;
        m.convertTo(f, CV_32F, 0.35, 0.65 * 90.0);
        f.convertTo(m, CV_8U);
        addNoise(18.0);
        break;
    }
    case Look::Overlays: {
        const int ms = int(std::lround(videoTime_s * 1000));
        const QString clock = QStringLiteral("%1:%2:%3.%4")
                                  .arg(10 + ms / 3600000, 2, 10, QLatin1Char('0'))
                                  .arg(ms / 60000 % 60, 2, 10, QLatin1Char('0'))
                                  .arg(ms / 1000 % 60, 2, 10, QLatin1Char('0'))
                                  .arg(ms % 1000, 3, 10, QLatin1Char('0'));
        const double scale = m.rows / 480.0;
        cv::putText(m, clock.toStdString(), cv::Point(int(10 * scale), int(30 * scale)), cv::FONT_HERSHEY_SIMPLEX, 0.9 * scale,
                    cv::Scalar(250), 2);
        cv::putText(m, QStringLiteral("FRM %1").arg(frameNumber, 6, 10, QLatin1Char('0')).toStdString(),
                    cv::Point(int(m.cols - 200 * scale), int(m.rows - 15 * scale)), cv::FONT_HERSHEY_SIMPLEX, 0.9 * scale,
                    cv::Scalar(250), 2);
        break;
    }
    case Look::Angle30: turn(60.0); addNoise(6.0); break;  // the rendered needle is vertical
    case Look::Angle90: turn(90.0); addNoise(6.0); break;
    case Look::VariableRate: break;  // frames, not pixels: see renderVideo
    case Look::Speckle: break;       // a sync look; the phase matrix does not draw it
    }
}


double agreement(const std::vector<QString>& truth, const Labels& labels, const std::vector<double>& time_s)
{
    const QStringList suggested = phasePerSample(labels, time_s);
    int agree = 0, counted = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (truth[i].isEmpty())
            continue;
        ++counted;
        agree += suggested.value(qsizetype(i)) == truth[i];
    }
    return counted ? double(agree) / counted : 0.0;
}

}  // namespace

QString PhaseMatrixCase::describe() const
{
    return QStringLiteral("%1 %2 Hz ±%3 mm, band ±%4 mm/s, gap %5 mm, noise %6 N, %7, %8")
        .arg(tissue)
        .arg(frequency_hz, 0, 'f', 2)
        .arg(amplitude_mm, 0, 'f', 1)
        .arg(stickBand_mm_s, 0, 'f', 1)
        .arg(plateGap_mm, 0, 'f', 2)
        .arg(forceNoise_N, 0, 'f', 4)
        .arg(phaseLookName(look), codecName(codec))
        + (thickness_mm != 30.0 ? QStringLiteral(", slab %1 mm").arg(thickness_mm, 0, 'f', 1) : QString());
}

void drawSlabThicknesses(std::vector<PhaseMatrixCase>& cases, unsigned seed, double lo_mm, double hi_mm)
{
    std::mt19937 slabs(seed ^ 0x5bd1e995u);
    std::uniform_real_distribution<double> t(lo_mm, hi_mm);
    for (PhaseMatrixCase& c : cases)
        c.thickness_mm = t(slabs);
}

std::vector<PhaseMatrixCase> drawPhaseMatrix(std::mt19937& rng, int count, bool small)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const QStringList tissues{QStringLiteral("liver1"), QStringLiteral("liver2"), QStringLiteral("liver3"),
                              QStringLiteral("liver5"), QStringLiteral("liver7")};
    std::vector<PhaseMatrixCase> out;
    for (int i = 0; i < count; ++i) {
        PhaseMatrixCase c;
        c.frequency_hz = 0.1 + 0.9 * u(rng);
        c.amplitude_mm = 4.0 + 6.0 * u(rng);
        c.stickBand_mm_s = 1.0 + 5.0 * u(rng);
        c.plateGap_mm = 0.5 + 2.5 * u(rng);
        c.forceNoise_N = 0.0005 * std::pow(20.0, u(rng));  // 0.5 to 10 mN, log-uniform
        c.tissue = tissues[int(rng() % tissues.size())];
        // At least three half-cycles, at most about 12 s of video.
        c.cycles = std::clamp(int(std::floor(12.0 * c.frequency_hz)), 2, 4);
        c.look = Look(rng() % 7);
        c.codec = Codec(rng() % 3);
        if (c.codec == Codec::Dv) {
            c.width = 720;
            c.height = 480;
        } else if (small) {
            c.width = 480;
            c.height = 360;
        }
        c.offset_s = 2.0 * u(rng);
        c.drift = 0.002 * u(rng);
        c.seed = unsigned(rng() % 100000 + 1);
        out.push_back(c);
    }
    return out;
}

PhaseMatrixOutcome runPhaseMatrixCase(const PhaseMatrixCase& c, const QString& executable, const QString& workDir)
{
    PhaseMatrixOutcome out;
    QDir().mkpath(workDir);
    const QString runPath = QDir(workDir).filePath(QStringLiteral("run.csv"));
    const QStringList args{QStringLiteral("--protocol"), QStringLiteral("friction"), QStringLiteral("--tissue"), c.tissue,
                           QStringLiteral("--frequency-hz"), QString::number(c.frequency_hz, 'f', 4),
                           QStringLiteral("--amplitude-mm"), QString::number(c.amplitude_mm, 'f', 3),
                           QStringLiteral("--stick-band-mm-s"), QString::number(c.stickBand_mm_s, 'f', 3),
                           QStringLiteral("--plate-gap-mm"), QString::number(c.plateGap_mm, 'f', 3),
                           QStringLiteral("--force-noise-n"), QString::number(c.forceNoise_N, 'f', 5),
                           QStringLiteral("--thickness-mm"), QString::number(c.thickness_mm, 'f', 2),
                           QStringLiteral("--cycles"), QString::number(c.cycles), QStringLiteral("--seed"), QString::number(c.seed % 1000 + 1)};
    if (const QString e = runSimulate(args, executable, runPath); !e.isEmpty()) {
        out.problem = e;
        return out;
    }
    try {
        const Run run = readRunFile(runPath).run;
        const auto* truthColumn = run.textColumn(QStringLiteral("phase"));
        if (!truthColumn || !run.numericColumn(QStringLiteral("tissue_position_mm"))) {
            out.problem = QStringLiteral("the simulated run has no phase or tissue column");
            return out;
        }
        const std::vector<QString> truth = *truthColumn;
        const Run blind = nbtest::withoutTruthColumns(run);
        const Labels withoutVideo = suggestLabels(blind);
        out.withoutVideo = agreement(truth, withoutVideo, blind.time_s);
        // Beside the run, to look at a case again (bench_accuracy --keep).
        writeLabelsFile(QDir(workDir).filePath(QStringLiteral("labels_without_video.csv")), withoutVideo);

        // The imaging view of the true motion (the renderer reads the tissue column of the
        // full run), given the case's look, codec and clock.
        const double fps = c.codec == Codec::Dv ? 30000.0 / 1001.0 : ((c.seed % 2) ? 30000.0 / 1001.0 : 25.0);
        devices::sim::ImagingOptions io;
        io.width = c.width;
        io.height = c.height;
        io.fps = fps;
        io.seed = c.seed;
        const devices::sim::ImagingRenderer renderer(run, io);
        const double duration = (1 + c.drift) * (run.time_s.back() + 1.0) + c.offset_s;
        std::vector<cv::Mat> frames;
        std::mt19937 frameRng(c.seed * 31u + 7u);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        cv::Mat last;
        for (int k = 0; k < int(duration * fps); ++k) {
            const double tv = k / fps;
            cv::Mat m;
            renderer.render((tv - c.offset_s) / (1 + c.drift), k, m);
            applyLook(c, k, tv, m);
            // Dropped and repeated frames at the container's constant rate: the capture shows
            // the previous picture again.
            if (c.look == Look::VariableRate && !last.empty() && u(frameRng) < 0.1)
                m = last.clone();
            last = m;
            frames.push_back(m);
        }
        const QString ext = c.codec == Codec::H264 ? QStringLiteral(".mp4") : QStringLiteral(".avi");
        const QString videoPath = QDir(workDir).filePath(QStringLiteral("video") + ext);
        if (const QString e = encodeConstantRate(frames, c.codec, fps, videoPath); !e.isEmpty()) {
            out.problem = e;
            return out;
        }
        frames.clear();
        const video::FrameIndex index = video::buildFrameIndex(videoPath);
        // The path `labels suggest --video` and Review's Suggest labels take.
        const video::VideoLabels found = video::suggestLabelsWithVideo(blind, index, {c.offset_s, c.drift}, QStringLiteral("video") + ext);
        out.videoUsed = found.videoUsed;
        const Labels& withVideo = found.labels;
        out.videoSource = out.videoUsed ? (withVideo.empty() ? QString() : withVideo.front().comment) : found.problem;
        out.withVideo = agreement(truth, withVideo, blind.time_s);
        int phaseLabels = 0, placed = 0;
        for (const Label& l : withVideo) {
            if (l.label != QLatin1String("a") && l.label != QLatin1String("b1") && l.label != QLatin1String("b2") && l.label != QLatin1String("c"))
                continue;
            ++phaseLabels;
            placed += l.comment.startsWith(QLatin1String("suggested from the tissue's motion"));
        }
        out.fromPicture = phaseLabels > 0 ? double(placed) / phaseLabels : 0.0;
        writeLabelsFile(QDir(workDir).filePath(QStringLiteral("labels_with_video.csv")), withVideo);
        // The clock the video was made on, for `labels suggest --video-offset-s --video-drift`.
        QFile clock(QDir(workDir).filePath(QStringLiteral("video_clock.txt")));
        if (clock.open(QIODevice::WriteOnly | QIODevice::Text))
            clock.write(QStringLiteral("--video-offset-s %1 --video-drift %2\n").arg(c.offset_s, 0, 'g', 17).arg(c.drift, 0, 'g', 17).toUtf8());
        out.ok = true;
    } catch (const RunFileError& e) {
        out.problem = e.message();
    } catch (const video::VideoError& e) {
        out.problem = e.message();
    } catch (const std::exception& e) {
        out.problem = QString::fromUtf8(e.what());
    }
    return out;
}

}  // namespace nb::accuracy

namespace nb::accuracy {
void applyMatrixLook(Look look, unsigned seed, int frameNumber, double videoTime_s, cv::Mat& m)
{
    PhaseMatrixCase c;
    c.look = look;
    c.seed = seed;
    applyLook(c, frameNumber, videoTime_s, m);
}
QString matrixLookName(Look look) { return phaseLookName(look); }
}  // namespace nb::accuracy
