// The run file format: round trips and every kind of bad input, on real files on disk.
#include "core/run_file.h"
#include "core/excerpt.h"
#include "core/calibration.h"
#include "core/labels.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <utility>
#include <new>
#include <sys/resource.h>

using namespace nb;

class TestRunFile : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& bytes)
    {
        const QString path = dir_.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            qFatal("cannot write %s", qPrintable(path));
        f.write(bytes);
        return path;
    }

    // Reads a file that must be refused, returns the error's line and reason.
    RunFileError refused(const QString& path)
    {
        try {
            readRunFile(path);
        } catch (const RunFileError& e) {
            return e;
        }
        return RunFileError(QString(), -1, QStringLiteral("accepted"));
    }

private slots:
    void roundTripKeepsMetadataColumnsAndFooter()
    {
        Run run;
        run.metadata.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
        run.metadata.set(QStringLiteral("rate_hz"), 500.0);
        auto& seq = run.addNumericColumn(QStringLiteral("seq"));
        auto& phase = run.addTextColumn(QStringLiteral("phase"));
        for (int i = 0; i < 1000; ++i) {
            run.time_s.push_back(i * 0.002);
            run.position_mm.push_back(i * 0.008);
            run.force_N.push_back(std::sin(i * 0.01));
            seq.push_back(i);
            phase.push_back(i < 500 ? QStringLiteral("a") : QStringLiteral("c"));
        }
        run.footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
        const QString path = dir_.filePath(QStringLiteral("round.csv"));
        writeRunFile(path, run);

        const auto back = readRunFile(path);
        QCOMPARE(back.run.size(), std::size_t(1000));
        QCOMPARE(back.run.metadata.value(QStringLiteral("protocol"), QString()), QStringLiteral("stiffness"));
        QCOMPARE(*back.run.metadata.number(QStringLiteral("rate_hz")), 500.0);
        QCOMPARE(back.run.meta(QStringLiteral("end_reason")).value_or(QString()), QStringLiteral("completed"));
        QVERIFY(back.run.footer.contains(QStringLiteral("end_reason")));
        QVERIFY(!back.run.metadata.contains(QStringLiteral("end_reason")));
        for (std::size_t i = 0; i < 1000; i += 97) {
            QVERIFY(std::abs(back.run.time_s[i] - run.time_s[i]) < 1e-9);
            QVERIFY(std::abs(back.run.force_N[i] - run.force_N[i]) < 1e-6);
        }
        QCOMPARE(back.run.numericColumn(QStringLiteral("seq"))->at(999), 999.0);
        QCOMPARE(back.run.textColumn(QStringLiteral("phase"))->at(999), QStringLiteral("c"));
        QVERIFY(back.warnings.isEmpty());
    }

    void keepsManyOptionalColumnsInFileOrder()
    {
        const QString path = write(QStringLiteral("many.csv"),
                                   "time_s,position_mm,force_N,velocity_mm_s,voltage_V,seq,device_time_s,"
                                   "tissue_position_mm,phase,event\n"
                                   "0,0,0,4,0.01,0,0.5,0.1,a,contact\n"
                                   "0.002,0.008,0.02,4.1,0.02,1,0.502,0.2,b1,\n");
        const auto r = readRunFile(path);
        QCOMPARE(r.run.numeric.size(), std::size_t(5));
        QCOMPARE(r.run.numeric[0].first, QStringLiteral("velocity_mm_s"));
        QCOMPARE(r.run.numericColumn(QStringLiteral("velocity_mm_s"))->at(1), 4.1);
        QCOMPARE(r.run.numericColumn(QStringLiteral("voltage_V"))->at(1), 0.02);
        QCOMPARE(r.run.numericColumn(QStringLiteral("seq"))->at(1), 1.0);
        QCOMPARE(r.run.numericColumn(QStringLiteral("device_time_s"))->at(0), 0.5);
        QCOMPARE(r.run.numericColumn(QStringLiteral("tissue_position_mm"))->at(1), 0.2);
        QCOMPARE(r.run.textColumn(QStringLiteral("phase"))->at(1), QStringLiteral("b1"));
        QCOMPARE(r.run.textColumn(QStringLiteral("event"))->at(0), QStringLiteral("contact"));
        QCOMPARE(r.run.textColumn(QStringLiteral("event"))->at(1), QString());
    }

    void streamingWriterMatchesReader()
    {
        const QString path = dir_.filePath(QStringLiteral("stream.csv"));
        Metadata m;
        m.set(QStringLiteral("protocol"), QStringLiteral("friction"));
        RunFileWriter w;
        w.open(path, m, {QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N"),
                         QStringLiteral("seq")});
        for (int i = 0; i < 250; ++i) {
            const double row[] = {i * 0.001, i * 0.004, 0.5, double(i)};
            w.writeRow(row);
            if (i == 100) {
                w.flush();
                // What a crash at this point would leave on disk reads back cleanly.
                const auto partial = readRunFile(path);
                QCOMPARE(partial.run.size(), std::size_t(101));
                QVERIFY(!partial.run.footer.contains(QStringLiteral("end_reason")));
            }
        }
        Metadata footer;
        footer.set(QStringLiteral("end_reason"), QStringLiteral("stopped by operator"));
        w.close(footer);
        const auto back = readRunFile(path);
        QCOMPARE(back.run.size(), std::size_t(250));
        QCOMPARE(back.run.meta(QStringLiteral("end_reason")).value_or(QString()), QStringLiteral("stopped by operator"));
    }

    void acceptsBomCrlfBlanksAndUnknownColumns()
    {
        const QString path = write(QStringLiteral("excel.csv"),
                                   "\xEF\xBB\xBF# specimen: liver 1\r\n\r\ntime_s, position_mm ,force_N,notes,velocity_mm_s\r\n"
                                   "0,0,0,hello,4\r\n0.002,0.008,+0.01,x,\r\n");
        const auto r = readRunFile(path);
        QCOMPARE(r.run.size(), std::size_t(2));
        QCOMPARE(r.run.metadata.value(QStringLiteral("specimen"), QString()), QStringLiteral("liver 1"));
        QCOMPARE(r.run.force_N[1], 0.01);
        QVERIFY(std::isnan(r.run.numericColumn(QStringLiteral("velocity_mm_s"))->at(1)));
        QVERIFY(r.warnings.join(' ').contains(QStringLiteral("notes")));
    }

    void refusesBadInputWithFileLineAndReason_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("reason");
        QTest::newRow("empty") << QByteArray() << 0 << "empty";
        QTest::newRow("only comments") << QByteArray("# a: b\n") << 0 << "no header";
        QTest::newRow("missing force") << QByteArray("time_s,position_mm\n0,0\n") << 1 << "force_N";
        QTest::newRow("text in number") << QByteArray("time_s,position_mm,force_N\n0,0,0\n0.1,abc,0\n") << 3
                                        << "'abc' is not a number";
        QTest::newRow("nan required") << QByteArray("time_s,position_mm,force_N\n0,0,nan\n") << 2 << "not a number";
        QTest::newRow("time repeats") << QByteArray("time_s,position_mm,force_N\n0,0,0\n0,1,0\n") << 3
                                      << "does not increase";
        QTest::newRow("time backwards") << QByteArray("time_s,position_mm,force_N\n1,0,0\n0.5,1,0\n") << 3
                                        << "does not increase";
        QTest::newRow("short row") << QByteArray("time_s,position_mm,force_N\n0,0,0\n1,2\n3,4,5\n") << 3
                                   << "expected 3 fields, found 2";
        QTest::newRow("truncated tail") << QByteArray("time_s,position_mm,force_N\n0,0,0\n1,2") << 3
                                        << "interrupted";
        QTest::newRow("duplicate column") << QByteArray("time_s,force_N,position_mm,force_N\n") << 1 << "twice";
        QTest::newRow("binary") << QByteArray("time_s,position_mm,force_N\n\0\0\0", 30) << 0 << "binary";
        QTest::newRow("semicolons") << QByteArray("# format: needlebench-run 1\ntime_s;position_mm;force_N\n0;0;0\n0,002;0,008;0\n") << 2
                                    << "separated by ';', not by commas";
        QTest::newRow("tabs") << QByteArray("time_s\tposition_mm\tforce_N\n0\t0\t0\n") << 1 << "separated by 'tab'";
        QTest::newRow("row after footer") << QByteArray("time_s,position_mm,force_N\n0,0,0\n# end: x\n1,1,1\n") << 4
                                          << "after the closing metadata";
    }
    void refusesBadInputWithFileLineAndReason()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, line);
        QFETCH(QString, reason);
        const QString path = write(QStringLiteral("bad.csv"), bytes);
        const RunFileError e = refused(path);
        QVERIFY2(e.line() != -1, "bad input was accepted");
        QCOMPARE(e.line(), line);
        QVERIFY2(e.reason().contains(reason), qPrintable(e.message()));
        QVERIFY(e.message().startsWith(path));
    }

    // The calibration and labels files a comma-decimal spreadsheet saved are said to be that, as
    // run files are: they were refused for "header needs columns mass_g and voltage_V".
    void spreadsheetSeparatorsAreNamedInEveryFile()
    {
        const QString cal = write(QStringLiteral("cal.csv"), "mass_g;voltage_V\r\n0;0,42\r\n10;0,54\r\n");
        const QString labels = write(QStringLiteral("run.labels.csv"), "\"track\";\"label\";\"start_s\";\"end_s\";\"comment\"\r\nphases;a;0,5;1,5;\r\n");
        try {
            readCalibrationFile(cal);
            QFAIL("a ';' calibration file was read");
        } catch (const RunFileError& e) {
            QVERIFY2(e.message().startsWith(cal) && e.reason().contains(QStringLiteral("separated by ';'")), qPrintable(e.message()));
        }
        try {
            readLabels(labels);
            QFAIL("a ';' labels file was read");
        } catch (const RunFileError& e) {
            QVERIFY2(e.message().startsWith(labels) && e.reason().contains(QStringLiteral("separated by ';'")), qPrintable(e.message()));
        }
    }

    // Numbers that tell how they were written are said, naming the file, and kept as written: a
    // force flat at its top while the needle moves on (a saturated amplifier), positions in metres.
    // A smooth peak, a hold at depth and a run in millimetres are not.
    void implausibleNumbersAreSaid()
    {
        const auto runText = [](auto force, auto position) {
            QByteArray t("# format: needlebench-run 1\ntime_s,position_mm,force_N\n");
            for (int i = 0; i < 2000; ++i) {
                const double s = i * 0.001;
                t += QStringLiteral("%1,%2,%3\n").arg(s, 0, 'f', 3).arg(position(s), 0, 'g', 9).arg(force(s), 0, 'g', 9).toUtf8();
            }
            return t;
        };
        const auto insertion = [](double s) { return 4.0 * s; };                       // 4 mm/s
        const auto rising = [](double s) { return 0.02 * 4.0 * s * 4.0 * s; };          // up to 1.28 N
        const auto clippedAt1 = [&](double s) { return std::min(1.0, rising(s)); };     // at 1 N from 1.77 s
        const auto peak = [](double s) { return std::round(1000.0 * (1.0 - (s - 1.0) * (s - 1.0))) / 1000.0; };  // 1 mN steps
        struct Case {
            const char* name;
            QByteArray text;
            const char* said;  // nullptr: nothing
        };
        const Case cases[] = {
            {"clipped", runText(clippedAt1, insertion), "saturated"},
            {"metres", runText(rising, [&](double s) { return insertion(s) / 1000.0; }), "metres"},
            {"smooth peak", runText(peak, insertion), nullptr},
            {"hold at depth", runText(rising, [](double) { return 12.0; }), nullptr},
            {"plain", runText(rising, insertion), nullptr},
        };
        for (const Case& c : cases) {
            const QString path = write(QStringLiteral("%1.csv").arg(QLatin1String(c.name)).replace(QLatin1Char(' '), QLatin1Char('_')), c.text);
            const RunReadResult r = readRunFile(path);
            const QString said = r.warnings.join(QLatin1Char('\n'));
            QCOMPARE(r.run.size(), std::size_t(2000));
            if (c.said)
                QVERIFY2(r.warnings.size() == 1 && said.startsWith(path) && said.contains(QLatin1String(c.said)), qPrintable(QLatin1String(c.name) + QStringLiteral(": ") + said));
            else
                QVERIFY2(r.warnings.isEmpty(), qPrintable(QLatin1String(c.name) + QStringLiteral(": ") + said));
        }
    }

    void recoveryDropsOnlyThePartialLastRow()
    {
        const QString path = write(QStringLiteral("crashed.csv"), "time_s,position_mm,force_N\n0,0,0\n0.1,1,0.2\n0.2,1.");
        RunReadOptions o;
        o.dropTruncatedLastRow = true;
        const auto r = readRunFile(path, o);
        QCOMPARE(r.run.size(), std::size_t(2));
        QCOMPARE(r.run.position_mm.size(), std::size_t(2));
        QCOMPARE(r.warnings.size(), 1);
    }

    void missingFileNamesTheFile()
    {
        const QString path = dir_.filePath(QStringLiteral("nope.csv"));
        const RunFileError e = refused(path);
        QVERIFY(e.message().contains(QStringLiteral("nope.csv")));
        QVERIFY(e.reason().contains(QStringLiteral("cannot open")));
    }

    // A file too large for the memory at hand is refused by name: it was said as "internal
    // error: out of memory" (a 1 GB file). The process's data limit is lowered to what it uses
    // and 150 MB more, and a file that needs more than that to read is given.
    void aFileTooLargeForMemoryIsNamed()
    {
#if defined(__SANITIZE_ADDRESS__)
        QSKIP("AddressSanitizer's shadow memory counts against the data limit this test lowers");
#else
        const QString path = dir_.filePath(QStringLiteral("huge.csv"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("time_s,position_mm,force_N\n");
            QByteArray rows;
            for (int i = 1; i <= 8'000'000; ++i) {
                rows += QByteArray::number(i) + ",0,0\n";
                if (rows.size() > (1 << 20))
                    f.write(std::exchange(rows, QByteArray()));
            }
            f.write(rows);
        }
        // 8 M rows of three numbers (90 MB): 190 MB more as vectors of doubles.
        QFile status(QStringLiteral("/proc/self/status"));
        QVERIFY(status.open(QIODevice::ReadOnly));
        long dataKb = -1;
        for (const QByteArray& line : status.readAll().split('\n'))
            if (line.startsWith("VmData:"))
                dataKb = line.mid(7).trimmed().split(' ').first().toLong();
        QVERIFY(dataKb > 0);
        rlimit before{};
        QCOMPARE(getrlimit(RLIMIT_DATA, &before), 0);
        rlimit lowered = before;
        lowered.rlim_cur = rlim_t(dataKb + 150 * 1024) * 1024;
        QCOMPARE(setrlimit(RLIMIT_DATA, &lowered), 0);
        QString message;
        bool threw = false;
        try {
            readRunFile(path);
        } catch (const RunFileError& e) {
            threw = true;
            message = e.message();
        } catch (const std::bad_alloc&) {
            message = QStringLiteral("std::bad_alloc escaped");
        }
        setrlimit(RLIMIT_DATA, &before);
        QVERIFY2(threw, qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("huge.csv")) && message.contains(QStringLiteral("too large to read into memory")),
                 qPrintable(message));
        QFile::remove(path);
#endif
    }

    // Issue 15: a second writer of the same file is refused, by name, and leaves it untouched.
    void secondWriterIsRefused()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("locked.csv"));
        nb::Metadata m;
        m.set(QStringLiteral("protocol"), QStringLiteral("stiffness"));
        const QStringList cols{QStringLiteral("time_s"), QStringLiteral("position_mm"), QStringLiteral("force_N")};
        nb::RunFileWriter first;
        first.open(path, m, cols);
        const double row[3] = {0.0, 1.0, 2.0};
        first.writeRow(row);
        first.flush();
        nb::RunFileWriter second;
        try {
            second.open(path, m, cols);
            QFAIL("a second writer was let in");
        } catch (const nb::RunFileError& e) {
            QCOMPARE(e.file(), path);
            QVERIFY2(e.reason().contains(QLatin1String("another process")), qPrintable(e.message()));
        }
        const double row2[3] = {0.002, 1.5, 2.5};
        first.writeRow(row2);
        nb::Metadata footer;
        footer.set(QStringLiteral("end_reason"), QStringLiteral("completed"));
        first.close(footer);
        const nb::Run run = nb::readRunFile(path).run;
        QCOMPARE(run.size(), std::size_t(2));
        QCOMPARE(run.footer.value(QStringLiteral("end_reason"), QString()), QStringLiteral("completed"));
        // Closed: the next writer may have it.
        nb::RunFileWriter third;
        third.open(path, m, cols);
        third.close();
        // A device that is always full: a clean error naming the cause, not a crash.
        if (QFileInfo::exists(QStringLiteral("/dev/full"))) {
            nb::RunFileWriter full;
            QVERIFY_THROWS_EXCEPTION(nb::RunFileError, full.open(QStringLiteral("/dev/full"), m, cols));
            QVERIFY(!full.isOpen());
        }
    }

    // Issue 15: metadata in linear time (the benchmark prints the time); every key kept.
    void manyMetadataLinesAllKept()
    {
        QByteArray text;
        const int n = 100000;
        for (int i = 0; i < n; ++i)
            text += "# key_" + QByteArray::number(i) + ": " + QByteArray::number(i) + '\n';
        text += "# key_7: again\ntime_s,position_mm,force_N\n0,0,0\n";
        const nb::Run run = nb::parseRunText(text, QStringLiteral("meta.csv")).run;
        QCOMPARE(run.metadata.entries().size(), std::size_t(n));
        QCOMPARE(run.metadata.value(QStringLiteral("key_7"), QString()), QStringLiteral("again"));
        QCOMPARE(run.metadata.value(QStringLiteral("key_99999"), QString()), QStringLiteral("99999"));
    }

    // Issue 15: a message quotes a short excerpt of a bad field, control characters escaped.
    void messagesQuoteAShortEscapedExcerpt()
    {
        QByteArray text = "time_s,position_mm,force_N\n0,0,\x1b[31m";
        text += QByteArray(1 << 20, 'x');
        text += "\n";
        try {
            nb::parseRunText(text, QStringLiteral("bad.csv"));
            QFAIL("accepted");
        } catch (const nb::RunFileError& e) {
            const QString msg = e.message();
            QVERIFY2(msg.size() < 400, qPrintable(msg.left(400)));
            QVERIFY(!msg.contains(QChar(0x1b)));
            QVERIFY2(msg.contains(QLatin1String("\\x1b[31m")), qPrintable(msg));
        }
        QCOMPARE(nb::excerpt(QStringLiteral("a\tb\nc"), 10), QStringLiteral("a\\tb\\nc"));
        QVERIFY(nb::excerpt(QString(100, QLatin1Char('y')), 10).startsWith(QString(10, QLatin1Char('y')) + QStringLiteral("…")));
    }

    // Numbers beyond fixed notation are written so that they read back, not as empty fields.
    void hugeNumbersRoundTrip()
    {
        QTemporaryDir dir;
        nb::Run run;
        run.time_s = {0.0, 0.001};
        run.position_mm = {0.0, 1e-300};
        run.force_N = {1e160, -3e200};
        nb::writeRunFile(dir.filePath(QStringLiteral("huge.csv")), run);
        const nb::RunReadResult read = nb::readRunFile(dir.filePath(QStringLiteral("huge.csv")));
        QCOMPARE(read.run.force_N, run.force_N);
        // Kept as written, but said: no load cell reads them.
        QCOMPARE(read.warnings.size(), qsizetype(1));
        QVERIFY2(read.warnings[0].contains(QStringLiteral("force_N of 1e+160 N at 0.000 s")) && read.warnings[0].contains(QStringLiteral("(2 such sample")),
                 qPrintable(read.warnings[0]));
    }
};

QTEST_GUILESS_MAIN(TestRunFile)
#include "test_run_file.moc"
