#include "ffprobe.h"

#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>

namespace nb::video {

std::optional<QByteArray> runFfprobe(const QStringList& args, int timeout_ms)
{
    const QString exe = QStandardPaths::findExecutable(QStringLiteral("ffprobe"));
    if (exe.isEmpty())
        return std::nullopt;
    QProcess p;
    p.start(exe, args);
    if (!p.waitForStarted(5000))
        return std::nullopt;
    if (!p.waitForFinished(timeout_ms)) {
        p.kill();
        p.waitForFinished(1000);
        return std::nullopt;
    }
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
        return std::nullopt;
    return p.readAllStandardOutput();
}

QString ffprobeInput(const QString& path) { return QStringLiteral("file:") + QFileInfo(path).absoluteFilePath(); }

}  // namespace nb::video
