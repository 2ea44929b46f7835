// The timeline's label names as an operator reads them: a run's events close together, and
// phases narrower than their names, each named where there is room and never one over another.

#include "widgets/label_model.h"
#include "widgets/timeline.h"

#include <QUndoStack>
#include <QtTest>

namespace {

nb::Label point(const char* name, double t) { return {QStringLiteral("events"), QLatin1String(name), t, t, {}}; }
nb::Label phase(const char* name, double start_s, double end_s) { return {QStringLiteral("insertion"), QLatin1String(name), start_s, end_s, {}}; }

}  // namespace

class TestTimeline : public QObject {
    Q_OBJECT
private slots:
    void namesNeverOverlap()
    {
        nb::LabelModel model;
        model.setDefinitions(nb::protocolLabelSet(QStringLiteral("friction")) + nb::protocolLabelSet(QStringLiteral("stiffness")));
        nb::Labels labels{
            // A contact and a puncture under a millisecond apart share one pixel at this zoom.
            point("puncture", 12.0004), point("contact", 12.0),
            // A phase of 50 ms is a few pixels wide; the phases beside it are wide.
            phase("a", 0.0, 10.0), phase("b1", 10.0, 10.05), phase("b2", 10.05, 20.0),
        };
        for (int i = 0; i < 12; ++i)  // a dozen internal punctures within a second
            labels.push_back(point("internal puncture", 30.0 + 0.08 * i));
        labels.push_back(point("relaxation", 45.0));
        model.setLabels(labels);
        QUndoStack undo;
        nb::Timeline timeline(&model, &undo);
        timeline.resize(800, timeline.sizeHint().height());
        timeline.setRange(0.0, 60.0);

        const std::vector<nb::Timeline::Name> names = timeline.labelNames();
        QStringList said;
        for (const auto& n : names)
            said << n.text;
        for (std::size_t i = 0; i < names.size(); ++i)
            for (std::size_t j = i + 1; j < names.size(); ++j)
                QVERIFY2(!names[i].rect.intersects(names[j].rect),
                         qPrintable(QStringLiteral("'%1' and '%2' are written over one another").arg(names[i].text, names[j].text)));
        // Named where there is room: the wide phases, the relaxation alone, one of the two
        // events on one pixel, the last internal puncture (room up to the relaxation).
        QVERIFY2(said.contains(QStringLiteral("a")) && said.contains(QStringLiteral("b2")) && said.contains(QStringLiteral("relaxation")),
                 qPrintable(said.join(QStringLiteral(", "))));
        QVERIFY2(!said.contains(QStringLiteral("b1")), qPrintable(said.join(QStringLiteral(", "))));
        QCOMPARE(said.count(QStringLiteral("puncture")) + said.count(QStringLiteral("contact")), 1);
        QVERIFY2(said.filter(QStringLiteral("internal")).size() >= 1, qPrintable(said.join(QStringLiteral(", "))));

        // Zoomed in on the two events, each has room for its own name.
        timeline.setRange(11.999, 12.002);
        said.clear();
        for (const auto& n : timeline.labelNames())
            said << n.text;
        QVERIFY2(said.contains(QStringLiteral("contact")) && said.contains(QStringLiteral("puncture")), qPrintable(said.join(QStringLiteral(", "))));
    }
};

QTEST_MAIN(TestTimeline)
#include "test_timeline.moc"
