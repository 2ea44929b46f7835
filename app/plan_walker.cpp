#include "plan_walker.h"
#include "core/plan_session.h"

#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <cmath>

namespace nb {

PlanWalker::PlanWalker(QObject* parent) : QObject(parent) {}

bool PlanWalker::openSession(const QString& sessionDir, QString* error, QStringList* notes)
{
    closeSession();
    sessionDir_ = sessionDir;
    const QString path = planFilePath(sessionDir);
    if (!QFileInfo::exists(path)) {
        emit changed();
        return true;
    }
    try {
        Plan plan = readPlanFile(path);
        const PlanResumption resumed = resumePlan(plan, sessionDir);
        for (const auto& [number, file] : resumed.endedBefore)
            if (notes)
                *notes << tr("Plan run %1 had ended before the interruption (%2).").arg(number).arg(file);
        for (int number : resumed.interrupted)
            if (notes)
                *notes << tr("Plan run %1 was interrupted; it runs again.").arg(number);
        plan_ = std::move(plan);
        if (!resumed.endedBefore.empty() || !resumed.interrupted.empty())
            if (!save(error))
                return false;
    } catch (const PlanError& e) {
        if (error)
            *error = e.message();
        emit changed();
        return false;
    }
    walking_ = true;
    arm();
    return true;
}

void PlanWalker::closeSession()
{
    plan_.reset();
    sessionDir_.clear();
    openAttempt_ = -1;
    armedIndex_ = -2;
    emit changed();
}

bool PlanWalker::adopt(const Plan& plan, QString* error)
{
    if (sessionDir_.isEmpty()) {
        if (error)
            *error = tr("Open a session first: the plan is kept in it.");
        return false;
    }
    if (attemptOpen()) {
        if (error)
            *error = tr("A plan run is recording: end it first.");
        return false;
    }
    // A plan with runs made is the record of them: never overwritten by another design.
    if (plan_ && !plan_->sameDesign(plan) &&
        std::any_of(plan_->runs.begin(), plan_->runs.end(), [](const PlannedRun& r) { return !r.attempts.empty(); })) {
        if (error)
            *error = tr("%1 already holds the plan \"%2\" with runs made; use another session for a new plan.")
                         .arg(QDir::toNativeSeparators(planPath()), plan_->name);
        return false;
    }
    // The same design again (e.g. its file opened once more): the session's record of the runs
    // made is kept, as `plan run` keeps it.
    const bool keepRecord = plan_ && plan_->sameDesign(plan);
    if (!keepRecord) {
        std::optional<Plan> before = plan_;
        plan_ = plan;
        if (!save(error)) {
            plan_ = before;
            return false;
        }
    }
    walking_ = true;
    armedIndex_ = -2;
    arm();
    return true;
}

QString PlanWalker::planPath() const { return sessionDir_.isEmpty() ? QString() : planFilePath(sessionDir_); }

void PlanWalker::leave()
{
    if (!walking_ || attemptOpen())
        return;
    walking_ = false;
    emit changed();
}

void PlanWalker::rejoin()
{
    if (walking_ || !plan_)
        return;
    walking_ = true;
    armedIndex_ = -2;  // the checklist again: the operator did things meanwhile
    arm();
}

int PlanWalker::nextIndex() const { return plan_ ? plan_->firstIncomplete() : -1; }

const PlannedRun* PlanWalker::nextRun() const
{
    const int i = nextIndex();
    return i < 0 ? nullptr : &plan_->runs[std::size_t(i)];
}

QJsonObject PlanWalker::nextSettings() const
{
    const PlannedRun* r = nextRun();
    return r ? plan_->settingsFor(*r) : QJsonObject();
}

bool PlanWalker::hasInstruction() const
{
    const PlannedRun* r = nextRun();
    return r && !r->instruction.isEmpty();
}

bool PlanWalker::checked(Check item) const
{
    switch (item) {
    case Check::Instruction:
        return instructionDone_;
    case Check::Bias:
        return biasDone_;
    case Check::Zero:
        return zeroDone_;
    }
    return false;
}

void PlanWalker::setChecked(Check item, bool on)
{
    bool& flag = item == Check::Instruction ? instructionDone_ : item == Check::Bias ? biasDone_ : zeroDone_;
    if (flag == on)
        return;
    flag = on;
    emit changed();
}

void PlanWalker::noteEngineCounts(quint64 biasCount, quint64 zeroCount)
{
    // After a switch the old engine's last statuses may still arrive: a new engine starts at 0.
    if (awaitingNewEngine_) {
        if (biasCount != 0 || zeroCount != 0)
            return;
        awaitingNewEngine_ = false;
    }
    // A count below the last one seen: a new engine (devices switched), counting from 0.
    if (biasCount < biasCount_ || zeroCount < zeroCount_)
        biasCount_ = zeroCount_ = biasBaseline_ = zeroBaseline_ = 0;
    bool news = false;
    if (biasCount != biasCount_ && biasCount > biasBaseline_ && !biasDone_)
        biasDone_ = news = true;
    if (zeroCount != zeroCount_ && zeroCount > zeroBaseline_ && !zeroDone_)
        zeroDone_ = news = true;
    biasCount_ = biasCount;
    zeroCount_ = zeroCount;
    if (news)
        emit changed();
}

void PlanWalker::engineReplaced()
{
    biasCount_ = zeroCount_ = 0;
    biasBaseline_ = zeroBaseline_ = 0;
    awaitingNewEngine_ = true;
}

QString PlanWalker::hold() const
{
    if (!walking())
        return {};
    QStringList missing;
    if (hasInstruction() && !instructionDone_)
        missing << tr("the operator's step");
    if (!biasDone_)
        missing << tr("bias");
    if (!zeroDone_)
        missing << tr("zero");
    if (missing.isEmpty())
        return {};
    return tr("Plan run %1: tick the checklist first (%2).").arg(nextRun()->number).arg(missing.join(QStringLiteral(", ")));
}

QString PlanWalker::progressText() const
{
    if (!plan_)
        return tr("No plan");
    const int total = int(plan_->runs.size());
    const PlannedRun* r = nextRun();
    if (!r)
        return tr("All %1 runs completed").arg(total);
    const double left_min = estimatedPlanTimeLeft_s(*plan_) / 60.0;
    const QString time = left_min < 1.0 ? tr("less than a minute left") : tr("about %1 min left").arg(std::lround(left_min));
    return tr("Run %1 of %2 · %3").arg(r->number).arg(total).arg(time);
}

bool PlanWalker::beginRun(const QString& proposedPath, QString* runPath, Metadata* metadata, QString* error)
{
    const int i = nextIndex();
    if (!walking() || i < 0) {
        if (error)
            *error = tr("No plan run is next.");
        return false;
    }
    if (const QString h = hold(); !h.isEmpty()) {
        if (error)
            *error = h;
        return false;
    }
    *runPath = unusedRunPath(*plan_, proposedPath);
    beginAttempt(*plan_, i, QFileInfo(*runPath).fileName(), QString(), QDateTime::currentDateTimeUtc());
    if (!save(error)) {
        plan_->runs[std::size_t(i)].attempts.pop_back();
        plan_->runs[std::size_t(i)].status = PlanRunStatus::Pending;
        return false;
    }
    *metadata = planRunMetadata(*plan_, plan_->runs[std::size_t(i)], planFileName());
    openAttempt_ = i;
    emit changed();
    return true;
}

QString PlanWalker::openAttemptPath() const
{
    if (openAttempt_ < 0 || sessionDir_.isEmpty())
        return {};
    return QDir(sessionDir_).filePath(plan_->runs[std::size_t(openAttempt_)].attempts.back().runFile);
}

bool PlanWalker::finishRun(const QString& endReason, QString* error)
{
    if (openAttempt_ < 0)
        return true;
    finishAttempt(*plan_, openAttempt_, endReason, QDateTime::currentDateTimeUtc());
    openAttempt_ = -1;
    const bool ok = save(error);
    arm();  // bias and zero again after every run; the operator's step only for a new run
    return ok;
}

bool PlanWalker::skipNext(const QString& reason, QString* error)
{
    const int i = nextIndex();
    if (i < 0 || attemptOpen() || reason.trimmed().isEmpty()) {
        if (error)
            *error = attemptOpen() ? tr("A plan run is recording: end it first.") : i < 0 ? tr("No plan run is next.") : tr("Give a reason.");
        return false;
    }
    skipRun(*plan_, i, reason.trimmed());
    const bool ok = save(error);
    arm();
    return ok;
}

int PlanWalker::lastDoneIndex() const
{
    if (!plan_)
        return -1;
    int best = -1;
    QDateTime latest;
    for (std::size_t i = 0; i < plan_->runs.size(); ++i)
        if (const PlanAttempt* a = plan_->runs[i].currentAttempt(); a && (best < 0 || a->ended > latest)) {
            best = int(i);
            latest = a->ended;
        }
    return best;
}

bool PlanWalker::redo(int index, const QString& reason, QString* error)
{
    if (!plan_ || index < 0 || index >= int(plan_->runs.size()) || attemptOpen() || reason.trimmed().isEmpty()) {
        if (error)
            *error = attemptOpen() ? tr("A plan run is recording: end it first.") : tr("Give a reason.");
        return false;
    }
    redoRun(*plan_, index, reason.trimmed());
    const bool ok = save(error);
    arm();
    return ok;
}

bool PlanWalker::save(QString* error)
{
    try {
        writePlanFile(planPath(), *plan_);
    } catch (const PlanError& e) {
        if (error)
            *error = e.message();
        return false;
    }
    return true;
}

void PlanWalker::arm()
{
    const int i = nextIndex();
    if (i != armedIndex_) {
        instructionDone_ = false;
        armedIndex_ = i;
    }
    biasDone_ = zeroDone_ = false;
    biasBaseline_ = biasCount_;
    zeroBaseline_ = zeroCount_;
    emit armed();
    emit changed();
}

}  // namespace nb
