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
private slots:
    void theLastTimeIsWrittenWhole()
    {
        // Under the force plot the axis ends where the plot's does, before the widget's edge: the
        // last number (10 of 0-10 s) was clipped at the axis' end to a sliver of its first digit.
        nb::LabelModel model;
        model.setDefinitions(nb::protocolLabelSet(QStringLiteral("friction")));
        QUndoStack undo;
        nb::Timeline timeline(&model, &undo);
        timeline.resize(800, timeline.sizeHint().height());
        timeline.setRange(0.0, 10.0);
        // Ink columns beside a tick, in the numbers' band at the bottom.
        auto inkColumns = [&timeline](double t, bool right) {
            const QImage image = timeline.grab().toImage();
            const int x = timeline.xOf(t);
            int columns = 0;
            for (int c = right ? x + 1 : x - 30; c < (right ? x + 30 : x); ++c) {
                bool ink = false;
                for (int y = image.height() - 14; y < image.height() && c >= 0 && c < image.width(); ++y)
                    ink = ink || qGray(image.pixel(c, y)) < 128;
                columns += ink;
            }
            return columns;
        };
        timeline.setAxisPixels(80, 800 - 80 - 50);  // room after the axis, as under the plot
        const int eight = inkColumns(8.0, true), ten = inkColumns(10.0, true);
        QVERIFY2(eight > 0 && ten > eight, qPrintable(QStringLiteral("ink columns: '8' %1, '10' %2").arg(eight).arg(ten)));
        timeline.setAxisPixels(80, 800 - 80);  // none: written left of its tick, within the widget
        QVERIFY2(inkColumns(10.0, false) > eight, qPrintable(QStringLiteral("ink columns left of the end: %1").arg(inkColumns(10.0, false))));
    }

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
