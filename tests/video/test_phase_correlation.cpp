// Phase correlation from kept spectra (video/phase_correlation) gives what cv::phaseCorrelate
// gives, shift and response, on textured pictures moved by a fraction of a pixel: at the
// tissue tracker's working size, at a size the transform pads, with
// heavy noise, and for a picture against itself; where OpenCV pads a side to an odd size, the
// right shift where OpenCV reads half a pixel off. The tissue tracker's figures were measured
// with cv::phaseCorrelate; the kept spectra only save transforms.
#include "video/phase_correlation.h"

#include <QtTest>

#include <opencv2/imgproc.hpp>

namespace {

// A blotchy texture moved by (dx, dy) (a fraction of a pixel) and cut out of a larger one, so
// that no edge is made up, tapered towards its edges as the tissue tracker tapers its
// pictures, with noise of its own.
std::pair<cv::Mat, cv::Mat> picturePair(cv::Size size, double dx, double dy, double noise)
{
    cv::theRNG().state = 7u;
    cv::Mat t(size.height + 100, size.width + 100, CV_32F);
    cv::randn(t, 0.0, 1.0);
    cv::GaussianBlur(t, t, cv::Size(0, 0), 2.0);
    cv::normalize(t, t, -40.0, 40.0, cv::NORM_MINMAX);
    cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy), u;
    cv::warpAffine(t, u, m, t.size(), cv::INTER_CUBIC, cv::BORDER_REFLECT);
    const cv::Rect cut(50, 50, size.width, size.height);
    cv::Mat a = t(cut).clone(), b = u(cut).clone(), n(size, CV_32F), window;
    cv::randn(n, 0.0, noise);
    a += n;
    cv::randn(n, 0.0, noise);
    b += n;
    cv::createHanningWindow(window, size, CV_32F);
    window = window.mul(window);
    return {a.mul(window), b.mul(window)};
}

QString pointText(cv::Point2d p)
{
    return QStringLiteral("(%1, %2)").arg(p.x, 0, 'f', 4).arg(p.y, 0, 'f', 4);
}

}  // namespace

class TestPhaseCorrelation : public QObject {
    Q_OBJECT
private slots:
    void sameAsOpenCv_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<double>("dx");
        QTest::addColumn<double>("dy");
        QTest::addColumn<double>("noise");
        QTest::newRow("working size") << 480 << 360 << 3.3 << -1.7 << 0.0;
        QTest::newRow("working size, noisy") << 480 << 360 << -0.4 << 0.25 << 30.0;
        QTest::newRow("padded") << 251 << 163 << 5.6 << 2.2 << 2.0;
        QTest::newRow("far") << 320 << 240 << 17.2 << -11.9 << 1.0;
        QTest::newRow("itself") << 480 << 270 << 0.0 << 0.0 << 0.0;
    }
    void sameAsOpenCv()
    {
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(double, dx);
        QFETCH(double, dy);
        QFETCH(double, noise);
        const auto [a, b] = picturePair(cv::Size(width, height), dx, dy, noise);
        double expectedResponse = 0.0, response = 0.0;
        const cv::Point2d expected = cv::phaseCorrelate(a, b, cv::noArray(), &expectedResponse);
        const cv::Point2d found = nb::video::phaseShift(nb::video::spectrumOf(a), nb::video::spectrumOf(b), &response);
        QVERIFY2(std::abs(found.x - expected.x) < 1e-4 && std::abs(found.y - expected.y) < 1e-4,
                 qPrintable(pointText(found) + QStringLiteral(" against OpenCV's ") + pointText(expected)));
        QVERIFY2(std::abs(response - expectedResponse) < 1e-5,
                 qPrintable(QStringLiteral("response %1 against OpenCV's %2").arg(response).arg(expectedResponse)));
        // And the shift itself, where the picture carries it.
        if (noise < 10)
            QVERIFY2(std::abs(found.x - dx) < 0.1 && std::abs(found.y - dy) < 0.1,
                     qPrintable(pointText(found) + QStringLiteral(" for ") + pointText({dx, dy})));
    }

    // A side that OpenCV pads to an odd size (121 to 125) reads zero shift half a pixel off
    // there; the kept spectra pad to an even size and read it right.
    void noHalfPixelOnAnOddSide()
    {
        const cv::Size size(223, 121);
        QCOMPARE(cv::getOptimalDFTSize(121), 125);
        for (double dx : {0.0, 1.0, -2.0}) {
            const auto [a, b] = picturePair(size, dx, 0.6, 1.0);
            const cv::Point2d found = nb::video::phaseShift(nb::video::spectrumOf(a), nb::video::spectrumOf(b));
            QVERIFY2(std::abs(found.x - dx) < 0.1 && std::abs(found.y - 0.6) < 0.1,
                     qPrintable(pointText(found) + QStringLiteral(" for ") + pointText({dx, 0.6})));
            const cv::Point2d opencv = cv::phaseCorrelate(a, b);
            QVERIFY2(std::abs(opencv.x - dx - 0.5) < 0.15,
                     qPrintable(QStringLiteral("OpenCV's half pixel is gone: ") + pointText(opencv) + QStringLiteral(" for ") + pointText({dx, 0.6})));
        }
    }
};

QTEST_GUILESS_MAIN(TestPhaseCorrelation)
#include "test_phase_correlation.moc"
