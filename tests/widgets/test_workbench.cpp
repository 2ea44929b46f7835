// The whole workbench on the simulated rig, driven like an operator would: the sequence
// from enable to a saved run file, the emergency stop key, stop motion vs end run, the
// calibration wizard on the simulated load cell, and recovery of a run cut off by a crash.
// Screenshots land in build-gui/screenshots/.
#include "main_window.h"
#include "support/needlebench_cli.h"
#include "support/simulated_window.h"
#include "widgets/export_dialog.h"
#include "widgets/label_model.h"
#include "widgets/review_workspace.h"
#include "translation.h"

#include "core/data_names.h"
#include "core/export/dataset_loader.h"
#include "core/export/fit_table.h"
#include "core/export/session_analysis.h"
#include "core/plan.h"
#include "core/plan_session.h"
#include "core/run_file.h"
#include "devices/acquisition_engine.h"
#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"
#include "widgets/calibration_wizard.h"
#include "widgets/control_panel.h"
#include "widgets/device_dialog.h"
#include "widgets/force_plots.h"
#include "widgets/session_info_dialog.h"
#include "widgets/session_view.h"
#include "widgets/welcome_dialog.h"
#include "widgets/simulated_rig_dialog.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QProcess>
#include <QRadioButton>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QSpinBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QDir>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QMessageBox>
#include <QTranslator>
#include <qcustomplot.h>
#include <QtTest>

using nb::Control;

namespace {

using nbtest::simulatedWindow;
// The window tests' rig: see support/simulated_window.h.
nb::WorkbenchOptions options(const QString& sessionDir, bool realtime,
                             std::shared_ptr<nb::devices::sim::SimulatedRig>* rig = nullptr)
{
    return simulatedWindow(sessionDir, realtime, rig);
}

QString screenshotDir()
{
    const QString dir = QStringLiteral(NB_BINARY_DIR "/screenshots");
    QDir().mkpath(dir);
    return dir;
}


// A completed linear run of one second (500 samples) at `path`, as the recorder writes it.
void writeCompletedRun(const QString& path)
{
    nb::RunFileWriter writer;
    nb::Metadata meta;
    meta.set(QStringLiteral("motion"), QStringLiteral("linear"));
    writer.open(path, meta, {QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N")});
    for (int i = 0; i < 500; ++i) {
        const double row[] = {i * 0.002, i * 0.008, 0.001 * i};
        writer.writeRow(row);
    }
    nb::Metadata footer;
    footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
    writer.close(footer);
}

// Enable, bias and zero through the panel's buttons, checking the start stays locked until all are done.
void prepare(nb::MainWindow& w)
{
    nb::ControlPanel* p = w.controlPanel();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().devicesRunning, 20000);
    QAbstractButton* start = p->button(Control::StartInsertion);
    QVERIFY(!start->isEnabled());
    QVERIFY(!p->button(Control::Zero)->isEnabled());
    QTest::mouseClick(p->button(Control::Enable), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().stageEnabled, 20000);
    QVERIFY(!start->isEnabled());
    QVERIFY(start->toolTip().contains(QStringLiteral("Bias")));
    QTest::mouseClick(p->button(Control::Bias), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().biased, 20000);
    QVERIFY(!start->isEnabled());
    QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::Zero)->isEnabled(), qPrintable(p->button(Control::Zero)->toolTip()), 20000);
    QTest::mouseClick(p->button(Control::Zero), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().zeroed, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(start->isEnabled(), 20000);
}

void setVelocityAndDepth(nb::ControlPanel& p, double velocity, double depth)
{
    p.findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->setValue(velocity);
    p.findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->setValue(depth);
}

void setMotion(nb::MainWindow& w, double velocity, double depth)
{
    w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->setValue(velocity);
    w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->setValue(depth);
}

}  // namespace

// The window's calibration wizard, opened as the operator opens it once the devices run
// (nullptr when it does not open).
static nb::CalibrationWizard* openCalibrationWizard(nb::MainWindow& w)
{
    if (!QTest::qWaitForWindowExposed(&w) || !QTest::qWaitFor([&w] { return w.controlPanel()->interlockState().devicesRunning; }, 20000))
        return nullptr;
    QTest::mouseClick(w.controlPanel()->button(Control::Calibrate), Qt::LeftButton);
    auto* wizard = w.findChild<nb::CalibrationWizard*>();
    return wizard && QTest::qWaitForWindowExposed(wizard) ? wizard : nullptr;
}

class TestWorkbench : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);  // the settings of the restart test, not the user's
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_workbench"));
    }

    void fullRunFromEnableToSavedFile()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("session"));
        nb::MainWindow w(options(dir, true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.session());
        setMotion(w, 10.0, 30.0);  // 3 s in real time, past the puncture of the simulated liver
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().recording, 20000);
        QVERIFY(!w.controlPanel()->button(Control::StartInsertion)->isEnabled());
        QVERIFY(!w.controlPanel()->button(Control::Bias)->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(w.plots()->sampleCount() > 1200, 20000);
        QVERIFY(w.grab().save(screenshotDir() + QStringLiteral("/main_window_run.png")));
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("completed"));
        QVERIFY(w.plots()->framesDrawn() > 10);
        QVERIFY(w.plots()->eventCount() >= 2);  // contact and puncture marked
        QVERIFY(w.grab().save(screenshotDir() + QStringLiteral("/main_window_after_run.png")));

        QCOMPARE(QFileInfo(w.lastRunPath()).fileName(), QStringLiteral("run_001_linear.csv"));
        QCOMPARE(QFileInfo(w.lastRunPath()).absolutePath(), QDir(dir).absolutePath());
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QVERIFY(r.run.size() > 1500);
        QCOMPARE(r.run.meta(QStringLiteral("end_reason")).value_or(QString()), QStringLiteral("completed"));
        QVERIFY(!r.run.meta(QStringLiteral("calibration")).value_or(QString()).isEmpty());
        QCOMPARE(r.run.meta(QStringLiteral("motion")).value_or(QString()), QStringLiteral("linear"));
        QCOMPARE(r.run.metadata.number(QStringLiteral("depth_mm")).value_or(0.0), 30.0);
        const double deepest = *std::max_element(r.run.position_mm.begin(), r.run.position_mm.end());
        QVERIFY2(deepest > 29.5 && deepest < 30.5, qPrintable(QString::number(deepest)));

        nb::RunListModel* model = w.sessionView()->model();
        QCOMPARE(model->rowCount(), 1);
        QCOMPARE(model->index(0, nb::RunListModel::State).data().toString(), QStringLiteral("completed"));
        // The next run gets the next name.
        QCOMPARE(QFileInfo(w.session()->nextRunPath(QStringLiteral("linear"))).fileName(), QStringLiteral("run_002_linear.csv"));
    }

    void emergencyStopKey()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        w.activateWindow();  // under X without a window manager (xvfb-run) nothing else does
        QVERIFY(QTest::qWaitForWindowActive(&w));
        setMotion(w, 5.0, 60.0);
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().moving, 20000);
        // Esc works wherever the focus is: here a plot has it.
        w.plots()->forceTimePlot()->setFocus();
        QTest::keyClick(w.plots()->forceTimePlot(), Qt::Key_Escape);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controlPanel()->interlockState().moving, 20000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("emergency_stop"));
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QCOMPARE(r.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("emergency_stop"));
        QCOMPARE(r.run.footer.value(QStringLiteral("emergency_stop"), QString()), QStringLiteral("operator"));
        // The stop latches: the drive is off and nothing moves until the operator enables it.
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().latched, 20000);
        QVERIFY(!w.controlPanel()->interlockState().stageEnabled);
        QVERIFY(!w.controlPanel()->button(Control::StartInsertion)->isEnabled());
        QVERIFY(!w.controlPanel()->button(Control::Withdraw)->isEnabled());
        const double deepest = *std::max_element(r.run.position_mm.begin(), r.run.position_mm.end());
        QVERIFY(deepest < 59.0);  // stopped well before the planned depth
    }

    void stopMotionKeepsRecordingUntilEndRun()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 5.0, 60.0);
        prepare(w);
        nb::ControlPanel* p = w.controlPanel();
        QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().moving, 20000);
        QVERIFY(!p->button(Control::EndRun)->isEnabled());  // End run never doubles as a stop
        QTest::mouseClick(p->button(Control::StopMotion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!p->interlockState().moving, 20000);
        const std::size_t before = w.plots()->sampleCount();
        QTRY_VERIFY_WITH_TIMEOUT(w.plots()->sampleCount() > before + 300, 20000);
        QVERIFY(p->interlockState().recording);  // the stop did not close the run
        QCOMPARE(w.runsEnded(), 0);
        QVERIFY(p->button(Control::Withdraw)->text() == QStringLiteral("Withdraw (recorded)"));
        QTRY_VERIFY_WITH_TIMEOUT(p->button(Control::EndRun)->isEnabled(), 20000);
        QTest::mouseClick(p->button(Control::EndRun), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 20000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("stopped"));
        QCOMPARE(w.sessionView()->model()->index(0, nb::RunListModel::State).data().toString(), QStringLiteral("ended by operator"));
    }

    void forceLimitStopsTheRunAndSaysSo()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 10.0, 40.0);
        w.controlPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("forceLimit"))->setValue(0.5);
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("force_limit"));
        QTRY_VERIFY_WITH_TIMEOUT(!w.controlPanel()->interlockState().moving, 20000);
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        const double deepest = *std::max_element(r.run.position_mm.begin(), r.run.position_mm.end());
        QVERIFY(deepest < 30.0);
        QCOMPARE(w.sessionView()->model()->index(0, nb::RunListModel::State).data().toString(),
                 QStringLiteral("force limit"));
        QVERIFY(w.plots()->eventCount() >= 1);  // the trip is marked on the plots
    }

    // The default 8 N limit is beyond the 7.79 N the nominal chain reads at +10 V: the margin
    // the panel and the plot show is to where the stage stops, the reading's end (the plot said
    // 8.00 N, the limit less the force).
    void theMarginIsToWhereTheStageStops()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        prepare(w);
        auto plotMargin = [&w] {
            for (QCustomPlot* p : w.plots()->findChildren<QCustomPlot*>())
                for (int i = 0; i < p->itemCount(); ++i)
                    if (auto* t = qobject_cast<QCPItemText*>(p->item(i)); t && t->text().contains(QStringLiteral("margin")))
                        return t->text();
            return QString();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(plotMargin().contains(QStringLiteral("margin 7.7")), qPrintable(plotMargin()), 10000);
        QVERIFY(w.engine()->status().forceMargin_N < 7.8);
    }

    void sensorUnpluggedDuringARun()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 5.0, 60.0);
        prepare(w);
        nb::ControlPanel* p = w.controlPanel();
        QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().moving, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.plots()->sampleCount() > 500, 20000);
        const double beforeFault_s = w.engine()->status().runTime_s;  // recorded by now, on the device clock
        rig->injectFault(nb::devices::sim::Fault::SensorSilent);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QCOMPARE(w.lastEndReason(), QStringLiteral("fault"));
        QTRY_VERIFY_WITH_TIMEOUT(!p->interlockState().fault.isEmpty(), 20000);
        // What was recorded is kept and readable; nothing but the E-stop invites a new run.
        // The file's times are rounded to the microsecond; the engine's clock is not (half a sample's slack).
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QVERIFY2(beforeFault_s > 0.3 && r.run.size() > 0 && r.run.time_s.back() >= beforeFault_s - 0.0005,
                 qPrintable(QStringLiteral("%1 samples to %2 s; %3 s recorded before the fault")
                                .arg(r.run.size()).arg(r.run.size() ? r.run.time_s.back() : 0.0).arg(beforeFault_s)));
        QVERIFY(r.run.size() >= std::size_t(beforeFault_s * 1000.0 * 0.999));  // 1 kHz, nothing lost
        QVERIFY(!p->button(Control::StartInsertion)->isEnabled());
        QVERIFY(p->button(Control::StartInsertion)->toolTip().contains(QStringLiteral("fault")));
        QVERIFY(p->button(Control::EmergencyStop)->isEnabled());
        QCOMPARE(w.sessionView()->model()->index(0, nb::RunListModel::State).data().toString(), QStringLiteral("device fault"));
    }

    void calibrationWizardOnTheSimulatedSensor()
    {
        QTemporaryDir tmp;
        // Real time: the wizard averages what the live stream delivers while the mass hangs.
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        nb::CalibrationWizard* wizard = openCalibrationWizard(w);
        QVERIFY(wizard);
        // The default masses stop short of the ±10 V input: 0 to 700 g in 50 g steps at the
        // simulated chain's 12.07 mV/g (800 g would saturate).
        const double slope = w.engine()->nominalSlope_V_per_g();
        const double top_g = std::floor(0.9 * 10.0 / slope / 50.0) * 50.0;
        QCOMPARE(wizard->rowCount(), int(top_g / 50.0) + 1);
        QVERIFY(top_g * slope < wizard->saturation_V());
        QVERIFY(wizard->promptText().contains(QStringLiteral("Step 1 of")));

        // Masses the sensor cannot read are refused, saying so, not taken as suspect points.
        wizard->setMasses(600.0, 850.0, 50.0);
        wizard->measureAll();
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->isMeasuring(), 60000);
        QVERIFY2(wizard->saturatedRows() >= 2, qPrintable(QString::number(wizard->saturatedRows())));  // 800 and 850 g
        QVERIFY(!wizard->table()->item(wizard->rowCount() - 1, 1)->data(Qt::UserRole).isValid());
        QVERIFY(wizard->findChild<QLabel*>(QStringLiteral("suspectLabel"))->text().contains(QStringLiteral("saturates")));
        QCOMPARE(wizard->calibration().points.size(), std::size_t(wizard->rowCount() - wizard->saturatedRows()));

        wizard->setMasses(0.0, 300.0, 50.0);
        QCOMPARE(wizard->rowCount(), 7);
        auto* measureAll = wizard->findChildren<QPushButton*>().at(0);
        for (QPushButton* b : wizard->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Measure all"))
                measureAll = b;
        QTest::mouseClick(measureAll, Qt::LeftButton);
        QVERIFY(wizard->isMeasuring());
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->isMeasuring(), 60000);
        QVERIFY(wizard->hasFit());
        const double nominal = nb::devices::sim::SensorChainConfig{}.slope_V_per_g();
        QVERIFY2(std::abs(wizard->fit().slope_V_per_g - nominal) < 0.02 * nominal,
                 qPrintable(QString::number(wizard->fit().slope_V_per_g)));
        QVERIFY(wizard->fit().r2 > 0.999);
        QCOMPARE(wizard->worstRow(), -1);

        // A mass mislabelled by the operator (150 g row measured with 230 g on the hook).
        wizard->setLoadMassHook([&rig](double g) { return std::optional(rig->setLoadMass_g(g == 150.0 ? 230.0 : g)); });
        wizard->table()->selectRow(3);
        wizard->measureCurrent();
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->isMeasuring(), 60000);
        QCOMPARE(wizard->worstRow(), 3);
        QVERIFY(wizard->fit().r2 < 0.999);
        QVERIFY(wizard->grab().save(screenshotDir() + QStringLiteral("/calibration_wizard_bad_point.png")));
        QTest::mouseClick(wizard->table()->viewport(), Qt::LeftButton, {},
                          wizard->table()->visualRect(wizard->table()->model()->index(3, 3)).center());
        // Unticking the point drops it from the fit (the click may land on the text, so make sure).
        if (wizard->worstRow() == 3)
            wizard->setPointUsed(3, false);
        QVERIFY(wizard->fit().r2 > 0.999);
        QCOMPARE(wizard->worstRow(), -1);  // what is left is sensor noise: nothing flagged
        QCOMPARE(wizard->calibration().removed.size(), 1u);
        QCOMPARE(wizard->calibration().points.size(), 6u);
        QVERIFY(wizard->grab().save(screenshotDir() + QStringLiteral("/calibration_wizard.png")));

        // Esc with the points measured and not saved asks first (it threw them away at once);
        // Cancel keeps the wizard and its points.
        bool asked = false;
        QTimer::singleShot(0, wizard, [&] {
            if (auto* q = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                q && q->objectName() == QLatin1String("discardPoints")) {
                asked = q->text().startsWith(QStringLiteral("Discard the 7 point"));
                q->button(QMessageBox::Cancel)->click();
            }
        });
        QTest::keyClick(wizard, Qt::Key_Escape);
        QVERIFY(asked);
        QVERIFY(wizard->isVisible());
        QCOMPARE(wizard->calibration().points.size(), 6u);

        for (QPushButton* b : wizard->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Save and use"))
                QTest::mouseClick(b, Qt::LeftButton);
        const auto active = w.session()->activeCalibration();
        QVERIFY(active);
        QCOMPARE(active->removed.size(), 1u);
        QTRY_COMPARE_WITH_TIMEOUT(w.engine()->status().calibrationName, active->name, 20000);
        QVERIFY(std::abs(w.engine()->status().slope_V_per_g - active->fit.slope_V_per_g) < 1e-12);
    }

    // Esc during Measure all: measuring waits while the operator is asked, so the question
    // names every point the table shows; kept, it goes on to the last row.
    void calibrationWaitsWhileDiscardIsAsked()
    {
        QTemporaryDir tmp;
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true, &rig));
        w.show();
        nb::CalibrationWizard* wizard = openCalibrationWizard(w);
        QVERIFY(wizard);
        wizard->setMasses(0.0, 300.0, 50.0);
        const auto measured = [wizard] {
            int n = 0;
            for (int row = 0; row < wizard->rowCount(); ++row)
                n += wizard->table()->item(row, 1)->data(Qt::UserRole).isValid();
            return n;
        };
        wizard->measureAll();
        QTRY_VERIFY_WITH_TIMEOUT(measured() >= 2, 60000);
        QVERIFY(wizard->isMeasuring());
        int asked = -1, whileAsked = -1;
        QTimer::singleShot(0, wizard, [&] {
            auto* q = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!q || q->objectName() != QLatin1String("discardPoints"))
                return;
            const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("Discard the (\\d+) point")).match(q->text());
            asked = m.hasMatch() ? m.captured(1).toInt() : -2;
            QTest::qWait(6000);  // the operator reads the question: a row's dwell and more
            whileAsked = measured();
            q->button(QMessageBox::Cancel)->click();
        });
        QTest::keyClick(wizard, Qt::Key_Escape);
        QVERIFY(asked >= 2);
        QCOMPARE(whileAsked, asked);
        QVERIFY(wizard->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->isMeasuring(), 90000);
        QCOMPARE(measured(), wizard->rowCount());
    }

    void recoversAnInterruptedRunAtStart()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("s"));
        nb::Session::create(dir, {});
        const QString crashed = QDir(dir).filePath(QStringLiteral("run_001_linear.csv"));
        {
            nb::RunFileWriter writer;
            nb::Metadata meta;
            meta.set(QStringLiteral("motion"), QStringLiteral("linear"));
            writer.open(crashed, meta, {QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N")});
            for (int i = 0; i < 500; ++i) {
                const double row[] = {i * 0.002, i * 0.008, 0.001 * i};
                writer.writeRow(row);
            }
            writer.flush();
            QFile f(crashed);  // the process died mid-row, before any footer
            QVERIFY(f.open(QIODevice::Append));
            f.write("1.0000,4.0");
        }
        nb::MainWindow w(options(dir, false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.recoveredRuns().size(), 1);
        // Said in a box that does not block the window (the status bar's line was overwritten
        // by the devices' first messages at once).
        auto* box = w.findChild<QMessageBox*>(QStringLiteral("interruptedRuns"));
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains(QStringLiteral("run_001_linear.csv")), qPrintable(box->text()));
        QCOMPARE(QApplication::activeModalWidget(), nullptr);
        box->accept();
        const nb::RunReadResult r = nb::readRunFile(crashed);
        QCOMPARE(r.run.size(), 500u);
        QCOMPARE(r.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("recovered"));
        QCOMPARE(w.sessionView()->model()->index(0, nb::RunListModel::State).data().toString(), QStringLiteral("recovered"));
        // The next run does not overwrite it.
        QCOMPARE(QFileInfo(w.session()->nextRunPath(QStringLiteral("linear"))).fileName(), QStringLiteral("run_002_linear.csv"));
    }

    // Review shows a run of the open session only (edits to a run of the last one went to its
    // files), and the keyboard goes to it with the tab (Space pressed the control panel's last
    // button: the stage was disabled and its zero lost).
    void reviewBelongsToTheOpenSession()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("a")), b = tmp.filePath(QStringLiteral("b"));
        nb::Session::create(a, {});
        const QString run = QDir(a).filePath(QStringLiteral("run_001_linear.csv"));
        writeCompletedRun(run);
        nb::MainWindow w(options(a, false));
        w.show();
        w.activateWindow();  // under X without a window manager (xvfb-run) nothing else does
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.controlPanel()->button(Control::Enable)->setFocus();
        w.reviewRun(run);
        QCOMPARE(w.workspaces()->currentWidget(), static_cast<QWidget*>(w.reviewWorkspace()));
        QTRY_VERIFY(w.reviewWorkspace()->hasFocus());
        QCOMPARE(w.reviewWorkspace()->runPath(), run);
        // Opened again from the session list, with Review already the tab: the keyboard leaves the list.
        QAbstractItemView* list = w.sessionView()->findChild<QTableView*>();
        QVERIFY(list);
        list->setFocus();
        QTRY_VERIFY(list->hasFocus());
        const QRect row = list->visualRect(list->model()->index(0, 0));
        QSignalSpy activated(w.sessionView(), &nb::SessionView::runActivated);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, row.center());  // as a double-click begins
        QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, row.center());
        QCOMPARE(activated.size(), 1);
        QTRY_VERIFY2(w.reviewWorkspace()->hasFocus(), qPrintable(QApplication::focusWidget() ? QApplication::focusWidget()->metaObject()->className() : QStringLiteral("none")));
        w.reviewWorkspace()->setCursorTime(0.7);
        QVERIFY(w.createSession(b, {}));
        QVERIFY(w.reviewWorkspace()->runPath().isEmpty());
        QCOMPARE(w.reviewWorkspace()->labelModel()->labels().size(), std::size_t(0));
        QCOMPARE(w.reviewWorkspace()->cursorTime(), 0.0);  // the old run's place goes with it
    }

    // A run that ended at depth leaves the needle in the tissue: quitting asks (it went at once,
    // and with it the panel that withdraws the needle); after To start it does not.
    void quitAsksWhileTheNeedleIsInTissue()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 10.0, 30.0);
        nbtest::prepareToRecord(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().inTissue, 10000);
        QVERIFY(!w.close());
        auto* question = w.findChild<QMessageBox*>(QStringLiteral("quitQuestion"));
        QVERIFY(question && question->isVisible());
        QVERIFY2(question->text().contains(QStringLiteral("still in the tissue")), qPrintable(question->text()));
        question->button(QMessageBox::No)->click();
        QVERIFY(w.isVisible());
        QVERIFY(w.controlPanel()->button(Control::Withdraw)->isEnabled());
    }

    // A run just saved comes into view in the session's list, below the runs before it (run 6
    // was half hidden, run 10 out of sight).
    void aRunJustSavedIsInView()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("s"));
        nb::Session::create(dir, {});
        for (int i = 1; i <= 12; ++i)
            writeCompletedRun(QDir(dir).filePath(QStringLiteral("run_%1_linear.csv").arg(i, 3, 10, QLatin1Char('0'))));
        nb::Session session = nb::Session::open(dir);
        nb::SessionView view;
        view.resize(700, 220);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setSession(&session);
        writeCompletedRun(QDir(dir).filePath(QStringLiteral("run_013_linear.csv")));
        view.refresh();
        QCOMPARE(view.model()->rowCount(), 13);
        const QModelIndex newest = view.model()->index(12, 0);
        QCOMPARE(newest.data(Qt::UserRole).toString(), QDir(dir).filePath(QStringLiteral("run_013_linear.csv")));
        QTRY_VERIFY(view.view()->viewport()->rect().contains(view.view()->visualRect(newest)));
    }

    // Jogged in (never recorded, so no contact is marked) and stopped there by the emergency
    // stop: quitting asks all the same; it went at once with the needle 7 mm deep.
    void quitAsksWhenJoggedAwayFromTheStart()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        nbtest::prepareToRecord(w);
        w.engine()->jog(7.0, 10.0);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().position_mm > 3.0, 10000);
        w.engine()->emergencyStop();
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().latched && !w.engine()->status().moving, 10000);
        QVERIFY(!w.controlPanel()->interlockState().inTissue);
        QVERIFY(!w.close());
        auto* question = w.findChild<QMessageBox*>(QStringLiteral("quitQuestion"));
        QVERIFY(question && question->isVisible());
        QVERIFY2(question->text().contains(QStringLiteral("mm from its start")), qPrintable(question->text()));
        question->button(QMessageBox::Yes)->click();
        QTRY_VERIFY(!w.isVisible());
    }

    // A signal closes the window without the question (nobody is there to answer it: after a
    // SIGTERM the process waited for ever), the needle away from its start all the same.
    void aSignalClosesWithoutAsking()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        nbtest::prepareToRecord(w);
        w.engine()->moveTo(5.0, 10.0);
        QTRY_VERIFY_WITH_TIMEOUT(!w.engine()->status().moving && w.engine()->status().position_mm > 4.0, 20000);
        QVERIFY(!w.close());  // the operator's quit asks
        QVERIFY(w.findChild<QMessageBox*>(QStringLiteral("quitQuestion")));
        w.closeWithoutAsking();  // a signal's does not wait for the answer
        QVERIFY(!w.isVisible());
    }

    // Zeroed with the needle in the tissue ("Zero anyway"): neither the position nor a contact
    // says it is in, but the force does, and quitting asks (it went at once at 0.6 N).
    void quitAsksWhileAForceIsOnTheNeedle()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        nbtest::prepareToRecord(w);
        w.engine()->moveTo(14.0, 10.0);
        QTRY_VERIFY_WITH_TIMEOUT(!w.engine()->status().moving && w.engine()->status().position_mm > 13.0, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().loaded, 10000);
        w.engine()->zeroStage(true);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(w.engine()->status().position_mm) < 0.1, 10000);
        QVERIFY(!w.controlPanel()->interlockState().inTissue);
        QVERIFY(w.engine()->status().loaded);
        QVERIFY(!w.close());
        auto* question = w.findChild<QMessageBox*>(QStringLiteral("quitQuestion"));
        QVERIFY(question && question->isVisible());
        QVERIFY2(question->text().contains(QStringLiteral("N is on the needle")), qPrintable(question->text()));
        // Its answers are said: the question asks "withdraw first, or quit?", which no Yes answers.
        QCOMPARE(question->button(QMessageBox::Yes)->text(), QStringLiteral("Quit"));
        QCOMPARE(question->button(QMessageBox::No)->text(), QStringLiteral("Don't quit"));
        question->button(QMessageBox::No)->click();
        QVERIFY(w.isVisible());
    }

    // The sensor's nominal calibration is refused while a run records, as the wizard is: taken,
    // it changed the run's force scale from one sample to the next, under a header naming the
    // calibration before.
    void noCalibrationChangeWhileRecording()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));  // in real time: the run lasts
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 0.5, 30.0);  // a minute's run: recording throughout
        nbtest::prepareToRecord(w);
        const QString before = w.engine()->status().calibrationName;
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().recording, 20000);
        QAction* nominal = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text().remove(QLatin1Char('&')) == QStringLiteral("Use the sensor's nominal calibration"))
                nominal = a;
        QVERIFY(nominal);
        nominal->trigger();
        QVERIFY2(w.statusBar()->currentMessage().startsWith(QStringLiteral("Not now")), qPrintable(w.statusBar()->currentMessage()));
        QTest::qWait(300);  // what the engine would have taken by now
        QCOMPARE(w.engine()->status().calibrationName, before);
        // The engine refuses it too, whoever asks.
        w.engine()->setCalibration(w.engine()->status().slope_V_per_g / 2, QStringLiteral("half"));
        QTest::qWait(300);
        QVERIFY(w.engine()->status().recording);
        QCOMPARE(w.engine()->status().calibrationName, before);
        w.engine()->emergencyStop();
    }

    // A second window on a session already open in one is refused, named in a box: it closed
    // the first's recording as "recovered" and both recorded into the folder. Free again once
    // the first window goes.
    void oneWindowASession()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("s"));
        auto first = std::make_unique<nb::MainWindow>(options(dir, false));
        QVERIFY(first->session());
        {
            nb::MainWindow second(options(QString(), false));
            QVERIFY(!second.openSession(dir));
            QVERIFY(!second.session());
            auto* box = second.findChild<QMessageBox*>(QStringLiteral("sessionInUse"));
            QVERIFY(box);
            QVERIFY2(box->text().contains(QDir::toNativeSeparators(dir)) && box->text().contains(QString::number(QCoreApplication::applicationPid())),
                     qPrintable(box->text()));
            // The first window opens its own session again without a word.
            QVERIFY(first->openSession(dir));
        }
        first.reset();
        nb::MainWindow third(options(QString(), false));
        QVERIFY(third.openSession(dir));
        QVERIFY(third.session());
    }

    // Start pressed and refused by the engine (here the session folder was deleted meanwhile):
    // the reason in a box, not only in a status line gone in a few seconds.
    void refusedStartIsSaidInABox()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("gone"));
        nb::MainWindow w(options(dir, false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 10.0, 5.0);
        nbtest::prepareToRecord(w);
        QVERIFY(QDir(dir).removeRecursively());
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QMessageBox* box = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT((box = w.findChild<QMessageBox*>(QStringLiteral("runNotStarted"))) && box->isVisible(), 20000);
        QVERIFY2(box->text().contains(QStringLiteral("run_001_linear.csv")), qPrintable(box->text()));
        QVERIFY(!box->isModal());
        QCOMPARE(w.runsEnded(), 0);
        box->accept();
    }

    // What the operator looked at comes back after a restart: the session, the Review tab, its
    // run and the place in it. A run deleted meanwhile is said to be gone, and Record shows.
    void restartKeepsTheReview()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("a"));
        nb::Session::create(a, {});
        const QString run = QDir(a).filePath(QStringLiteral("run_001_linear.csv"));
        writeCompletedRun(run);
        auto persisted = [](const QString& dir) {
            nb::WorkbenchOptions o = options(dir, false);
            o.persistSettings = true;
            return o;
        };
        {
            nb::MainWindow w(persisted(a));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.reviewRun(run);
            w.reviewWorkspace()->setCursorTime(0.5);
            // The operator slows playback down, in the box beside Play.
            auto* speed = w.reviewWorkspace()->findChild<QComboBox*>(QStringLiteral("reviewSpeed"));
            QVERIFY(speed);
            speed->setCurrentIndex(speed->findData(0.25));
            QCOMPARE(w.reviewWorkspace()->speed(), 0.25);
            QVERIFY(w.close());
        }
        {
            nb::MainWindow w(persisted(QString()));  // the last session, as a plain start opens it
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.session());
            QCOMPARE(QDir(w.session()->dir()).canonicalPath(), QDir(a).canonicalPath());
            QCOMPARE(w.workspaces()->currentWidget(), static_cast<QWidget*>(w.reviewWorkspace()));
            QCOMPARE(w.reviewWorkspace()->runPath(), run);
            QCOMPARE(w.reviewWorkspace()->cursorTime(), 0.5);
            QCOMPARE(w.reviewWorkspace()->speed(), 0.25);
            QCOMPARE(w.reviewWorkspace()->findChild<QComboBox*>(QStringLiteral("reviewSpeed"))->currentData().toDouble(), 0.25);
            // and it is the run selected in the session's list
            const QModelIndexList selected = w.sessionView()->view()->selectionModel()->selectedRows();
            QCOMPARE(selected.size(), 1);
            QCOMPARE(selected.first().data(Qt::UserRole).toString(), run);
            QVERIFY(w.close());
        }
        // With the run's own video, 3 s long against the run's 1 s: a place in the video past the
        // recording comes back too (it was clamped to the run's end, the video not yet indexed).
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-f", "lavfi", "-i", "testsrc=size=160x120:rate=30:duration=3",
                                               "-c:v", "mjpeg", QDir(a).filePath(QStringLiteral("run_001_linear.avi"))});
        QVERIFY2(ffmpeg.waitForStarted(10000), "the ffmpeg tool is missing (scripts/install-deps.sh installs it)");
        QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        {
            nb::MainWindow w(persisted(QString()));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QTRY_VERIFY_WITH_TIMEOUT(w.reviewWorkspace()->currentFrame() >= 0, 30000);
            w.reviewWorkspace()->setCursorTime(2.5);
            QCOMPARE(w.reviewWorkspace()->cursorTime(), 2.5);
            QVERIFY(w.close());
        }
        {
            nb::MainWindow w(persisted(QString()));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QTRY_VERIFY_WITH_TIMEOUT(w.reviewWorkspace()->currentFrame() >= 0, 30000);
            QTRY_COMPARE(w.reviewWorkspace()->cursorTime(), 2.5);
            QVERIFY(w.close());
        }
        QVERIFY(QFile::remove(run));
        {
            nb::MainWindow w(persisted(QString()));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCOMPARE(w.workspaces()->currentWidget(), static_cast<QWidget*>(w.plots()));
            QVERIFY(w.reviewWorkspace()->runPath().isEmpty());
            QVERIFY2(w.statusBar()->toolTip().contains(QStringLiteral("run_001_linear.csv")), qPrintable(w.statusBar()->toolTip()));
            QVERIFY2(w.reviewWorkspace()->status().contains(QStringLiteral("run_001_linear.csv")), qPrintable(w.reviewWorkspace()->status()));
            QVERIFY(w.close());
        }
        QSettings().remove(QStringLiteral("session/last"));
        QSettings().remove(QStringLiteral("review/run"));
        QSettings().remove(QStringLiteral("review/speed"));
    }

    // The panel's fields come back after a restart, and after a crash too: they were written
    // only at quit, so a kill -9 brought back an older, higher force limit; the mode, cycles and
    // jog step were not kept at all.
    void restartKeepsThePanel()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("a"));
        nb::Session::create(a, {});
        nb::WorkbenchOptions o = options(a, false);
        o.persistSettings = true;
        {
            nb::MainWindow w(o);
            nb::ControlPanel* p = w.controlPanel();
            p->findChild<QRadioButton*>(QStringLiteral("sine"))->setChecked(true);
            p->findChild<QSpinBox*>(QStringLiteral("cycles"))->setValue(4);
            auto* jog = p->findChild<QComboBox*>(QStringLiteral("jogStep"));
            jog->setCurrentIndex(jog->findData(0.1));
            QVERIFY(jog->currentIndex() >= 0);
            p->setForceLimit(2.0);
            p->setWithdrawForceLimit(6.0);
            // No close(): the window goes as a crash takes it, without its closeEvent.
        }
        {
            nb::MainWindow w(o);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            nb::ControlPanel* p = w.controlPanel();
            // The limits restored are no news for the status line ("withdrawal force limit 6 N").
            QTest::qWait(500);
            QVERIFY2(!w.statusBar()->currentMessage().contains(QStringLiteral("force limit")), qPrintable(w.statusBar()->currentMessage()));
            QCOMPARE(p->withdrawForceLimit(), 6.0);
            QVERIFY(p->findChild<QRadioButton*>(QStringLiteral("sine"))->isChecked());
            QCOMPARE(p->findChild<QSpinBox*>(QStringLiteral("cycles"))->value(), 4);
            QCOMPARE(p->findChild<QComboBox*>(QStringLiteral("jogStep"))->currentData().toDouble(), 0.1);
            QCOMPARE(p->forceLimit(), 2.0);
            p->findChild<QRadioButton*>(QStringLiteral("linear"))->setChecked(true);
            p->setForceLimit(8.0);
            p->setWithdrawForceLimit(9.5);
            QVERIFY(w.close());
        }
        for (const char* key : {"motion/sine", "motion/cycles", "motion/jogStep_mm"})
            QSettings().remove(QLatin1String(key));
    }

    // Open session… starts beside the open session (it started in the working folder).
    void openSessionStartsBesideTheOpenOne()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("a"));
        nb::Session::create(a, {});
        nb::MainWindow w(options(a, false));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QAction* open = nullptr;
        for (QAction* action : w.findChildren<QAction*>())
            if (action->text() == QStringLiteral("&Open session…"))
                open = action;
        QVERIFY(open);
        QString shown;
        QTimer::singleShot(200, &w, [&] {
            if (auto* chooser = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
                shown = chooser->directory().absolutePath();
                chooser->reject();
            }
        });
        open->trigger();
        QCOMPARE(QDir(shown).canonicalPath(), QDir(tmp.path()).canonicalPath());

        // Opened from a window that had none, the status line no longer says there is none.
        nb::WorkbenchOptions none = options(QString(), false);
        none.welcome = false;
        nb::MainWindow bare(none);
        QVERIFY(bare.statusBar()->currentMessage().startsWith(QStringLiteral("No session open")));
        const QString b = tmp.filePath(QStringLiteral("b"));
        nb::Session::create(b, {});
        QVERIFY(bare.openSession(b));
        QVERIFY2(!bare.statusBar()->currentMessage().startsWith(QStringLiteral("No session open")), qPrintable(bare.statusBar()->currentMessage()));
    }

    // Export session… opens where the last export of this session went, with its formats: it
    // went back to SESSION/export and the defaults, and Export again wrote elsewhere.
    void exportRemembersItsFolderAndFormats()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("a"));
        nb::Session::create(a, {});
        writeCompletedRun(QDir(a).filePath(QStringLiteral("run_001_linear.csv")));
        nb::WorkbenchOptions o = options(a, false);
        o.persistSettings = true;
        const QString out = tmp.filePath(QStringLiteral("elsewhere"));
        {
            nb::MainWindow w(o);
            nb::ExportDialog* dialog = w.exportSession();
            QVERIFY(dialog);
            dialog->setTargetDir(out);
            dialog->setChoice({.csv = false, .hdf5 = false, .eaf = true, .figures = false, .tables = false});
            QSignalSpy done(dialog, &nb::ExportDialog::exportFinished);
            dialog->start();
            QVERIFY(done.wait(60000));
            QCOMPARE(done.first().first().toBool(), true);
            dialog->close();
        }
        {
            nb::MainWindow w(o);
            nb::ExportDialog* dialog = w.exportSession();
            QVERIFY(dialog);
            QCOMPARE(dialog->targetDir(), out);
            QCOMPARE(dialog->choice().eaf, true);
            QCOMPARE(dialog->choice().hdf5, false);
            QCOMPARE(dialog->choice().csv, false);
            dialog->close();
        }
        for (const char* key : {"export/session", "export/target", "export/choice"})
            QSettings().remove(QLatin1String(key));
    }

    // A plan sets the panel's motion; leaving it gives the operator's own back, and the
    // operator's are what is kept meanwhile (the plan's 4 mm/s and 40 mm stayed, deeper than the
    // specimen, and came back after a restart).
    void leavingAPlanGivesTheMotionBack()
    {
        nb::ControlPanel panel;
        setVelocityAndDepth(panel, 2.5, 22.0);
        nb::devices::RunPlan plan;
        plan.motion = nb::devices::RunPlan::Motion::Sine;
        plan.linear = {4.0, 40.0};
        plan.sine = {5.0, 0.5, 3};
        QVERIFY(panel.lockMotion(plan, QStringLiteral("the plan's")).isEmpty());
        QVERIFY(panel.findChild<QRadioButton*>(QStringLiteral("sine"))->isChecked());
        QCOMPARE(panel.findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->value(), 40.0);
        QTemporaryDir tmp;
        {
            QSettings kept(tmp.filePath(QStringLiteral("kept.ini")), QSettings::IniFormat);
            panel.saveSettings(kept);
        }
        QSettings kept(tmp.filePath(QStringLiteral("kept.ini")), QSettings::IniFormat);
        QCOMPARE(kept.value(QStringLiteral("motion/depth")).toDouble(), 22.0);
        QCOMPARE(kept.value(QStringLiteral("motion/velocity")).toDouble(), 2.5);
        QCOMPARE(kept.value(QStringLiteral("motion/sine")).toBool(), false);
        panel.unlockMotion();
        QVERIFY(panel.findChild<QRadioButton*>(QStringLiteral("linear"))->isChecked());
        QCOMPARE(panel.findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->value(), 2.5);
        QCOMPARE(panel.findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->value(), 22.0);
    }

    // A session folder renamed between two starts: the window says the last session is not
    // there any more, and the welcome lists it as not found (not a silent "No recent sessions").
    void aSessionRenamedBetweenStartsIsSaidToBeGone()
    {
        QTemporaryDir tmp;
        const QString a = tmp.filePath(QStringLiteral("liver_3"));
        nb::Session::create(a, {});
        nb::WorkbenchOptions o = options(a, false);
        o.persistSettings = true;
        QSettings().remove(QStringLiteral("session/recent"));  // what the tests before left there
        {
            nb::MainWindow w(o);
            QVERIFY(w.session());
            QVERIFY(w.close());
        }
        QVERIFY(QDir().rename(a, tmp.filePath(QStringLiteral("liver_3_done"))));
        o.sessionDir.clear();
        o.welcome = true;
        nb::MainWindow w(o);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(!w.session());
        QVERIFY2(w.statusBar()->toolTip().contains(QStringLiteral("liver_3")) && w.statusBar()->toolTip().contains(QStringLiteral("not there")),
                 qPrintable(w.statusBar()->toolTip()));
        nb::WelcomeDialog* welcome = nullptr;
        QTRY_VERIFY((welcome = w.findChild<nb::WelcomeDialog*>()) && welcome->isVisible());
        auto* recent = welcome->findChild<QListWidget*>(QStringLiteral("welcomeRecent"));
        QVERIFY(recent && recent->isVisible());
        QList<QListWidgetItem*> gone = recent->findItems(QStringLiteral("liver_3 (not found)"), Qt::MatchStartsWith);
        QCOMPARE(gone.size(), 1);
        QCOMPARE(gone.first()->data(Qt::UserRole).toString(), a);
        QVERIFY(!(gone.first()->flags() & Qt::ItemIsEnabled));  // nothing there to open
        welcome->reject();
        // The engine's echo of the window's own settings ("withdrawal force limit 9.5 N") came
        // later and replaced what the status line said at start.
        QTest::qWait(500);
        QVERIFY2(w.statusBar()->toolTip().contains(QStringLiteral("not there")), qPrintable(w.statusBar()->toolTip()));
        // Said before the window had its width, it is shortened to the room beside the summary.
        w.resize(700, 600);
        QTRY_VERIFY2(QFontMetrics(w.statusBar()->font()).horizontalAdvance(w.statusBar()->currentMessage()) < w.statusBar()->width() - 200,
                     qPrintable(w.statusBar()->currentMessage()));
        // Whole where the room holds it (the window's least width, 1087 px, holds it in X's fonts),
        // else shortened with an ellipsis where it was cut.
        QVERIFY2(w.statusBar()->currentMessage() == w.statusBar()->toolTip() || w.statusBar()->currentMessage().contains(QChar(0x2026)),
                 qPrintable(w.statusBar()->currentMessage()));
        QSettings().remove(QStringLiteral("session/last"));
        QSettings().remove(QStringLiteral("session/recent"));
    }

    // Last: the German translation, chosen as in the Language menu, reaches the widgets.
    void germanTranslation()
    {
        QVERIFY(nb::availableLanguages().contains(QStringLiteral("de")));
        nb::setPreferredLanguage(QStringLiteral("de"));
        QCOMPARE(nb::preferredLanguage(), QStringLiteral("de"));
        nb::installTranslation(*QCoreApplication::instance());
        // Whatever fails below, the tests after this one run in English.
        auto english = qScopeGuard([] {
            for (QTranslator* t : QCoreApplication::instance()->findChildren<QTranslator*>())
                QCoreApplication::removeTranslator(t);
            nb::setPreferredLanguage(QStringLiteral("en"));
        });
        QTemporaryDir tmp;
        {
            nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), false));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCOMPARE(w.controlPanel()->button(Control::EmergencyStop)->text(), QStringLiteral("NOT-HALT (Esc)"));
            QCOMPARE(w.controlPanel()->button(Control::EndRun)->text(), QStringLiteral("Lauf beenden (Datei zu)"));
            QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().devicesRunning, 20000);
            // Interlock reasons (free functions) are translated too.
            QVERIFY(w.controlPanel()->button(Control::StartInsertion)->toolTip().contains(QStringLiteral("Zuerst die Achse einschalten")));
            // The calibration's name goes into every run file: the same words in every language,
            // shown translated.
            QCOMPARE(w.engine()->status().calibrationName, QStringLiteral("nominal (device)"));
            QTRY_COMPARE(w.controlPanel()->findChild<QLabel*>(QStringLiteral("status_calibration"))->text(), QStringLiteral("nominal (Gerät)"));
            QVERIFY2(w.engine()->deviceDescription().contains(QStringLiteral("Spitze: abgeschrägt")), qPrintable(w.engine()->deviceDescription()));
            // A session's tip and protocol as the demo writes them, several file values in one.
            nb::SessionInfo info = w.session()->info();
            info.tip = QStringLiteral("beveled/diamond");
            info.protocol = QStringLiteral("stiffness + friction");
            QVERIFY(w.setSessionInfo(info));
            const QString header = w.sessionView()->findChild<QLabel*>(QStringLiteral("sessionHeader"))->text();
            QVERIFY2(header.contains(QStringLiteral("Spitze abgeschrägt/Diamantschliff")) && header.contains(QStringLiteral("Steifigkeit + Reibung")),
                     qPrintable(header));
            QVERIFY(w.grab().save(screenshotDir() + QStringLiteral("/main_window_de.png")));
            // A run recorded in German is written in the files' one language: a dataset of
            // several operators mixes none.
            setMotion(w, 10.0, 5.0);
            nbtest::prepareToRecord(w);
            QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
            QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
            const nb::Run run = nb::readRunFile(w.lastRunPath()).run;
            const QString device = run.meta(QStringLiteral("device")).value_or(QString());
            QVERIFY2(device.startsWith(QStringLiteral("simulated rig (")) && device.contains(QStringLiteral("beveled tip")), qPrintable(device));
            QCOMPARE(run.meta(QStringLiteral("position_source")).value_or(QString()),
                     QStringLiteral("stage read-back, interpolated to the sample clock"));
            QCOMPARE(run.meta(QStringLiteral("end_reason")).value_or(QString()), QStringLiteral("completed"));
            // The fit tables' CSV is data too: "pooled" whatever the window speaks ("gepoolt"
            // broke the scripts that read it); the window and the LaTeX report say it in German.
            const QString twoRuns = tmp.filePath(QStringLiteral("two"));
            QVERIFY(QDir().mkpath(twoRuns));
            for (const char* seed : {"1", "2"})
                QCOMPARE(nbtest::runCli({"simulate", "--protocol", "stiffness", "--tissue", "liver1", "--seed", QLatin1String(seed), "--out",
                                         QDir(twoRuns).filePath(QStringLiteral("run_00%1_linear.csv").arg(QLatin1String(seed)))})
                             .code,
                         0);
            const nb::SessionAnalysis analysis = nb::analyseDataset(nb::loadDataset(twoRuns).dataset);
            const nb::FitTable pooled = nb::stiffnessPooledTable(analysis);
            QVERIFY(!pooled.rows.empty());
            const QByteArray csv = nb::fitTableCsv(pooled);
            QVERIFY2(csv.contains(",pooled,") && csv.contains(",mean of runs,") && !csv.contains("gepoolt"), csv.constData());
            QVERIFY(nb::fitTableLatex(pooled).contains("gepoolt"));
            QCOMPARE(nb::tableValueDisplayName(QStringLiteral("pooled")), QStringLiteral("gepoolt"));
            // Event labels and factors, stored in English, said in German (Review's keys, the
            // timeline, Analysis ▸ By factor).
            QCOMPARE(nb::labelDisplayName(QStringLiteral("puncture")), QStringLiteral("Durchstich"));
            QCOMPARE(nb::labelDisplayName(QStringLiteral("b1")), QStringLiteral("b1"));
            QCOMPARE(nb::factorDisplayName(QStringLiteral("frequency_hz")), QStringLiteral("Frequenz [Hz]"));
        }
        {
            // A template's plan that an English window wrote is said in German in the Plan
            // dock: its title, its runs (numbers in German notation) and the instruction.
            const QString dir = tmp.filePath(QStringLiteral("s"));
            nb::Plan plan = nb::generatePlan(*nb::findPlanTemplate(QStringLiteral("friction-imaging")), nb::PlanOrder::Listed, 1);
            plan.runs[0].instruction = QStringLiteral("Mount liver7. Mount the 30 mm slab. Fit the diamond tip. Move the slab to site 1.");
            nb::writePlanFile(QDir(dir).filePath(nb::planFileName()), plan);
            const QLocale before;
            QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
            auto locale = qScopeGuard([before] { QLocale::setDefault(before); });
            nb::MainWindow w(options(dir, false));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            auto* title = w.findChild<QLabel*>(QStringLiteral("planTitle"));
            auto* next = w.findChild<QLabel*>(QStringLiteral("planNext"));
            auto* instruction = w.findChild<QLabel*>(QStringLiteral("planInstruction"));
            QVERIFY(title && next && instruction);
            // The template's identifier is a key for files, not words: not shown.
            QTRY_COMPARE(title->text(), QStringLiteral("Reibung unter Bildgebung"));
            QVERIFY2(next->text().contains(QStringLiteral("Reibung Stelle 1 0,2 Hz")), qPrintable(next->text()));
            QVERIFY2(instruction->text().contains(QStringLiteral("Leber 7 einspannen. Die 30-mm-Gewebescheibe einspannen.")),
                     qPrintable(instruction->text()));
        }
        {
            // Data names (tips, tissue presets) are shown in German and stored as they are.
            nb::SessionInfo info;
            info.tip = QStringLiteral("beveled");
            nb::SessionInfoDialog d(nb::SessionInfoDialog::Mode::Edit, info);
            auto* tip = d.findChild<QComboBox*>(QStringLiteral("tip"));
            QCOMPARE(tip->currentText(), QStringLiteral("abgeschrägt"));
            QCOMPARE(d.info().tip, QStringLiteral("beveled"));
            tip->setCurrentText(QStringLiteral("stumpf"));
            QCOMPARE(d.info().tip, QStringLiteral("blunt"));
            tip->setCurrentText(QStringLiteral("Trokar"));  // a tip of the operator's own
            QCOMPARE(d.info().tip, QStringLiteral("Trokar"));

            nb::devices::SimulatedRigSpec spec;
            spec.tissue = QStringLiteral("liver2");
            spec.tip = QStringLiteral("diamond");
            nb::SimulatedRigDialog rig(spec, 1000.0);
            auto* tissue = rig.findChild<QComboBox*>(QStringLiteral("tissue"));
            QCOMPARE(tissue->currentText(), QStringLiteral("Leber 2"));
            QCOMPARE(rig.findChild<QComboBox*>(QStringLiteral("tip"))->currentText(), QStringLiteral("Diamantschliff"));
            QCOMPARE(rig.spec().tissue, QStringLiteral("liver2"));
            QCOMPARE(rig.spec().tip, QStringLiteral("diamond"));
            // Where a friction fit took D from, as the Analysis table shows it.
            QCOMPARE(nb::staticSourceDisplayName(QStringLiteral("velocity band")), QStringLiteral("Geschwindigkeitsband"));
            QCOMPARE(nb::staticSourceDisplayName(QStringLiteral("phase a")), QStringLiteral("Phase a"));
            tissue->setCurrentIndex(tissue->findText(QStringLiteral("Prostata")));
            QCOMPARE(rig.spec().tissue, QStringLiteral("prostate"));
            // No stored English name is shown anywhere in either dialog.
            const QStringList stored = nb::devices::simulatedTissues() + nb::devices::tipNames();
            for (const QDialog* dialog : std::initializer_list<const QDialog*>{&d, &rig})
                for (const QComboBox* box : dialog->findChildren<QComboBox*>())
                    for (int i = 0; i < box->count(); ++i)
                        QVERIFY2(!stored.contains(box->itemText(i)), qPrintable(box->itemText(i)));
        }
    }

    // Devices ▸ Choose devices…: what is connected is listed, the choice becomes a device spec,
    // and an incomplete choice is refused inside the dialog.
    void deviceDialogBuildsTheSpec()
    {
        using nb::devices::ConnectedDevice;
        const auto lister = [] {
            return std::vector<ConnectedDevice>{
                {QStringLiteral("daq"), QStringLiteral("u6:360012345"), QStringLiteral("LabJack U6 (USB bus 1 device 4)"), {}},
                {QStringLiteral("daq"), QString(), QStringLiteral("USB"), QStringLiteral("no permission for /dev/bus/usb")},
                {QStringLiteral("serial"), QStringLiteral("zaber:/dev/ttyUSB0"), QStringLiteral("FT232R USB UART"), {}}};
        };
        nb::DeviceDialog d(nb::devices::DeviceSpec{}, lister);
        auto* daq = d.findChild<QComboBox*>(QStringLiteral("daq"));
        auto* stage = d.findChild<QComboBox*>(QStringLiteral("stage"));
        QVERIFY(daq && stage);
        QCOMPARE(daq->count(), 4);    // simulated, first U6, the listed U6, by serial number
        QCOMPARE(stage->count(), 3);  // simulated, the listed port, another port
        QCOMPARE(daq->currentData().toString(), QStringLiteral("sim"));
        QVERIFY(!d.findChild<QSpinBox*>(QStringLiteral("u6Channel"))->isEnabled());
        const QString found = d.findChild<QLabel*>(QStringLiteral("found"))->text();
        QVERIFY2(found.contains(QStringLiteral("no permission")) && found.contains(QLatin1Char('1')), qPrintable(found));

        daq->setCurrentIndex(daq->findData(QStringLiteral("u6:360012345")));
        stage->setCurrentIndex(stage->findData(QStringLiteral("zaber:/dev/ttyUSB0")));
        QVERIFY(d.findChild<QSpinBox*>(QStringLiteral("u6Channel"))->isEnabled());
        d.findChild<QComboBox*>(QStringLiteral("u6Gain"))->setCurrentIndex(1);
        d.findChild<QDoubleSpinBox*>(QStringLiteral("zaberMicrosteps"))->setValue(10000.0);
        nb::devices::DeviceSpec s = d.spec();
        QCOMPARE(s.daq, QStringLiteral("u6:360012345"));
        QCOMPARE(s.stage, QStringLiteral("zaber:/dev/ttyUSB0"));
        QCOMPARE(s.u6GainIndex, 1);
        QCOMPARE(s.zaberMicrostepsPerMm, 10000.0);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(d.grab().save(screenshotDir() + QStringLiteral("/device_dialog.png")));
        d.accept();
        QCOMPARE(d.result(), int(QDialog::Accepted));

        // What is not connected now is kept, typed in; an empty port is refused with a reason.
        s.daq = QStringLiteral("u6:42");
        s.stage = QStringLiteral("zaber:/dev/ttyS9");
        nb::DeviceDialog again(s, lister);
        QCOMPARE(again.spec().daq, QStringLiteral("u6:42"));
        QCOMPARE(again.spec().stage, QStringLiteral("zaber:/dev/ttyS9"));
        QCOMPARE(again.spec().u6GainIndex, 1);
        again.findChild<QLineEdit*>(QStringLiteral("stagePort"))->clear();
        again.show();
        again.accept();
        QVERIFY(again.isVisible());
        QVERIFY2(again.problem().contains(QStringLiteral("zaber:")), qPrintable(again.problem()));
        QVERIFY(again.findChild<QLabel*>(QStringLiteral("error"))->isVisible());
    }

    // Switching devices replaces the engine: a stage or a DAQ that cannot be opened falls back
    // to the simulated rig with a message naming it, and the simulated rig chosen again works
    // through the panel. Never mid-run.
    void switchingDevices()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().devicesRunning, 20000);

        nb::devices::DeviceSpec spec;
        spec.stage = QStringLiteral("zaber:/dev/ttyNoSuchPort");
        QVERIFY(!w.switchDevices(spec));
        // The whole message in the tooltip, the bar's line shortened to its room.
        QVERIFY2(w.statusBar()->toolTip().contains(QStringLiteral("ttyNoSuchPort")), qPrintable(w.statusBar()->toolTip()));
        QVERIFY2(w.statusBar()->currentMessage().startsWith(QStringLiteral("Could not open the chosen devices")) &&
                     w.statusBar()->currentMessage().endsWith(QStringLiteral("using the simulated rig.")),
                 qPrintable(w.statusBar()->currentMessage()));
        QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().running, 20000);

        spec.stage = QStringLiteral("sim");
        spec.daq = QStringLiteral("u6:999999999");
        QVERIFY(!w.switchDevices(spec));
        QVERIFY2(w.statusBar()->toolTip().contains(QStringLiteral("999999999")), qPrintable(w.statusBar()->toolTip()));
        QVERIFY(w.engine()->deviceDescription().contains(QStringLiteral("simulated")));
        QVERIFY(!w.controlPanel()->button(Control::StartInsertion)->isEnabled());

        spec.daq = QStringLiteral("sim");
        QVERIFY(w.switchDevices(spec));
        setMotion(w, 5.0, 60.0);
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().recording, 20000);
        nb::devices::AcquisitionEngine* recordingEngine = w.engine();
        QVERIFY(!w.switchDevices(spec));
        QCOMPARE(w.engine(), recordingEngine);
        QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("A run is recording")));
        w.controlPanel()->button(Control::EmergencyStop)->click();
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 20000);
    }

    // Session ▸ Details…: what the operator changes is saved in session.json, the creation
    // time stays, and the runs recorded after carry it.
    void sessionDetailsAreEditable()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("s"));
        nb::MainWindow w(options(dir, false));
        QVERIFY(w.session());
        const nb::SessionInfo before = w.session()->info();
        nb::SessionInfoDialog d(nb::SessionInfoDialog::Mode::Edit, before);
        QVERIFY(!d.findChild<QLineEdit*>(QStringLiteral("parentFolder")));  // the folder is fixed once made
        d.findChild<QLineEdit*>(QStringLiteral("organ"))->setText(QStringLiteral("bovine liver"));
        d.findChild<QLineEdit*>(QStringLiteral("specimen"))->setText(QStringLiteral("7"));
        d.findChild<QComboBox*>(QStringLiteral("tip"))->setCurrentText(QStringLiteral("diamond"));
        d.findChild<QDoubleSpinBox*>(QStringLiteral("thickness"))->setValue(25.0);
        d.findChild<QPlainTextEdit*>(QStringLiteral("notes"))->setPlainText(QStringLiteral("left lobe, 4 h post mortem"));
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(d.grab().save(screenshotDir() + QStringLiteral("/session_details.png")));
        QVERIFY(w.setSessionInfo(d.info()));

        const nb::Session reopened = nb::Session::open(dir);
        QCOMPARE(reopened.info().organ, QStringLiteral("bovine liver"));
        QCOMPARE(reopened.info().tip, QStringLiteral("diamond"));
        QCOMPARE(reopened.info().thickness_mm, 25.0);
        QCOMPARE(reopened.info().notes, QStringLiteral("left lobe, 4 h post mortem"));
        QCOMPARE(reopened.info().created, before.created);

        setMotion(w, 20.0, 8.0);
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        const nb::RunReadResult r = nb::readRunFile(w.lastRunPath());
        QCOMPARE(r.run.meta(QStringLiteral("organ")).value_or(QString()), QStringLiteral("bovine liver"));
        QCOMPARE(r.run.meta(QStringLiteral("tip")).value_or(QString()), QStringLiteral("diamond"));
    }

    // The next specimen of the day: New session… starts from the open session's details and
    // folder, the specimen and notes blank, and the session made carries what was kept.
    void newSessionStartsFromTheOpenOne()
    {
        QTemporaryDir tmp;
        const QString first = tmp.filePath(QStringLiteral("first"));
        nb::SessionInfo info;
        info.organ = QStringLiteral("bovine liver");
        info.specimen = QStringLiteral("3");
        info.tip = QStringLiteral("diamond");
        info.thickness_mm = 20.0;
        info.operatorName = QStringLiteral("Ada");
        info.protocol = QStringLiteral("friction");
        info.notes = QStringLiteral("left lobe");
        nb::Session::create(first, info);
        nb::MainWindow w(options(first, false));
        QVERIFY(w.session());
        QAction* newSession = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->shortcut() == QKeySequence(QKeySequence::New))
                newSession = a;
        QVERIFY(newSession);
        bool seen = false;
        QTimer::singleShot(0, &w, [&] {
            auto* d = qobject_cast<nb::SessionInfoDialog*>(QApplication::activeModalWidget());
            if (!d)
                return;
            seen = true;
            QCOMPARE(d->findChild<QLineEdit*>(QStringLiteral("organ"))->text(), info.organ);
            QCOMPARE(d->findChild<QLineEdit*>(QStringLiteral("operator"))->text(), info.operatorName);
            QCOMPARE(d->findChild<QLineEdit*>(QStringLiteral("protocol"))->text(), info.protocol);
            QCOMPARE(d->findChild<QDoubleSpinBox*>(QStringLiteral("thickness"))->value(), 20.0);
            QVERIFY(d->findChild<QLineEdit*>(QStringLiteral("specimen"))->text().isEmpty());
            QVERIFY(d->findChild<QPlainTextEdit*>(QStringLiteral("notes"))->toPlainText().isEmpty());
            QCOMPARE(QDir(d->findChild<QLineEdit*>(QStringLiteral("parentFolder"))->text()).canonicalPath(), QDir(tmp.path()).canonicalPath());
            d->findChild<QLineEdit*>(QStringLiteral("specimen"))->setText(QStringLiteral("4"));
            d->accept();
        });
        newSession->trigger();
        QVERIFY2(seen, "no New session dialog");
        QVERIFY(w.session());
        QVERIFY(QDir(w.session()->dir()) != QDir(first));
        QCOMPARE(QDir(QFileInfo(w.session()->dir()).absolutePath()).canonicalPath(), QDir(tmp.path()).canonicalPath());
        const nb::SessionInfo made = nb::Session::open(w.session()->dir()).info();
        QCOMPARE(made.specimen, QStringLiteral("4"));
        QCOMPARE(made.organ, info.organ);
        QCOMPARE(made.tip, info.tip);
        QCOMPARE(made.operatorName, info.operatorName);
        QVERIFY(made.notes.isEmpty());
        QVERIFY(made.created.isValid());
    }

    // Contact and puncture are marked while the needle still moves, and the marks give way to
    // the whole run's when it ends: one of each.
    void liveEventsMarkedDuringTheRun()
    {
        QTemporaryDir tmp;
        nb::MainWindow w(options(tmp.filePath(QStringLiteral("s")), true));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setMotion(w, 10.0, 45.0);  // the simulated liver 1 punctures at ~20 mm: 2 s in, 2.5 s to go
        prepare(w);
        QTest::mouseClick(w.controlPanel()->button(Control::StartInsertion), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controlPanel()->interlockState().recording, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(w.plots()->eventLabels().contains(QStringLiteral("contact")), 20000);
        QVERIFY(w.controlPanel()->interlockState().moving);
        QTRY_VERIFY_WITH_TIMEOUT(w.plots()->eventLabels().contains(QStringLiteral("puncture")), 20000);
        QVERIFY2(w.controlPanel()->interlockState().recording, "the puncture was marked only after the run");
        QVERIFY(w.grab().save(screenshotDir() + QStringLiteral("/main_window_live_events.png")));
        QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 30000);
        const QStringList labels = w.plots()->eventLabels();
        QCOMPARE(labels.count(QStringLiteral("contact")), 1);
        QCOMPARE(labels.count(QStringLiteral("puncture")), 1);
    }
};

QTEST_MAIN(TestWorkbench)
#include "test_workbench.moc"
