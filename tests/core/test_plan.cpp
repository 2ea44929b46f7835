// Experiment plans (core/plan.h): generation from factors, the three orders, operator
// instructions, plan.json round trips and errors that name the file and field, and the
// status bookkeeping that lets an interrupted plan resume at the first run not completed.
#include "core/plan.h"
#include "core/plan_session.h"
#include "core/run_file.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>
#include <set>

using namespace nb;

namespace {

QString key(const PlannedRun& r)
{
    return QString::fromUtf8(QJsonDocument(r.factors).toJson(QJsonDocument::Compact));
}

std::multiset<QString> cells(const Plan& p)
{
    std::multiset<QString> s;
    for (const PlannedRun& r : p.runs)
        s.insert(key(r));
    return s;
}

const PlanTemplate& tmpl(const char* name)
{
    const PlanTemplate* t = findPlanTemplate(QLatin1String(name));
    if (!t)
        qFatal("no template %s", name);
    return *t;
}

void writeJson(const QString& path, const QJsonObject& o)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QJsonDocument(o).toJson());
}

}  // namespace

class TestPlan : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void templatesGiveTheThesisRuns_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("runs");
        QTest::addColumn<QString>("tissue");
        QTest::addColumn<bool>("video");
        QTest::newRow("overall stiffness") << "overall-stiffness" << 21 << "liver1" << false;
        QTest::newRow("internal stiffness") << "internal-stiffness" << 7 << "liver7" << false;
        QTest::newRow("friction") << "friction" << 21 << "liver3" << false;
        QTest::newRow("stiffness imaging") << "stiffness-imaging" << 11 << "liver5" << true;
        QTest::newRow("friction imaging") << "friction-imaging" << 15 << "liver7" << true;
        QTest::newRow("prostate") << "prostate" << 9 << "prostate" << false;
    }
    void templatesGiveTheThesisRuns()
    {
        QFETCH(QString, name);
        QFETCH(int, runs);
        QFETCH(QString, tissue);
        QFETCH(bool, video);
        const PlanTemplate* t = findPlanTemplate(name);
        QVERIFY(t);
        const Plan p = generatePlan(*t, PlanOrder::Listed, 1);
        QCOMPARE(int(p.runs.size()), runs);
        QCOMPARE(int(cells(p).size()), runs);
        for (const PlannedRun& r : p.runs) {
            const QJsonObject s = p.settingsFor(r);
            QCOMPARE(s.value(QStringLiteral("tissue")).toString(), tissue);
            QCOMPARE(s.value(QStringLiteral("video")).toBool(), video);
            QVERIFY(r.factors.contains(QStringLiteral("site")));
            QCOMPARE(r.status, PlanRunStatus::Pending);
        }
        // No cell twice.
        const auto c = cells(p);
        QCOMPARE(std::set<QString>(c.begin(), c.end()).size(), c.size());
    }

    void frictionImagingIsFiveSitesByThreeFrequencies()
    {
        const Plan p = generatePlan(tmpl("friction-imaging"), PlanOrder::Listed, 1);
        QCOMPARE(p.runs.size(), std::size_t(15));
        for (int site = 1; site <= 5; ++site)
            for (double f : {0.2, 0.5, 0.8}) {
                const auto n = std::count_if(p.runs.begin(), p.runs.end(), [&](const PlannedRun& r) {
                    return r.factors.value(QStringLiteral("site")).toDouble() == site && r.factors.value(QStringLiteral("frequency_hz")).toDouble() == f;
                });
                QCOMPARE(n, 1);
            }
        // Listed: the first factor varies slowest.
        QCOMPARE(p.runs[0].factors.value(QStringLiteral("site")).toInt(), 1);
        QCOMPARE(p.runs[2].factors.value(QStringLiteral("site")).toInt(), 1);
        QCOMPARE(p.runs[3].factors.value(QStringLiteral("site")).toInt(), 2);
        QCOMPARE(p.runs[1].factors.value(QStringLiteral("frequency_hz")).toDouble(), 0.5);
        QCOMPARE(p.settingsFor(p.runs[0]).value(QStringLiteral("motion")).toString(), QStringLiteral("sine"));
        QCOMPARE(describeRun(p, p.runs[4]), QStringLiteral("friction site 2 0.5 Hz"));
    }

    void randomOrderIsAReproduciblePermutation()
    {
        const Plan listed = generatePlan(tmpl("friction"), PlanOrder::Listed, 1);
        const Plan a = generatePlan(tmpl("friction"), PlanOrder::Random, 42);
        const Plan b = generatePlan(tmpl("friction"), PlanOrder::Random, 42);
        const Plan c = generatePlan(tmpl("friction"), PlanOrder::Random, 43);
        QCOMPARE(cells(a), cells(listed));
        QStringList ka, kb, kc, kl;
        for (std::size_t i = 0; i < a.runs.size(); ++i) {
            ka << key(a.runs[i]);
            kb << key(b.runs[i]);
            kc << key(c.runs[i]);
            kl << key(listed.runs[i]);
            QCOMPARE(a.runs[i].number, int(i) + 1);
        }
        QCOMPARE(ka, kb);
        QVERIFY(ka != kc);
        QVERIFY(ka != kl);
        QCOMPARE(a.seed, quint64(42));
        // The seed is recorded and read back.
        const QString path = dir_.filePath(QStringLiteral("random.json"));
        writePlanFile(path, a);
        const Plan back = readPlanFile(path);
        QCOMPARE(back.seed, quint64(42));
        QCOMPARE(back.order, PlanOrder::Random);
        QVERIFY(back.sameDesign(a));
    }

    void blockedOrderKeepsEachSiteTogether()
    {
        const Plan p = generatePlan(tmpl("friction"), PlanOrder::Blocked, 5);
        QCOMPARE(p.runs.size(), std::size_t(21));
        bool shuffledWithin = false;
        for (int site = 1; site <= 7; ++site) {
            QList<double> freqs;
            for (int k = 0; k < 3; ++k) {
                const PlannedRun& r = p.runs[std::size_t((site - 1) * 3 + k)];
                QCOMPARE(r.factors.value(QStringLiteral("site")).toInt(), site);
                freqs << r.factors.value(QStringLiteral("frequency_hz")).toDouble();
            }
            if (freqs != QList<double>{0.2, 0.5, 0.8})
                shuffledWithin = true;
            std::sort(freqs.begin(), freqs.end());
            QCOMPARE(freqs, (QList<double>{0.2, 0.5, 0.8}));
            // One move per block: the instruction at each block's first run only.
            QVERIFY(p.runs[std::size_t((site - 1) * 3)].instruction.contains(QStringLiteral("site %1").arg(site)));
            QVERIFY(p.runs[std::size_t((site - 1) * 3 + 1)].instruction.isEmpty());
        }
        QVERIFY(shuffledWithin);

        PlanTemplate noSite = tmpl("friction");
        noSite.factors.erase(noSite.factors.begin());
        try {
            generatePlan(noSite, PlanOrder::Blocked, 1);
            QFAIL("blocked without a site factor was accepted");
        } catch (const PlanError& e) {
            QCOMPARE(e.field(), QStringLiteral("order"));
            QVERIFY(e.message().contains(QStringLiteral("site")));
        }
    }

    void instructionsWhenHandsAreNeeded()
    {
        PlanTemplate t = tmpl("friction-imaging");
        t.factors.push_back({QStringLiteral("tip"), {QJsonValue(QStringLiteral("diamond")), QJsonValue(QStringLiteral("beveled"))}, true});
        t.defaults.remove(QStringLiteral("tip"));
        const Plan p = generatePlan(t, PlanOrder::Listed, 1);
        QCOMPARE(p.runs.size(), std::size_t(30));
        QCOMPARE(p.runs[0].instruction, QStringLiteral("Mount Liver 7. Mount the 30 mm slab. Fit the diamond tip. Move the slab to site 1."));
        QCOMPARE(p.runs[1].instruction, QStringLiteral("Change to the beveled tip."));
        // 0.5 Hz, diamond: the tip changes back; the frequency needs no hands.
        QCOMPARE(p.runs[2].instruction, QStringLiteral("Change to the diamond tip."));
        // Next site, diamond again after beveled.
        QCOMPARE(p.runs[6].instruction, QStringLiteral("Change to the diamond tip. Move the slab to site 2."));
        const Plan stiff = generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1);
        QCOMPARE(stiff.runs[1].instruction, QStringLiteral("Move the specimen to site 2."));
    }

    void durationsMetadataAndRunFileNames()
    {
        Plan p = generatePlan(tmpl("friction-imaging"), PlanOrder::Listed, 1);
        QCOMPARE(expectedRunDuration_s(p.settingsFor(p.runs[0])), 35.0);  // 7 cycles at 0.2 Hz
        QCOMPARE(remainingPlanDuration_s(p), 5 * (7 / 0.2 + 7 / 0.5 + 7 / 0.8));
        beginAttempt(p, 0, QStringLiteral("run_004_sine.csv"), {}, QDateTime::currentDateTimeUtc());
        finishAttempt(p, 0, QStringLiteral("completed"), QDateTime::currentDateTimeUtc());
        QCOMPARE(remainingPlanDuration_s(p), 5 * (7 / 0.2 + 7 / 0.5 + 7 / 0.8) - 35.0);
        QCOMPARE(remainingPlanDuration_s(generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1)), 21 * 40.0 / 4.0);

        QCOMPARE(unusedRunPath(p, QStringLiteral("/s/run_003_sine.csv")), QStringLiteral("/s/run_005_sine.csv"));
        QCOMPARE(unusedRunPath(p, QStringLiteral("/s/run_009_sine.csv")), QStringLiteral("/s/run_009_sine.csv"));

        const Metadata m = planRunMetadata(p, p.runs[4], QStringLiteral("plan.json"));
        QCOMPARE(m.value(QStringLiteral("factor_site")).value_or(QString()), QStringLiteral("2"));
        QCOMPARE(m.value(QStringLiteral("factor_frequency_hz")).value_or(QString()), QStringLiteral("0.5"));
        QCOMPARE(m.value(QStringLiteral("plan_run")).value_or(QString()), QStringLiteral("5"));
        QCOMPARE(m.value(QStringLiteral("plan_runs")).value_or(QString()), QStringLiteral("15"));
        QCOMPARE(m.entries().front().first, QStringLiteral("factor_site"));  // in the plan's factor order
    }

    void roundTripKeepsEverything()
    {
        Plan p = generatePlan(tmpl("friction-imaging"), PlanOrder::Blocked, 9);
        p.runs[3].settings.insert(QStringLiteral("stop_at"), QStringLiteral("puncture:2"));
        p.runs[3].settings.insert(QStringLiteral("slow_after_puncture_mm_s"), 1.0);
        beginAttempt(p, 0, QStringLiteral("run_001_sine.csv"), QStringLiteral("run_001_sine.avi"), QDateTime(QDate(2026, 11, 22), QTime(10, 0), Qt::UTC));
        finishAttempt(p, 0, QStringLiteral("completed"), QDateTime(QDate(2026, 11, 22), QTime(10, 1), Qt::UTC));
        skipRun(p, 1, QStringLiteral("slab torn"));
        const QString path = dir_.filePath(QStringLiteral("plan.json"));
        writePlanFile(path, p);
        const Plan back = readPlanFile(path);
        QCOMPARE(planToJson(back), planToJson(p));
        QVERIFY(back.sameDesign(p));
        QCOMPARE(back.settingsFor(back.runs[3]).value(QStringLiteral("stop_at")).toString(), QStringLiteral("puncture:2"));
        QCOMPARE(back.settingsFor(back.runs[3]).value(QStringLiteral("slow_after_puncture_mm_s")).toDouble(), 1.0);
        QCOMPARE(back.runs[1].reason, QStringLiteral("slab torn"));
        // A reason longer than a line (it was written as {} and the plan could not be read again).
        const QString longReason = QStringLiteral("the slab tore along the whole of its left edge when the platform reversed, "
                                                  "and the needle left a track that the next insertion would follow");
        skipRun(p, 2, longReason);
        writePlanFile(path, p);
        QCOMPARE(readPlanFile(path).runs[2].reason, longReason);
        // A plan an earlier version broke that way is read, its reason said to be lost.
        QFile broken(path);
        QVERIFY(broken.open(QIODevice::ReadOnly));
        QByteArray brokenText = broken.readAll();
        broken.close();
        brokenText.replace(QJsonDocument(QJsonArray{longReason}).toJson(QJsonDocument::Compact).mid(1).chopped(1), "{}");
        QVERIFY(brokenText.contains("\"reason\": {}"));
        QVERIFY(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
        broken.write(brokenText);
        broken.close();
        QVERIFY(readPlanFile(path).runs[2].reason.contains(QStringLiteral("lost")));
        QCOMPARE(back.runs[0].currentAttempt()->videoFile, QStringLiteral("run_001_sine.avi"));
        // A person reads it: one run's factors on one line.
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY2(text.contains("\"factors\": {\"frequency_hz\": "), text.left(2000).constData());
        QVERIFY(text.contains("{\"name\": \"site\", \"levels\": [1, 2, 3, 4, 5]}"));

        Plan other = back;
        other.runs[5].factors.insert(QStringLiteral("site"), 4);
        QVERIFY(!other.sameDesign(p));
    }

    void aHandWrittenPlanIsAccepted()
    {
        // Minimal: no format, no numbers, no instructions: they are filled in.
        const QString path = dir_.filePath(QStringLiteral("hand.json"));
        writeJson(path, QJsonObject{{QStringLiteral("defaults"), QJsonObject{{QStringLiteral("protocol"), QStringLiteral("stiffness")},
                                                                               {QStringLiteral("tissue"), QStringLiteral("liver2")}}},
                                    {QStringLiteral("factors"), QJsonArray{QJsonObject{{QStringLiteral("name"), QStringLiteral("rotation_deg")},
                                                                                       {QStringLiteral("levels"), QJsonArray{0, 90}},
                                                                                       {QStringLiteral("operator"), true}}}},
                                    {QStringLiteral("runs"), QJsonArray{QJsonObject{{QStringLiteral("factors"), QJsonObject{{QStringLiteral("rotation_deg"), 0}}}},
                                                                        QJsonObject{{QStringLiteral("factors"), QJsonObject{{QStringLiteral("rotation_deg"), 90}}}}}}});
        const Plan p = readPlanFile(path);
        QCOMPARE(p.runs.size(), std::size_t(2));
        QCOMPARE(p.runs[1].number, 2);
        QCOMPARE(p.settingsFor(p.runs[0]).value(QStringLiteral("motion")).toString(), QStringLiteral("linear"));
        QVERIFY(p.runs[0].instruction.contains(QStringLiteral("Mount Liver 2.")));
        QCOMPARE(p.runs[1].instruction, QStringLiteral("Set rotation_deg to 90."));
    }

    void errorsNameTheFileAndField_data()
    {
        QTest::addColumn<QString>("pointer");  // what to break, see below
        QTest::addColumn<QString>("field");
        QTest::newRow("not a number") << "runs.2.factors.frequency_hz=fast" << "runs[2].factors.frequency_hz";
        QTest::newRow("unknown setting") << "defaults.velocty_mm_s=4" << "defaults.velocty_mm_s";
        QTest::newRow("bad status") << "runs.0.status=finished" << "runs[0].status";
        QTest::newRow("bad stop_at") << "runs.1.settings.stop_at=punture" << "runs[1].settings.stop_at";
        QTest::newRow("bad order") << "order=sorted" << "order";
        QTest::newRow("motion against protocol") << "runs.4.settings.motion=linear" << "runs[4]";
        QTest::newRow("negative level") << "factors.1.levels.0=-0.2" << "factors[1].levels[0]";
        QTest::newRow("done without attempt") << "runs.3.status=done" << "runs[3].status";
        QTest::newRow("wrong format") << "format=something-else" << "format";
    }
    void errorsNameTheFileAndField()
    {
        QFETCH(QString, pointer);
        QFETCH(QString, field);
        QJsonObject o = planToJson(generatePlan(tmpl("friction-imaging"), PlanOrder::Listed, 1));
        const QStringList path = pointer.section(QLatin1Char('='), 0, 0).split(QLatin1Char('.'));
        const QString text = pointer.section(QLatin1Char('='), 1);
        bool isNumber = false;
        const double number = text.toDouble(&isNumber);
        const QJsonValue value = isNumber ? QJsonValue(number) : QJsonValue(text);
        // Set o[path...] = value through nested objects and arrays.
        std::function<QJsonValue(QJsonValue, int)> set = [&](QJsonValue node, int depth) -> QJsonValue {
            if (depth == path.size())
                return value;
            bool idx = false;
            const int i = path[depth].toInt(&idx);
            if (idx) {
                QJsonArray a = node.toArray();
                a[i] = set(a[i], depth + 1);
                return a;
            }
            QJsonObject obj = node.toObject();
            obj[path[depth]] = set(obj.value(path[depth]), depth + 1);
            return obj;
        };
        o = set(o, 0).toObject();
        const QString file = dir_.filePath(QStringLiteral("broken.json"));
        writeJson(file, o);
        try {
            readPlanFile(file);
            QFAIL("accepted");
        } catch (const PlanError& e) {
            QCOMPARE(e.file(), file);
            QCOMPARE(e.field(), field);
            QVERIFY2(e.message().startsWith(file + QStringLiteral(": ") + field + QStringLiteral(": ")), qPrintable(e.message()));
        }
    }

    void malformedJsonNamesTheLine()
    {
        const QString file = dir_.filePath(QStringLiteral("malformed.json"));
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\n  \"name\": \"x\",\n  \"runs\": [\n    {\"number\": 1,,}\n  ]\n}\n");
        f.close();
        try {
            readPlanFile(file);
            QFAIL("accepted");
        } catch (const PlanError& e) {
            QCOMPARE(e.field(), QStringLiteral("line 4"));
        }
        try {
            readPlanFile(dir_.filePath(QStringLiteral("absent.json")));
            QFAIL("accepted");
        } catch (const PlanError& e) {
            QVERIFY(e.message().contains(QStringLiteral("absent.json")));
        }
        // An empty file, or a run file given for a plan: said so, not only Qt's "illegal value".
        const QString empty = dir_.filePath(QStringLiteral("empty.json")), csv = dir_.filePath(QStringLiteral("run.csv"));
        QFile(empty).open(QIODevice::WriteOnly);
        {
            QFile r(csv);
            QVERIFY(r.open(QIODevice::WriteOnly));
            r.write("time_s,position_mm,force_N\n0,0,0\n");
        }
        for (const auto& [path, says] : {std::pair{empty, QStringLiteral("empty")}, {csv, QStringLiteral("not JSON")}}) {
            try {
                readPlanFile(path);
                QFAIL("accepted");
            } catch (const PlanError& e) {
                QVERIFY2(e.message().contains(path) && e.message().contains(says), qPrintable(e.message()));
            }
        }
    }

    void aCrashedPlanResumesAtTheFirstRunNotCompleted()
    {
        const QString path = dir_.filePath(QStringLiteral("resume.json"));
        Plan p = generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1);
        const QDateTime t0 = QDateTime::currentDateTimeUtc();
        for (int i = 0; i < 3; ++i) {
            beginAttempt(p, i, QStringLiteral("run_%1_linear.csv").arg(i + 1, 3, 10, QLatin1Char('0')), {}, t0);
            writePlanFile(path, p);
            finishAttempt(p, i, QStringLiteral("completed"), t0);
            writePlanFile(path, p);
        }
        beginAttempt(p, 3, QStringLiteral("run_004_linear.csv"), {}, t0);
        writePlanFile(path, p);  // ... and the process dies here.

        Plan q = readPlanFile(path);
        QCOMPARE(q.runs[3].status, PlanRunStatus::Running);
        QCOMPARE(recoverInterruptedRuns(q), std::vector<int>{4});
        QCOMPARE(q.firstIncomplete(), 3);
        QCOMPARE(q.runs[3].attempts.back().result, QStringLiteral("interrupted"));
        QVERIFY(!q.runs[3].currentAttempt());

        beginAttempt(q, 3, QStringLiteral("run_005_linear.csv"), {}, t0);
        finishAttempt(q, 3, QStringLiteral("completed"), t0);
        QCOMPARE(q.runs[3].status, PlanRunStatus::Redone);
        QCOMPARE(q.runs[3].currentAttempt()->runFile, QStringLiteral("run_005_linear.csv"));
        QCOMPARE(q.firstIncomplete(), 4);

        // A fault leaves it pending; a skip moves past it; a redo brings an earlier one back.
        beginAttempt(q, 4, QStringLiteral("run_006_linear.csv"), {}, t0);
        finishAttempt(q, 4, QStringLiteral("fault"), t0);
        QCOMPARE(q.runs[4].status, PlanRunStatus::Pending);
        QCOMPARE(q.firstIncomplete(), 4);
        skipRun(q, 4, QStringLiteral("needle bent"));
        QCOMPARE(q.firstIncomplete(), 5);
        redoRun(q, 1, QStringLiteral("bias forgotten"));
        QCOMPARE(q.firstIncomplete(), 1);
        QCOMPARE(q.runs[1].attempts.back().discarded, QStringLiteral("bias forgotten"));
        QCOMPARE(q.countWith(PlanRunStatus::Skipped), 1);
        QVERIFY(isCompletingEndReason(QStringLiteral("puncture")));
        QVERIFY(isCompletingEndReason(QStringLiteral("force_limit")));
        QVERIFY(!isCompletingEndReason(QStringLiteral("stopped")));
    }

    // The window and `plan run` settle a plan left "running" the same way (core/plan_session).
    void resumeKeepsARunThatEndedBeforeTheCrash()
    {
        QTemporaryDir session;
        Plan p = generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1);
        const QDateTime t0 = QDateTime::currentDateTimeUtc();
        auto runFile = [&](int index, const QString& name, const QString& endReason) {
            Run r;
            for (int i = 0; i < 10; ++i) {
                r.time_s.push_back(i * 0.01);
                r.position_mm.push_back(i * 0.1);
                r.force_N.push_back(0.0);
            }
            r.metadata = planRunMetadata(p, p.runs[std::size_t(index)], planFileName());
            if (!endReason.isEmpty())
                r.footer.set(QStringLiteral("end_reason"), endReason);
            writeRunFile(QDir(session.path()).filePath(name), r);
        };
        // Run 1 ended and was written, then the program died before plan.json said so.
        beginAttempt(p, 0, QStringLiteral("run_001_linear.csv"), {}, t0);
        runFile(0, QStringLiteral("run_001_linear.csv"), QStringLiteral("completed"));
        // Run 2 (in another plan.json state) died mid-run: its file has no end reason.
        beginAttempt(p, 1, QStringLiteral("run_002_linear.csv"), {}, t0);
        runFile(1, QStringLiteral("run_002_linear.csv"), {});
        // Run 3 died before its file existed.
        beginAttempt(p, 2, QStringLiteral("run_003_linear.csv"), {}, t0);
        const PlanResumption r = resumePlan(p, session.path());
        QCOMPARE(r.endedBefore.size(), std::size_t(1));
        QCOMPARE(r.endedBefore[0].first, 1);
        QCOMPARE(r.endedBefore[0].second, QStringLiteral("run_001_linear.csv"));
        QCOMPARE(r.interrupted, (std::vector<int>{2, 3}));
        QCOMPARE(p.runs[0].status, PlanRunStatus::Done);
        QCOMPARE(p.runs[1].attempts.back().result, QStringLiteral("interrupted"));
        QCOMPARE(p.firstIncomplete(), 1);
        QCOMPARE(planFilePath(session.path()), QDir(session.path()).filePath(QStringLiteral("plan.json")));
    }

    void timeLeftFollowsThePlansPace()
    {
        Plan p = generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1);  // 21 runs of 10 s motion
        QCOMPARE(estimatedPlanTimeLeft_s(p), 21 * 10.0);  // no pace yet: the motion alone
        const QDateTime t0 = QDateTime::currentDateTimeUtc();
        // Three runs, one every 60 s (the operator's steps included).
        for (int i = 0; i < 3; ++i) {
            beginAttempt(p, i, QStringLiteral("run_%1_linear.csv").arg(i + 1), {}, t0.addSecs(60 * i));
            finishAttempt(p, i, QStringLiteral("completed"), t0.addSecs(60 * i + 10));
        }
        QCOMPARE(estimatedPlanTimeLeft_s(p), 18 * 60.0);
        // A break of two hours is not the pace.
        beginAttempt(p, 3, QStringLiteral("run_4_linear.csv"), {}, t0.addSecs(120 + 7200));
        finishAttempt(p, 3, QStringLiteral("completed"), t0.addSecs(120 + 7210));
        QCOMPARE(estimatedPlanTimeLeft_s(p), 17 * 60.0);
        // A crash and its restart (20 min) is one long gap, not the pace: the mean made it 345 s.
        beginAttempt(p, 4, QStringLiteral("run_5_linear.csv"), {}, t0.addSecs(120 + 7200 + 1200));
        finishAttempt(p, 4, QStringLiteral("completed"), t0.addSecs(120 + 7200 + 1210));
        beginAttempt(p, 5, QStringLiteral("run_6_linear.csv"), {}, t0.addSecs(120 + 7200 + 1260));
        finishAttempt(p, 5, QStringLiteral("completed"), t0.addSecs(120 + 7200 + 1270));
        QCOMPARE(estimatedPlanTimeLeft_s(p), 15 * 60.0);
        // Never below the motion still to come.
        Plan fast = generatePlan(tmpl("overall-stiffness"), PlanOrder::Listed, 1);
        beginAttempt(fast, 0, QStringLiteral("a.csv"), {}, t0);
        beginAttempt(fast, 1, QStringLiteral("b.csv"), {}, t0.addSecs(1));
        QCOMPARE(estimatedPlanTimeLeft_s(fast), remainingPlanDuration_s(fast));
    }
};

QTEST_GUILESS_MAIN(TestPlan)
#include "test_plan.moc"
