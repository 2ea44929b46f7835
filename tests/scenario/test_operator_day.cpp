// An operator's day in the real window on the simulated rig, end to end: no session → a new
// one → guided calibration → a linear run → a sine run → its video attached → Auto sync →
// Accept → labels by hotkey → the window destroyed and built again on the same session (a
// restart) → the video, offset, drift, how they were found and the labels are all back →
// export HDF5 from the window → read back with the HDF5 C API: offset and video link present.
#include "main_window.h"
#include "support/hdf5_attributes.h"
#include "support/simulated_window.h"

#include "core/export/session_hdf5.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "core/run_video_link.h"
#include "devices/acquisition_engine.h"
#include "devices/sim/imaging_render.h"
#include "devices/sim/rig_config.h"
#include "devices/sim/simulated_rig.h"
#include "widgets/calibration_wizard.h"
#include "widgets/control_panel.h"
#include "widgets/export_dialog.h"
#include "widgets/label_model.h"
#include "widgets/review_workspace.h"
#include "widgets/video_view.h"
#include "widgets/welcome_dialog.h"

#include <QDir>
#include <QLabel>
#include <QStatusBar>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <hdf5.h>

using nb::Control;

namespace {

nb::WorkbenchOptions options(const QString& sessionDir, std::shared_ptr<nb::devices::sim::SimulatedRig>* rig)
{
    nb::WorkbenchOptions o = nbtest::simulatedWindow(sessionDir, true, rig);
    o.calibrationDwell_s = 2.0;  // the thesis's dwell, as an operator gets it
    return o;
}

void prepare(nb::MainWindow& w)
{
    nb::ControlPanel* p = w.controlPanel();
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().devicesRunning, 20000);
    if (!p->interlockState().stageEnabled) {
        QTest::mouseClick(p->button(Control::Enable), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().stageEnabled, 20000);
    }
    QTest::mouseClick(p->button(Control::Bias), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().biased, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(p->button(Control::Zero)->isEnabled(), 20000);
    QTest::mouseClick(p->button(Control::Zero), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(p->interlockState().zeroed, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(p->button(Control::StartInsertion)->isEnabled(), 20000);
}

}  // namespace

class TestOperatorDay : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_operator_day"));
        QSettings().remove(QStringLiteral("labelSets"));
    }

    void wholeDay()
    {
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const QString sessionDir = tmp.filePath(QStringLiteral("liver3_day"));
        const QString sessionsRoot =
            QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).filePath(QStringLiteral("sessions"));
        const QStringList before = QDir(sessionsRoot).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
        std::shared_ptr<nb::devices::sim::SimulatedRig> rig;
        QString linearPath, sinePath, videoPath;
        nb::TimelineMapping accepted;
        std::size_t labelCount = 0;
        double confidence = -1.0;
        {
            // First start: no session is made behind the operator's back; the welcome asks.
            nb::MainWindow w(options(QString(), &rig));
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QTRY_VERIFY(w.findChild<nb::WelcomeDialog*>() && w.findChild<nb::WelcomeDialog*>()->isVisible());
            QVERIFY(!w.session());
            QCOMPARE(QDir(sessionsRoot).entryList(QDir::Dirs | QDir::NoDotAndDotDot), before);
            w.findChild<nb::WelcomeDialog*>()->reject();

            nb::SessionInfo info;
            info.organ = QStringLiteral("liver");
            info.specimen = QStringLiteral("3");
            info.tip = QStringLiteral("beveled");
            info.thickness_mm = 20.0;
            info.protocol = QStringLiteral("friction");
            QVERIFY(w.createSession(sessionDir, info));
            QVERIFY(w.session());

            // Guided calibration: the rig hangs each mass; the wizard settles, measures, fits.
            // As an operator would, once the devices are running (the sensor's first batch).
            QTRY_VERIFY_WITH_TIMEOUT(w.engine()->status().running, 20000);
            nb::CalibrationWizard* wizard = w.openCalibrationWizard();
            QVERIFY2(wizard, qPrintable(w.statusBar()->currentMessage()));  // refused: the window says why
            QVERIFY(QTest::qWaitForWindowExposed(wizard));
            QVERIFY(wizard->rowCount() >= 4);  // the default masses, from the sensor's range
            QElapsedTimer calibrationClock;
            calibrationClock.start();
            wizard->measureAll();
            QTRY_VERIFY_WITH_TIMEOUT(!wizard->isMeasuring(), 120000);
            qInfo("guided calibration of %d masses (0 to %.0f g) took %.1f s", wizard->rowCount(),
                  wizard->calibration().points.back().mass_g, calibrationClock.elapsed() / 1000.0);
            QCOMPARE(wizard->saturatedRows(), 0);
            QVERIFY(wizard->hasFit());
            QVERIFY2(wizard->fit().r2 > 0.999, qPrintable(QString::number(wizard->fit().r2)));
            QPushButton* save = nullptr;
            for (QPushButton* b : wizard->findChildren<QPushButton*>())
                if (b->objectName() == QLatin1String("calibrationSave"))
                    save = b;
            QVERIFY(save && save->isEnabled());
            QTest::mouseClick(save, Qt::LeftButton);
            QTRY_VERIFY(w.session()->activeCalibration().has_value());

            // A linear insertion, then a sine run in the tissue.
            nb::ControlPanel* p = w.controlPanel();
            p->findChild<QDoubleSpinBox*>(QStringLiteral("velocity"))->setValue(10.0);
            p->findChild<QDoubleSpinBox*>(QStringLiteral("depth"))->setValue(30.0);
            prepare(w);
            QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
            QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 1, 60000);
            linearPath = w.lastRunPath();
            QCOMPARE(w.lastEndReason(), QStringLiteral("completed"));
            // A plain "Run saved" is news, not an alarm: not in bold red.
            QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("Run saved")));
            QVERIFY2(!w.statusBar()->styleSheet().contains(QStringLiteral("bold")), qPrintable(w.statusBar()->styleSheet()));
            QTRY_VERIFY_WITH_TIMEOUT(!p->interlockState().moving, 20000);

            p->findChild<QRadioButton*>(QStringLiteral("sine"))->setChecked(true);
            p->findChild<QDoubleSpinBox*>(QStringLiteral("amplitude"))->setValue(2.0);
            p->findChild<QDoubleSpinBox*>(QStringLiteral("frequency"))->setValue(0.5);
            p->findChild<QSpinBox*>(QStringLiteral("cycles"))->setValue(3);
            QTRY_VERIFY2_WITH_TIMEOUT(p->button(Control::StartInsertion)->isEnabled(),
                                      qPrintable(p->button(Control::StartInsertion)->toolTip()), 20000);
            QTest::mouseClick(p->button(Control::StartInsertion), Qt::LeftButton);
            QTRY_COMPARE_WITH_TIMEOUT(w.runsEnded(), 2, 60000);
            sinePath = w.lastRunPath();
            QVERIFY(sinePath.endsWith(QLatin1String("_sine.csv")));

            // The imaging video of the sine run, made here with OpenCV; it starts 1.3 s early.
            videoPath = QDir(sessionDir).filePath(QStringLiteral("imaging_liver3.avi"));
            nb::devices::sim::ImagingOptions io;
            io.leadIn_s = 1.3;
            io.width = 360;
            io.height = 240;
            const nb::devices::sim::ImagingTruth truth = nb::devices::sim::renderImagingVideo(nb::readRunFile(sinePath).run, videoPath, io);

            // Review: the sine run; Open video attaches it; a drift typed; Auto sync; Accept.
            w.reviewRun(sinePath);
            nb::ReviewWorkspace* review = w.reviewWorkspace();
            QCOMPARE(review->runPath(), sinePath);
            QSignalSpy opened(review, &nb::ReviewWorkspace::videoOpened);
            // No video yet: the placeholder offers Open video…; the operator drops the file on it.
            QVERIFY(review->videoView()->openButton()->isVisible());
            {
                QMimeData mime;
                mime.setUrls({QUrl::fromLocalFile(videoPath)});
                const QPoint at = review->videoView()->rect().center();
                QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
                QCoreApplication::sendEvent(review->videoView(), &enter);
                QVERIFY(enter.isAccepted());
                QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
                QCoreApplication::sendEvent(review->videoView(), &drop);
            }
            QCOMPARE(review->videoPath(), QFileInfo(videoPath).absoluteFilePath());
            QVERIFY(opened.wait(60000));
            QDoubleSpinBox* drift = nullptr;
            for (QDoubleSpinBox* b : review->findChildren<QDoubleSpinBox*>())
                if (b->suffix().contains(QLatin1String("ppm")))
                    drift = b;
            QVERIFY(drift);
            drift->setValue(150.0);  // the camera clock's known drift, typed
            QSignalSpy synced(review, &nb::ReviewWorkspace::syncFinished);
            review->startAutoSync();
            QVERIFY(synced.wait(120000));
            QVERIFY(review->pendingSync());
            confidence = review->pendingSync()->confidence;
            // The displacement sync measures the drift itself and Accept takes it; a sync on
            // the speed alone keeps the drift typed.
            const bool driftMeasured = review->pendingSync()->scale_px_per_mm != 0.0;
            const double expectedDrift = driftMeasured ? review->pendingSync()->drift : 150e-6;
            review->acceptSync();
            accepted = review->mapping();
            QVERIFY2(std::abs(accepted.offset_s - truth.offset_s) < 2.0 / truth.fps,
                     qPrintable(QStringLiteral("found %1 s, true %2 s").arg(accepted.offset_s).arg(truth.offset_s)));
            QCOMPARE(accepted.drift, expectedDrift);
            QCOMPARE(review->syncMethod(), nb::SyncMethod::Automatic);

            // Labels by hotkey: friction phases a, then b1, closed by the same key.
            const double t0 = review->cursorTime();
            review->setCursorTime(t0 + 0.5);
            QTest::keyClick(review, Qt::Key_1);
            review->setCursorTime(t0 + 1.5);
            QTest::keyClick(review, Qt::Key_2);
            review->setCursorTime(t0 + 2.5);
            QTest::keyClick(review, Qt::Key_2);
            QCOMPARE(review->labelModel()->labels().size(), std::size_t(2));
            // c on insertion, then 5 (withdrawal a): the open c is closed there, not dropped.
            review->setCursorTime(t0 + 3.0);
            QTest::keyClick(review, Qt::Key_4);
            review->setCursorTime(t0 + 3.5);
            QTest::keyClick(review, Qt::Key_5);
            review->setCursorTime(t0 + 4.0);
            QTest::keyClick(review, Qt::Key_5);
            labelCount = review->labelModel()->labels().size();
            QCOMPARE(labelCount, std::size_t(4));
            bool closedC = false;
            for (const nb::Label& l : review->labelModel()->labels())
                closedC |= l.label == QLatin1String("c") && std::abs(l.start_s - (t0 + 3.0)) < 1e-9 && std::abs(l.end_s - (t0 + 3.5)) < 1e-9;
            QVERIFY(closedC);
            QCOMPARE(review->findChild<QLabel*>(QStringLiteral("labelCount"))->text(), QStringLiteral("labels: 4"));

            // A run without a video: switching to it clears the video and the offset.
            w.reviewRun(linearPath);
            QVERIFY(review->videoPath().isEmpty());
            QCOMPARE(review->mapping(), nb::TimelineMapping{});
            QVERIFY(review->videoView()->openButton()->isVisible());
        }  // the window is destroyed: the application quit

        {
            nb::MainWindow w(options(sessionDir, &rig));
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            nb::ReviewWorkspace* review = w.reviewWorkspace();
            QSignalSpy opened(review, &nb::ReviewWorkspace::videoOpened);
            w.reviewRun(sinePath);
            QVERIFY(opened.wait(60000));
            QCOMPARE(QFileInfo(review->videoPath()).canonicalFilePath(), QFileInfo(videoPath).canonicalFilePath());
            QCOMPARE(review->mapping(), accepted);
            QCOMPARE(review->syncMethod(), nb::SyncMethod::Automatic);
            QCOMPARE(review->syncConfidence().value_or(-1.0), confidence);
            QCOMPARE(review->labelModel()->labels().size(), labelCount);

            // Export HDF5 from the window (Session ▸ Export session…).
            nb::ExportDialog* dialog = w.exportSession();
            QVERIFY(dialog);
            dialog->setChoice({.csv = false, .hdf5 = true, .eaf = false, .figures = false, .tables = false});
            dialog->setTargetDir(tmp.filePath(QStringLiteral("export")));
            QSignalSpy done(dialog, &nb::ExportDialog::exportFinished);
            dialog->start();
            QVERIFY(done.wait(120000));
            QCOMPARE(done.first().first().toBool(), true);
            const QString h5 = dialog->hdf5Path();
            QVERIFY(QFileInfo::exists(h5));

            const hid_t f = H5Fopen(h5.toUtf8().constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
            QVERIFY(f >= 0);
            const QByteArray group = (QStringLiteral("/runs/") + nb::hdf5GroupName(QFileInfo(sinePath).completeBaseName())).toUtf8();
            const hid_t g = H5Gopen2(f, group.constData(), H5P_DEFAULT);
            QVERIFY2(g >= 0, group.constData());
            const double offset = nbtest::readDoubleAttribute(g, "sync_offset_s");
            const QString video = nbtest::readStringAttribute(g, "video_file").text;
            const QString method = nbtest::readStringAttribute(g, "sync_method").text;
            const double driftRead = nbtest::readDoubleAttribute(g, "sync_drift");
            H5Gclose(g);
            H5Fclose(f);
            QVERIFY2(std::abs(offset - accepted.offset_s) < 1e-9, qPrintable(QString::number(offset)));
            QCOMPARE(video, QStringLiteral("imaging_liver3.avi"));
            QCOMPARE(method, QStringLiteral("automatic"));
            QVERIFY(std::abs(driftRead - accepted.drift) < 1e-12);
        }
    }
};

QTEST_MAIN(TestOperatorDay)
#include "test_operator_day.moc"
