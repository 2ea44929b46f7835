#pragma once
// The window's walk through a session's experiment plan (issue 16): which run is next, the
// short checklist before it, its attempts written into plan.json as `plan run` writes them, and
// whether the operator walks the plan (its settings locked in the control panel) or has left
// it. No widgets and no devices: the window shows it (PlanPanel) and feeds it the engine's news.

#include "core/plan.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <optional>

namespace nb {

class PlanWalker : public QObject {
    Q_OBJECT
public:
    enum class Check { Instruction, Bias, Zero };

    explicit PlanWalker(QObject* parent = nullptr);

    // Opens the session's plan.json if it has one and resumes it: a run left "running" by a
    // crash becomes interrupted and runs again (recover the session's run files first). True
    // when there was none or it opened (`notes` says what was resumed); false with `error`.
    bool openSession(const QString& sessionDir, QString* error, QStringList* notes = nullptr);
    void closeSession();
    // Makes `plan` the session's plan (written to plan.json) and walks it. Refused while a
    // plan run records, and over a plan.json that already holds runs of another design.
    bool adopt(const Plan& plan, QString* error);

    bool hasPlan() const { return plan_.has_value(); }
    const Plan& plan() const { return *plan_; }
    QString planPath() const;
    QString sessionDir() const { return sessionDir_; }

    // Walking: the next run's settings are the panel's, locked. Leaving releases them (runs
    // made meanwhile are not the plan's); rejoining takes them up again.
    bool walking() const { return plan_ && walking_ && nextIndex() >= 0; }
    void leave();
    void rejoin();

    // Index into plan().runs of the run to make next (the first not completed); -1 when done.
    int nextIndex() const;
    const PlannedRun* nextRun() const;
    QJsonObject nextSettings() const;

    // The checklist of the next run; the instruction item only when the run has one.
    bool hasInstruction() const;
    bool checked(Check item) const;
    void setChecked(Check item, bool on);
    // Bias and zero tick themselves when the engine has done them since the run was armed.
    // Counts are the engine's since it started; a new engine starts again from 0.
    void noteEngineCounts(quint64 biasCount, quint64 zeroCount);
    void engineReplaced();
    // What keeps Start back (unticked items), for its tooltip; empty when ready or not walking.
    QString hold() const;

    // "Run 7 of 21 · about 12 min left"; "All 21 runs completed" at the end.
    QString progressText() const;

    // Start: the next run's file (`proposedPath` renumbered past the plan's attempts), its
    // metadata (factor_*, plan_*), and the attempt begun in plan.json. False with `error`.
    bool beginRun(const QString& proposedPath, QString* runPath, Metadata* metadata, QString* error);
    bool attemptOpen() const { return openAttempt_ >= 0; }
    QString openAttemptPath() const;
    // The open attempt's end as the engine reported it ("completed", "emergency_stop", ...; "not
    // started" when it was refused). Written to plan.json; the next run is armed.
    bool finishRun(const QString& endReason, QString* error);

    // Skips the next run with `reason`.
    bool skipNext(const QString& reason, QString* error);
    // The run done last (its attempt ended latest), which redo would make again; -1: none.
    int lastDoneIndex() const;
    bool redo(int index, const QString& reason, QString* error);

signals:
    // Anything shown changed (plan, next run, checklist, walking).
    void changed();
    // A new run is next (after opening, a run's end, skip or redo): its settings must be set.
    void armed();

private:
    bool save(QString* error);
    void arm();

    std::optional<Plan> plan_;
    QString sessionDir_;
    bool walking_ = true;
    int openAttempt_ = -1;
    int armedIndex_ = -2;
    bool instructionDone_ = false, biasDone_ = false, zeroDone_ = false;
    quint64 biasCount_ = 0, zeroCount_ = 0;            // the engine's, last seen
    quint64 biasBaseline_ = 0, zeroBaseline_ = 0;      // when the run was armed
    bool awaitingNewEngine_ = false;                   // until the new engine's first status
};

}  // namespace nb
