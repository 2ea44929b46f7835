#pragma once
// Load cell calibration (models.md section 2, eqs. 1-6): V = d·m + c from known masses.

#include <QString>
#include <span>
#include <vector>

namespace nb {

struct CalibrationPoint {
    double mass_g = 0.0;
    double voltage_V = 0.0;
};

struct CalibrationFit {
    double slope_V_per_g = 0.0;   // d
    double intercept_V = 0.0;     // c
    double r2 = 0.0;
    double rms_V = 0.0;
    std::vector<double> residuals_V;  // measured - fitted, one per point, in input order: a bad point stands out

    // Eq. 6 with this slope: newtons from a voltage, v0 the voltage at bias (tare).
    double newtons(double volts, double v0_V) const;
};

// Least squares by QR (not the normal equations). Throws FitError for fewer than two points,
// non-finite values or masses that are all equal.
CalibrationFit fitCalibration(std::span<const CalibrationPoint> points);

// Reads a CSV with columns mass_g and voltage_V (others ignored, `#` lines skipped).
// Throws RunFileError naming the file, line and reason.
std::vector<CalibrationPoint> readCalibrationFile(const QString& path);

}  // namespace nb
