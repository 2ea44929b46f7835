#pragma once
// The load cell calibration (models.md section 2): known masses hung on the sensor, the
// voltage averaged over a dwell per mass, V = d·m + c fitted as the points come in, r² and
// residuals shown so that a bad point stands out; a point can be struck out and the fit
// follows. The wizard reads voltages handed to it (addSample) from the live stream.

#include "core/session.h"

#include <QDialog>
#include <functional>
#include <optional>

class QCustomPlot;
class QLabel;
class QPushButton;
class QSpinBox;
class QDoubleSpinBox;
class QTableWidget;

namespace nb {

class CalibrationWizard : public QDialog {
    Q_OBJECT
public:
    explicit CalibrationWizard(const QString& sensorName, QWidget* parent = nullptr);

    // Averaging time per mass (2 s in the thesis; tests use less).
    void setDwell(double seconds);
    double dwell() const { return dwell_s_; }
    // Puts a mass on the sensor without the operator (the simulated rig) and says from which
    // device time every sample carries it, when it knows. Without a hook the wizard asks the
    // operator to hang each mass and press Measure.
    using LoadMassHook = std::function<std::optional<double>(double grams)>;
    void setLoadMassHook(LoadMassHook hook) { loadMass_ = std::move(hook); }
    // Masses from..to in steps (grams); replaces the table.
    void setMasses(double from_g, double to_g, double step_g);
    // The input range (±V) and the sensor's nominal slope: readings within 0.2 % of the range
    // are saturated and refused, and the default masses stop at 90 % of the range (in 50 g
    // steps). Without a nominal slope the masses stay as they are.
    void setSensorRange(double fullScale_V, double nominalSlope_V_per_g);
    double saturation_V() const { return 0.998 * fullScale_V_; }
    // Rows refused because the reading saturated.
    int saturatedRows() const;
    QString promptText() const;

    // The live stream: device time and voltage of each sample.
    void addSample(double time_s, double volts);
    // The device clock now (from the engine's status): samples older than the moment a mass
    // was hung, still queued in the live ring, are not averaged into it.
    void setDeviceTime(double time_s) { deviceNow_ = time_s; }

    bool isMeasuring() const { return measuringRow_ >= 0; }
    int rowCount() const;
    // Strikes a point out of the fit (or puts it back).
    void setPointUsed(int row, bool used);
    bool hasFit() const { return hasFit_; }
    const CalibrationFit& fit() const { return fit_; }
    // The row whose residual is largest (-1 without a fit).
    int worstRow() const;
    StoredCalibration calibration() const;

    QCustomPlot* plot() const { return plot_; }
    QTableWidget* table() const { return table_; }

public slots:
    void measureCurrent();
    void measureAll();
    void stopMeasuring();
    // Esc or Cancel with points measured and not saved asks first: it threw them away at once.
    void reject() override;

signals:
    void calibrationAccepted(const nb::StoredCalibration& calibration);
    void measuringChanged(bool on);

private:
    void beginRow(int row);
    void finishRow();
    void refit();
    void findSuspect(const std::vector<CalibrationPoint>& points);
    void redraw();
    double massAt(int row) const;
    bool usedAt(int row) const;
    bool measuredAt(int row) const;

    QString sensor_;
    double dwell_s_ = 2.0;
    double fullScale_V_ = 10.0;
    // Settle detection on the live reading: the mean of consecutive windows stops moving.
    double windowStart_ = -1.0, windowSum_ = 0.0, windowSumSq_ = 0.0, previousMean_ = NAN;
    int windowCount_ = 0;
    bool settled_ = false;
    double peakAbs_V_ = 0.0;
    void refuseSaturated(int row, double volts);
    void showStepPrompt(int row);
    void showSaturation();
    QString saturationNote_;
    LoadMassHook loadMass_;
    QTableWidget* table_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    QLabel* fitLabel_ = nullptr;
    QLabel* prompt_ = nullptr;
    QLabel* suspect_ = nullptr;
    QPushButton* measure_ = nullptr;
    QPushButton* measureAll_ = nullptr;
    QPushButton* save_ = nullptr;
    QDoubleSpinBox* from_ = nullptr;
    QDoubleSpinBox* to_ = nullptr;
    QDoubleSpinBox* step_ = nullptr;
    int measuringRow_ = -1;
    bool all_ = false;
    bool askingToDiscard_ = false;  // measuring paused while the operator is asked
    double startTime_ = -1.0;
    double deviceNow_ = -1.0;
    double notBefore_ = -1.0;
    double lastSample_ = -1.0;  // device time of the newest sample seen
    double sum_ = 0.0;
    int count_ = 0;
    bool hasFit_ = false;
    CalibrationFit fit_;
    std::vector<int> fitRows_;  // table rows behind fit_.residuals_V
    bool updating_ = false;
    int worst_ = -1;
    double worstSigmas_ = 0.0;
};

}  // namespace nb
