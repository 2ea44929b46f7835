// The command-line contract: the real executable, run as a user's script would.
#include <QProcess>
#include "support/needlebench_cli.h"

#include <QtTest>

class TestCli : public QObject {
    Q_OBJECT

    static nbtest::CliResult run(const QStringList& args) { return nbtest::runCli(args); }

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
    void versionRunsHeadless()
    {
        // No display: the command must not need one.
        QProcess p;
        auto env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(NB_EXECUTABLE), {QStringLiteral("version")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(p.readAllStandardOutput().startsWith("needlebench "));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
