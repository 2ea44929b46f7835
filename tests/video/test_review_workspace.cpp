// The review workspace driven like an operator: real simulated run and rendered video,
// hotkeys, undo/redo, edge drag, frame steps, auto sync; saves a screenshot.
#include "core/labels.h"
#include "core/run_video_link.h"
#include "core/run_file.h"
#include "widgets/label_model.h"
#include "widgets/label_set_dialog.h"
#include "widgets/review_workspace.h"
#include "widgets/timeline.h"
#include "widgets/video_view.h"
#include "video/frame_index.h"
#include "support/needlebench_cli.h"

#include <QCheckBox>
#include <algorithm>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMessageBox>
#include <QPointer>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QThread>
#include <QLabel>
#include <QtTest>
#include <qcustomplot.h>

using nb::Label;

class TestReviewWorkspace : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString run_, video_;
    double truthOffset_ = 0.0;

    static bool has(const nb::Labels& labels, const QString& track, const QString& name, double s, double e)
    {
        for (const Label& l : labels)
            if (l.track == track && l.label == name && std::abs(l.start_s - s) < 1e-6 && std::abs(l.end_s - e) < 1e-6)
                return true;
        return false;
    }

private slots:
    void initTestCase()
    {
        // Edited label sets live in QSettings: keep the test's apart and start from the defaults.
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("NeedleBenchTest");
        QSettings().remove("labelSets");
        run_ = dir_.filePath("run.csv");
        video_ = dir_.filePath("run.avi");
        QProcess p;
        p.start(QStringLiteral(NB_EXECUTABLE),
                {"simulate", "--protocol", "friction", "--tissue", "liver7", "--cycles", "2", "--out", run_, "--truth",
                 dir_.filePath("truth.json"), "--video", video_, "--video-offset-s", "1.2"});
        QVERIFY(p.waitForFinished(240000));
        QCOMPARE(p.exitCode(), 0);
        QFile tf(dir_.filePath("truth.json"));
        QVERIFY(tf.open(QIODevice::ReadOnly));
        truthOffset_ = QJsonDocument::fromJson(tf.readAll()).object()["video_offset_s"].toDouble();
    }

    void labellingWithHotkeysAndUndo()
    {
        nb::ReviewWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(ws.openRun(run_));
        auto* model = ws.labelModel();
        QCOMPARE(model->labels().size(), std::size_t(0));

        ws.setCursorTime(0.2);
        QTest::keyClick(&ws, Qt::Key_1);  // insertion a starts
        ws.setCursorTime(0.4);
        QTest::keyClick(&ws, Qt::Key_2);  // a ends, b1 starts
        ws.setCursorTime(0.5);
        QTest::keyClick(&ws, Qt::Key_2);  // b1 ends
        QCOMPARE(model->labels().size(), std::size_t(2));
        QVERIFY(has(model->labels(), "insertion", "a", 0.2, 0.4));
        QVERIFY(has(model->labels(), "insertion", "b1", 0.4, 0.5));
        // Saved beside the run after every change.
        QCOMPARE(nb::readLabelsFile(dir_.filePath("run.labels.csv")), model->labels());

        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(model->labels().size(), std::size_t(1));
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(model->labels().size(), std::size_t(0));
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTest::keyClick(&ws, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(model->labels().size(), std::size_t(2));
        QCOMPARE(nb::readLabelsFile(dir_.filePath("run.labels.csv")).size(), std::size_t(2));

        // An overlapping phase is refused and the operator told.
        ws.setCursorTime(0.3);
        QTest::keyClick(&ws, Qt::Key_3);
        ws.setCursorTime(0.45);
        QTest::keyClick(&ws, Qt::Key_3);
        QCOMPARE(model->labels().size(), std::size_t(2));
        QVERIFY(ws.status().contains("overlaps"));

        // Split a at 0.3, delete the right half, undo the delete.
        ws.setCursorTime(0.3);
        QTest::keyClick(&ws, Qt::Key_S);
        QVERIFY(has(model->labels(), "insertion", "a", 0.2, 0.3));
        QVERIFY(has(model->labels(), "insertion", "a", 0.3, 0.4));
        ws.setCursorTime(0.35);
        QTest::keyClick(&ws, Qt::Key_Delete);
        QVERIFY(!has(model->labels(), "insertion", "a", 0.3, 0.4));
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(has(model->labels(), "insertion", "a", 0.3, 0.4));

        // Withdrawal track and a point-free protocol: key 5 is withdrawal a.
        ws.setCursorTime(1.0);
        QTest::keyClick(&ws, Qt::Key_5);
        ws.setCursorTime(1.2);
        QTest::keyClick(&ws, Qt::Key_5);
        QVERIFY(has(model->labels(), "withdrawal", "a", 1.0, 1.2));

        // Drag the end of b1 (0.5 s) to the right with the mouse: one undoable edit.
        nb::Timeline* tl = ws.timeline();
        const int y = tl->rowTop("insertion") + tl->rowHeight() / 2;
        const int x0 = tl->xOf(0.5), x1 = tl->xOf(0.7);
        QTest::mousePress(tl, Qt::LeftButton, {}, QPoint(x0, y));
        QTest::mouseMove(tl, QPoint((x0 + x1) / 2, y));
        QTest::mouseMove(tl, QPoint(x1, y));
        QTest::mouseRelease(tl, Qt::LeftButton, {}, QPoint(x1, y));
        bool moved = false;
        for (const Label& l : model->labels())
            moved |= l.label == "b1" && std::abs(l.end_s - 0.7) < 0.02 && l.start_s == 0.4;
        QVERIFY(moved);
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(has(model->labels(), "insertion", "b1", 0.4, 0.5));
    }

    void labelSetEditedInTheDialog()
    {
        nb::ReviewWorkspace ws;
        ws.resize(1200, 800);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QPointer<nb::LabelSetDialog> dialog = ws.editLabelSet();
        QVERIFY(dialog->isVisible());
        QTableWidget* table = dialog->table();
        const int rows = table->rowCount();
        QCOMPARE(rows, 8);
        QPushButton* add = nullptr;
        for (QPushButton* b : dialog->findChildren<QPushButton*>())
            if (b->text() == "Add label")
                add = b;
        QVERIFY(add);
        QTest::mouseClick(add, Qt::LeftButton);
        QCOMPARE(table->rowCount(), rows + 1);
        table->item(rows, nb::LabelSetDialog::Track)->setText("events");
        table->item(rows, nb::LabelSetDialog::Name)->setText("bubble");
        static_cast<QComboBox*>(table->cellWidget(rows, nb::LabelSetDialog::Kind))->setCurrentIndex(1);
        QPushButton* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);

        // Refused: a hotkey another label has, a key the workspace uses, a duplicate name.
        table->item(rows, nb::LabelSetDialog::Hotkey)->setText("3");
        QTest::mouseClick(ok, Qt::LeftButton);
        QVERIFY(dialog->isVisible());
        QVERIFY2(dialog->problem().contains("insertion/b2"), qPrintable(dialog->problem()));
        table->item(rows, nb::LabelSetDialog::Hotkey)->setText("S");
        QTest::mouseClick(ok, Qt::LeftButton);
        QVERIFY(dialog->isVisible());
        QVERIFY2(dialog->problem().contains("split"), qPrintable(dialog->problem()));
        table->item(rows, nb::LabelSetDialog::Hotkey)->setText("B");
        table->item(rows, nb::LabelSetDialog::Track)->setText("insertion");
        table->item(rows, nb::LabelSetDialog::Name)->setText("a");
        QTest::mouseClick(ok, Qt::LeftButton);
        QVERIFY(dialog->isVisible());
        QVERIFY2(dialog->problem().contains("twice"), qPrintable(dialog->problem()));
        QVERIFY(!ws.labelModel()->definitionForKey(Qt::Key_B));

        table->item(rows, nb::LabelSetDialog::Track)->setText("events");
        table->item(rows, nb::LabelSetDialog::Name)->setText("bubble");
        QTest::mouseClick(ok, Qt::LeftButton);
        QTRY_VERIFY(!dialog);

        // The new hotkey places the new point label at the cursor, on its own track.
        ws.setCursorTime(0.8);
        QTest::keyClick(&ws, Qt::Key_B);
        QVERIFY(has(ws.labelModel()->labels(), "events", "bubble", 0.8, 0.8));
        QVERIFY(ws.labelModel()->tracks().contains("events"));
        // Kept for the protocol: the next workspace has it too.
        QCOMPARE(nb::savedLabelSet("friction").size(), qsizetype(rows + 1));
        nb::ReviewWorkspace other;
        QVERIFY(other.openRun(run_));
        QVERIFY(other.labelModel()->definitionForKey(Qt::Key_B));
        QSettings().remove("labelSets");
    }

    void videoFollowsTheCursorAndSyncs()
    {
        // The labels the earlier cases placed would leave no room for the suggestion below.
        QFile::remove(nb::labelsPathFor(run_));
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QSignalSpy shown(&ws, &nb::ReviewWorkspace::frameShown);
        ws.openVideo(video_);
        QVERIFY(opened.wait(60000));
        QTRY_VERIFY_WITH_TIMEOUT(ws.currentFrame() == 0, 20000);

        // Not synchronised yet: the picture has no place on the force's clock, so Suggest
        // answers at once from force and position and says how to have the video used.
        ws.suggestLabels();
        QVERIFY(!ws.isSuggesting());
        QVERIFY2(ws.status().contains(QLatin1String("synchronise the video")), qPrintable(ws.status()));
        const std::size_t fromForce = ws.labelModel()->labels().size();
        QVERIFY(fromForce > 8);
        // Pressed again, it places nothing twice: its events stood three times over after a
        // third press, and were saved so.
        ws.suggestLabels();
        QCOMPARE(ws.labelModel()->labels().size(), fromForce);
        QVERIFY2(ws.status().contains(QLatin1String("left out")), qPrintable(ws.status()));
        ws.undoStack()->undo();
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(0));

        // Offset 0: recording time t shows video frame floor(t·29.97).
        ws.setCursorTime(1.0);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 29, 20000);
        QTest::keyClick(&ws, Qt::Key_Right);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 30, 20000);
        QTest::keyClick(&ws, Qt::Key_Right, Qt::ShiftModifier);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 40, 20000);
        QTest::keyClick(&ws, Qt::Key_Left);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 39, 20000);

        // Automatic sync on the region around the needle tip in the middle pane.
        ws.videoView()->setRoi(QRect(240, 300, 240, 180));
        QSignalSpy synced(&ws, &nb::ReviewWorkspace::syncFinished);
        ws.startAutoSync();
        QVERIFY(synced.wait(120000));
        QVERIFY(ws.pendingSync().has_value());
        QVERIFY2(std::abs(ws.pendingSync()->offset_s - truthOffset_) < 1.0 / 29.97,
                 qPrintable(QString::number(ws.pendingSync()->offset_s)));
        // The correlation curve is shown, its peak at the offset reported, until accepted.
        QCustomPlot* plot = ws.syncPlot();
        QVERIFY(plot->isVisible());
        QVERIFY(plot->graph(0)->dataCount() > 100);
        auto peak = plot->graph(0)->data()->constBegin();
        for (auto it = peak; it != plot->graph(0)->data()->constEnd(); ++it)
            if (it->value > peak->value)
                peak = it;
        QVERIFY2(std::abs(peak->key - ws.pendingSync()->offset_s) <= 0.05 + 1e-9,
                 qPrintable(QString("peak %1, offset %2").arg(peak->key).arg(ws.pendingSync()->offset_s)));
        auto* marker = qobject_cast<QCPItemStraightLine*>(plot->item(0));
        QVERIFY(marker);
        QCOMPARE(marker->point1->coords().x(), ws.pendingSync()->offset_s);
        const double confidence = ws.pendingSync()->confidence;
        ws.acceptSync();
        QVERIFY(std::abs(ws.mapping().offset_s - truthOffset_) < 1.0 / 29.97);
        QVERIFY(!plot->isVisible());
        // Kept with the run in its folder: video, offset, how it was found and the confidence.
        const std::optional<nb::RunVideoLink> kept = nb::readRunVideoLink(run_);
        QVERIFY(kept);
        QCOMPARE(QFileInfo(kept->video).canonicalFilePath(), QFileInfo(video_).canonicalFilePath());
        QCOMPARE(kept->mapping, ws.mapping());
        QCOMPARE(kept->method, nb::SyncMethod::Automatic);
        QCOMPARE(kept->confidence.value_or(-1.0), confidence);
        ws.setCursorTime(1.0);  // now shows video time 1.0 + offset
        const int expected = int(std::floor((1.0 + ws.mapping().offset_s) * 29.97 + 1e-9));
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), expected, 20000);

        // Suggest reads the tissue's motion in the synchronised video, in the background, and
        // places what `labels suggest --video` gives for the same run, video and offset.
        QSignalSpy suggested(&ws, &nb::ReviewWorkspace::labelsSuggested);
        ws.suggestLabels();
        QVERIFY(ws.isSuggesting());
        QVERIFY(!ws.suggestButton()->isEnabled());
        QVERIFY(suggested.wait(240000));
        QVERIFY(ws.suggestButton()->isEnabled());
        QVERIFY2(ws.status().contains(QLatin1String("the tissue's motion in run.avi")), qPrintable(ws.status()));
        const nb::Labels placed = ws.labelModel()->labels();
        QVERIFY(placed.size() > 8);
        const QString cliLabels = dir_.filePath("cli.labels.csv");
        QProcess cli;
        cli.start(QStringLiteral(NB_EXECUTABLE),
                  {"labels", "suggest", run_, "--video", video_, "--video-offset-s", QString::number(ws.mapping().offset_s, 'g', 17),
                   "--video-drift", QString::number(ws.mapping().drift, 'g', 17), "--out", cliLabels});
        QVERIFY(cli.waitForFinished(240000));
        QCOMPARE(cli.exitCode(), 0);
        const nb::Labels fromCli = nb::readLabelsFile(cliLabels);
        QCOMPARE(placed.size(), fromCli.size());
        std::size_t fromVideo = 0;
        for (const Label& l : fromCli) {
            QVERIFY2(std::any_of(placed.begin(), placed.end(),
                                 [&](const Label& p) {
                                     return p.track == l.track && p.label == l.label && std::abs(p.start_s - l.start_s) < 1e-3 &&
                                            std::abs(p.end_s - l.end_s) < 1e-3 && p.comment == l.comment;
                                 }),
                     qPrintable(QString("%1 %2 %3-%4 %5").arg(l.track, l.label).arg(l.start_s).arg(l.end_s).arg(l.comment)));
            fromVideo += l.comment.contains(QLatin1String("run.avi")) ? 1 : 0;
        }
        QVERIFY2(fromVideo > 0, "no suggested label says it came from the video");
        // One undoable step.
        ws.undoStack()->undo();
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(0));
        ws.undoStack()->redo();
        QCOMPARE(ws.labelModel()->labels().size(), placed.size());
        // Opening the run again while a suggestion reads the video stops it: nothing lands on
        // the run opened after it.
        ws.undoStack()->undo();
        ws.suggestLabels();
        QVERIFY(ws.isSuggesting());
        QVERIFY(ws.openRun(run_));
        QVERIFY(suggested.wait(240000));
        QVERIFY2(ws.status().contains(QLatin1String("stopped")), qPrintable(ws.status()));
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(0));
        ws.suggestLabels();
        QVERIFY(suggested.wait(240000));
        QCOMPARE(ws.labelModel()->labels().size(), placed.size());
        ws.setCursorTime(2.3);
        QTRY_VERIFY_WITH_TIMEOUT(ws.currentFrame() == int(std::floor((2.3 + ws.mapping().offset_s) * 29.97 + 1e-9)), 20000);
        QTest::qWait(200);
        const QString shots = QStringLiteral(NB_BINARY_DIR "/screenshots");
        QDir().mkpath(shots);
        QVERIFY(ws.grab().save(shots + "/review_workspace.png"));
    }

    // The needle tracked in the video lies over the recorded position once the sync is
    // accepted, and visibly apart before (offset 0) and after a nudge: the operator sees
    // whether the two agree. The tracking runs in the background as soon as the run's own
    // video is found beside it, and Auto sync takes its answer.
    // The operator marks the picture with the mouse: a drag draws the region the needle is read
    // in, a drag with Shift the needle's line (where the picture does not show it plainly enough
    // to be found), and Auto sync reads the tip along that line inside the region, as `sync
    // --needle --roi` does. A click clears the region, a Shift-click the line.
    void needleLineDrawnWithShift()
    {
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        ws.openVideo(video_);
        QVERIFY(opened.wait(60000));
        QTRY_VERIFY_WITH_TIMEOUT(ws.currentFrame() >= 0, 20000);  // where the run's kept offset puts the cursor
        nb::VideoView* view = ws.videoView();
        const nb::video::FrameIndex index = nb::video::buildFrameIndex(video_);
        const QRect picture = view->pictureRect();
        QVERIFY(picture.width() > 100);
        auto onView = [&](QPointF video) {
            return QPoint(int(std::lround(picture.x() + video.x() * picture.width() / index.width)),
                          int(std::lround(picture.y() + video.y() * picture.height() / index.height)));
        };
        auto drag = [&](QPointF from, QPointF to, Qt::KeyboardModifiers keys) {
            QTest::mousePress(view, Qt::LeftButton, keys, onView(from));
            QTest::mouseMove(view, onView((from + to) / 2));
            QTest::mouseMove(view, onView(to));
            QTest::mouseRelease(view, Qt::LeftButton, keys, onView(to));
        };
        const double pixel = std::max(double(index.width) / picture.width(), 1.0) + 0.5;  // a view pixel in the video's, rounded

        // The needle's line as `sync` finds it, drawn from the shaft to the tip.
        const nbtest::CliResult found = nbtest::runCli({"sync", run_, video_, "--json"}, 240000);
        QCOMPARE(found.code, 0);
        const QJsonArray a = found.json()["needle"].toArray();
        QCOMPARE(a.size(), 4);
        const QLineF needle(a[0].toDouble(), a[1].toDouble(), a[2].toDouble(), a[3].toDouble());
        const QRect region(240, 300, 240, 180);
        drag(region.topLeft(), region.bottomRight() + QPoint(1, 1), Qt::NoModifier);
        QVERIFY2((view->roi().topLeft() - region.topLeft()).manhattanLength() <= 2 * pixel &&
                     (view->roi().bottomRight() - region.bottomRight()).manhattanLength() <= 2 * pixel,
                 qPrintable(QStringLiteral("%1,%2 %3x%4").arg(view->roi().x()).arg(view->roi().y()).arg(view->roi().width()).arg(view->roi().height())));
        drag(needle.p1(), needle.p2(), Qt::ShiftModifier);
        QVERIFY(QLineF(view->needleLine().p1(), needle.p1()).length() <= pixel);
        QVERIFY(QLineF(view->needleLine().p2(), needle.p2()).length() <= pixel);
        QVERIFY(!view->roi().isEmpty());  // the line leaves the region as it was

        // Kept with the run's link to its video: a restart finds both drawn again.
        {
            const std::optional<nb::RunVideoLink> kept = nb::readRunVideoLink(run_);
            QVERIFY(kept);
            QCOMPARE(kept->marks.region, view->roi());
            QCOMPARE(kept->marks.needle, view->needleLine());
            nb::ReviewWorkspace restarted;
            restarted.resize(1280, 820);
            restarted.show();
            QSignalSpy reopened(&restarted, &nb::ReviewWorkspace::videoOpened);
            QVERIFY(restarted.openRun(run_));
            QVERIFY(reopened.wait(60000));
            QCOMPARE(restarted.videoView()->roi(), view->roi());
            QCOMPARE(restarted.videoView()->needleLine(), view->needleLine());
        }

        QSignalSpy synced(&ws, &nb::ReviewWorkspace::syncFinished);
        ws.startAutoSync();
        QVERIFY(synced.wait(240000));
        QVERIFY2(ws.pendingSync().has_value(), qPrintable(ws.status()));
        QVERIFY2(std::abs(ws.pendingSync()->offset_s - truthOffset_) < 1.0 / 29.97, qPrintable(QString::number(ws.pendingSync()->offset_s)));
        ws.rejectSync();

        // The line is the one read: drawn where the region leaves none of it, the sync says so.
        const QRect corner(0, 0, 40, 40);
        drag(corner.topLeft(), corner.bottomRight() + QPoint(1, 1), Qt::NoModifier);
        drag(QPointF(index.width - 200, index.height - 20), QPointF(index.width - 20, index.height - 20), Qt::ShiftModifier);
        QSignalSpy again(&ws, &nb::ReviewWorkspace::syncFinished);
        ws.startAutoSync();
        QVERIFY(again.wait(240000));
        QVERIFY(!ws.pendingSync().has_value());
        QVERIFY2(ws.status().contains(QLatin1String("does not cross the region")), qPrintable(ws.status()));

        // A Shift-click clears the line and a click the region.
        QTest::mouseClick(view, Qt::LeftButton, Qt::ShiftModifier, onView(QPointF(100, 100)));
        QVERIFY(view->needleLine().isNull());
        QVERIFY(!view->roi().isEmpty());
        QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, onView(QPointF(100, 100)));
        QVERIFY(view->roi().isEmpty());
        const std::optional<nb::RunVideoLink> cleared = nb::readRunVideoLink(run_);
        QVERIFY(cleared && cleared->marks.region.isEmpty() && cleared->marks.needle.isNull());
    }

    void trackedTraceLinesUpWithThePosition()
    {
        QTemporaryDir own;
        const QString run = own.filePath("run.csv");
        QVERIFY(QFile::copy(run_, run));
        QVERIFY(QFile::copy(video_, own.filePath("run.avi")));  // the run's own video, found beside it
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QSignalSpy tracked(&ws, &nb::ReviewWorkspace::trackingFinished);
        QVERIFY(ws.openRun(run));
        QVERIFY(ws.positionGraph()->dataCount() > 100);
        // The window stays responsive while the needle is tracked: frames still follow the cursor.
        QTRY_VERIFY_WITH_TIMEOUT(ws.currentFrame() == 0, 60000);
        ws.setCursorTime(1.0);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 29, 20000);
        QVERIFY(tracked.count() > 0 || tracked.wait(120000));
        QVERIFY(!ws.isTracking());

        const nb::Run recorded = nb::readRunFile(run).run;
        const auto [pmin, pmax] = std::minmax_element(recorded.position_mm.begin(), recorded.position_mm.end());
        const double span = *pmax - *pmin;
        // Root-mean-square gap between the trace and the recorded position where both exist.
        auto gap = [&](int* points) {
            double sum = 0.0;
            int n = 0;
            for (auto it = ws.trackedGraph()->data()->constBegin(); it != ws.trackedGraph()->data()->constEnd(); ++it) {
                if (!std::isfinite(it->value) || it->key < recorded.time_s.front() || it->key > recorded.time_s.back())
                    continue;
                const auto k = std::size_t(std::lower_bound(recorded.time_s.begin(), recorded.time_s.end(), it->key) - recorded.time_s.begin());
                const double e = it->value - recorded.position_mm[std::min(k, recorded.size() - 1)];
                sum += e * e;
                ++n;
            }
            *points = n;
            return n ? std::sqrt(sum / n) : 1e9;
        };
        int points = 0;
        const double atZero = gap(&points);
        QVERIFY2(points > 100, qPrintable(QString::number(points)));

        QSignalSpy synced(&ws, &nb::ReviewWorkspace::syncFinished);
        ws.startAutoSync();
        QVERIFY(synced.wait(120000));
        QVERIFY(ws.pendingSync().has_value());
        QVERIFY2(ws.pendingSync()->acceptable(), qPrintable(QString::number(ws.pendingSync()->confidence)));
        QVERIFY(std::abs(ws.pendingSync()->offset_s - truthOffset_) < 1.0 / 29.97);
        // Before Accept the trace already shows the offset found.
        const double preview = gap(&points);
        ws.acceptSync();
        const double accepted = gap(&points);
        QVERIFY2(points > 100, qPrintable(QString::number(points)));
        qInfo("trace vs recorded position: %.3f mm at offset 0, %.3f mm at the offset found, %.3f mm accepted (span %.1f mm)",
              atZero, preview, accepted, span);
        QVERIFY2(accepted < 0.03 * span, qPrintable(QString::number(accepted)));
        QVERIFY(std::abs(preview - accepted) < 1e-9);
        QVERIFY2(atZero > 5 * accepted, qPrintable(QString::number(atZero)));
        // Three frames off show as a gap the eye can see.
        ws.setMapping({ws.mapping().offset_s + 3 / 29.97, ws.mapping().drift});
        QVERIFY(gap(&points) > 2 * accepted);

        const QString shots = QStringLiteral(NB_BINARY_DIR "/screenshots");
        QDir().mkpath(shots);
        ws.setMapping({ws.mapping().offset_s - 3 / 29.97, ws.mapping().drift});
        QTest::qWait(200);
        QVERIFY(ws.grab().save(shots + "/review_tracked_trace.png"));
    }

    // A video synchronised against a run it does not show: the answer is plainly marked as low
    // and Accept only works once the operator ticks the override.
    void lowConfidenceNeedsTheOverride()
    {
        nb::Run run = nb::readRunFile(run_).run;
        for (std::size_t i = 0; i < run.size(); ++i)
            run.position_mm[i] = 10.0 * std::sin(2.0 * M_PI * 0.37 * run.time_s[i]) * std::exp(-0.2 * run.time_s[i]);
        const QString other = dir_.filePath("other.csv");
        nb::writeRunFile(other, run);
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(other));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        ws.openVideo(video_);
        QVERIFY(opened.wait(60000));
        QSignalSpy synced(&ws, &nb::ReviewWorkspace::syncFinished);
        ws.startAutoSync();
        QVERIFY(synced.wait(120000));
        QVERIFY(ws.pendingSync().has_value());
        QVERIFY2(!ws.pendingSync()->acceptable(), qPrintable(QString::number(ws.pendingSync()->confidence)));
        QVERIFY(!ws.acceptButton()->isEnabled());
        QVERIFY(ws.acceptOverride()->isVisible());
        // It says what the operator can do: draw the needle's line and a region, and sync again.
        QVERIFY2(ws.status().contains(QLatin1String("Shift+drag")), qPrintable(ws.status()));
        const nb::TimelineMapping before = ws.mapping();
        ws.acceptSync();  // refused
        QCOMPARE(ws.mapping(), before);
        QVERIFY(ws.pendingSync().has_value());
        const double found = ws.pendingSync()->offset_s;
        ws.acceptOverride()->setChecked(true);
        QVERIFY(ws.acceptButton()->isEnabled());
        QTest::mouseClick(ws.acceptButton(), Qt::LeftButton);
        QCOMPARE(ws.mapping().offset_s, found);
        QVERIFY(!ws.pendingSync().has_value());
        QVERIFY(!ws.acceptOverride()->isVisible());
    }

    // Marking one event in both sets the offset; a second, three seconds later, the drift too.
    // The frames are picked so that the marks mean a video clock 1001 ppm fast.
    void twoMarkedEventsSetOffsetAndDrift()
    {
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        // The run keeps the sync accepted in the test before (videos.json); attaching the video
        // again starts from offset 0.
        QVERIFY(ws.attachVideo(video_));
        QCOMPARE(ws.mapping(), nb::TimelineMapping{});
        QVERIFY(opened.wait(60000));
        QTRY_VERIFY_WITH_TIMEOUT(ws.currentFrame() == 0, 20000);
        const double fps = 29.97;  // what the simulated imaging renders at
        // The frame for a new cursor arrives from the decoder thread: wait for it before stepping.
        auto moveCursor = [&](double t) {
            ws.setCursorTime(t);
            QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), int(std::floor(ws.mapping().toVideo(t) * fps + 1e-9)), 20000);
        };
        auto showFrame = [&](int n) {
            ws.stepFrames(n - ws.currentFrame());
            QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), n, 20000);
        };

        moveCursor(0.5);
        ws.markEventInRecording();
        showFrame(30);
        ws.markEventInVideo();
        QVERIFY2(std::abs(ws.mapping().offset_s - (30 / fps - 0.5)) < 1e-6,
                 qPrintable(QStringLiteral("offset %1: %2").arg(ws.mapping().offset_s, 0, 'g', 10).arg(ws.status())));
        QCOMPARE(ws.mapping().drift, 0.0);
        QVERIFY(ws.status().contains(QStringLiteral("second event")));

        moveCursor(3.5);
        ws.markEventInRecording();
        showFrame(120);
        ws.markEventInVideo();
        const double drift = (120 - 30) / fps / 3.0 - 1.0;  // 1001 ppm
        QVERIFY2(std::abs(ws.mapping().drift - drift) < 1e-6, qPrintable(ws.status()));
        QVERIFY2(std::abs(ws.mapping().toVideo(0.5) - 30 / fps) < 1e-6 && std::abs(ws.mapping().toVideo(3.5) - 120 / fps) < 1e-6,
                 qPrintable(ws.status()));
        QVERIFY(ws.status().contains(QStringLiteral("1001 ppm")));
        // Both marked instants now show their frames.
        ws.setCursorTime(3.5 + 1e-4);
        QTRY_COMPARE_WITH_TIMEOUT(ws.currentFrame(), 120, 20000);

        // A third pair that would mean a 5 % clock error is a wrong mark: only the offset moves.
        moveCursor(1.5);
        ws.markEventInRecording();
        showFrame(ws.currentFrame() + 4);
        const double before = ws.mapping().drift;
        ws.markEventInVideo();
        QCOMPARE(ws.mapping().drift, before);
        QVERIFY2(ws.status().contains(QStringLiteral("no clock has")), qPrintable(ws.status()));

        // Each mark is one step of Ctrl+Z, with the labels': the wrong mark took the two
        // events' offset away for good. Undone, the offset and drift are the two events' again,
        // and so is the event a next mark pairs with; undone to the start, offset 0.
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY2(std::abs(ws.mapping().toVideo(0.5) - 30 / fps) < 1e-6 && std::abs(ws.mapping().drift - drift) < 1e-6,
                 qPrintable(QStringLiteral("offset %1 drift %2").arg(ws.mapping().offset_s).arg(ws.mapping().drift)));
        QCOMPARE(ws.syncMethod(), nb::SyncMethod::EventMarks);
        // The status line says what was undone, not what the undone mark had said.
        QVERIFY2(ws.status().startsWith(QStringLiteral("Undone: set the offset from an event")), qPrintable(ws.status()));
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY2(ws.status().startsWith(QStringLiteral("Redone: set the offset from an event")), qPrintable(ws.status()));
        QTest::keyClick(&ws, Qt::Key_Z, Qt::ControlModifier);
        ws.undoStack()->undo();
        ws.undoStack()->undo();
        QCOMPARE(ws.mapping(), nb::TimelineMapping{});
        ws.undoStack()->redo();
        ws.undoStack()->redo();
        QVERIFY(std::abs(ws.mapping().drift - drift) < 1e-6);
    }

    // A run file that carries its own sync (as the demo's and exported runs do) opens at that
    // offset, not at 0 (the demo's runs were shown 0.6 to 1.3 s off).
    void theRunsOwnSyncIsUsed()
    {
        QTemporaryDir own;
        const QString run = own.filePath("carried.csv"), video = own.filePath("carried.avi");
        QFile in(run_), out(run);
        QVERIFY(in.open(QIODevice::ReadOnly) && out.open(QIODevice::WriteOnly));
        out.write("# sync_offset_s: 1.2\n# sync_confidence: 0.97\n# video_file: carried.avi\n");
        out.write(in.readAll());
        out.close();
        QVERIFY(QFile::copy(video_, video));
        nb::ReviewWorkspace ws;
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QVERIFY(ws.openRun(run));
        QCOMPARE(ws.mapping().offset_s, 1.2);
        QVERIFY(opened.wait(60000));
        QCOMPARE(ws.videoPath(), QFileInfo(video).absoluteFilePath());

        // Its video moved away: said missing, by name, at the offset kept (it said "No video").
        QVERIFY(QFile::rename(video, own.filePath("elsewhere.avi")));
        QVERIFY(ws.openRun(run_));
        QVERIFY(ws.openRun(run));
        QCOMPARE(ws.mapping().offset_s, 1.2);
        QVERIFY2(ws.videoView()->message().contains(QStringLiteral("missing")) && ws.videoView()->message().contains(QStringLiteral("carried.avi")),
                 qPrintable(ws.videoView()->message()));
    }

    // Labels that cannot be written beside the run (its folder read-only, the disk full: here a
    // run name so long that its labels file's name is past the file system's limit, which stops
    // root too) are kept in the user's data folder and said in a box, not lost with the next
    // run opened.
    void labelsThatCannotBeSavedAreKeptElsewhere()
    {
        QStandardPaths::setTestModeEnabled(true);
        QTemporaryDir own;
        const QString stem = QString(246, QLatin1Char('r'));
        const QString run = own.filePath(stem + ".csv");
        QVERIFY(QFile::copy(run_, run));
        nb::ReviewWorkspace ws;
        ws.show();
        QVERIFY(ws.openRun(run));
        QVERIFY(ws.labelModel()->insertLabel({QStringLiteral("events"), QStringLiteral("contact"), 0.5, 0.5, {}}));
        auto* box = ws.findChild<QMessageBox*>(QStringLiteral("labelsNotSaved"));
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains(stem.left(100)), qPrintable(box->text()));
        const QString kept = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                                 .filePath(QStringLiteral("unsaved-labels/%1/%2.labels.csv").arg(QDir(own.path()).dirName(), stem.left(189)));
        QVERIFY2(box->text().contains(QDir::toNativeSeparators(kept)), qPrintable(box->text()));
        const nb::Labels back = nb::readLabelsFile(kept);
        QCOMPARE(back.size(), std::size_t(1));
        QCOMPARE(back.front().label, QStringLiteral("contact"));
        box->accept();
        // Another run, then this one again: the labels kept are shown, and the next label adds
        // to them (it replaced them: the contact was lost).
        QVERIFY(ws.openRun(run_));
        QVERIFY(ws.openRun(run));
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(1));
        QVERIFY2(ws.status().contains(QDir::toNativeSeparators(kept)), qPrintable(ws.status()));
        QVERIFY(ws.labelModel()->insertLabel({QStringLiteral("events"), QStringLiteral("puncture"), 0.8, 0.8, {}}));
        QCOMPARE(nb::readLabelsFile(kept).size(), std::size_t(2));
        QFile::remove(kept);
    }

    // A labels file edited by hand with one row typed backwards: the run opens with the other
    // labels, the row is named by line, and the file as typed is copied aside before the next
    // label saved over it drops the row. It kept the run out of Review ("end_s ... before").
    void aBadLabelsRowDoesNotKeepTheRunOut()
    {
        QTemporaryDir own;
        const QString run = own.filePath(QStringLiteral("hand.csv"));
        QVERIFY(QFile::copy(run_, run));
        const QByteArray typed = "track,label,start_s,end_s,comment\n"
                                 "insertion,a,0.2,0.6,\n"
                                 "insertion,b1,0.9,0.7,typed backwards\n"
                                 "events,puncture,1.5,1.5,\n";
        QFile f(own.filePath(QStringLiteral("hand.labels.csv")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(typed);
        f.close();
        nb::ReviewWorkspace ws;
        ws.show();
        QVERIFY2(ws.openRun(run), qPrintable(ws.status()));
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(2));
        QVERIFY2(ws.status().contains(QStringLiteral("hand.labels.csv:3")) && ws.status().contains(QStringLiteral("before start_s")),
                 qPrintable(ws.status()));
        const QString copy = own.filePath(QStringLiteral("hand.unread.labels.csv"));
        QVERIFY2(ws.status().contains(QDir::toNativeSeparators(copy)), qPrintable(ws.status()));
        QVERIFY(ws.labelModel()->insertLabel({QStringLiteral("events"), QStringLiteral("contact"), 0.1, 0.1, {}}));
        QCOMPARE(nb::readLabelsFile(f.fileName()).size(), std::size_t(3));
        QFile kept(copy);
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), typed);
        // A file that cannot be read at all (no header) leaves the run open without labels.
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("insertion;a;0.2;0.6\n");
        f.close();
        QVERIFY2(ws.openRun(run), qPrintable(ws.status()));
        QCOMPARE(ws.labelModel()->labels().size(), std::size_t(0));
        QVERIFY2(ws.status().contains(QStringLiteral("hand.unread-2.labels.csv")), qPrintable(ws.status()));
    }

    // What the decoder reports of a file opened before the last one is not passed on: an index
    // (or a frame) of the run shown before, arriving after another video was asked for, gave
    // the run in review that video's needle trace and its errors.
    void theDecoderSpeaksOnlyOfTheLastFileOpened()
    {
        nb::video::VideoDecoder decoder;
        QSignalSpy opened(&decoder, &nb::video::VideoDecoder::opened);
        QSignalSpy failed(&decoder, &nb::video::VideoDecoder::failed);
        decoder.open(video_);
        QVERIFY(opened.wait(60000));  // indexed once: the next open is quick
        opened.clear();
        decoder.open(video_ + QStringLiteral(".again"));  // no such file: fails
        decoder.open(video_);
        // The worker answers both before this thread looks: the first answer, queued ahead of
        // the second, is about a file no longer wanted.
        QThread::msleep(1500);
        decoder.open(dir_.filePath("missing.avi"));
        QVERIFY(failed.wait(20000));
        QTest::qWait(300);
        QCOMPARE(opened.count(), 0);
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.first().first().toString().contains("missing.avi"));
    }

    // Suggesting again on a labelled run says what it added (nothing) and what it left out.
    void suggestingTwiceSaysWhatItAdded()
    {
        QTemporaryDir own;
        const QString run = own.filePath("suggest.csv");
        QVERIFY(QFile::copy(run_, run));
        nb::ReviewWorkspace ws;
        QVERIFY(ws.openRun(run));
        ws.suggestLabels();
        const std::size_t first = ws.labelModel()->labels().size();
        QVERIFY(first > 0);
        QVERIFY2(!ws.status().contains("left out"), qPrintable(ws.status()));
        ws.suggestLabels();
        QCOMPARE(ws.labelModel()->labels().size(), first);
        QVERIFY2(ws.status().startsWith("0 label") && ws.status().contains("left out"), qPrintable(ws.status()));
    }

    // Auto sync says how far it is while the operator waits (a long video showed "correlating…"
    // for minutes with nothing moving), and the operator can stop it: its button stops it,
    // nothing is pending, the tracking is not started again behind the operator's back, and
    // Auto sync can be asked again and finishes.
    void autoSyncCanBeStopped()
    {
        QTemporaryDir own;
        const QString run = own.filePath("stopped.csv"), video = own.filePath("stopped.avi");
        QVERIFY(QFile::copy(run_, run));
        QVERIFY(QFile::copy(video_, video));
        nb::ReviewWorkspace ws;
        ws.resize(970, 520);  // what a 1366x768 laptop leaves it beside the panel and the session
        ws.show();
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QSignalSpy finished(&ws, &nb::ReviewWorkspace::syncFinished);
        QVERIFY(ws.openRun(run));
        QVERIFY(opened.wait(60000));
        auto* button = ws.findChild<QPushButton*>(QStringLiteral("autoSync"));
        auto* label = ws.findChild<QLabel*>(QStringLiteral("syncResult"));
        QVERIFY(button && label);
        QCOMPARE(button->text(), QStringLiteral("Auto sync"));
        button->click();
        QTRY_VERIFY_WITH_TIMEOUT(label->text().startsWith(QStringLiteral("correlating: frame")), 60000);
        QCOMPARE(button->text(), QStringLiteral("Stop sync"));
        button->click();
        QCOMPARE(label->text(), QStringLiteral("Automatic sync stopped"));
        QCOMPARE(button->text(), QStringLiteral("Auto sync"));
        QTRY_VERIFY_WITH_TIMEOUT(!ws.isTracking(), 20000);
        QTest::qWait(500);
        QVERIFY(!ws.isTracking());
        QVERIFY(finished.isEmpty());
        QVERIFY(!ws.pendingSync());
        QCOMPARE(label->text(), QStringLiteral("Automatic sync stopped"));
        QVERIFY(ws.trackedGraph()->data()->isEmpty());
        button->click();
        QVERIFY(ws.isTracking());
        QVERIFY(finished.wait(120000));
        QVERIFY(ws.pendingSync());
        QCOMPARE(button->text(), QStringLiteral("Auto sync"));
        // While the sync waits the legend keeps two names a row (one a row took a third of the
        // force plot on a laptop, beside the sync's curve), none of them cut off.
        auto* plot = ws.findChild<QCustomPlot*>(QStringLiteral("reviewForcePlot"));
        QVERIFY(plot);
        plot->replot();
        QCOMPARE(plot->legend->wrap(), 2);
        for (int i = 0; i < plot->legend->itemCount(); ++i) {
            QCPAbstractLegendItem* item = plot->legend->item(i);
            if (!item)
                continue;  // an empty cell of the grid
            QVERIFY2(item->outerRect().width() >= item->minimumOuterSizeHint().width(),
                     qPrintable(QStringLiteral("legend item %1: %2 px for %3").arg(i).arg(item->outerRect().width()).arg(item->minimumOuterSizeHint().width())));
        }
        ws.rejectSync();
        QCOMPARE(plot->legend->wrap(), 2);
    }

    void badFilesAreReported()
    {
        nb::ReviewWorkspace ws;
        QVERIFY(!ws.openRun(dir_.filePath("missing.csv")));
        QVERIFY(ws.status().contains("missing.csv"));
        QSignalSpy failed(ws.decoder(), &nb::video::VideoDecoder::failed);
        ws.openVideo(dir_.filePath("missing.avi"));
        QVERIFY(failed.wait(20000));
        QVERIFY(failed.first().first().toString().contains("missing.avi"));
    }

    // A file that does not open as video (here the head of an H.264 MP4 whose index was never
    // written) is not attached: the run keeps the video it had, in the session and on screen.
    // At offset 0 only the run's span could be reached: the video's frames after the recording's
    // end (or all of them, for a video that starts long before it) could not be shown, and an
    // event in them could not be marked to set the offset (video probe). The cursor now goes
    // over the whole video, and the plot follows it.
    void theWholeVideoCanBeReached()
    {
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QVERIFY(ws.attachVideo(video_));  // the offset starts from 0
        QVERIFY(opened.wait(60000));
        QCOMPARE(ws.mapping().offset_s, 0.0);
        const nb::video::FrameIndexPtr index = ws.decoder()->index();
        QVERIFY(index);
        const nb::Run run = nb::readRunFile(run_).run;
        const double runEnd = run.time_s.back();
        QVERIFY2(index->frames.back().time_s > runEnd + 0.5, "the simulated video ends with the run");
        ws.stepFrames(index->size());
        QTRY_COMPARE(ws.currentFrame(), index->size() - 1);
        QVERIFY(ws.cursorTime() > runEnd + 0.5);
        QCustomPlot* plot = nullptr;
        for (QCustomPlot* p : ws.findChildren<QCustomPlot*>())
            if (p->xAxis->label().startsWith(QStringLiteral("recording time")))
                plot = p;
        QVERIFY(plot);
        const QCPRange shown = plot->xAxis->range();
        QVERIFY2(shown.lower <= ws.cursorTime() && ws.cursorTime() <= shown.upper,
                 qPrintable(QStringLiteral("cursor %1 s outside the plot's %2 to %3 s").arg(ws.cursorTime()).arg(shown.lower).arg(shown.upper)));
        ws.stepFrames(-index->size());
        QTRY_COMPARE(ws.currentFrame(), 0);
        // Beyond both, the cursor stops at their ends.
        ws.setCursorTime(1e6);
        QCOMPARE(ws.cursorTime(), std::max(runEnd, index->frames.back().time_s));

        // After the recording there is no force to label or mark: said, and nothing placed (a
        // label at -20 s and a force mark before the first sample were taken without a word).
        const std::size_t labels = ws.labelModel()->labels().size();
        QTest::keyClick(&ws, Qt::Key_1);
        QCOMPARE(ws.labelModel()->labels().size(), labels);
        QVERIFY2(ws.status().contains(QStringLiteral("outside the recording")), qPrintable(ws.status()));
        ws.markEventInRecording();
        QVERIFY2(ws.status().contains(QStringLiteral("outside the recording")), qPrintable(ws.status()));

        // The event marked in the video is the frame at the cursor, not the one still on screen
        // while the cursor's frame is decoded: a far step and a quick mark took the frame before
        // (probe: 11 frames off, the status naming the old frame's time).
        ws.setCursorTime(0.5);
        QTRY_COMPARE(ws.currentFrame(), index->frameAt(0.5));
        ws.setCursorTime(3.0);
        ws.markEventInVideo();  // before the frame at 3 s is shown
        ws.setCursorTime(1.0);
        ws.markEventInRecording();
        QCOMPARE(ws.mapping().offset_s, index->frames[std::size_t(index->frameAt(3.0))].time_s - 1.0);
    }

    // A run whose video fails to open (or is still being indexed), left for a run without one
    // before the decoder answers: its answer is not this run's. "cannot reopen the video" of the
    // video gone, or "Indexing the video", stood over a run without video (video probe).
    void aRunWithoutVideoHearsNothingOfTheLastOne()
    {
        const QString broken = dir_.filePath("gone.mp4"), withVideo = dir_.filePath("with.csv"), without = dir_.filePath("without.csv");
        QFile cut(broken);
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(QByteArray::fromHex("0000001c667479706973736f6d0000020069736f6d69736f32617663310000000866726565"));
        cut.write(QByteArray(40000, '\x5a'));
        cut.close();
        QFile::remove(withVideo);
        QFile::remove(without);
        QVERIFY(QFile::copy(run_, withVideo) && QFile::copy(run_, without));
        nb::writeRunVideoLink(withVideo, nb::RunVideoLink{broken, {}, nb::SyncMethod::None, std::nullopt, {}});
        nb::writeRunVideoLink(without, std::nullopt);
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QSignalSpy failed(ws.decoder(), &nb::video::VideoDecoder::failed);
        QVERIFY(ws.openRun(withVideo));
        QCOMPARE(ws.videoPath(), broken);
        QVERIFY(ws.openRun(without));  // before the decoder has answered
        QVERIFY(ws.videoPath().isEmpty());
        QTest::qWait(2000);
        QCOMPARE(failed.count(), 0);
        QVERIFY2(!ws.status().contains(QStringLiteral("gone.mp4")), qPrintable(ws.status()));
        QVERIFY2(!ws.videoView()->message().contains(QStringLiteral("gone.mp4")) && !ws.videoView()->message().contains(QStringLiteral("Indexing")),
                 qPrintable(ws.videoView()->message()));
        // The run with the video, opened again, still says why it cannot be shown.
        QVERIFY(ws.openRun(withVideo));
        QVERIFY(failed.wait(20000));
        QTRY_VERIFY2(ws.videoView()->message().contains(QStringLiteral("gone.mp4")) || ws.status().contains(QStringLiteral("gone.mp4")),
                     qPrintable(ws.status() + " / " + ws.videoView()->message()));
    }

    void theRunsVideoAttachedAgainWhileItIsIndexed()
    {
        // The run's own video (RUN.avi beside it) is still being indexed when the operator
        // attaches that same file, or opens the run again: the first indexing, stopped, said "no
        // frame could be decoded" of the file now asked for, and the attach was undone. Copies in
        // folders of their own, so no index is stored for them yet.
        QTemporaryDir fresh, other;
        QVERIFY(fresh.isValid() && other.isValid());
        for (const QTemporaryDir* d : {&fresh, &other})
            QVERIFY(QFile::copy(run_, d->filePath("run.csv")) && QFile::copy(video_, d->filePath("run.avi")));
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QSignalSpy failed(ws.decoder(), &nb::video::VideoDecoder::failed);
        auto saidFailed = [&failed] { return failed.isEmpty() ? QString() : failed.first().first().toString(); };
        const QString run = fresh.filePath("run.csv"), video = QFileInfo(fresh.filePath("run.avi")).absoluteFilePath();
        QVERIFY(ws.openRun(run));
        QCOMPARE(ws.videoPath(), video);
        QVERIFY(ws.attachVideo(video));  // before the first indexing has answered
        QVERIFY(opened.wait(60000));
        QTest::qWait(500);  // anything the stopped indexing still had to say
        QVERIFY2(failed.isEmpty(), qPrintable(saidFailed()));
        QVERIFY2(!ws.status().contains(QStringLiteral("not attached")), qPrintable(ws.status()));
        const auto link = nb::readRunVideoLink(run);
        QVERIFY(link);
        QCOMPARE(link->video, video);

        // The other copy opened twice in a row, as a double-click that lands twice: its video is
        // shown, and nothing is said to be wrong with it.
        opened.clear();
        QVERIFY(ws.openRun(other.filePath("run.csv")) && ws.openRun(other.filePath("run.csv")));
        QVERIFY(opened.wait(60000));
        QTest::qWait(500);
        QVERIFY2(failed.isEmpty(), qPrintable(saidFailed()));
        QVERIFY2(!ws.videoView()->message().contains(QStringLiteral("decoded")), qPrintable(ws.videoView()->message()));
        QCOMPARE(ws.videoPath(), QFileInfo(other.filePath("run.avi")).absoluteFilePath());
    }

    void aVideoThatFailsToOpenIsNotAttached()
    {
        const QString broken = dir_.filePath("broken.mp4");
        QFile cut(broken);
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(QByteArray::fromHex("0000001c667479706973736f6d0000020069736f6d69736f32617663310000000866726565"));
        cut.write(QByteArray(40000, '\x5a'));
        cut.close();
        nb::ReviewWorkspace ws;
        ws.resize(1280, 820);
        ws.show();
        QVERIFY(ws.openRun(run_));
        QSignalSpy opened(&ws, &nb::ReviewWorkspace::videoOpened);
        QVERIFY(ws.attachVideo(video_));
        QVERIFY(opened.wait(60000));
        auto linked = [this] {
            const auto link = nb::readRunVideoLink(run_);
            return link ? link->video : QStringLiteral("(none)");
        };
        QCOMPARE(linked(), QFileInfo(video_).absoluteFilePath());
        QSignalSpy failed(ws.decoder(), &nb::video::VideoDecoder::failed);
        QVERIFY(ws.attachVideo(broken));
        QVERIFY(failed.wait(20000));
        QTRY_VERIFY2(ws.status().contains(QStringLiteral("not attached")), qPrintable(ws.status()));
        QVERIFY2(ws.status().contains(QStringLiteral("broken.mp4")), qPrintable(ws.status()));
        QCOMPARE(linked(), QFileInfo(video_).absoluteFilePath());
        QTRY_COMPARE(ws.videoPath(), QFileInfo(video_).absoluteFilePath());
        QVERIFY(opened.wait(60000));  // the run's own video, shown again

        // The same where the run's own video has a warning of its own (a phone's rotation tag):
        // shown again, its warning took the place of why the other was not attached.
        const QString turned = dir_.filePath("turned.mov");
        QProcess ffmpeg;
        ffmpeg.start(QStringLiteral("ffmpeg"), {"-v", "error", "-y", "-i", video_, "-c", "copy", "-metadata:s:v:0", "rotate=90", turned});
        QVERIFY(ffmpeg.waitForFinished(60000) && ffmpeg.exitCode() == 0);
        QVERIFY(ws.attachVideo(turned));
        QVERIFY(opened.wait(60000));
        QTRY_VERIFY2(ws.status().contains(QStringLiteral("turned by 90")), qPrintable(ws.status()));
        QVERIFY(ws.attachVideo(broken));
        QVERIFY(failed.wait(20000));
        QVERIFY(opened.wait(60000));  // turned.mov again, with its warning
        QCoreApplication::processEvents();
        QVERIFY2(ws.status().contains(QStringLiteral("not attached")), qPrintable(ws.status()));
    }
};

QTEST_MAIN(TestReviewWorkspace)
#include "test_review_workspace.moc"
