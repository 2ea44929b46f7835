#include "zaber_protocol.h"
#include "core/tr.h"

#include <QCoreApplication>
#include <QList>
#include <cmath>

namespace nb::devices::zaber {

QByteArray command(int device, int axis, const QByteArray& text)
{
    return '/' + QByteArray::number(device) + ' ' + QByteArray::number(axis) + ' ' + text + '\n';
}

namespace {

// Zaber's LRC: the two's complement of the byte sum of everything after the type character.
std::uint8_t lrc(const QByteArray& body)
{
    unsigned s = 0;
    for (char c : body)
        s += std::uint8_t(c);
    return std::uint8_t((~s + 1) & 0xff);
}

}  // namespace

std::optional<Message> parse(const QByteArray& rawLine)
{
    QByteArray line = rawLine.trimmed();
    if (line.size() < 2)
        return std::nullopt;
    const char type = line.at(0);
    if (type != '@' && type != '!' && type != '#')
        return std::nullopt;
    const qsizetype colon = line.lastIndexOf(':');
    if (colon > 0 && colon == line.size() - 3) {
        bool ok = false;
        const unsigned sum = line.mid(colon + 1).toUInt(&ok, 16);
        if (!ok || sum != lrc(line.mid(1, colon - 1)))
            return std::nullopt;
        line.truncate(colon);
    }
    const QList<QByteArray> f = line.mid(1).split(' ');
    Message m;
    m.type = type;
    bool okDev = false, okAxis = false;
    if (f.size() < 2)
        return std::nullopt;
    m.device = f[0].toInt(&okDev);
    m.axis = f[1].toInt(&okAxis);
    if (!okDev || !okAxis)
        return std::nullopt;
    if (type == '#') {
        m.data = f.mid(2).join(' ');
        return m;
    }
    qsizetype i = 2;
    if (type == '@') {
        if (f.size() < 5 || (f[2] != "OK" && f[2] != "RJ"))
            return std::nullopt;
        m.rejected = f[2] == "RJ";
        i = 3;
    }
    if (f.size() < i + 2 || (f[i] != "BUSY" && f[i] != "IDLE"))
        return std::nullopt;
    m.busy = f[i] == "BUSY";
    m.warning = f[i + 1];
    m.data = f.mid(i + 2).join(' ');
    return m;
}

QByteArray format(const Message& m)
{
    QByteArray s;
    s += m.type;
    s += QByteArray::number(m.device).rightJustified(2, '0') + ' ' + QByteArray::number(m.axis) + ' ';
    if (m.type == '#')
        return s + m.data;
    if (m.type == '@')
        s += m.rejected ? "RJ " : "OK ";
    s += m.busy ? "BUSY " : "IDLE ";
    s += m.warning.isEmpty() ? QByteArray("--") : m.warning;
    if (m.type == '@')
        s += ' ' + (m.data.isEmpty() ? QByteArray("0") : m.data);
    return s;
}

QString rejectionText(const QByteArray& reason)
{
    struct Entry {
        const char* code;
        const char* text;
    };
    static const Entry table[] = {
        {"AGAIN", QT_TRANSLATE_NOOP("nb::TrDevices", "the controller is busy; try again")},
        {"BADAXIS", QT_TRANSLATE_NOOP("nb::TrDevices", "no such axis on this controller")},
        {"BADCOMMAND", QT_TRANSLATE_NOOP("nb::TrDevices", "the controller does not know this command")},
        {"BADDATA", QT_TRANSLATE_NOOP("nb::TrDevices", "a value is out of range for this stage")},
        {"BADMESSAGEID", QT_TRANSLATE_NOOP("nb::TrDevices", "bad message id")},
        {"DEVICEONLY", QT_TRANSLATE_NOOP("nb::TrDevices", "the command must be sent to the whole device")},
        {"DRIVERDISABLED", QT_TRANSLATE_NOOP("nb::TrDevices", "the motor driver is disabled (enable it; check motor power)")},
        {"FULL", QT_TRANSLATE_NOOP("nb::TrDevices", "the controller's buffer is full")},
        {"LOCKSTEP", QT_TRANSLATE_NOOP("nb::TrDevices", "the axis is in lockstep")},
        {"NOACCESS", QT_TRANSLATE_NOOP("nb::TrDevices", "access level too low for this setting")},
        {"PARKED", QT_TRANSLATE_NOOP("nb::TrDevices", "the axis is parked (unpark it first)")},
        {"REMOTE", QT_TRANSLATE_NOOP("nb::TrDevices", "the controller is under remote control")},
        {"STATUSBUSY", QT_TRANSLATE_NOOP("nb::TrDevices", "the axis is moving")},
        {"NOTHOMED", QT_TRANSLATE_NOOP("nb::TrDevices", "the axis has not been homed")},
        {"SYSTEMERROR", QT_TRANSLATE_NOOP("nb::TrDevices", "the controller reports a system error")},
    };
    for (const Entry& e : table)
        if (reason == e.code)
            return nb::TrDevices::tr(e.text);
    return nb::TrDevices::tr("rejected: %1").arg(QString::fromLatin1(reason));
}

QString faultText(const QByteArray& w)
{
    if (w == "FS")
        return nb::TrDevices::tr("stalled and stopped (obstruction or overload?)");
    if (w == "FE")
        return nb::TrDevices::tr("limit error");
    if (w == "FQ")
        return nb::TrDevices::tr("encoder error");
    if (w == "FD")
        return nb::TrDevices::tr("driver disabled by a fault (over-temperature or power)");
    return {};
}

std::int64_t Units::steps(double mm) const
{
    return std::llround(mm * microstepsPerMm);
}

std::int64_t Units::speedData(double mm_s) const
{
    return std::llround(mm_s * microstepsPerMm * speedScale);
}

}  // namespace nb::devices::zaber
