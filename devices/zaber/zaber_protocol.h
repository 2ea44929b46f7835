#pragma once
// The Zaber ASCII protocol: command lines, reply/alert parsing, units, rejection reasons.
// Pure functions shared by the QSerialPort driver and the pty emulator in the tests.

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <optional>

namespace nb::devices::zaber {

// `/1 1 move abs 2000\n`
QByteArray command(int device, int axis, const QByteArray& text);

struct Message {
    char type = 0;         // '@' reply, '!' alert, '#' info
    int device = 0;
    int axis = 0;
    bool rejected = false; // reply flag RJ (OK otherwise)
    bool busy = false;     // BUSY / IDLE
    QByteArray warning;    // "--" when none, else e.g. "FZ"
    QByteArray data;       // the rest: a number, a rejection reason, or text
};

// Parses one line without its line ending; nothing if it is not a Zaber message. A trailing
// ":XX" checksum, when present, must match (longitudinal redundancy check).
std::optional<Message> parse(const QByteArray& line);
// Formats a reply as a controller would send it (used by the emulator).
QByteArray format(const Message& m);

// Operator-readable text for a rejection reason ("DRIVERDISABLED", "BADDATA", ...).
QString rejectionText(const QByteArray& reason);
// Operator-readable text for a warning flag ("FS" stall, "FQ" encoder error, ...); empty when
// the flag is harmless.
QString faultText(const QByteArray& warning);

// Position and speed scales from configuration: Zaber speaks micro-steps, and its speed data
// is micro-steps per second times 1.6384 on most controllers.
struct Units {
    double microstepsPerMm = 20997.375;  // 0.047625 um micro-step (e.g. X-LSM series)
    double speedScale = 1.6384;

    std::int64_t steps(double mm) const;
    double mm(double steps) const { return steps / microstepsPerMm; }
    std::int64_t speedData(double mm_s) const;
    double mmPerSecond(double speedData) const { return speedData / speedScale / microstepsPerMm; }
};

}  // namespace nb::devices::zaber
