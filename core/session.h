#pragma once
// A lab session is a folder: the specimen and protocol (session.json), the sensor
// calibrations made for it (calibrations/*.json, one of them active), and its runs
// (run_001_linear.csv, ...), each a run file whose footer says how it ended.
//
//   liver3_2026-11-21/
//     session.json
//     calibrations/cal_20261121_093000.json
//     run_001_linear.csv
//     run_002_sine.csv
//
// A run without a footer was cut off by a crash; recoverInterrupted() finds it at the next
// start, drops a partial last row and closes it with `end_reason: recovered`.

#include "core/calibration.h"
#include "core/error.h"
#include "core/run.h"

#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>
#include <vector>

class QLockFile;

namespace nb {

// A session folder that cannot be created, read or written: names the file and the reason.
class SessionError : public Error {
public:
    SessionError(QString file, QString reason) : Error(std::move(file), std::move(reason)) {}
    const QString& file() const { return subject(); }
};

struct SessionInfo {
    QString organ;
    QString specimen;     // specimen number
    QString tip;          // beveled, blunt, diamond
    double thickness_mm = 0.0;
    QString operatorName;
    QString protocol;     // overall stiffness, friction, ...
    QString notes;
    QDateTime created;
};

// The session's details as run metadata (organ, specimen, tip, thickness_mm, operator,
// protocol): what every run of the session and every export of it carries.
Metadata sessionMetadata(const SessionInfo& info);
// A new session's folder name: organ and specimen as the operator wrote them (letters of any
// language kept, "Leber ü" stays "Leber_ü"; what a file system or shell trips over becomes
// "_"), then the time; "session" when both are empty.
QString sessionFolderName(const SessionInfo& info, const QDateTime& created);

struct StoredCalibration {
    QString name;         // file base name, e.g. cal_20261121_093000
    QDateTime date;
    QString sensor;       // which load cell / DAQ it was made with
    std::vector<CalibrationPoint> points;  // the points used in the fit
    std::vector<CalibrationPoint> removed; // points the operator struck out (kept for the record)
    CalibrationFit fit;
    bool nominal = false; // the sensor chain's nominal slope, not measured
};

enum class RunState {
    Interrupted,     // no footer: cut off by a crash (or still recording); recovered at a start
    Complete,
    Stopped,         // ended by the operator before the motion finished
    StoppedByLimit,  // the force limit stopped it
    Fault,           // a device fault ended it
    Recovered,       // was interrupted, recovered at a later start
    Unreadable,
    // The rest of core/end_reason.h's reasons, so the list tells them apart.
    MotionStopped,   // the stage stopped by itself (limit switch, stall)
    EmergencyStop,
    Puncture,        // stopped at a puncture, as the run asked
    WriteError,
    Aborted,
    ClosedOnSignal,  // closed whole when a signal (SIGTERM, SIGHUP, Ctrl+C) ended the program
};

struct RunEntry {
    QString path;
    QString fileName;
    int number = 0;
    QString motion;       // from metadata (motion: linear | sine), may be empty
    RunState state = RunState::Interrupted;
    QString endReason;    // raw footer value
    QString calibration;  // calibration named in the run
    QString detail;       // e.g. why unreadable
    QDateTime modified;
};

RunState runStateForEndReason(const QString& endReason);
// Operator-facing name of a state (translated).
QString runStateName(RunState state);
// Reads only the head and tail of a run file: cheap for long recordings.
RunEntry inspectRun(const QString& path);
// Closes an interrupted run file in place: drops a partial last row, appends
// `end_reason: recovered`. Returns warnings. Throws RunFileError.
QStringList recoverRunFile(const QString& path);

class Session {
public:
    // Creates the folder (or adopts an empty one) and writes session.json. Throws SessionError.
    static Session create(const QString& dir, const SessionInfo& info);
    // Throws SessionError when dir has no readable session.json.
    static Session open(const QString& dir);
    static bool isSession(const QString& dir);

    const QString& dir() const { return dir_; }
    const SessionInfo& info() const { return info_; }
    void setInfo(const SessionInfo& info);  // saves

    // The next free run file name, numbered after the highest existing one.
    QString nextRunPath(const QString& motion) const;
    std::vector<RunEntry> runs() const;
    // Recovers every interrupted run except `busyPath` (a run this process is recording).
    // Returns one line per recovered file; problems go to *problems.
    QStringList recoverInterrupted(const QString& busyPath = {}, QStringList* problems = nullptr);

    // Saves it under calibrations/ (naming it by its date if unnamed) and makes it active.
    QString saveCalibration(StoredCalibration calibration);
    std::vector<StoredCalibration> calibrations() const;
    std::optional<StoredCalibration> activeCalibration() const;
    void setActiveCalibration(const QString& name);
    // The simulated rig's settings the session runs on (tissue, tip, seed, rate), as the device
    // chooser writes them; empty when none were chosen. Saved in session.json.
    const QJsonObject& simulatedRig() const { return simulatedRig_; }
    void setSimulatedRig(const QJsonObject& settings);  // saves

private:
    void save() const;
    QString dir_;
    SessionInfo info_;
    QString activeCalibration_;
    QJsonObject simulatedRig_;
};

// A session held by one program (a window, `plan run`) while the lock lives: a second one
// "recovered" the run the first was recording (its file closed with a footer under it), and
// both recorded into the folder. `heldBy` says who has it when another program does ("process
// 4711 on lab-pc"); a folder that takes no lock file (read-only media) is not refused, as
// nothing records there. A crashed program's lock is taken over.
struct SessionLock {
    std::unique_ptr<QLockFile> file;  // null when refused or not lockable
    QString heldBy;
    bool refused() const { return !heldBy.isEmpty(); }
};
SessionLock lockSession(const QString& dir);

}  // namespace nb
