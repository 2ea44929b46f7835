// The analysis workspace on runs recorded by the real simulator: every view is filled, follows
// the run choice and label edits, and is grabbed to build-export/screenshots/ for a human look.
#include "core/export/dataset_loader.h"
#include "core/label_suggest.h"
#include "core/export/export_error.h"
#include "support/needlebench_cli.h"
#include "widgets/analysis/analysis_plots.h"
#include "widgets/analysis/analysis_workspace.h"
#include "widgets/analysis/figure_export.h"

#include <QDir>
#include <QRegularExpression>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QLocale>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QComboBox>
#include <QFileDialog>
#include <QPushButton>
#include <QFileInfo>
#include <QtTest>
#include <qcustomplot.h>

using namespace nb;

namespace {

bool simulate(const QStringList& args)
{
    return nbtest::runCli(QStringList{QStringLiteral("simulate")} + args, 60000).code == 0;
}

// How many distinct colours an image has in a coarse sample: a blank or failed render has 1-2.
int colourCount(const QImage& image)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7)
            colours.insert(image.pixel(x, y));
    return int(colours.size());
}

}  // namespace

class TestAnalysisViews : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        const QDir d(dir_.path());
        for (int seed = 1; seed <= 4; ++seed)
            QVERIFY(simulate({"--protocol", "stiffness", "--tissue", "liver1", "--seed", QString::number(seed), "--out",
                              d.filePath(QStringLiteral("run_00%1_linear.csv").arg(seed))}));
        QVERIFY(simulate({"--protocol", "friction", "--frequency-hz", "0.5", "--cycles", "3", "--out",
                          d.filePath(QStringLiteral("run_005_sine.csv")), "--truth", d.filePath(QStringLiteral("truth5.json"))}));
        // Phase labels for the friction run where the simulator says the phases were.
        QFile truth(d.filePath(QStringLiteral("truth5.json")));
        QVERIFY(truth.open(QIODevice::ReadOnly));
        Labels labels;
        for (const QJsonValue& v : QJsonDocument::fromJson(truth.readAll()).object().value(QStringLiteral("phases")).toArray()) {
            const QJsonObject p = v.toObject();
            const double a = std::max(0.0, p.value(QStringLiteral("start_s")).toDouble());
            if (p.value(QStringLiteral("end_s")).toDouble() > a)
                labels.push_back({QStringLiteral("phase"), p.value(QStringLiteral("label")).toString(), a,
                                  p.value(QStringLiteral("end_s")).toDouble(), {}});
        }
        QVERIFY(labels.size() >= 12);
        writeLabelsFile(d.filePath(QStringLiteral("run_005_sine.labels.csv")), labels);
        QDir().mkpath(QStringLiteral(NB_BINARY_DIR "/screenshots"));
    }

    void viewsShowTheSession()
    {
        AnalysisWorkspace w;
        w.resize(1400, 900);
        QVERIFY(w.openSession(dir_.path()));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const SessionAnalysis& a = w.analysis();
        QCOMPARE(a.stiffness.size(), std::size_t(4));
        QCOMPARE(a.stiffnessGroups.size(), std::size_t(1));
        QCOMPARE(a.stiffnessGroups[0].group, QStringLiteral("liver1"));
        QCOMPARE(a.friction.size(), std::size_t(1));
        QVERIFY2(a.friction[0].ok(), qPrintable(a.friction[0].error));
        QCOMPARE(a.friction[0].fit.staticSource, QStringLiteral("phase a"));  // the labels chose the samples
        QCOMPARE(w.stiffnessRunsModel()->rowCount(), 4);
        QCOMPARE(w.stiffnessPooledModel()->rowCount(), 2);  // pooled + mean of runs
        QCOMPARE(w.frictionSummaryModel()->rowCount(), 4);  // 0.5 Hz and overall, mean and std
        QCOMPARE(w.validationModel()->rowCount(), 4);
        QVERIFY(w.stiffnessPlot()->graphCount() >= 9);       // 4 runs x (points + fit) + pooled
        QVERIFY(w.phasesPlot()->itemCount() >= 12);         // shaded phases

        const char* names[] = {"stiffness", "friction", "validation"};
        for (int t = 0; t < 3; ++t) {
            w.tabs()->setCurrentIndex(t);
            QCoreApplication::processEvents();
            const QImage shot = w.grab().toImage();
            QVERIFY(shot.save(QStringLiteral(NB_BINARY_DIR "/screenshots/analysis_%1.png").arg(QLatin1String(names[t]))));
            QVERIFY(colourCount(shot) > 20);
        }

        // Save figure offers the session's folder and a name; a name typed without a suffix
        // is saved with the chosen type's (it was refused: "unknown figure format ''").
        w.tabs()->setCurrentIndex(0);
        QPushButton* save = nullptr;
        for (QPushButton* b : w.tabs()->currentWidget()->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Save figure…"))
                save = b;
        QVERIFY(save);
        save->click();
        QFileDialog* chooser = nullptr;
        QTRY_VERIFY((chooser = w.findChild<QFileDialog*>()) != nullptr);
        QCOMPARE(QDir(chooser->directory()).canonicalPath(), QDir(dir_.path()).canonicalPath());
        QCOMPARE(chooser->defaultSuffix(), QStringLiteral("png"));
        QVERIFY2(QFileInfo(chooser->selectedFiles().value(0)).completeBaseName() == QStringLiteral("stiffness"), qPrintable(chooser->selectedFiles().value(0)));
        auto* types = chooser->findChild<QComboBox*>(QStringLiteral("fileTypeCombo"));
        QVERIFY(types);
        auto chooseType = [types](int i) {  // as the operator picks it in the list
            types->setCurrentIndex(i);
            emit types->activated(i);
            emit types->textActivated(types->itemText(i));
        };
        chooseType(1);
        QCOMPARE(chooser->defaultSuffix(), QStringLiteral("svg"));
        chooseType(0);
        QCOMPARE(chooser->defaultSuffix(), QStringLiteral("png"));
        const QString typed = QDir(dir_.path()).filePath(QStringLiteral("a1_by_motion"));
        chooser->selectFile(typed);
        static_cast<QDialog*>(chooser)->accept();  // as the Save button does
        QTRY_VERIFY(QFileInfo(typed + QStringLiteral(".png")).size() > 1000);
    }

    // Runs that name no tissue (recorded in the window, say) are one group said so, not a
    // blank entry; choosing it plots them.
    void runsWithoutATissueAreNamed()
    {
        QTemporaryDir tmp;
        const QDir d(tmp.path());
        QVERIFY(QFile::copy(QDir(dir_.path()).filePath(QStringLiteral("run_001_linear.csv")), d.filePath(QStringLiteral("run_001_linear.csv"))));
        QFile in(QDir(dir_.path()).filePath(QStringLiteral("run_002_linear.csv")));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        QVERIFY(text.contains("# tissue: liver1\n"));
        text.replace("# tissue: liver1\n", "");
        QFile out(d.filePath(QStringLiteral("run_002_linear.csv")));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text);
        out.close();

        AnalysisWorkspace w;
        QVERIFY(w.openSession(tmp.path()));
        QCOMPARE(w.analysis().stiffnessGroups.size(), std::size_t(2));
        QComboBox* groups = nullptr;
        for (QComboBox* box : w.findChildren<QComboBox*>())
            if (box->findData(QStringLiteral("liver1")) >= 0)
                groups = box;
        QVERIFY(groups);
        const int unnamed = groups->findData(QString());
        QVERIFY(unnamed >= 0);
        QCOMPARE(groups->itemText(unnamed), QStringLiteral("no tissue given"));
        groups->setCurrentIndex(unnamed);
        QVERIFY(w.stiffnessPlot()->graphCount() >= 3);  // the run (points + fit) + pooled
        bool saidInTable = false;
        for (int r = 0; r < w.stiffnessRunsModel()->rowCount(); ++r)
            saidInTable |= w.stiffnessRunsModel()->item(r, 1)->text() == QStringLiteral("no tissue given");
        QVERIFY(saidInTable);

        // Numbers in the window's tables as the plots write them: 0,0474 in German.
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        AnalysisWorkspace german;
        QVERIFY(german.openSession(tmp.path()));
        QLocale::setDefault(before);
        const QString a1 = german.stiffnessRunsModel()->item(0, 2)->text();
        QVERIFY2(a1.startsWith(QStringLiteral("0,")), qPrintable(a1));
        QVERIFY2(german.stiffnessRunsModel()->horizontalHeaderItem(3)->text().endsWith(QStringLiteral("[N/mm²]")),
                 qPrintable(german.stiffnessRunsModel()->horizontalHeaderItem(3)->text()));
    }

    // A run the judgement leaves out and a run taken but not fitted are two lists, each under
    // its own heading: the unfitted run followed the left-out list unheaded, as if left out.
    void leftOutAndNotFittedAreTwoLists()
    {
        QTemporaryDir tmp;
        const QDir d(tmp.path());
        QVERIFY(QFile::copy(QDir(dir_.path()).filePath(QStringLiteral("run_001_linear.csv")), d.filePath(QStringLiteral("run_001_linear.csv"))));
        QFile in(QDir(dir_.path()).filePath(QStringLiteral("run_002_linear.csv")));
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray text = in.readAll();
        auto write = [&](const char* name, const QByteArray& bytes) {
            QFile out(d.filePath(QLatin1String(name)));
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(bytes);
        };
        QByteArray stopped = text;
        QVERIFY(stopped.contains("# end_reason: completed\n"));
        stopped.replace("# end_reason: completed\n", "# end_reason: force_limit\n");
        write("run_002_linear.csv", stopped);
        // Ended by the operator 3 s in: in the tissue, before its puncture.
        QByteArray early;
        for (const QByteArray& line : text.split('\n')) {
            bool number = false;
            const double t = line.left(line.indexOf(',')).toDouble(&number);
            if (line.startsWith("# end_reason"))
                early += "# end_reason: stopped\n";
            else if (!line.isEmpty() && (!number || t <= 3.0))
                early += line + '\n';
        }
        write("run_003_linear.csv", early);

        AnalysisWorkspace w;
        QVERIFY(w.openSession(tmp.path()));
        const QStringList lines = w.statusText().split(QLatin1Char('\n'));
        const qsizetype leftOut = lines.indexOf(QStringLiteral("Left out (switch above to include them):"));
        const qsizetype notFitted = lines.indexOf(QStringLiteral("Not fitted:"));
        QVERIFY2(leftOut >= 0 && notFitted > leftOut, qPrintable(w.statusText()));
        QVERIFY2(lines.at(leftOut + 1).startsWith(QStringLiteral("run_002_linear: ")), qPrintable(w.statusText()));
        QVERIFY2(lines.at(notFitted + 1).startsWith(QStringLiteral("run_003_linear: no stiffness fit")), qPrintable(w.statusText()));
        QCOMPARE(lines.first(), QStringLiteral("2 run(s) analysed"));  // no translation loaded: the source's plural
    }

    // One compliant slab (liver3, the thesis's Table 4) at three frequencies and no insertion:
    // the page opens on Friction and the summary carries the line through the peak speeds.
    void compliantSlabOpensOnFrictionWithThePeakSpeedLine()
    {
        QTemporaryDir tmp;
        const QDir d(tmp.path());
        int k = 1;
        for (const char* f : {"0.2", "0.5", "0.8"})
            QVERIFY(simulate({"--protocol", "friction", "--tissue", "liver3", "--frequency-hz", QLatin1String(f), "--cycles", "4",
                              "--seed", "11", "--out", d.filePath(QStringLiteral("run_00%1_sine.csv").arg(k++))}));
        AnalysisWorkspace w;
        QVERIFY(w.openSession(tmp.path()));
        QCOMPARE(w.tabs()->currentIndex(), 1);
        QCOMPARE(w.analysis().frictionPeakLines.size(), std::size_t(1));
        bool lineRow = false;
        for (int r = 0; r < w.frictionSummaryModel()->rowCount(); ++r)
            lineRow |= w.frictionSummaryModel()->item(r, 0)->text() == QStringLiteral("peak speeds, Liver 3");
        QVERIFY(lineRow);
        // Each run's own C agrees with the line now that the fit follows the slab's spring-back
        // (the 0.8 Hz run departed by 25 % before), so the status names none.
        QVERIFY2(!w.statusText().contains(QStringLiteral("departs")), qPrintable(w.statusText()));
        QCOMPARE(w.analysis().friction.size(), std::size_t(3));
        for (const auto& r : w.analysis().friction)
            QVERIFY2(!r.peakLineDeparture || !r.peakLineDeparture->significant, qPrintable(r.run));
    }

    // A run that does not determine Cp and bp (a slab at the knee of its plate contact): its
    // row leaves them empty and names them, the group mean leaves them out, the status says why.
    void undeterminedValuesAreEmptyAndNamed()
    {
        QTemporaryDir tmp;
        const QDir d(tmp.path());
        QVERIFY(simulate({"--protocol", "friction", "--tissue", "liver3", "--frequency-hz", "0.23", "--amplitude-mm", "5.6",
                          "--stick-band-mm-s", "1.2", "--plate-gap-mm", "2.46", "--force-noise-n", "0.0006", "--cycles", "4", "--seed", "5",
                          "--out", d.filePath(QStringLiteral("run_001_sine.csv"))}));
        AnalysisWorkspace w;
        QVERIFY(w.openSession(tmp.path()));
        QCOMPARE(w.analysis().friction.size(), std::size_t(1));
        QVERIFY(w.analysis().friction.front().fit.notPhysicalValues.contains(QStringLiteral("Cp")));
        QVERIFY2(w.statusText().contains(QStringLiteral("run_001_sine: Cp and bp are not determined by this run")), qPrintable(w.statusText()));
        QStandardItemModel* runs = w.frictionRunsModel();
        int cpColumn = -1, namedColumn = -1;
        for (int c = 0; c < runs->columnCount(); ++c) {
            const QString h = runs->horizontalHeaderItem(c)->text();
            if (h.startsWith(QStringLiteral("Cp")))
                cpColumn = c;
            if (h.startsWith(QStringLiteral("not determined")))
                namedColumn = c;
        }
        QVERIFY(cpColumn >= 0 && namedColumn >= 0);
        bool ok = false;
        runs->item(0, cpColumn)->text().toDouble(&ok);
        QVERIFY2(!ok, qPrintable(runs->item(0, cpColumn)->text()));
        QVERIFY(runs->item(0, namedColumn)->text().contains(QStringLiteral("Cp")));
        QVERIFY(!std::isfinite(w.analysis().frictionOverall->mean.Cp_N_per_m));
        QVERIFY(std::isfinite(w.analysis().frictionOverall->mean.Cn_N_per_m));
    }

    void runChoiceAndLabelEditsUpdateResults()
    {
        AnalysisWorkspace w;
        QVERIFY(w.openSession(dir_.path()));
        QSignalSpy updated(&w, &AnalysisWorkspace::analysisUpdated);
        // Untick the first run in the list, as the user would.
        auto* list = w.findChild<QListWidget*>();
        QVERIFY(list);
        list->item(0)->setCheckState(Qt::Unchecked);
        QCOMPARE(updated.count(), 1);
        QCOMPARE(w.analysis().stiffness.size(), std::size_t(3));
        QCOMPARE(w.stiffnessRunsModel()->rowCount(), 3);
        w.setRuns({});
        QCOMPARE(w.analysis().stiffness.size(), std::size_t(4));

        // A puncture label moves the detected puncture and so the table's depth.
        const auto before = w.analysis().stiffness[1].events;
        const double labelled = before.puncture.time_s - 0.5;
        const QString labels = QDir(dir_.path()).filePath(QStringLiteral("run_002_linear.labels.csv"));
        writeLabelsFile(labels, {{QStringLiteral("events"), QStringLiteral("puncture"), labelled, labelled, {}}});
        w.reloadLabels();
        const auto after = w.analysis().stiffness[1].events;
        QVERIFY(std::abs(after.puncture.time_s - labelled) <= 0.0501);  // snapped to the peak within 50 ms
        QVERIFY(after.punctureDepth_mm() < before.punctureDepth_mm() - 1.0);
        QVERIFY(QFile::remove(labels));
        // The watcher notices the removal by itself.
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(w.analysis().stiffness[1].events.puncture.time_s - before.puncture.time_s) < 1e-9, 10000);
    }

    void brokenLabelsKeepTheLastGoodOnes()
    {
        AnalysisWorkspace w;
        QVERIFY(w.openSession(dir_.path()));
        const QString path = QDir(dir_.path()).filePath(QStringLiteral("run_005_sine.labels.csv"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray good = f.readAll();
        f.close();
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("track,label,start_s,end_s,comment\nphase,a,zero,1,\n");
        f.close();
        w.reloadLabels();
        QCOMPARE(w.analysis().friction[0].fit.staticSource, QStringLiteral("phase a"));
        QVERIFY(w.findChild<QLabel*>() != nullptr);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(good);
        f.close();
    }

    void figuresInEveryFormat()
    {
        const LoadedDataset loaded = loadDataset(dir_.path());
        const SessionAnalysis a = analyseDataset(loaded.dataset);
        QCustomPlot plot;
        plotStiffness(&plot, a, QStringLiteral("liver1"));
        QTemporaryDir out;
        for (const char* ext : {"png", "svg", "pdf"}) {
            const QString path = out.filePath(QStringLiteral("stiffness.%1").arg(QLatin1String(ext)));
            saveFigure(&plot, path, 800, 500);
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray head = f.read(8);
            if (QLatin1String(ext) == QLatin1String("png"))
                QVERIFY(head.startsWith("\x89PNG"));
            else if (QLatin1String(ext) == QLatin1String("pdf"))
                QVERIFY(head.startsWith("%PDF"));
            else
                QVERIFY(f.readAll().contains("<svg"));
        }
        QImage png(out.filePath(QStringLiteral("stiffness.png")));
        QCOMPARE(png.size(), QSize(800, 500));
        QVERIFY(colourCount(png) > 10);
        QVERIFY_THROWS_EXCEPTION(ExportError, saveFigure(&plot, out.filePath(QStringLiteral("x.bmp"))));
        QVERIFY_THROWS_EXCEPTION(ExportError, saveFigure(&plot, QStringLiteral("/nonexistent-nb/x.png")));
        // Only the three figures: no temporaries left behind by the failures.
        QCOMPARE(QDir(out.path()).entryList(QDir::Files | QDir::Hidden).size(), 3);
    }

    // Issue 15: figures a journal takes. PNG (300 dpi), PDF and SVG at 175 and 85 mm, text
    // 7-9 pt, a margin round the data, colour-blind-safe colours, insertion and withdrawal
    // told apart by line style, fitted samples marked, velocity in mm/s. Kept under
    // build/figures-journal for a look.
    void journalFigures()
    {
        LoadedDataset loaded = loadDataset(dir_.path());
        DatasetRun* sine = nullptr;
        for (DatasetRun& r : loaded.dataset.runs)
            if (r.name == QLatin1String("run_005_sine"))
                sine = &r;
        QVERIFY(sine);
        const SessionAnalysis a = analyseDataset(loaded.dataset);
        const QString outDir = QStringLiteral(NB_BINARY_DIR "/figures-journal");
        QDir(outDir).removeRecursively();
        QVERIFY(QDir().mkpath(outDir));
        QCustomPlot plot;
        plot.resize(900, 600);
        auto check = [&](const QString& name) {
            // No data touches the frame: every point lies inside the axes with room to spare.
            for (int i = 0; i < plot.graphCount(); ++i) {
                bool found = false;
                const QCPRange xr = plot.graph(i)->getKeyRange(found);
                if (!found)
                    continue;
                const QCPRange yr = plot.graph(i)->getValueRange(found);
                QVERIFY2(xr.lower > plot.xAxis->range().lower && xr.upper < plot.xAxis->range().upper, qPrintable(name));
                QVERIFY2(yr.lower > plot.yAxis->range().lower && yr.upper < plot.yAxis->range().upper, qPrintable(name));
            }
            const QFont screenTicks = plot.xAxis->tickLabelFont();
            const QStringList files = saveJournalFigures(&plot, QDir(outDir).filePath(name + QStringLiteral(".png")));
            QCOMPARE(files.size(), 6);
            QCOMPARE(plot.xAxis->tickLabelFont(), screenTicks);  // the screen's style is back
            const QImage two(QDir(outDir).filePath(name + QStringLiteral(".png")));
            const QImage one(QDir(outDir).filePath(name + QStringLiteral("_85mm.png")));
            QVERIFY(std::abs(two.width() - 175.0 / 25.4 * 300) < 4);
            QVERIFY(std::abs(one.width() - 85.0 / 25.4 * 300) < 4);
            QVERIFY(std::abs(one.dotsPerMeterX() - 300 / 0.0254) < 50);
            QVERIFY(colourCount(one) > 10);
            QFile pdf(QDir(outDir).filePath(name + QStringLiteral("_85mm.pdf")));
            QVERIFY(pdf.open(QIODevice::ReadOnly));
            const QByteArray pdfBytes = pdf.readAll();
            const QRegularExpressionMatch box = QRegularExpression(QStringLiteral("/MediaBox \\[0 0 ([0-9.]+) ([0-9.]+)\\]")).match(QString::fromLatin1(pdfBytes));
            QVERIFY2(box.hasMatch(), "no MediaBox");
            QVERIFY(std::abs(box.captured(1).toDouble() - 85.0 / 25.4 * 72) < 1.5);
            QFile svg(QDir(outDir).filePath(name + QStringLiteral("_85mm.svg")));
            QVERIFY(svg.open(QIODevice::ReadOnly));
            const QString svgText = QString::fromUtf8(svg.readAll());
            const QRegularExpressionMatch width = QRegularExpression(QStringLiteral("width=\"([0-9.]+)mm\"")).match(svgText);
            QVERIFY2(width.hasMatch() && std::abs(width.captured(1).toDouble() - 85.0) < 1.0, qPrintable(width.captured(0)));
            // Every text 7 to 9 pt.
            auto sizes = QRegularExpression(QStringLiteral("font-size=\"([0-9.]+)\"")).globalMatch(svgText);
            int texts = 0;
            while (sizes.hasNext()) {
                const double pt = sizes.next().captured(1).toDouble();
                QVERIFY2(pt >= 7.0 && pt <= 9.0, qPrintable(QStringLiteral("%1: %2 pt").arg(name).arg(pt)));
                ++texts;
            }
            QVERIFY(texts > 3);
        };
        plotStiffness(&plot, a, QStringLiteral("liver1"));
        check(QStringLiteral("stiffness_liver1"));
        for (const FrictionRunResult& f : a.friction)
            if (f.run == QLatin1String("run_005_sine")) {
                plotFrictionVelocity(&plot, *sine, f);
                QVERIFY(plot.xAxis->label().contains(QLatin1String("mm/s")));
                QStringList names;
                for (int i = 0; i < plot.graphCount(); ++i)
                    names << plot.graph(i)->name();
                QVERIFY2(names.contains(QStringLiteral("recorded, fitted")) && names.contains(QStringLiteral("recorded, not fitted")),
                         qPrintable(names.join(QLatin1Char(','))));
                check(QStringLiteral("friction_velocity"));
            }
        // Direction labels as the label suggester makes them: withdrawal drawn dashed.
        sine->labels = suggestLabels(sine->run);
        plotPhases(&plot, *sine);
        bool dashed = false;
        for (int i = 0; i < plot.graphCount(); ++i)
            dashed = dashed || (plot.graph(i)->pen().style() == Qt::DashLine && plot.graph(i)->name().contains(QLatin1String("withdrawal")));
        QVERIFY(dashed);
        check(QStringLiteral("phases"));
        for (const ValidationResult& v : a.validation) {
            plotValidation(&plot, v);
            check(QStringLiteral("validation"));
            break;
        }
    }
};

QTEST_MAIN(TestAnalysisViews)
#include "test_analysis_views.moc"
