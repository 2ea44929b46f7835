#include "calibration.h"
#include "core/tr.h"
#include "core/spreadsheet_separator.h"

#include "fit_error.h"
#include "models.h"
#include "run_file.h"
#include "statistics.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <QFile>
#include <cmath>

namespace nb {

double CalibrationFit::newtons(double volts, double v0_V) const
{
    return forceFromVolts(volts, v0_V, slope_V_per_g);
}

CalibrationFit fitCalibration(std::span<const CalibrationPoint> points)
{
    const auto n = Eigen::Index(points.size());
    if (n < 2)
        throw FitError(nb::TrCore::tr("calibration needs at least two points, got %1").arg(n));
    Eigen::MatrixXd A(n, 2);
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto& p = points[std::size_t(i)];
        if (!std::isfinite(p.mass_g) || !std::isfinite(p.voltage_V))
            throw FitError(nb::TrCore::tr("calibration point %1 is not a finite number").arg(i + 1));
        if (p.mass_g < 0.0)
            throw FitError(nb::TrCore::tr("calibration point %1 has a negative mass (%2 g)").arg(i + 1).arg(p.mass_g));
        A(i, 0) = 1.0;
        A(i, 1) = p.mass_g;
        v(i) = p.voltage_V;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if (qr.rank() < 2)
        throw FitError(nb::TrCore::tr("calibration needs at least two different masses"));
    const Eigen::Vector2d x = qr.solve(v);
    CalibrationFit fit;
    fit.intercept_V = x(0);
    fit.slope_V_per_g = x(1);
    const Eigen::VectorXd r = v - A * x;
    fit.residuals_V.assign(r.data(), r.data() + r.size());
    std::vector<double> observed(v.data(), v.data() + v.size());
    fit.r2 = rSquared(observed, fit.residuals_V);
    fit.rms_V = rms(fit.residuals_V);
    // A slope the points cannot tell from zero is no calibration: every force would read as
    // the same voltage (a sensor unplugged, an amplifier off).
    const double meanMass = A.col(1).mean();
    const double sxx = (A.col(1).array() - meanMass).square().sum();
    const double slopeError = n > 2 ? std::sqrt(r.squaredNorm() / double(n - 2) / sxx) : 0.0;
    if (fit.slope_V_per_g == 0.0 || std::abs(fit.slope_V_per_g) < 3.0 * slopeError)
        throw FitError(nb::TrCore::tr("the voltage does not change with the mass (slope %1 V/g, standard error %2): "
                                      "is the sensor connected and its amplifier on?")
                           .arg(fit.slope_V_per_g, 0, 'g', 3)
                           .arg(slopeError, 0, 'g', 3));
    return fit;
}

std::vector<CalibrationPoint> readCalibrationFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot open: %1").arg(file.errorString()));
    QString text = QString::fromUtf8(file.readAll());
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    std::vector<CalibrationPoint> points;
    int massCol = -1, voltCol = -1;
    bool haveHeader = false;
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        QStringList f = line.split(QLatin1Char(','));
        for (QString& s : f)
            s = s.trimmed();
        if (!haveHeader) {
            haveHeader = true;
            massCol = int(f.indexOf(QLatin1String("mass_g")));
            voltCol = int(f.indexOf(QLatin1String("voltage_V")));
            if (const QString problem = otherSeparatorProblem(line, QStringLiteral("mass_g")); !problem.isEmpty())
                throw RunFileError(path, i + 1, problem);
            if (massCol < 0 || voltCol < 0)
                throw RunFileError(path, i + 1,
                                   nb::TrCore::tr("header needs columns mass_g and voltage_V"));
            continue;
        }
        if (f.size() <= std::max(massCol, voltCol))
            throw RunFileError(path, i + 1, nb::TrCore::tr("expected %1 fields, got %2")
                                                .arg(std::max(massCol, voltCol) + 1)
                                                .arg(f.size()));
        bool ok1 = false, ok2 = false;
        CalibrationPoint p{f[massCol].toDouble(&ok1), f[voltCol].toDouble(&ok2)};
        if (!ok1 || !ok2 || !std::isfinite(p.mass_g) || !std::isfinite(p.voltage_V))
            throw RunFileError(path, i + 1, nb::TrCore::tr("mass_g and voltage_V must be numbers"));
        points.push_back(p);
    }
    if (!haveHeader)
        throw RunFileError(path, 0, nb::TrCore::tr("empty file (expected a header mass_g,voltage_V)"));
    return points;
}

}  // namespace nb
