// The command-line contract: the real executable, run as a user's script would.
#include <QProcess>
#include <QTemporaryDir>
#include "support/needlebench_cli.h"

#include <QtTest>

class TestCli : public QObject {
    Q_OBJECT

    static nbtest::CliResult run(const QStringList& args) { return nbtest::runCli(args); }

    QTemporaryDir settings_;  // no language chosen in the settings: the C locale's English

    // The executable as a user on an SSH session meets it: no display at all.
    QProcessEnvironment withoutDisplay() const
    {
        auto env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), settings_.path());
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C.UTF-8"));
        return env;
    }

private slots:
    void unknownCommandPrintsUsageAndFails()
    {
        const auto r = run({QStringLiteral("frobnicate")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QStringLiteral("unknown command 'frobnicate'")));
        QVERIFY(r.err.contains(QStringLiteral("Usage:")));
    }
    void helpListsCommands()
    {
        const auto r = run({QStringLiteral("help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains(QStringLiteral("version")));
    }
    void badOptionFails()
    {
        const auto r = run({QStringLiteral("version"), QStringLiteral("--bogus")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QStringLiteral("bogus")));
    }
    void versionRunsHeadless_data()
    {
        QTest::addColumn<QString>("asked");
        QTest::newRow("version") << QStringLiteral("version");
        QTest::newRow("--version") << QStringLiteral("--version");
        QTest::newRow("-v") << QStringLiteral("-v");
    }
    void versionRunsHeadless()
    {
        // The command must not need a display, nor the option a user types by habit (it used
        // to start the window, which without a display aborted).
        QFETCH(QString, asked);
        QProcess p;
        p.setProcessEnvironment(withoutDisplay());
        p.start(QStringLiteral(NB_EXECUTABLE), {asked});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(p.readAllStandardOutput().startsWith("needlebench "));
    }
    void windowWithoutDisplaySaysWhatToDo()
    {
        // Qt aborts without a display and advises reinstalling; the operator is told instead
        // what is missing and what runs without it.
        QProcess p;
        p.setProcessEnvironment(withoutDisplay());
        p.start(QStringLiteral(NB_EXECUTABLE), QStringList());
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("DISPLAY")) && err.contains(QStringLiteral("needlebench demo")), qPrintable(err));
        QVERIFY2(!err.contains(QStringLiteral("einstall")), qPrintable(err));
    }
    void windowOnADisplayThatDoesNotAnswerSaysWhatToDo()
    {
        // A stale DISPLAY (the SSH session's forwarding gone): Qt cannot connect and aborts.
        QProcessEnvironment env = withoutDisplay();
        env.insert(QStringLiteral("DISPLAY"), QStringLiteral(":9731"));
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(NB_EXECUTABLE), QStringList());
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("':9731'")) && err.contains(QStringLiteral("needlebench demo")), qPrintable(err));
        QVERIFY2(!err.contains(QStringLiteral("einstall")), qPrintable(err));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
