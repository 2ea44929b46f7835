#pragma once
// Runs the real needlebench executable the way users' scripts do: without a display, within a
// time limit, and reports the exit code (-1 when it crashed or had to be killed), standard
// output and standard error.

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>

namespace nbtest {

struct CliResult {
    int code = -1;
    QString out, err;
    // Standard output as JSON, from its first '{' (progress lines may come before it).
    QJsonObject json() const { return QJsonDocument::fromJson(out.mid(out.indexOf(QLatin1Char('{'))).toUtf8()).object(); }
};

inline CliResult runCli(const QStringList& args, int timeout_ms = 120000)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));  // no command may need one
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(NB_EXECUTABLE), args);
    if (!p.waitForFinished(timeout_ms)) {
        p.kill();
        p.waitForFinished();
        return {-1, QString::fromUtf8(p.readAllStandardOutput()),
                QStringLiteral("needlebench %1: killed after %2 ms\n").arg(args.join(QLatin1Char(' '))).arg(timeout_ms) +
                    QString::fromUtf8(p.readAllStandardError())};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

inline QJsonObject readJsonFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

}  // namespace nbtest
