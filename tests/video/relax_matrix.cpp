#include "relax_matrix.h"
#include "phase_matrix.h"

#include "support/truth_columns.h"

#include "core/label_suggest.h"
#include "core/run_file.h"
#include "devices/sim/imaging_render.h"
#include "video/frame_index.h"
#include "video/frame_reader.h"
#include "video/surface_trace.h"
#include "video/tissue_tracker.h"
#include "video/video_error.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace nb::accuracy {

QString RelaxMatrixCase::describe() const
{
    return QStringLiteral("%1 %2 mm/s seed %3, %4, %5 %6x%7 %8 fps")
        .arg(tissue)
        .arg(velocity_mm_s, 0, 'f', 2)
        .arg(seed)
        .arg(matrixLookName(look), codecName(codec))
        .arg(width)
        .arg(height)
        .arg(fps, 0, 'f', 2);
}

std::vector<RelaxMatrixCase> drawRelaxMatrix(std::mt19937& rng, int count, bool small)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const QStringList tissues{QStringLiteral("liver1"), QStringLiteral("liver2"), QStringLiteral("liver5"), QStringLiteral("prostate")};
    std::vector<RelaxMatrixCase> out;
    for (int i = 0; i < count; ++i) {
        RelaxMatrixCase c;
        c.tissue = tissues[int(rng() % tissues.size())];
        c.velocity_mm_s = 2.0 + 6.0 * u(rng);
        c.look = Look(rng() % 7);
        c.codec = (rng() % 2) ? Codec::H264 : Codec::Mjpeg;
        if (small) {
            c.width = 480;
            c.height = 360;
        }
        c.fps = (rng() % 2) ? 30000.0 / 1001.0 : 25.0;
        c.offset_s = 2.0 * u(rng);
        c.drift = 0.002 * u(rng);
        c.seed = unsigned(rng() % 100000 + 1);
        out.push_back(c);
    }
    return out;
}

RelaxMatrixOutcome runRelaxMatrixCase(const RelaxMatrixCase& c, const QString& executable, const QString& workDir)
{
    RelaxMatrixOutcome out;
    QDir().mkpath(workDir);
    const QString runPath = QDir(workDir).filePath(QStringLiteral("run.csv"));
    const QString truthPath = QDir(workDir).filePath(QStringLiteral("truth.json"));
    {
        QProcess p;
        p.start(executable, QStringList{QStringLiteral("simulate"), QStringLiteral("--protocol"), QStringLiteral("stiffness"),
                                        QStringLiteral("--tissue"), c.tissue, QStringLiteral("--velocity-mm-s"),
                                        QString::number(c.velocity_mm_s, 'f', 3), QStringLiteral("--seed"), QString::number(c.seed % 1000 + 1),
                                        QStringLiteral("--out"), runPath, QStringLiteral("--truth"), truthPath});
        if (!p.waitForFinished(180000) || p.exitCode() != 0) {
            out.problem = QStringLiteral("simulate failed: ") + QString::fromUtf8(p.readAllStandardError());
            return out;
        }
    }
    try {
        QFile tf(truthPath);
        if (!tf.open(QIODevice::ReadOnly)) {
            out.problem = QStringLiteral("no truth file");
            return out;
        }
        const QJsonObject truth = QJsonDocument::fromJson(tf.readAll()).object();
        out.truth_s = truth.value(QStringLiteral("relaxed_s")).toDouble(-1.0);  // already on the run's clock
        const Run run = readRunFile(runPath).run;
        if (!(out.truth_s > 0.0) || out.truth_s > run.time_s.back()) {
            out.problem = QStringLiteral("the simulated run has no relaxation");
            return out;
        }
        const Run blind = nbtest::withoutTruthColumns(run);
        const Labels without = suggestEventLabels(blind);
        out.suggestedWithoutVideo = std::any_of(without.begin(), without.end(), [](const Label& l) { return l.label == QLatin1String("relaxation"); });

        // The imaging view of the true motion (the renderer reads the full run's tissue column).
        devices::sim::ImagingOptions io;
        io.width = c.width;
        io.height = c.height;
        io.fps = c.fps;
        io.seed = c.seed;
        const devices::sim::ImagingRenderer renderer(run, io);
        const double duration = (1 + c.drift) * (run.time_s.back() + 0.5) + c.offset_s;
        std::vector<cv::Mat> frames;
        std::mt19937 frameRng(c.seed * 31u + 7u);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        cv::Mat last;
        for (int k = 0; k < int(duration * c.fps); ++k) {
            const double tv = k / c.fps;
            cv::Mat m;
            renderer.render((tv - c.offset_s) / (1 + c.drift), k, m);
            applyMatrixLook(c.look, c.seed, k, tv, m);
            if (c.look == Look::VariableRate && !last.empty() && u(frameRng) < 0.1)
                m = last.clone();  // dropped frame: the capture shows the previous picture again
            last = m;
            frames.push_back(m);
        }
        const QString ext = c.codec == Codec::H264 ? QStringLiteral(".mp4") : QStringLiteral(".avi");
        const QString videoPath = QDir(workDir).filePath(QStringLiteral("video") + ext);
        if (const QString e = encodeConstantRate(frames, c.codec, c.fps, videoPath); !e.isEmpty()) {
            out.problem = e;
            return out;
        }
        frames.clear();
        const video::FrameIndex index = video::buildFrameIndex(videoPath);
        video::FrameReader reader(index);
        const std::vector<SurfaceTrace> traces =
            video::surfaceTraces(reader, video::trackTissueShifts(reader), {c.offset_s, c.drift}, QStringLiteral("video") + ext);
        // Beside the run, to look at a case again (bench_accuracy --keep).
        for (std::size_t k = 0; k < traces.size(); ++k) {
            QFile traceFile(QDir(workDir).filePath(QStringLiteral("surface_trace%1.csv").arg(k)));
            if (traceFile.open(QIODevice::WriteOnly | QIODevice::Text)) {
                traceFile.write("time_s,displacement_px\n");
                for (std::size_t i = 0; i < traces[k].time_s.size(); ++i)
                    traceFile.write(QStringLiteral("%1,%2\n").arg(traces[k].time_s[i], 0, 'f', 4).arg(traces[k].displacement_px[i], 0, 'f', 3).toUtf8());
            }
        }
        QString problem;
        const Labels labels = suggestEventLabels(blind, traces, &problem);
        const auto relax = std::find_if(labels.begin(), labels.end(), [](const Label& l) { return l.label == QLatin1String("relaxation"); });
        out.suggested = relax != labels.end();
        out.why = out.suggested ? relax->comment : problem;
        if (out.suggested) {
            out.suggested_s = relax->start_s;
            out.errorFrames = (out.suggested_s - out.truth_s) * c.fps;
        }
        writeLabelsFile(QDir(workDir).filePath(QStringLiteral("labels_with_video.csv")), labels);
        // What a lab has, and the clock the video was made on, for `labels suggest blind.csv
        // --video VIDEO --video-offset-s --video-drift`.
        writeRunFile(QDir(workDir).filePath(QStringLiteral("blind.csv")), blind);
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
