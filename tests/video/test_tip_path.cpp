// The tip's course through frames too noisy to show it one by one (TipPath, issue 13): score
// maps made here frame by frame, a tip's edge a few σ high at its true place in unit noise,
// pushed through the search as the tracker pushes them. Alone, a frame's highest score is the
// tip's in fewer than half of the frames; along the course, in nearly all.
#include "video/tip_path.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <random>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Outcome {
    double withinTwo = 0.0;       // share of frames the course puts within 2 samples of the tip
    double argmaxWithinTwo = 0.0;  // the same for each frame's highest score on its own
};

// `course(k)`: the tip's true position in frame k; its edge scores `height` there (a little
// less a sample either side), on unit Gaussian noise.
Outcome follow(int length, int frames, double height, const std::function<double(int)>& course, unsigned seed,
               int lag = 48, double frame_s = 1.0 / 30.0)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    nb::video::TipPath path(length, lag, frame_s);
    std::vector<int> found;
    int argmaxHits = 0;
    for (int k = 0; k < frames; ++k) {
        std::vector<double> score(static_cast<std::size_t>(length));
        for (double& s : score)
            s = noise(rng);
        const double tip = course(k);
        for (int i = 0; i < length; ++i)
            score[std::size_t(i)] += height * std::exp(-0.5 * std::pow((i - tip) / 0.8, 2));
        const int argmax = int(std::max_element(score.begin(), score.end()) - score.begin());
        argmaxHits += std::abs(argmax - tip) <= 2.0;
        if (const std::optional<int> at = path.push(score)) {
            if (path.decided() != int(found.size()) + 1)
                return {};
            found.push_back(*at);
        }
    }
    for (int at : path.finish())
        found.push_back(at);
    if (int(found.size()) != frames)
        return {};
    int hits = 0;
    for (int k = 0; k < frames; ++k)
        hits += std::abs(found[std::size_t(k)] - course(k)) <= 2.0;
    return {double(hits) / frames, double(argmaxHits) / frames};
}

}  // namespace

class TestTipPath : public QObject {
    Q_OBJECT
private slots:
    void followsAFaintTip_data()
    {
        QTest::addColumn<QString>("motion");
        QTest::addColumn<double>("height");
        QTest::addColumn<unsigned>("seed");
        QTest::newRow("sine 2.5 sigma") << "sine" << 2.5 << 11u;
        QTest::newRow("sine 3 sigma") << "sine" << 3.0 << 12u;
        QTest::newRow("stroke 2.5 sigma") << "stroke" << 2.5 << 13u;
        QTest::newRow("fast sine 3 sigma") << "fast" << 3.0 << 14u;
        QTest::newRow("quick turns 3 sigma") << "quick" << 3.0 << 15u;
    }
    void followsAFaintTip()
    {
        QFETCH(QString, motion);
        QFETCH(double, height);
        QFETCH(unsigned, seed);
        constexpr int kLength = 400, kFrames = 600;
        std::function<double(int)> course;
        if (motion == "sine")  // 60 samples either way, 1.9 samples a frame at the most
            course = [](int k) { return 200.0 + 60.0 * std::sin(2.0 * kPi * k / 200.0); };
        else if (motion == "fast")  // 120 samples either way, 9.4 samples a frame at the most
            course = [](int k) { return 200.0 + 120.0 * std::sin(2.0 * kPi * k / 80.0); };
        else if (motion == "quick")  // 30 samples either way, turning by 3 samples a frame each frame
            course = [](int k) { return 200.0 + 30.0 * std::sin(2.0 * kPi * k / 20.0); };
        else  // at rest, a steady stroke of 0.6 samples a frame, at rest again
            course = [](int k) { return 80.0 + 0.6 * std::clamp(k - 150, 0, 400); };
        const Outcome o = follow(kLength, kFrames, height, course, seed);
        qInfo("%s, tip %.1f sigma: within 2 samples in %.1f %% of frames along the course, %.1f %% by each frame's highest score",
              qPrintable(motion), height, 100.0 * o.withinTwo, 100.0 * o.argmaxWithinTwo);
        QVERIFY2(o.argmaxWithinTwo < 0.6, "the frames alone should not show this tip");
        QVERIFY2(o.withinTwo >= 0.95, qPrintable(QString("along its course the tip was within 2 samples in only %1 of frames")
                                                     .arg(o.withinTwo)));
    }

    // The same motion seen at a lower frame rate moves further and turns more each frame: a
    // sine of 0.91 Hz and 63 samples either way at 15 frames/s, 24 samples a frame at its
    // fastest and turning by up to 9 a frame (probe seed 161803 case 14). Told the frame rate,
    // the course follows it (93-97 % of frames within 2 samples, against 99 % at 30 frames/s,
    // where each second has twice the frames to add up); with the bounds of 30 frames/s it can
    // neither move that fast nor turn that much for what a faint tip scores (10 %).
    void followsAtTheVideosFrameRate_data()
    {
        QTest::addColumn<double>("fps");
        QTest::addColumn<double>("toldFps");
        QTest::addColumn<bool>("follows");
        QTest::newRow("30 frames/s") << 30.0 << 30.0 << true;
        QTest::newRow("15 frames/s") << 15.0 << 15.0 << true;
        QTest::newRow("15 frames/s taken for 30") << 15.0 << 30.0 << false;
    }
    void followsAtTheVideosFrameRate()
    {
        QFETCH(double, fps);
        QFETCH(double, toldFps);
        QFETCH(bool, follows);
        const auto course = [fps](int k) { return 250.0 + 63.0 * std::sin(2.0 * kPi * 0.91 * k / fps); };
        double worst = 1.0;
        for (unsigned seed : {21u, 22u, 23u}) {
            const Outcome o = follow(500, int(20 * fps), 3.0, course, seed, 48, 1.0 / toldFps);
            qInfo("seen at %.0f frames/s, taken for %.0f, seed %u: within 2 samples in %.1f %% of frames", fps, toldFps, seed,
                  100.0 * o.withinTwo);
            worst = std::min(worst, o.withinTwo);
        }
        if (follows)
            QVERIFY2(worst >= 0.9, qPrintable(QString("the course was within 2 samples in only %1 of frames").arg(worst)));
        else
            QVERIFY2(worst < 0.5, qPrintable(QString("with 30 frames/s bounds the course still followed: %1").arg(worst)));
    }

    // Fewer frames than the lag are all decided at the end; a frame's position is decided once.
    void decidesEveryFrameOnce()
    {
        for (int frames : {1, 5, 48, 49, 120}) {
            const Outcome o = follow(100, frames, 6.0, [](int k) { return 30.0 + 0.5 * k / 2.0; }, 7u);
            QVERIFY2(o.withinTwo >= 0.95, qPrintable(QString("%1 frames: %2").arg(frames).arg(o.withinTwo)));
        }
    }

    // A tip that is not there: the course wanders, but nothing breaks and every frame gets a place.
    void noiseAlone()
    {
        nb::video::TipPath path(50, 10);
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0.0, 1.0);
        int decided = 0;
        for (int k = 0; k < 200; ++k) {
            std::vector<double> score(50);
            for (double& s : score)
                s = noise(rng);
            score[7] = std::numeric_limits<double>::quiet_NaN();
            if (const auto at = path.push(score)) {
                QVERIFY(*at >= 0 && *at < 50);
                ++decided;
            }
        }
        const std::vector<int> rest = path.finish();
        QCOMPARE(decided + int(rest.size()), 200);
        for (int at : rest)
            QVERIFY(at >= 0 && at < 50);
    }
};

QTEST_APPLESS_MAIN(TestTipPath)
#include "test_tip_path.moc"
