// The lab session folder: metadata, run naming and states, calibrations, crash recovery.
#include "core/run_file.h"
#include "core/session.h"

#include <QTemporaryDir>
#include <QtTest>

namespace {

void writeRun(const QString& path, int rows, const QString& endReason, bool partialTail = false)
{
    nb::Metadata meta;
    meta.set(QStringLiteral("motion"), QStringLiteral("linear"));
    meta.set(QStringLiteral("calibration"), QStringLiteral("cal_x"));
    nb::RunFileWriter w;
    w.open(path, meta, {QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N")});
    for (int i = 0; i < rows; ++i) {
        const double row[] = {i * 0.001, i * 0.004, i * 0.01};
        w.writeRow(row);
    }
    if (endReason.isEmpty()) {
        w.flush();
        // A crash: no footer, and maybe half a row.
        QFile f(path);
        QVERIFY(f.open(QIODevice::Append));
        if (partialTail)
            f.write("0.9990,3.99");
        return;
    }
    nb::Metadata footer;
    footer.set(QStringLiteral("end_reason"), endReason);
    w.close(footer);
}

}  // namespace

class TestSession : public QObject {
    Q_OBJECT
private slots:
    // What the operator typed names the folder, in any language; what a file system or a
    // shell trips over does not.
    void folderNameKeepsTheOperatorsWords()
    {
        const QDateTime at(QDate(2026, 11, 30), QTime(3, 8, 39));
        nb::SessionInfo info;
        info.organ = QStringLiteral("Leber ü");
        info.specimen = QStringLiteral("S 1/x");
        QCOMPARE(nb::sessionFolderName(info, at), QStringLiteral("Leber_ü_S_1_x_20261130_030839"));
        info.organ = QStringLiteral("../prostate.");
        info.specimen.clear();
        QCOMPARE(nb::sessionFolderName(info, at), QStringLiteral("prostate_20261130_030839"));
        QCOMPARE(nb::sessionFolderName({}, at), QStringLiteral("session_20261130_030839"));
    }

    void createOpenAndName()
    {
        QTemporaryDir tmp;
        const QString dir = tmp.filePath(QStringLiteral("liver3"));
        nb::SessionInfo info;
        info.organ = QStringLiteral("liver");
        info.specimen = QStringLiteral("3");
        info.tip = QStringLiteral("beveled");
        info.thickness_mm = 42.5;
        info.operatorName = QStringLiteral("Ana");
        info.notes = QStringLiteral("capsule intact, ünïcode");
        nb::Session s = nb::Session::create(dir, info);
        QVERIFY(nb::Session::isSession(dir));
        QVERIFY_THROWS_EXCEPTION(nb::SessionError, nb::Session::create(dir, info));
        const nb::Session o = nb::Session::open(dir);
        QCOMPARE(o.info().notes, info.notes);
        QCOMPARE(o.info().thickness_mm, 42.5);
        QVERIFY(o.info().created.isValid());
        QCOMPARE(QFileInfo(s.nextRunPath(QStringLiteral("linear"))).fileName(), QStringLiteral("run_001_linear.csv"));
        writeRun(s.nextRunPath(QStringLiteral("linear")), 10, QStringLiteral("completed"));
        writeRun(tmp.filePath(QStringLiteral("liver3/run_007_sine.csv")), 10, QStringLiteral("force_limit"));
        QCOMPARE(QFileInfo(s.nextRunPath(QStringLiteral("sine"))).fileName(), QStringLiteral("run_008_sine.csv"));
        QVERIFY_THROWS_EXCEPTION(nb::SessionError, nb::Session::open(tmp.path()));
    }

    void runStates()
    {
        QTemporaryDir tmp;
        nb::Session s = nb::Session::create(tmp.path(), {});
        writeRun(tmp.filePath(QStringLiteral("run_001_linear.csv")), 50, QStringLiteral("completed"));
        writeRun(tmp.filePath(QStringLiteral("run_002_linear.csv")), 50, QStringLiteral("force_limit"));
        writeRun(tmp.filePath(QStringLiteral("run_003_linear.csv")), 50, QStringLiteral("fault"));
        writeRun(tmp.filePath(QStringLiteral("run_004_linear.csv")), 50, QStringLiteral("stopped"));
        writeRun(tmp.filePath(QStringLiteral("run_005_linear.csv")), 50, QString());
        QFile junk(tmp.filePath(QStringLiteral("run_006.csv")));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("# only: metadata\n");
        junk.close();
        const auto runs = s.runs();
        QCOMPARE(runs.size(), 6u);
        QCOMPARE(runs[0].state, nb::RunState::Complete);
        QCOMPARE(runs[0].calibration, QStringLiteral("cal_x"));
        QCOMPARE(runs[0].motion, QStringLiteral("linear"));
        QCOMPARE(runs[1].state, nb::RunState::StoppedByLimit);
        QCOMPARE(runs[2].state, nb::RunState::Fault);
        QCOMPARE(runs[3].state, nb::RunState::Stopped);
        QCOMPARE(runs[4].state, nb::RunState::Interrupted);
        QCOMPARE(runs[5].state, nb::RunState::Unreadable);
    }

    void recoversAnInterruptedRun()
    {
        QTemporaryDir tmp;
        nb::Session s = nb::Session::create(tmp.path(), {});
        const QString crashed = tmp.filePath(QStringLiteral("run_001_linear.csv"));
        const QString busy = tmp.filePath(QStringLiteral("run_002_linear.csv"));
        writeRun(crashed, 2000, QString(), true);
        writeRun(busy, 10, QString());
        QStringList problems;
        const QStringList recovered = s.recoverInterrupted(busy, &problems);
        QCOMPARE(recovered.size(), 1);
        QVERIFY(recovered.first().startsWith(QStringLiteral("run_001_linear.csv")));
        QVERIFY(problems.isEmpty());
        const nb::RunReadResult r = nb::readRunFile(crashed);  // strict read now succeeds
        QCOMPARE(r.run.size(), 2000u);                          // every complete row kept
        QCOMPARE(r.run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("recovered"));
        QCOMPARE(r.run.force_N.back(), 1999 * 0.01);
        QCOMPARE(r.run.metadata.value(QStringLiteral("motion"), QString()), QStringLiteral("linear"));
        QCOMPARE(nb::inspectRun(crashed).state, nb::RunState::Recovered);
        QCOMPARE(nb::inspectRun(busy).state, nb::RunState::Interrupted);  // left alone
        QVERIFY(s.recoverInterrupted(busy).isEmpty());                    // nothing twice

        // A run closed whole when a signal ended the program (its footer written, end reason
        // "interrupted") is not recovered: a start rewrote it as "recovered", the signal lost.
        const QString signalled = tmp.filePath(QStringLiteral("run_003_linear.csv"));
        writeRun(signalled, 20, QStringLiteral("interrupted"));
        const QByteArray before = [&] {
            QFile f(signalled);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        QCOMPARE(nb::inspectRun(signalled).state, nb::RunState::ClosedOnSignal);
        QCOMPARE(nb::runStateName(nb::RunState::ClosedOnSignal), QStringLiteral("interrupted"));
        QVERIFY(s.recoverInterrupted(busy).isEmpty());
        QFile after(signalled);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), before);
    }

    void calibrations()
    {
        QTemporaryDir tmp;
        nb::Session s = nb::Session::create(tmp.path(), {});
        QVERIFY(!s.activeCalibration());
        nb::StoredCalibration c;
        c.sensor = QStringLiteral("U6 #1");
        c.points = {{0, 0.42}, {100, 1.63}, {200, 2.84}};
        c.removed = {{50, 9.9}};
        c.fit = nb::fitCalibration(c.points);
        c.date = QDateTime(QDate(2026, 11, 21), QTime(9, 30));
        const QString name = s.saveCalibration(c);
        QCOMPARE(name, QStringLiteral("cal_20261121_093000"));
        const nb::Session reopened = nb::Session::open(tmp.path());
        const auto active = reopened.activeCalibration();
        QVERIFY(active);
        QCOMPARE(active->sensor, QStringLiteral("U6 #1"));
        QCOMPARE(active->points.size(), 3u);
        QCOMPARE(active->removed.size(), 1u);
        QVERIFY(qFuzzyCompare(active->fit.slope_V_per_g, c.fit.slope_V_per_g));
        QCOMPARE(active->date, c.date);
    }
};

QTEST_MAIN(TestSession)
#include "test_session.moc"
