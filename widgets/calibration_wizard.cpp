#include "calibration_wizard.h"
#include "core/local_number.h"

#include "core/fit_error.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QLocale>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qcustomplot.h>

namespace nb {

namespace {
enum Column { Mass, Voltage, Residual, Use, Columns };
}

CalibrationWizard::CalibrationWizard(const QString& sensorName, QWidget* parent)
    : QDialog(parent), sensor_(sensorName)
{
    setWindowTitle(tr("Calibrate force sensor – %1").arg(sensorName));
    setObjectName(QStringLiteral("calibrationWizard"));

    auto* massRow = new QHBoxLayout;
    from_ = new QDoubleSpinBox(this);
    to_ = new QDoubleSpinBox(this);
    step_ = new QDoubleSpinBox(this);
    for (QDoubleSpinBox* s : {from_, to_, step_}) {
        s->setRange(0.0, 2000.0);
        s->setDecimals(1);
        s->setSuffix(tr(" g"));
    }
    from_->setValue(0.0);
    to_->setValue(850.0);
    step_->setValue(25.0);
    step_->setMinimum(1.0);
    auto* setMasses = new QPushButton(tr("Set masses"), this);
    setMasses->setToolTip(tr("Replaces the table with these masses (individual masses can be edited in the table)"));
    massRow->addWidget(new QLabel(tr("Masses from"), this));
    massRow->addWidget(from_);
    massRow->addWidget(new QLabel(tr("to"), this));
    massRow->addWidget(to_);
    massRow->addWidget(new QLabel(tr("step"), this));
    massRow->addWidget(step_);
    massRow->addWidget(setMasses);
    massRow->addStretch();
    connect(setMasses, &QPushButton::clicked, this, [this] { this->setMasses(from_->value(), to_->value(), step_->value()); });

    table_ = new QTableWidget(0, Columns, this);
    table_->setHorizontalHeaderLabels({tr("Mass [g]"), tr("Voltage [V]"), tr("Residual [mV]"), tr("Use")});
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->setVisible(false);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    // Wide enough for every column's title with the scroll bar beside them: in German the
    // last column ("Verwenden") went behind a horizontal scroll bar.
    {
        int titles = 0;
        for (int c = 0; c < Columns; ++c)
            titles += table_->horizontalHeader()->fontMetrics().horizontalAdvance(table_->horizontalHeaderItem(c)->text()) + 28;
        table_->setMinimumWidth(std::max(360, titles + table_->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 2 * table_->frameWidth() + 8));
    }
    connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (updating_)
            return;
        if (item->column() == Use || item->column() == Mass) {
            refit();
            redraw();
        }
    });

    plot_ = new QCustomPlot(this);
    plot_->setMinimumSize(420, 360);
    plot_->xAxis->setLabel(tr("mass [g]"));
    plot_->yAxis->setLabel(tr("voltage [V]"));
    auto* residualRect = new QCPAxisRect(plot_);
    plot_->plotLayout()->addElement(1, 0, residualRect);
    plot_->plotLayout()->setRowStretchFactor(1, 0.45);
    residualRect->axis(QCPAxis::atBottom)->setLabel(tr("mass [g]"));
    residualRect->axis(QCPAxis::atLeft)->setLabel(tr("residual [mV]"));
    auto* used = plot_->addGraph();
    used->setLineStyle(QCPGraph::lsNone);
    used->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QColor(20, 90, 180), 6));
    auto* removed = plot_->addGraph();
    removed->setLineStyle(QCPGraph::lsNone);
    removed->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QColor(150, 150, 150), 8));
    auto* line = plot_->addGraph();
    line->setPen(QPen(QColor(200, 30, 30), 1.5));
    auto* residuals = plot_->addGraph(residualRect->axis(QCPAxis::atBottom), residualRect->axis(QCPAxis::atLeft));
    residuals->setLineStyle(QCPGraph::lsImpulse);
    residuals->setPen(QPen(QColor(20, 90, 180)));
    residuals->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QColor(20, 90, 180), 5));
    auto* worst = plot_->addGraph(residualRect->axis(QCPAxis::atBottom), residualRect->axis(QCPAxis::atLeft));
    worst->setLineStyle(QCPGraph::lsNone);
    worst->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(200, 30, 30), 2), Qt::NoBrush, 11));

    fitLabel_ = new QLabel(tr("No fit yet: measure at least two masses."), this);
    fitLabel_->setObjectName(QStringLiteral("fitLabel"));
    fitLabel_->setWordWrap(true);
    fitLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    suspect_ = new QLabel(this);
    suspect_->setObjectName(QStringLiteral("suspectLabel"));
    suspect_->setWordWrap(true);
    suspect_->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
    prompt_ = new QLabel(this);
    prompt_->setObjectName(QStringLiteral("calibrationPrompt"));
    prompt_->setWordWrap(true);
    prompt_->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 13pt;"));

    measure_ = new QPushButton(tr("Measure"), this);
    measure_->setDefault(true);
    measure_->setToolTip(tr("Waits until the reading settles, then averages the sensor voltage over the dwell time for the selected mass"));
    measureAll_ = new QPushButton(tr("Measure all"), this);
    measureAll_->setToolTip(tr("Measures every row in turn"));
    auto* stop = new QPushButton(tr("Stop"), this);
    save_ = new QPushButton(tr("Save and use"), this);
    save_->setObjectName(QStringLiteral("calibrationSave"));
    measure_->setObjectName(QStringLiteral("calibrationMeasure"));
    measureAll_->setObjectName(QStringLiteral("calibrationMeasureAll"));
    save_->setToolTip(tr("Saves this calibration in the session and uses it for every following run"));
    save_->setEnabled(false);
    auto* cancel = new QPushButton(tr("Cancel"), this);
    connect(measure_, &QPushButton::clicked, this, &CalibrationWizard::measureCurrent);
    connect(measureAll_, &QPushButton::clicked, this, &CalibrationWizard::measureAll);
    connect(stop, &QPushButton::clicked, this, &CalibrationWizard::stopMeasuring);
    connect(save_, &QPushButton::clicked, this, [this] {
        emit calibrationAccepted(calibration());
        accept();
    });
    connect(cancel, &QPushButton::clicked, this, &QDialog::reject);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(measure_);
    buttons->addWidget(measureAll_);
    buttons->addWidget(stop);
    buttons->addStretch();
    buttons->addWidget(save_);
    buttons->addWidget(cancel);

    auto* split = new QSplitter(this);
    split->addWidget(table_);
    split->addWidget(plot_);
    split->setStretchFactor(1, 1);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(massRow);
    layout->addWidget(prompt_);
    layout->addWidget(split, 1);
    layout->addWidget(fitLabel_);
    layout->addWidget(suspect_);
    layout->addLayout(buttons);
    resize(980, 640);

    this->setMasses(0.0, 850.0, 25.0);
}

void CalibrationWizard::setSensorRange(double fullScale_V, double nominalSlope_V_per_g)
{
    if (fullScale_V > 0.0)
        fullScale_V_ = fullScale_V;
    if (!(nominalSlope_V_per_g > 0.0))
        return;
    // 90 % of the range leaves room for the bias and a swinging mass.
    constexpr double kStep_g = 50.0;
    const double top = std::floor(0.9 * fullScale_V_ / nominalSlope_V_per_g / kStep_g) * kStep_g;
    if (top >= 2 * kStep_g)
        setMasses(0.0, top, kStep_g);
}

int CalibrationWizard::saturatedRows() const
{
    int n = 0;
    for (int r = 0; r < table_->rowCount(); ++r)
        if (table_->item(r, Voltage)->data(Qt::UserRole + 1).toBool())
            ++n;
    return n;
}

QString CalibrationWizard::promptText() const { return prompt_->text(); }

void CalibrationWizard::showStepPrompt(int row)
{
    if (row < 0 || row >= table_->rowCount())
        return;
    prompt_->setText(loadMass_ ? tr("Step %1 of %2: the rig hangs %3 g; press Measure.").arg(row + 1).arg(table_->rowCount()).arg(massAt(row))
                               : tr("Step %1 of %2: hang %3 g on the sensor, then press Measure.").arg(row + 1).arg(table_->rowCount()).arg(massAt(row)));
}

void CalibrationWizard::refuseSaturated(int row, double volts)
{
    auto* item = table_->item(row, Voltage);
    updating_ = true;
    item->setData(Qt::UserRole, QVariant());
    item->setData(Qt::UserRole + 1, true);
    item->setText(tr("saturated"));
    table_->item(row, Use)->setCheckState(Qt::Unchecked);
    for (int c = 0; c < Columns; ++c)
        table_->item(row, c)->setBackground(QColor(255, 235, 190));
    updating_ = false;
    saturationNote_ = tr("%1 g saturates the input (%2 V, the range ends at ±%3 V): the point is refused. "
                         "Calibrate only up to the masses the sensor can read.")
                          .arg(massAt(row))
                          .arg(localNumber(volts, 4))
                          .arg(localNumber(fullScale_V_, 1));
    suspect_->setText(saturationNote_);
}

void CalibrationWizard::setDwell(double seconds) { dwell_s_ = std::max(0.01, seconds); }

void CalibrationWizard::setMasses(double from_g, double to_g, double step_g)
{
    stopMeasuring();
    saturationNote_.clear();
    for (auto [box, value] : {std::pair{from_, from_g}, {to_, to_g}, {step_, step_g}}) {
        const QSignalBlocker block(box);
        box->setValue(value);
    }
    updating_ = true;
    table_->setRowCount(0);
    for (double m = from_g; m <= to_g + 1e-9 && step_g > 0; m += step_g) {
        const int row = table_->rowCount();
        table_->insertRow(row);
        auto* mass = new QTableWidgetItem(QLocale().toString(m, 'f', 1));
        table_->setItem(row, Mass, mass);
        for (int c : {Voltage, Residual}) {
            auto* item = new QTableWidgetItem(QStringLiteral("–"));
            item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            table_->setItem(row, c, item);
        }
        auto* use = new QTableWidgetItem;
        use->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        use->setCheckState(Qt::Checked);
        table_->setItem(row, Use, use);
    }
    updating_ = false;
    table_->selectRow(0);
    refit();
    redraw();
    if (prompt_)
        showStepPrompt(0);
}

int CalibrationWizard::rowCount() const { return table_->rowCount(); }
// In the operator's notation (German "50,5"), as the spin boxes beside it; a point is taken too.
// Read with toDouble alone, "50,5" was 0 g.
double CalibrationWizard::massAt(int row) const
{
    const QString text = table_->item(row, Mass)->text().trimmed();
    bool ok = false;
    const double grams = QLocale().toDouble(text, &ok);
    return ok ? grams : QLocale::c().toDouble(text);
}
bool CalibrationWizard::usedAt(int row) const { return table_->item(row, Use)->checkState() == Qt::Checked; }
bool CalibrationWizard::measuredAt(int row) const { return table_->item(row, Voltage)->data(Qt::UserRole).isValid(); }

void CalibrationWizard::reject()
{
    int measured = 0;
    for (int row = 0; row < table_->rowCount(); ++row)
        measured += measuredAt(row);
    if (measured > 0 || isMeasuring()) {
        // Measuring waits while the operator is asked: it went on behind the question, which
        // then named fewer points than the table showed. Kept, the row is measured afresh.
        askingToDiscard_ = true;
        QMessageBox question(QMessageBox::Question, windowTitle(),
                             tr("Discard the %n point(s) measured? They are not saved.", nullptr, measured),
                             QMessageBox::Discard | QMessageBox::Cancel, this);
        question.setObjectName(QStringLiteral("discardPoints"));
        question.setDefaultButton(QMessageBox::Cancel);
        const bool discard = question.exec() == QMessageBox::Discard;
        askingToDiscard_ = false;
        if (!discard) {
            if (isMeasuring())
                beginRow(measuringRow_);
            return;
        }
    }
    stopMeasuring();
    QDialog::reject();
}

void CalibrationWizard::setPointUsed(int row, bool used)
{
    table_->item(row, Use)->setCheckState(used ? Qt::Checked : Qt::Unchecked);
}

void CalibrationWizard::measureCurrent()
{
    const int row = table_->currentRow() < 0 ? 0 : table_->currentRow();
    all_ = false;
    beginRow(row);
}

void CalibrationWizard::measureAll()
{
    all_ = true;
    beginRow(0);
}

void CalibrationWizard::stopMeasuring()
{
    const bool was = measuringRow_ >= 0;
    measuringRow_ = -1;
    all_ = false;
    if (prompt_)
        prompt_->clear();
    if (was)
        emit measuringChanged(false);
}

void CalibrationWizard::beginRow(int row)
{
    if (row < 0 || row >= table_->rowCount()) {
        stopMeasuring();
        return;
    }
    const bool was = measuringRow_ >= 0;
    measuringRow_ = row;
    startTime_ = -1.0;
    // Samples already seen (the rest of this batch too) were taken before the mass changed.
    notBefore_ = std::max(deviceNow_, lastSample_);
    sum_ = 0.0;
    count_ = 0;
    windowStart_ = -1.0;
    windowSum_ = windowSumSq_ = 0.0;
    windowCount_ = 0;
    previousMean_ = NAN;
    settled_ = false;
    peakAbs_V_ = 0.0;
    table_->selectRow(row);
    if (loadMass_)
        if (const auto from = loadMass_(massAt(row)))
            notBefore_ = std::max(notBefore_, *from);
    prompt_->setText(tr("Step %1 of %2: %3 g – waiting for the reading to settle, then averaging %4 s; keep the mass still…")
                         .arg(row + 1)
                         .arg(table_->rowCount())
                         .arg(massAt(row))
                         .arg(dwell_s_));
    if (!was)
        emit measuringChanged(true);
}

void CalibrationWizard::addSample(double time_s, double volts)
{
    lastSample_ = std::max(lastSample_, time_s);
    if (measuringRow_ < 0 || askingToDiscard_ || time_s <= notBefore_)
        return;
    if (startTime_ < 0.0)
        startTime_ = time_s;
    // A saturated reading says nothing about the mass: refuse the point at once.
    peakAbs_V_ = std::max(peakAbs_V_, std::abs(volts));
    if (peakAbs_V_ >= saturation_V()) {
        const int row = measuringRow_;
        refuseSaturated(row, volts);
        refit();
        redraw();
        const int next = row + 1;
        if (all_ && next < table_->rowCount())
            beginRow(next);
        else
            stopMeasuring();
        return;
    }
    if (!settled_) {
        // The swing after hanging a mass dies out: settled when the mean of a 0.1 s window moves
        // less than 3 standard errors (and 0.2 mV) from the window before. At most 5 s.
        constexpr double kWindow_s = 0.1, kMaxSettle_s = 5.0;
        if (windowStart_ < 0.0)
            windowStart_ = time_s;
        windowSum_ += volts;
        windowSumSq_ += volts * volts;
        ++windowCount_;
        if (time_s - windowStart_ < kWindow_s && time_s - startTime_ < kMaxSettle_s)
            return;
        const double mean = windowSum_ / windowCount_;
        const double var = std::max(0.0, windowSumSq_ / windowCount_ - mean * mean);
        const double tolerance = std::max(2e-4, 3.0 * std::sqrt(var / windowCount_) * std::sqrt(2.0));
        const bool steady = std::isfinite(previousMean_) && std::abs(mean - previousMean_) < tolerance;
        previousMean_ = mean;
        windowStart_ = -1.0;
        windowSum_ = windowSumSq_ = 0.0;
        windowCount_ = 0;
        if (!steady && time_s - startTime_ < kMaxSettle_s)
            return;
        settled_ = true;
        startTime_ = time_s;  // the dwell starts now
        return;
    }
    sum_ += volts;
    ++count_;
    if (time_s - startTime_ >= dwell_s_)
        finishRow();
}

void CalibrationWizard::finishRow()
{
    const int row = measuringRow_;
    const double mean = sum_ / std::max(1, count_);
    auto* item = table_->item(row, Voltage);
    item->setData(Qt::UserRole, mean);
    item->setData(Qt::UserRole + 1, QVariant());  // not (or no longer) saturated
    updating_ = true;
    item->setText(QLocale().toString(mean, 'f', 5));
    updating_ = false;
    refit();
    redraw();
    const int next = row + 1;
    if (all_ && next < table_->rowCount()) {
        beginRow(next);
        return;
    }
    stopMeasuring();
    if (next < table_->rowCount()) {
        table_->selectRow(next);
        showStepPrompt(next);
    } else {
        prompt_->setText(hasFit_ ? tr("All masses measured: check the fit and its residuals, then Save and use.")
                                 : tr("All masses measured, but there is no fit yet."));
    }
}

void CalibrationWizard::refit()
{
    std::vector<CalibrationPoint> points;
    fitRows_.clear();
    for (int r = 0; r < table_->rowCount(); ++r) {
        if (measuredAt(r) && usedAt(r)) {
            points.push_back({massAt(r), table_->item(r, Voltage)->data(Qt::UserRole).toDouble()});
            fitRows_.push_back(r);
        }
    }
    hasFit_ = false;
    try {
        if (points.size() >= 2) {
            fit_ = fitCalibration(points);
            hasFit_ = fit_.slope_V_per_g > 0.0;
        }
    } catch (const FitError& e) {
        fitLabel_->setText(e.message());
    }
    findSuspect(points);
    updating_ = true;
    for (int r = 0; r < table_->rowCount(); ++r) {
        table_->item(r, Residual)->setText(QStringLiteral("–"));
        for (int c = 0; c < Columns; ++c)
            table_->item(r, c)->setBackground(QBrush());
    }
    const int worst = worstRow();
    for (std::size_t k = 0; hasFit_ && k < fitRows_.size(); ++k)
        table_->item(fitRows_[k], Residual)->setText(QLocale().toString(fit_.residuals_V[k] * 1000.0, 'f', 3));
    if (worst >= 0)
        for (int c = 0; c < Columns; ++c)
            table_->item(worst, c)->setBackground(QColor(255, 205, 205));
    updating_ = false;
    if (hasFit_) {
        QString text = tr("d = %1 mV/g,  c = %2 V,  r² = %3,  rms residual = %4 mV,  %5 points")
                           .arg(QLocale().toString(fit_.slope_V_per_g * 1000.0, 'f', 4))
                           .arg(QLocale().toString(fit_.intercept_V, 'f', 4))
                           .arg(QLocale().toString(fit_.r2, 'f', 6))
                           .arg(QLocale().toString(fit_.rms_V * 1000.0, 'f', 3))
                           .arg(fitRows_.size());
        suspect_->clear();
        if (worst >= 0)
            suspect_->setText(tr("Suspect point: %1 g lies %2× the scatter of the other points off their line. Untick it to leave it out.")
                                                .arg(massAt(worst))
                                                .arg(localNumber(worstSigmas_, 0)));
        fitLabel_->setText(text);
    } else if (points.size() < 2) {
        suspect_->clear();
        fitLabel_->setText(tr("No fit yet: measure at least two masses."));
    }
    save_->setEnabled(hasFit_);
}

int CalibrationWizard::worstRow() const { return worst_; }

void CalibrationWizard::findSuspect(const std::vector<CalibrationPoint>& points)
{
    // The point farthest off the line is suspect when the line through the others misses it
    // by far more than those others scatter (a leave-one-out check: one bad point pulls the
    // full fit towards itself and hides in its rms).
    worst_ = -1;
    worstSigmas_ = 0.0;
    if (!hasFit_ || points.size() < 4)
        return;
    std::size_t k = 0;
    for (std::size_t i = 1; i < fit_.residuals_V.size(); ++i)
        if (std::abs(fit_.residuals_V[i]) > std::abs(fit_.residuals_V[k]))
            k = i;
    std::vector<CalibrationPoint> others = points;
    others.erase(others.begin() + std::ptrdiff_t(k));
    try {
        const CalibrationFit loo = fitCalibration(others);
        const double miss = points[k].voltage_V - (loo.intercept_V + loo.slope_V_per_g * points[k].mass_g);
        // Scatter below 0.01 % of the calibrated span is ADC quantisation, not a bad point.
        double lo = points.front().mass_g, hi = lo;
        for (const CalibrationPoint& p : points) {
            lo = std::min(lo, p.mass_g);
            hi = std::max(hi, p.mass_g);
        }
        const double scatter = std::max({loo.rms_V, 1e-4 * std::abs(loo.slope_V_per_g) * (hi - lo), 1e-6});
        worstSigmas_ = std::abs(miss) / scatter;
        if (worstSigmas_ > 6.0)
            worst_ = fitRows_[k];
    } catch (const FitError&) {
    }
}

void CalibrationWizard::showSaturation()
{
    // The refusal stays in view next to whatever the fit says.
    if (saturationNote_.isEmpty() || saturatedRows() == 0)
        return;
    const QString fitNote = suspect_->text();
    suspect_->setText(fitNote.isEmpty() || fitNote == saturationNote_ ? saturationNote_ : saturationNote_ + QLatin1Char('\n') + fitNote);
}

void CalibrationWizard::redraw()
{
    showSaturation();
    QVector<double> um, uv, rm, rv, wm, wv, xm, xv;
    for (int r = 0; r < table_->rowCount(); ++r) {
        if (!measuredAt(r))
            continue;
        const double v = table_->item(r, Voltage)->data(Qt::UserRole).toDouble();
        (usedAt(r) ? um : xm).push_back(massAt(r));
        (usedAt(r) ? uv : xv).push_back(v);
    }
    for (std::size_t k = 0; hasFit_ && k < fitRows_.size(); ++k) {
        rm.push_back(massAt(fitRows_[k]));
        rv.push_back(fit_.residuals_V[k] * 1000.0);
        if (fitRows_[k] == worst_) {
            wm.push_back(rm.back());
            wv.push_back(rv.back());
        }
    }
    plot_->graph(0)->setData(um, uv);
    plot_->graph(1)->setData(xm, xv);
    if (hasFit_) {
        const double lo = std::min(0.0, massAt(0)), hi = massAt(table_->rowCount() - 1);
        plot_->graph(2)->setData({lo, hi}, {fit_.intercept_V + fit_.slope_V_per_g * lo, fit_.intercept_V + fit_.slope_V_per_g * hi});
    } else {
        plot_->graph(2)->data()->clear();
    }
    plot_->graph(3)->setData(rm, rv);
    plot_->graph(4)->setData(wm, wv);
    double vLo = 0.0, vHi = 1.0;
    bool any = false;
    for (const QVector<double>* vs : {&uv, &xv}) {
        for (double v : *vs) {
            vLo = any ? std::min(vLo, v) : v;
            vHi = any ? std::max(vHi, v) : v;
            any = true;
        }
    }
    const double pad = std::max(0.05 * (vHi - vLo), 0.01);
    plot_->yAxis->setRange(vLo - pad, vHi + pad);
    const double last = table_->rowCount() ? massAt(table_->rowCount() - 1) : 100.0;
    plot_->xAxis->setRange(std::min(0.0, table_->rowCount() ? massAt(0) : 0.0) - 0.03 * last, 1.03 * last);
    auto* residualRect = plot_->axisRect(1);
    residualRect->axis(QCPAxis::atBottom)->setRange(plot_->xAxis->range());
    const double span = rv.isEmpty() ? 1.0 : std::max(1e-3, std::max(std::abs(*std::max_element(rv.begin(), rv.end())),
                                                                      std::abs(*std::min_element(rv.begin(), rv.end()))));
    residualRect->axis(QCPAxis::atLeft)->setRange(-1.2 * span, 1.2 * span);
    plot_->replot();
}

StoredCalibration CalibrationWizard::calibration() const
{
    StoredCalibration c;
    c.date = QDateTime::currentDateTime();
    c.sensor = sensor_;
    c.fit = fit_;
    for (int r = 0; r < table_->rowCount(); ++r) {
        if (!measuredAt(r))
            continue;
        const CalibrationPoint p{massAt(r), table_->item(r, Voltage)->data(Qt::UserRole).toDouble()};
        (usedAt(r) ? c.points : c.removed).push_back(p);
    }
    return c;
}

}  // namespace nb
