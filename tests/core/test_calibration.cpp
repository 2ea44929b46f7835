// Load cell calibration (eqs. 1-6): QR fit, residuals that show a bad point, the CSV reader.
#include "core/calibration.h"
#include "core/fit_error.h"
#include "core/run_file.h"
#include "synthetic.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace nb;

class TestCalibration : public QObject {
    Q_OBJECT

    static std::vector<CalibrationPoint> points(const synthetic::CalibrationData& d)
    {
        std::vector<CalibrationPoint> p;
        for (std::size_t i = 0; i < d.mass_g.size(); ++i)
            p.push_back({d.mass_g[i], d.voltage_V[i]});
        return p;
    }
    static void write(const QString& path, const QByteArray& text)
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
    }

private slots:
    void exactLineIsRecovered()
    {
        const auto fit = fitCalibration(points(synthetic::makeCalibration(1.2e-4, 0.015, 0.0, 1)));
        QVERIFY(std::fabs(fit.slope_V_per_g - 1.2e-4) < 1e-12);
        QVERIFY(std::fabs(fit.intercept_V - 0.015) < 1e-12);
        QVERIFY(std::fabs(fit.r2 - 1.0) < 1e-12);
        QCOMPARE(fit.residuals_V.size(), std::size_t(35));
        for (double r : fit.residuals_V)
            QVERIFY(std::fabs(r) < 1e-12);
    }
    void noisyLineWithinNoise()
    {
        for (std::uint32_t seed = 1; seed <= 5; ++seed) {
            const auto fit = fitCalibration(points(synthetic::makeCalibration(1.2e-4, 0.015, 2e-4, seed)));
            QVERIFY2(std::fabs(fit.slope_V_per_g - 1.2e-4) < 2e-6, qPrintable(QString::number(fit.slope_V_per_g)));
            QVERIFY(std::fabs(fit.intercept_V - 0.015) < 3e-4);
            QVERIFY(fit.r2 > 0.999 && fit.r2 < 1.0);
            QVERIFY(fit.rms_V > 1e-4 && fit.rms_V < 4e-4);
        }
    }
    void badPointStandsOutInResiduals()
    {
        auto d = synthetic::makeCalibration(1.2e-4, 0.015, 1e-4, 3);
        d.voltage_V[12] += 0.01;  // a mass put on the pan crooked
        const auto fit = fitCalibration(points(d));
        std::size_t worst = 0;
        for (std::size_t i = 0; i < fit.residuals_V.size(); ++i)
            if (std::fabs(fit.residuals_V[i]) > std::fabs(fit.residuals_V[worst]))
                worst = i;
        QCOMPARE(worst, std::size_t(12));
        QVERIFY(fit.residuals_V[12] > 0.009);
    }
    void newtonsFollowEquation6()
    {
        // 100 g on a cell with d = 1.2e-4 V/g reads 0.012 V above tare: 0.981 N.
        CalibrationFit fit;
        fit.slope_V_per_g = 1.2e-4;
        QVERIFY(std::fabs(fit.newtons(0.5 + 0.012, 0.5) - 0.981) < 1e-12);
    }
    void tooFewOrDegeneratePointsThrow()
    {
        const std::vector<CalibrationPoint> one{{100, 0.1}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(one));
        const std::vector<CalibrationPoint> same{{100, 0.1}, {100, 0.2}, {100, 0.3}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(same));
        const std::vector<CalibrationPoint> nan{{0, 0.1}, {100, std::nan("")}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(nan));
        // A sensor that reads the same whatever the mass (unplugged): no calibration, where
        // one with a slope of 0 V/g used to be printed.
        const std::vector<CalibrationPoint> flat{{0, 0.42}, {100, 0.42}, {200, 0.42}, {500, 0.42}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(flat));
        const std::vector<CalibrationPoint> noise{{0, 0.4201}, {100, 0.4199}, {200, 0.4202}, {500, 0.4200}, {1000, 0.4199}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(noise));
        const std::vector<CalibrationPoint> negative{{0, 0.015}, {-100, 0.003}, {200, 0.039}};
        QVERIFY_THROWS_EXCEPTION(FitError, fitCalibration(negative));
    }
    void readsFileFromDisk()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cal.csv"));
        write(path, "# load cell 1\r\nvoltage_V,mass_g,comment\r\n0.015,0,tare\r\n0.027,100,\r\n0.039,200,x\r\n");
        const auto p = readCalibrationFile(path);
        QCOMPARE(p.size(), std::size_t(3));
        QCOMPARE(p[1].mass_g, 100.0);
        QCOMPARE(p[2].voltage_V, 0.039);
        const auto fit = fitCalibration(p);
        QVERIFY(std::fabs(fit.slope_V_per_g - 1.2e-4) < 1e-12);
    }
    void badFilesNameFileAndLine()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("nope.csv"));
        try {
            readCalibrationFile(missing);
            QFAIL("no error");
        } catch (const RunFileError& e) {
            QCOMPARE(e.file(), missing);
        }
        const QString bad = dir.filePath(QStringLiteral("bad.csv"));
        write(bad, "mass_g,voltage_V\n0,0.01\n25,abc\n");
        try {
            readCalibrationFile(bad);
            QFAIL("no error");
        } catch (const RunFileError& e) {
            QCOMPARE(e.line(), 3);
            QVERIFY(e.message().contains(QStringLiteral("bad.csv")));
        }
        const QString noCol = dir.filePath(QStringLiteral("nocol.csv"));
        write(noCol, "mass,volts\n0,0.01\n");
        QVERIFY_THROWS_EXCEPTION(RunFileError, readCalibrationFile(noCol));
        const QString shortRow = dir.filePath(QStringLiteral("short.csv"));
        write(shortRow, "mass_g,voltage_V\n0\n");
        QVERIFY_THROWS_EXCEPTION(RunFileError, readCalibrationFile(shortRow));
    }
};

QTEST_GUILESS_MAIN(TestCalibration)
#include "test_calibration.moc"
