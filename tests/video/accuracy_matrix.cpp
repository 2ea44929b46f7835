#include "accuracy_matrix.h"

#include "core/fit_error.h"
#include "core/label_suggest.h"
#include "core/labels.h"
#include "core/friction_fit.h"
#include "core/run_file.h"
#include "core/synthetic.h"
#include "devices/sim/imaging_render.h"
#include "video/frame_index.h"
#include "video/video_error.h"
#include "video/video_sync.h"
#include "video/video_fixtures.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace nb::accuracy {

QString lookName(Look l)
{
    switch (l) {
    case Look::Rendered: return QStringLiteral("rendered imaging view");
    case Look::Plain: return QStringLiteral("plain needle, flat background");
    case Look::NoisyLowContrast: return QStringLiteral("heavy noise, low contrast");
    case Look::Overlays: return QStringLiteral("burnt-in clock and frame counter");
    case Look::Angle30: return QStringLiteral("needle at 30 deg");
    case Look::Angle90: return QStringLiteral("needle at 90 deg");
    case Look::VariableRate: return QStringLiteral("variable rate, dropped/duplicated frames");
    case Look::Speckle: return QStringLiteral("faint thin needle on grainy tissue");
    }
    return {};
}

QString codecName(Codec c)
{
    switch (c) {
    case Codec::Mjpeg: return QStringLiteral("MJPEG");
    case Codec::H264: return QStringLiteral("H.264 -bf 2");
    case Codec::Dv: return QStringLiteral("DV");
    }
    return {};
}

QString SyncCase::describe() const
{
    const QString motion = sine ? QStringLiteral("sine %1 Hz x%2").arg(frequency_hz, 0, 'f', 2).arg(cycles)
                                : QStringLiteral("linear %1 mm/s").arg(velocity_mm_s, 0, 'f', 1);
    return QStringLiteral("%1, offset %2 s, drift %3 %, %4, %5")
        .arg(motion)
        .arg(offset_s, 0, 'f', 3)
        .arg(100 * drift, 0, 'f', 3)
        .arg(lookName(look), codecName(codec))
        + (overlaysOnNeedleLine ? QStringLiteral(", clock and counter on the needle's line") : QString());
}

double quantile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const double k = p * double(v.size() - 1);
    const std::size_t i = std::size_t(std::floor(k));
    const std::size_t j = std::min(v.size() - 1, i + 1);
    return v[i] + (k - double(i)) * (v[j] - v[i]);
}

std::vector<SyncCase> drawSyncCases(std::mt19937& rng, int count, bool small)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<SyncCase> out;
    for (int i = 0; i < count; ++i) {
        SyncCase c;
        c.seed = unsigned(rng() % 100000 + 1);
        c.sine = u(rng) < 0.6;
        c.frequency_hz = 0.1 + 0.9 * u(rng);
        c.amplitude_mm = 5.0 + 5.0 * u(rng);
        // Enough cycles to see the motion, few enough to keep the video short.
        c.cycles = std::max(2, int(std::lround((small ? 6.0 : 12.0) * c.frequency_hz)));
        c.velocity_mm_s = 1.0 + 9.0 * u(rng);
        c.depth_mm = std::clamp(c.velocity_mm_s * (small ? 4.0 : 6.0), 8.0, 40.0);
        const double motion_s = c.sine ? c.cycles / c.frequency_hz : c.depth_mm / c.velocity_mm_s;
        // A video that starts after the recording still has to see some motion (3 s).
        const double lowest = std::max(-5.0, -(motion_s - 3.0));
        c.offset_s = lowest + (15.0 - lowest) * u(rng);
        if (small)
            c.offset_s = lowest + (std::min(15.0, 6.0) - lowest) * u(rng);
        c.drift = 0.002 * u(rng);
        c.look = Look(rng() % 7);
        c.codec = Codec(rng() % 3);
        if (c.codec == Codec::Dv) {
            c.width = 720;  // DV is NTSC 720x480 at 29.97 frames/s
            c.height = 480;
        } else if (small) {
            c.width = 320;
            c.height = 240;
        }
        out.push_back(c);
    }
    return out;
}

namespace {

// The run through `needlebench simulate` (a public command whose flags are promises); a case
// drawn again into a kept folder (bench_accuracy --keep) replaces its run.
QString simulate(const QStringList& args, const QString& executable, const QString& out)
{
    QProcess p;
    p.start(executable, QStringList{QStringLiteral("simulate"), QStringLiteral("--overwrite")} << args << QStringLiteral("--out") << out);
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return QStringLiteral("simulate failed: ") + QString::fromUtf8(p.readAllStandardError());
    return {};
}

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x)
{
    if (x <= t.front())
        return v.front();
    if (x >= t.back())
        return v.back();
    const std::size_t i = std::size_t(std::upper_bound(t.begin(), t.end(), x) - t.begin());
    const double w = (x - t[i - 1]) / (t[i] - t[i - 1]);
    return v[i - 1] + w * (v[i] - v[i - 1]);
}

// Draws one synthetic picture: a needle along `angle` through the picture's centre, its tip
// `tip_px` along it from the centre; background, contrast and noise by look.
struct Painter {
    const SyncCase& c;
    double angle_deg = 0.0;
    double background = 120, needle = 40, noise = 4, width = 4;
    cv::Mat texture;
    cv::Mat along, shaft;  // Speckle: position along the axis, and the shaft's brightness

    explicit Painter(const SyncCase& sc) : c(sc)
    {
        std::mt19937 rng(c.seed * 7u + 3u);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        switch (c.look) {
        case Look::Plain: angle_deg = 180.0 * u(rng); noise = 3; break;
        case Look::NoisyLowContrast:
            angle_deg = 180.0 * u(rng);
            background = 90;
            needle = 90 + (u(rng) < 0.5 ? -1 : 1) * 28;
            noise = 18;
            width = 3;
            break;
        case Look::Overlays: angle_deg = 180.0 * u(rng); noise = 6; break;
        case Look::Angle30: angle_deg = 30.0; needle = 220; background = 70; noise = 8; break;
        case Look::Angle90: angle_deg = 90.0; noise = 8; break;
        case Look::VariableRate: angle_deg = 180.0 * u(rng); noise = 6; break;
        case Look::Speckle: angle_deg = 180.0 * u(rng); background = 110; needle = 140; noise = 6; break;
        case Look::Rendered: break;
        }
        // A soft, fixed texture (anatomy) so that the background is not perfectly flat.
        if (c.look == Look::Speckle) {
            // Grains of 4 pixels, as strong as the needle is bright: the shaft is lost in
            // them in any one picture; only its tip moves.
            cv::Mat grains(c.height / 4 + 1, c.width / 4 + 1, CV_32F);
            cv::randn(grains, 0.0, 25.0);
            cv::resize(grains, texture, cv::Size(grains.cols * 4, grains.rows * 4), 0, 0, cv::INTER_NEAREST);
            texture = texture(cv::Rect(0, 0, c.width, c.height)).clone();
            // The needle as a smooth profile across its axis (not a rasterised line, whose
            // edge pixels shift as its end moves): distance along and across the axis.
            const double th = angle_deg * M_PI / 180.0;
            along.create(c.height, c.width, CV_32F);
            shaft.create(c.height, c.width, CV_32F);
            for (int y = 0; y < c.height; ++y)
                for (int x = 0; x < c.width; ++x) {
                    const double dx = x - c.width / 2.0, dy = y - c.height / 2.0;
                    const double across = -dx * std::sin(th) + dy * std::cos(th);
                    along.at<float>(y, x) = float(dx * std::cos(th) + dy * std::sin(th));
                    shaft.at<float>(y, x) = float((needle - background) * std::exp(-0.5 * across * across / (1.5 * 1.5)));
                }
        } else if (c.look != Look::Plain) {
            texture.create(c.height, c.width, CV_32F);
            cv::randn(texture, 0.0, 20.0);
            cv::GaussianBlur(texture, texture, cv::Size(0, 0), 6.0);
        }
    }

    void paint(double tip_px, int frameNumber, double videoTime_s, cv::Mat& out) const
    {
        cv::Mat f(c.height, c.width, CV_32F, cv::Scalar(background));
        if (!texture.empty())
            f += texture;
        const double th = angle_deg * M_PI / 180.0;
        const cv::Point2d u(std::cos(th), std::sin(th));
        const cv::Point2d centre(c.width / 2.0, c.height / 2.0);
        const cv::Point2d tip = centre + u * tip_px;
        const cv::Point2d tail = centre - u * 2.0 * std::hypot(c.width, c.height);
        // Drawn at 8x sub-pixel precision so that the tip moves smoothly.
        constexpr int shift = 3;
        auto fixed = [](const cv::Point2d& p) { return cv::Point(int(std::lround(p.x * 8)), int(std::lround(p.y * 8))); };
        if (c.look == Look::Speckle) {
            // shaft / (1 + exp((along - tip) / 1 px)): the shaft, ending softly at the tip.
            cv::Mat ending;
            cv::exp(along - tip_px, ending);
            f += shaft / (1.0 + ending);
        } else {
            cv::line(f, fixed(tail), fixed(tip), cv::Scalar(needle), int(width), cv::LINE_AA, shift);
        }
        if (noise > 0) {
            cv::Mat n(f.size(), CV_32F);
            cv::RNG rng(std::uint64_t(c.seed) * 7919u + std::uint64_t(frameNumber));
            rng.fill(n, cv::RNG::NORMAL, 0.0, noise);
            f += n;
        }
        f.convertTo(out, CV_8U);
        if (c.look == Look::Overlays || c.overlaysOnNeedleLine) {
            const int ms = int(std::lround(videoTime_s * 1000));
            const QString clock = QStringLiteral("%1:%2:%3.%4")
                                      .arg(10 + ms / 3600000, 2, 10, QLatin1Char('0'))
                                      .arg(ms / 60000 % 60, 2, 10, QLatin1Char('0'))
                                      .arg(ms / 1000 % 60, 2, 10, QLatin1Char('0'))
                                      .arg(ms % 1000, 3, 10, QLatin1Char('0'));
            const double scale = c.height / 480.0;
            const QString counter = QStringLiteral("FRM %1").arg(frameNumber, 6, 10, QLatin1Char('0'));
            cv::Point clockAt(int(10 * scale), int(30 * scale)), counterAt(int(c.width - 200 * scale), int(c.height - 15 * scale));
            if (c.overlaysOnNeedleLine) {
                // The tip travels ±20 % of the shorter side around the centre; the text starts
                // 10 px beyond that, however it lies across the line.
                auto centredOnLine = [&](double side, const QString& text) {
                    int base = 0;
                    const cv::Size size = cv::getTextSize(text.toStdString(), cv::FONT_HERSHEY_SIMPLEX, 0.9 * scale, 2, &base);
                    const double along = std::abs(u.x) * size.width / 2.0 + std::abs(u.y) * size.height / 2.0;
                    const cv::Point2d p = centre + u * side * (0.2 * std::min(c.width, c.height) + 10.0 + along);
                    return cv::Point(int(p.x - size.width / 2.0), int(p.y + size.height / 2.0));
                };
                clockAt = centredOnLine(-1.0, clock);
                counterAt = centredOnLine(1.0, counter);
            }
            cv::putText(out, clock.toStdString(), clockAt, cv::FONT_HERSHEY_SIMPLEX, 0.9 * scale, cv::Scalar(250), 2);
            cv::putText(out, counter.toStdString(), counterAt, cv::FONT_HERSHEY_SIMPLEX, 0.9 * scale, cv::Scalar(250), 2);
        }
    }
};

// Frames in video time: regular, or (VariableRate) with some dropped and some repeated.
struct Timing {
    std::vector<double> time_s;   // presentation time of each written frame
    std::vector<int> source;      // which regular slot's picture it shows
};

Timing timing(const SyncCase& c, double fps, double duration_s)
{
    Timing t;
    const int n = int(duration_s * fps);
    std::mt19937 rng(c.seed * 31u + 1u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const bool vfr = c.look == Look::VariableRate;
    int lastSource = 0;
    for (int k = 0; k < n; ++k) {
        if (vfr && k > 0 && c.codec != Codec::Dv && u(rng) < 0.05)
            continue;  // dropped: a gap in the timestamps
        const bool repeat = vfr && k > 0 && u(rng) < 0.05;  // the capture repeats the last picture
        t.time_s.push_back(k / fps);
        t.source.push_back(repeat ? lastSource : k);
        lastSource = t.source.back();
    }
    return t;
}

QString encode(const SyncCase& c, const std::vector<cv::Mat>& frames, const Timing& t, double fps, const QString& dir,
               QString* path)
{
    const bool vfr = c.look == Look::VariableRate && c.codec != Codec::Dv;
    const QString ext = vfr ? QStringLiteral(".mkv") : c.codec == Codec::H264 ? QStringLiteral(".mp4") : QStringLiteral(".avi");
    *path = QDir(dir).filePath(QStringLiteral("video") + ext);
    if (!vfr)
        return encodeConstantRate(frames, c.codec, fps, *path);
    // Timestamps as written: raw frames at a fine clock, each shown until the next.
    // ffmpeg's concat demuxer takes a duration per picture. Each picture is opened at the
    // case's timestamp clock ("option framerate"), a millisecond unless the case asks for a
    // coarse one: at the image reader's default of 25 per second the timestamps land on a
    // 40 ms grid, bumped by 1 ms where two meet.
    QFile list(QDir(dir).filePath(QStringLiteral("frames.txt")));
    if (!list.open(QIODevice::WriteOnly))
        return QStringLiteral("cannot write the frame list");
    list.write("ffconcat version 1.0\n");
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const QString name = QDir(dir).filePath(QStringLiteral("f%1.pgm").arg(k, 6, 10, QLatin1Char('0')));
        cv::Mat m = frames[k];
        QFile f(name);
        if (!f.open(QIODevice::WriteOnly))
            return QStringLiteral("cannot write a frame");
        f.write(QStringLiteral("P5\n%1 %2\n255\n").arg(m.cols).arg(m.rows).toLatin1());
        f.write(reinterpret_cast<const char*>(m.data), qint64(m.total()));
        f.close();
        const double next = k + 1 < frames.size() ? t.time_s[k + 1] : t.time_s[k] + 1.0 / fps;
        list.write(QStringLiteral("file '%1'\noption framerate %3\nduration %2\n").arg(name).arg(next - t.time_s[k], 0, 'f', 6).arg(c.timestampClock_hz).toUtf8());
    }
    list.close();
    QProcess p;
    p.start(QStringLiteral("ffmpeg"), QStringList{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y"), QStringLiteral("-f"),
                                                  QStringLiteral("concat"), QStringLiteral("-safe"), QStringLiteral("0"), QStringLiteral("-i"),
                                                  list.fileName(), QStringLiteral("-fps_mode"), QStringLiteral("vfr"),
                                                  QStringLiteral("-enc_time_base"), QStringLiteral("1/1000")}
                                          << codecArguments(c.codec) << *path);
    if (!p.waitForFinished(300000) || p.exitCode() != 0)
        return QStringLiteral("ffmpeg: ") + QString::fromUtf8(p.readAllStandardError());
    return {};
}

}  // namespace

QStringList codecArguments(Codec c)
{
    switch (c) {
    case Codec::Mjpeg: return {QStringLiteral("-c:v"), QStringLiteral("mjpeg"), QStringLiteral("-q:v"), QStringLiteral("4"), QStringLiteral("-pix_fmt"), QStringLiteral("yuvj420p")};
    case Codec::H264: return {QStringLiteral("-c:v"), QStringLiteral("libx264"), QStringLiteral("-bf"), QStringLiteral("2"), QStringLiteral("-g"), QStringLiteral("30"), QStringLiteral("-preset"), QStringLiteral("veryfast"), QStringLiteral("-pix_fmt"), QStringLiteral("yuv420p")};
    case Codec::Dv: return {QStringLiteral("-c:v"), QStringLiteral("dvvideo"), QStringLiteral("-pix_fmt"), QStringLiteral("yuv411p")};
    }
    return {};
}

QString encodeConstantRate(const std::vector<cv::Mat>& frames, Codec codec, double fps, const QString& path)
{
    if (frames.empty())
        return QStringLiteral("no frames to encode");
    const QString rate = codec == Codec::Dv ? QStringLiteral("30000/1001") : QString::number(fps, 'f', 6);
    QProcess p;
    p.start(QStringLiteral("ffmpeg"), QStringList{QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-y"), QStringLiteral("-f"),
                                                  QStringLiteral("rawvideo"), QStringLiteral("-pix_fmt"), QStringLiteral("gray"), QStringLiteral("-s"),
                                                  QStringLiteral("%1x%2").arg(frames.front().cols).arg(frames.front().rows),
                                                  QStringLiteral("-r"), rate, QStringLiteral("-i"), QStringLiteral("-")}
                                          << codecArguments(codec) << path);
    if (!p.waitForStarted(10000))
        return QStringLiteral("ffmpeg did not start");
    for (std::size_t k = 0; k < frames.size(); ++k) {
        cv::Mat m = frames[k];
        if (k == 0) {
            m = m.clone();
            nb::test::keepFromReadingAsId3(m);
        }
        p.write(reinterpret_cast<const char*>(m.data), qint64(m.total()));
        while (p.bytesToWrite() > 0)
            if (!p.waitForBytesWritten(60000))
                return QStringLiteral("ffmpeg stopped reading: ") + QString::fromUtf8(p.readAllStandardError());
    }
    p.closeWriteChannel();
    if (!p.waitForFinished(300000) || p.exitCode() != 0)
        return QStringLiteral("ffmpeg: ") + QString::fromUtf8(p.readAllStandardError());
    return {};
}

SyncOutcome runSyncCase(const SyncCase& c, const QString& executable, const QString& workDir)
{
    SyncOutcome out;
    out.c = c;
    QDir().mkpath(workDir);
    const QString runPath = QDir(workDir).filePath(QStringLiteral("run.csv"));
    QStringList args{QStringLiteral("--seed"), QString::number(c.seed % 1000 + 1)};
    if (c.sine)
        args << QStringLiteral("--protocol") << QStringLiteral("friction") << QStringLiteral("--tissue") << QStringLiteral("liver7")
             << QStringLiteral("--frequency-hz") << QString::number(c.frequency_hz, 'f', 4) << QStringLiteral("--amplitude-mm")
             << QString::number(c.amplitude_mm, 'f', 3) << QStringLiteral("--cycles") << QString::number(c.cycles);
    else
        args << QStringLiteral("--protocol") << QStringLiteral("stiffness") << QStringLiteral("--tissue") << QStringLiteral("liver3")
             << QStringLiteral("--velocity-mm-s") << QString::number(c.velocity_mm_s, 'f', 3) << QStringLiteral("--depth-mm")
             << QString::number(c.depth_mm, 'f', 2) << QStringLiteral("--max-force-n") << QStringLiteral("40");
    if (const QString e = simulate(args, executable, runPath); !e.isEmpty()) {
        out.problem = e;
        return out;
    }
    Run run;
    try {
        run = readRunFile(runPath).run;
    } catch (const RunFileError& e) {
        out.problem = e.message();
        return out;
    }
    const double fps = c.codec == Codec::Dv ? 30000.0 / 1001.0 : ((c.seed % 2) ? 30000.0 / 1001.0 : 25.0);
    const double runEnd = run.time_s.back();
    // The video runs from its own time 0 to two seconds after the recording ends.
    const double duration = (1 + c.drift) * (runEnd + 2.0) + c.offset_s;
    const Timing t = timing(c, fps, duration);
    // Pictures per regular slot, in recording time (t_rec = (t_video − offset)/(1 + drift)).
    std::vector<cv::Mat> frames;
    const auto [pmin, pmax] = std::minmax_element(run.position_mm.begin(), run.position_mm.end());
    const double span_mm = std::max(1.0, *pmax - *pmin);
    const Painter painter(c);
    devices::sim::ImagingOptions io;
    io.width = c.width;
    io.height = c.height;
    io.fps = fps;
    io.seed = c.seed;
    std::optional<devices::sim::ImagingRenderer> renderer;
    if (c.look == Look::Rendered)
        renderer.emplace(run, io);
    // The tip travels over 40 % of the shorter side (scale varies with the motion's size).
    const double ppmm = 0.4 * std::min(c.width, c.height) / span_mm;
    const double centreMm = 0.5 * (*pmin + *pmax);
    for (std::size_t k = 0; k < t.time_s.size(); ++k) {
        const int slot = t.source[k];
        const double tv = slot / fps;
        const double tr = (tv - c.offset_s) / (1 + c.drift);
        cv::Mat m;
        if (renderer)
            renderer->render(tr, slot, m);
        else
            painter.paint((interpolate(run.time_s, run.position_mm, tr) - centreMm) * ppmm, slot, tv, m);
        frames.push_back(m);
    }
    QString path;
    if (const QString e = encode(c, frames, t, fps, workDir, &path); !e.isEmpty()) {
        out.problem = e;
        return out;
    }
    frames.clear();
    QElapsedTimer timer;
    timer.start();
    try {
        const video::FrameIndex index = video::buildFrameIndex(path);
        video::VideoSyncOptions options;
        const video::VideoSync vs = video::syncVideoToRun(index, run, options);
        out.seconds = timer.elapsed() / 1000.0;
        out.confidence = vs.result.confidence;
        out.acceptable = vs.result.acceptable();
        if (!vs.track.time_s.empty())
            out.maskedFraction = double(vs.track.masked) / double(vs.track.time_s.size());
        double worst = 0.0;
        for (double tr = 0.0; tr <= runEnd; tr += 0.1)
            worst = std::max(worst, std::abs(vs.result.mapping().toVideo(tr) - ((1 + c.drift) * tr + c.offset_s)));
        out.errorFrames = worst * fps;
        out.ok = true;
    } catch (const video::VideoError& e) {
        out.problem = e.message();
    } catch (const std::exception& e) {
        out.problem = QString::fromUtf8(e.what());
    }
    return out;
}

}  // namespace nb::accuracy

namespace nb::accuracy {

std::vector<FrictionCase> drawFrictionCases(std::mt19937& rng, int count)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<FrictionCase> out;
    for (int i = 0; i < count; ++i) {
        FrictionCase c;
        c.frequency_hz = 0.2 + 0.6 * u(rng);
        c.band_mm_s = 1.0 + 5.0 * u(rng);
        c.amplitude_mm = 10.0;
        c.seed = unsigned(rng() % 100000 + 1);
        out.push_back(c);
    }
    return out;
}

FrictionOutcome runFrictionCase(const FrictionCase& c)
{
    FrictionOutcome out;
    out.c = c;
    std::mt19937 rng(c.seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    synthetic::Friction p;
    p.frequency_hz = c.frequency_hz;
    p.amplitude_mm = c.amplitude_mm;
    p.cycles = 6;
    p.seed = c.seed;
    p.writePhases = false;  // the fit has to find the band itself
    p.model.Cp_N = 0.1 + 0.3 * u(rng);
    p.model.Cn_N = 0.1 + 0.3 * u(rng);
    p.model.bp_Ns_per_m = 2.0 + 6.0 * u(rng);
    p.model.bn_Ns_per_m = 2.0 + 6.0 * u(rng);
    p.model.Dp_N = p.model.Cp_N * (1.3 + 0.7 * u(rng));
    p.model.Dn_N = -p.model.Cn_N * (1.3 + 0.7 * u(rng));
    p.model.band_m_s = 2.0 * c.band_mm_s / 1000.0;
    try {
        FrictionOptions o;
        o.thickness_mm = 30.0;
        o.estimateBand = true;
        const FrictionFit f = fitFriction(synthetic::makeFriction(p), o);
        auto rel = [](double got, double truth) { return std::abs(got - truth) / std::abs(truth); };
        out.errC = std::max(rel(f.model.Cp_N, p.model.Cp_N), rel(f.model.Cn_N, p.model.Cn_N));
        out.errB = std::max(rel(f.model.bp_Ns_per_m, p.model.bp_Ns_per_m), rel(f.model.bn_Ns_per_m, p.model.bn_Ns_per_m));
        out.bandFound_mm_s = f.band_m_s * 500.0;
        out.flagged = !f.notPhysical.isEmpty();
        out.ok = true;
    } catch (const FitError& e) {
        out.problem = e.message();
    }
    return out;
}

}  // namespace nb::accuracy
