// The window on a 1366×768 laptop, in English and in German: no widget's minimum size makes
// the window wider or taller than the screen (with long results shown), the session list
// shows more than two runs, the control panel's status needs no scrolling at 700 px, and the
// label timeline shares the force plot's time axis to the pixel.
//
// With NB_SCREENSHOT_DIR set (and a real X server: xvfb-run -s "-screen 0 1366x768x24"), it
// also photographs the screen with ImageMagick's `import -window root` on each workspace.
#include "main_window.h"
#include "translation.h"

#include "core/data_names.h"
#include "core/export/session_analysis.h"
#include "core/labels.h"
#include "core/plan.h"
#include "core/plan_session.h"
#include "core/run_file.h"
#include "core/session.h"
#include "widgets/analysis/analysis_workspace.h"
#include "widgets/control_panel.h"
#include "devices/acquisition_engine.h"
#include "widgets/export_dialog.h"
#include "widgets/welcome_dialog.h"
#include "widgets/label_model.h"
#include "widgets/review_workspace.h"
#include "widgets/session_view.h"
#include "widgets/session_info_dialog.h"
#include "widgets/simulated_rig_dialog.h"
#include "widgets/calibration_wizard.h"
#include "widgets/timeline.h"

#include <algorithm>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QDockWidget>
#include <QStatusBar>
#include <QGuiApplication>
#include <QLabel>
#include <QMenuBar>
#include <QProcess>
#include <QRadioButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>
#include <qcustomplot.h>

namespace {

// A session with a few runs, made by the CLI as on a real day.
bool makeSession(const QString& dir)
{
    if (!nb::Session::isSession(dir))
        nb::Session::create(dir, {});
    for (const auto& [protocol, name] : {std::pair{"stiffness", "run_001_linear.csv"}, {"friction", "run_002_sine.csv"},
                                         {"stiffness", "run_003_linear.csv"}, {"stiffness", "run_004_linear.csv"}}) {
        QStringList args{QStringLiteral("simulate"), QStringLiteral("--protocol"), QLatin1String(protocol),
                         QStringLiteral("--out"), QDir(dir).filePath(QLatin1String(name))};
        if (QLatin1String(protocol) == QLatin1String("friction"))  // its imaging video beside it
            args << QStringLiteral("--cycles") << QStringLiteral("3") << QStringLiteral("--video")
                 << QDir(dir).filePath(QStringLiteral("run_002_sine.avi")) << QStringLiteral("--video-offset-s") << QStringLiteral("0.8");
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE), args);
        if (!p.waitForFinished(120000) || p.exitCode() != 0)
            return false;
    }
    return true;
}

}  // namespace

class TestLaptopLayout : public QObject {
    Q_OBJECT
    QTemporaryDir tmp_;
    QString session_;

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("NeedleBenchTest"));
        QCoreApplication::setApplicationName(QStringLiteral("test_laptop_layout"));
        session_ = tmp_.filePath(QStringLiteral("liver_laptop"));
        QVERIFY(makeSession(session_));
        // A plan being walked, as on a lab day: its dock shows the next run's instruction, the
        // longest line of the window in German (it widened the window to 1437 px).
        nb::writePlanFile(nb::planFilePath(session_),
                          nb::generatePlan(*nb::findPlanTemplate(QStringLiteral("friction-imaging")), nb::PlanOrder::Listed, 1));
    }

    void fitsALaptop_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("de") << QStringLiteral("de");
    }

    void fitsALaptop()
    {
        QFETCH(QString, language);
        nb::setPreferredLanguage(language);
        nb::installTranslation(*QCoreApplication::instance());
        {
            nb::WorkbenchOptions o;
            o.sessionDir = session_;
            o.persistSettings = false;
            o.devicesFromSettings = false;
            o.realtime = true;
            nb::MainWindow w(o);
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QSignalSpy opened(w.reviewWorkspace(), &nb::ReviewWorkspace::videoOpened);
            const QString sine = QDir(session_).filePath(QStringLiteral("run_002_sine.csv"));
            QFile::remove(nb::labelsPathFor(sine));  // each language suggests afresh
            w.reviewRun(sine);
            QVERIFY(opened.count() > 0 || opened.wait(60000));
            // The operator sets the video's offset (the one it was made with), then asks for
            // labels: they come from the tissue's motion in the video, read in the background.
            w.reviewWorkspace()->setMapping({0.8, 0.0}, nb::SyncMethod::Manual);
            QSignalSpy suggested(w.reviewWorkspace(), &nb::ReviewWorkspace::labelsSuggested);
            w.reviewWorkspace()->suggestLabels();
            QVERIFY(suggested.count() > 0 || suggested.wait(240000));
            const nb::Labels placed = w.reviewWorkspace()->labelModel()->labels();
            QVERIFY2(std::any_of(placed.begin(), placed.end(),
                                 [](const nb::Label& l) { return l.comment.contains(QLatin1String("the tissue's motion in run_002_sine.avi")); }),
                     qPrintable(w.reviewWorkspace()->status()));
            QVERIFY2(w.reviewWorkspace()->status().contains(QLatin1String("run_002_sine.avi")), qPrintable(w.reviewWorkspace()->status()));
            w.reviewWorkspace()->setCursorTime(4.0);
            QTest::qWait(300);
            // The default label tracks are said in the operator's language (stored as insertion).
            const QString keys = w.reviewWorkspace()->findChild<QLabel*>(QStringLiteral("keysHelp"))->text();
            QVERIFY2(keys.contains(language == QLatin1String("de") ? QStringLiteral("1 Einstich/a") : QStringLiteral("1 insertion/a")), qPrintable(keys));
            QVERIFY(w.reviewWorkspace()->labelModel()->tracks().contains(QStringLiteral("insertion")));
            // Where each friction fit took D from is stored in English ("phase a") and shown in
            // the operator's language in the Analysis table.
            {
                w.workspaces()->setCurrentIndex(2);
                const auto& friction = w.analysisWorkspace()->analysis().friction;
                const auto fitted = std::find_if(friction.begin(), friction.end(), [](const nb::FrictionRunResult& f) { return f.ok(); });
                QVERIFY(fitted != friction.end());
                const QString stored = fitted->fit.staticSource, shown = nb::staticSourceDisplayName(stored);
                QVERIFY(stored == QLatin1String("phase a") || stored == QLatin1String("velocity band"));
                if (language == QLatin1String("de"))
                    QVERIFY2(shown != stored, qPrintable(shown));
                bool found = false;
                for (const QTableView* table : w.analysisWorkspace()->findChildren<QTableView*>()) {
                    const QAbstractItemModel* m = table->model();
                    for (int c = 0; m && c < m->columnCount(); ++c)
                        if (m->headerData(c, Qt::Horizontal).toString() == (language == QLatin1String("de") ? QStringLiteral("D aus") : QStringLiteral("D from")))
                            for (int r = 0; r < m->rowCount(); ++r)
                                found |= m->index(r, c).data().toString() == shown;
                }
                QVERIFY2(found, qPrintable(shown));
                w.workspaces()->setCurrentIndex(0);
            }

            if (const QString shots = qEnvironmentVariable("NB_SCREENSHOT_DIR");
                !shots.isEmpty() && QGuiApplication::platformName() == QLatin1String("xcb")) {
                QDir().mkpath(shots);
                w.setWindowState(Qt::WindowMaximized);
                w.setGeometry(0, 0, 1366, 768);
                w.analysisWorkspace()->findChild<QTabWidget*>()->setCurrentIndex(0);
                for (int tab = 0; tab < w.workspaces()->count(); ++tab) {
                    w.workspaces()->setCurrentIndex(tab);
                    QTest::qWait(800);
                    const QString name = QStringLiteral("%1/%2_%3.png").arg(shots, QStringList{"record", "review", "analysis"}.value(tab), language);
                    QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"), name});
                }
                // Analysis' other figures, and the panel with the sine's fields.
                auto* analysisTabs = w.analysisWorkspace()->findChild<QTabWidget*>();
                for (int inner = 1; inner < analysisTabs->count(); ++inner) {
                    analysisTabs->setCurrentIndex(inner);
                    QTest::qWait(800);
                    QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"),
                                                                QStringLiteral("%1/analysis%2_%3.png").arg(shots).arg(inner).arg(language)});
                }
                analysisTabs->setCurrentIndex(0);
                w.controlPanel()->findChild<QRadioButton*>(QStringLiteral("sine"))->setChecked(true);
                w.workspaces()->setCurrentIndex(0);
                QTest::qWait(800);
                QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"),
                                                            QStringLiteral("%1/record_sine_%2.png").arg(shots, language)});
                w.controlPanel()->findChild<QRadioButton*>(QStringLiteral("linear"))->setChecked(true);
                // The dialogs a new operator meets: the welcome and Export session….
                w.workspaces()->setCurrentIndex(0);
                nb::WelcomeDialog* welcome = w.showWelcome();
                QTest::qWait(800);
                QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"),
                                                            QStringLiteral("%1/welcome_%2.png").arg(shots, language)});
                welcome->reject();
                nb::ExportDialog* exporter = w.exportSession();
                QTest::qWait(800);
                QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"),
                                                            QStringLiteral("%1/export_%2.png").arg(shots, language)});
                exporter->reject();
                // The dialogs that show data names (tips, tissue presets) and the calibration.
                auto shoot = [&](QWidget* dialog, const char* name) {
                    dialog->show();
                    QTest::qWait(600);
                    QProcess::execute(QStringLiteral("import"), {QStringLiteral("-window"), QStringLiteral("root"),
                                                                QStringLiteral("%1/%2_%3.png").arg(shots, QLatin1String(name), language)});
                    dialog->close();
                };
                nb::SessionInfo info;
                info.tip = QStringLiteral("beveled");
                info.organ = QStringLiteral("liver");
                nb::SessionInfoDialog details(nb::SessionInfoDialog::Mode::Edit, info, QString(), &w);
                shoot(&details, "session_details");
                nb::SimulatedRigDialog rig(nb::devices::SimulatedRigSpec{}, 1000.0, &w);
                shoot(&rig, "simulated_rig");
                shoot(w.openCalibrationWizard(), "calibration");
            }
            // Long results: every result line the operator may see, filled with a long text.
            const QString longText = QStringLiteral("found 1.2345 s (confidence 0.93, r = 0.88) ").repeated(8);
            for (QLabel* l : w.findChildren<QLabel*>())
                if (l->objectName() == QLatin1String("syncResult") || l->objectName() == QLatin1String("reviewStatus") ||
                    l->objectName() == QLatin1String("analysisStatus"))
                    l->setText(longText);
            w.statusBar()->showMessage(longText);
            QApplication::processEvents();

            const QSize min = w.minimumSizeHint().expandedTo(w.minimumSize());
            if (qEnvironmentVariableIsSet("NB_LAYOUT_DEBUG")) {
                for (QWidget* c : w.controlPanel()->findChildren<QWidget*>())
                    if (c->isVisibleTo(w.controlPanel()) && c->minimumSizeHint().width() > 150)
                        qInfo("   panel %s %s '%s': hint %d x %d", c->metaObject()->className(), qPrintable(c->objectName()),
                              qPrintable(c->property("text").toString() + c->property("title").toString()),
                              c->minimumSizeHint().width(), c->sizeHint().height());
                for (QDockWidget* d : w.findChildren<QDockWidget*>())
                    qInfo("dock %s: %d", qPrintable(d->objectName()), d->minimumSizeHint().width());
                for (int i = 0; i < w.workspaces()->count(); ++i) {
                    QWidget* page = w.workspaces()->widget(i);
                    qInfo("tab %d: %d x %d", i, page->minimumSizeHint().width(), page->minimumSizeHint().height());
                    for (QWidget* c : page->findChildren<QWidget*>())
                        if (c->minimumSizeHint().width() > 500 || c->minimumWidth() > 500)
                            qInfo("   %s %s: hint %d min %d", c->metaObject()->className(), qPrintable(c->objectName()),
                                  c->minimumSizeHint().width(), c->minimumWidth());
                }
            }
            qInfo("%s: window minimum %d x %d", qPrintable(language), min.width(), min.height());
            QVERIFY2(min.width() <= 1366, qPrintable(QStringLiteral("%1: minimum width %2 px").arg(language).arg(min.width())));
            // 768 less a desktop panel and the title bar.
            QVERIFY2(min.height() <= 700, qPrintable(QStringLiteral("%1: minimum height %2 px").arg(language).arg(min.height())));
            QCOMPARE(w.width(), 1366);

            // The plan's instruction wraps in its dock, and a click on it ticks it done.
            w.findChild<QDockWidget*>(QStringLiteral("planDock"))->raise();
            QApplication::processEvents();
            auto* instructionText = w.findChild<QLabel*>(QStringLiteral("planInstruction"));
            auto* instructionBox = w.findChild<QCheckBox*>(QStringLiteral("planCheckInstruction"));
            QVERIFY(instructionText && instructionBox && instructionText->wordWrap());
            QVERIFY2(instructionText->text().size() > 60, qPrintable(instructionText->text()));
            QVERIFY(instructionBox->isEnabled() && !instructionBox->isChecked());
            QTest::mouseClick(instructionText, Qt::LeftButton);
            QTRY_VERIFY(instructionBox->isChecked());

            // The session list shows more than two runs.
            w.findChild<QDockWidget*>(QStringLiteral("sessionDock"))->raise();
            QApplication::processEvents();
            auto* runs = w.sessionView()->view();
            QVERIFY(runs);
            const int rowHeight = runs->verticalHeader()->defaultSectionSize();
            QVERIFY2(runs->viewport()->height() >= 3 * rowHeight,
                     qPrintable(QStringLiteral("%1 px for rows of %2 px").arg(runs->viewport()->height()).arg(rowHeight)));

            // At 700 px high the control panel (E-stop, status) shows whole: no scrolling.
            w.resize(1366, 700);
            QApplication::processEvents();
            QTest::qWait(100);
            auto* panelScroll = qobject_cast<QScrollArea*>(w.controlPanel()->parentWidget()->parentWidget());
            QVERIFY(panelScroll);
            qInfo("%s: control panel minimum %d x %d, dock %d px wide, %d px high for the panel at 700",
                  qPrintable(language), w.controlPanel()->minimumSizeHint().width(), w.controlPanel()->minimumSizeHint().height(),
                  panelScroll->parentWidget()->width(), panelScroll->viewport()->height());
            QVERIFY2(panelScroll->verticalScrollBar()->maximum() == 0,
                     qPrintable(QStringLiteral("%1: the control panel scrolls by %2 px at 700 px")
                                    .arg(language).arg(panelScroll->verticalScrollBar()->maximum())));
            // The sine's fields (two rows) fit too.
            w.controlPanel()->findChild<QRadioButton*>(QStringLiteral("sine"))->setChecked(true);
            QApplication::processEvents();
            QTest::qWait(100);
            QVERIFY2(panelScroll->verticalScrollBar()->maximum() == 0,
                     qPrintable(QStringLiteral("%1, sine: the control panel scrolls by %2 px at 700 px")
                                    .arg(language).arg(panelScroll->verticalScrollBar()->maximum())));
            w.controlPanel()->findChild<QRadioButton*>(QStringLiteral("linear"))->setChecked(true);
            // Busy values fit their place in the status (none clipped): values never widen the
            // panel, so the panel's width must hold them. Checked at once, before the engine's
            // next status replaces them.
            {
                nb::devices::EngineStatus busy;
                busy.running = busy.stageEnabled = busy.biased = busy.zeroed = busy.moving = true;
                busy.rateHz = 10000.0;
                busy.force_N = -1.234;
                busy.forceMargin_N = 8.234;
                busy.forceMarginOf_N = 9.5;
                busy.position_mm = 123.456;
                busy.velocity_mm_s = 12.5;
                busy.bias_V = -1.2345;
                busy.dropped = 1234;
                busy.overruns = 56;
                busy.calibrationName = QStringLiteral("nominal (device)");
                w.controlPanel()->setStatus(busy);
                for (QLabel* value : w.controlPanel()->findChildren<QLabel*>())
                    if (value->objectName().startsWith(QLatin1String("status_")) && !value->wordWrap())
                        QVERIFY2(value->sizeHint().width() <= value->width(),
                                 qPrintable(QStringLiteral("%1: '%2' needs %3 px, has %4").arg(language, value->text())
                                                .arg(value->sizeHint().width()).arg(value->width())));
            }
            // Narrow enough to leave the plots room: about 420 px in either language.
            QDockWidget* panelDock = w.findChild<QDockWidget*>(QStringLiteral("controlDock"));
            QVERIFY2(panelDock->minimumSizeHint().width() <= 420,
                     qPrintable(QStringLiteral("%1: the control panel's dock needs %2 px").arg(language).arg(panelDock->minimumSizeHint().width())));
            QVERIFY2(panelDock->width() <= 420, qPrintable(QStringLiteral("%1: the control panel's dock is %2 px wide").arg(language).arg(panelDock->width())));

            // The label timeline and the force plot: one time axis, pixel for pixel, zooming together.
            w.resize(1366, 768);
            w.workspaces()->setCurrentWidget(w.reviewWorkspace());
            QApplication::processEvents();
            QTest::qWait(100);
            nb::Timeline* timeline = w.reviewWorkspace()->timeline();
            QCustomPlot* plot = nullptr;
            for (QCustomPlot* p : w.reviewWorkspace()->findChildren<QCustomPlot*>())
                if (p->objectName() == QLatin1String("reviewForcePlot"))
                    plot = p;
            QVERIFY(plot);
            auto check = [&] {
                for (double t : {plot->xAxis->range().lower + 0.1 * plot->xAxis->range().size(),
                                 plot->xAxis->range().center(), plot->xAxis->range().upper - 0.1 * plot->xAxis->range().size()}) {
                    const int px = plot->mapTo(w.reviewWorkspace(), QPoint(int(std::lround(plot->xAxis->coordToPixel(t))), 0)).x();
                    const int tx = timeline->mapTo(w.reviewWorkspace(), QPoint(timeline->xOf(t), 0)).x();
                    QVERIFY2(std::abs(px - tx) <= 1, qPrintable(QStringLiteral("t = %1 s: plot x %2, timeline x %3").arg(t).arg(px).arg(tx)));
                }
            };
            check();
            plot->xAxis->setRange(1.0, 3.0);  // a zoom in the plot
            plot->replot();
            QCOMPARE(timeline->xOf(1.0) < timeline->xOf(3.0), true);
            QApplication::processEvents();
            check();

            // Alt+letter reaches one place: the menus' and the workspace tabs' mnemonics differ
            // (Alt+V is the View menu, not the Review tab).
            QStringList mnemonics;
            auto mnemonicOf = [](const QString& text) {
                const qsizetype i = text.indexOf(QLatin1Char('&'));
                return i >= 0 && i + 1 < text.size() ? text.at(i + 1).toLower() : QChar();
            };
            for (QAction* a : w.menuBar()->actions())
                mnemonics << QString(mnemonicOf(a->text())) + QLatin1Char(' ') + a->text();
            for (int i = 0; i < w.workspaces()->count(); ++i)
                mnemonics << QString(mnemonicOf(w.workspaces()->tabText(i))) + QLatin1Char(' ') + w.workspaces()->tabText(i);
            QSet<QChar> seen;
            for (const QString& m : mnemonics) {
                QVERIFY2(!seen.contains(m.at(0)), qPrintable(QStringLiteral("%1: Alt+%2 is taken twice (%3)")
                                                                 .arg(language, m.at(0), mnemonics.join(QStringLiteral(", ")))));
                seen.insert(m.at(0));
            }

        }
        for (QTranslator* t : QCoreApplication::instance()->findChildren<QTranslator*>())
            QCoreApplication::removeTranslator(t);
        nb::setPreferredLanguage(QStringLiteral("en"));
    }
};

QTEST_MAIN(TestLaptopLayout)
#include "test_laptop_layout.moc"
