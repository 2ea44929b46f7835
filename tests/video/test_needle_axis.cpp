// The needle's line, found or drawn, points from the shaft to the tip whichever side of the
// picture the needle enters from, and along it the tip is followed in every frame (issue 13).
// A line found in the picture used to point left to right or downwards: a needle entering from
// the right or from below then had its shaft ahead of the tip, the tip was lost in most frames
// and the sync went by what was left (probe seed 187716, case 10: 116 frames off).
#include "support/case_share.h"
#include "needle_video.h"

#include <QtTest>

#include <array>
#include <cmath>

namespace {

using namespace nb::needle_video;

QPointF unit(const nb::video::NeedleAxis& axis)
{
    return (axis.p2() - axis.p1()) / axis.length();
}

double dot(const QPointF& a, const QPointF& b)
{
    return a.x() * b.x() + a.y() * b.y();
}

struct TipErrors {
    int seen = 0, close = 0;  // frames with a tip, and of them within 2 px of the truth
    double worst = 0.0;
};

// How far `track`'s tip is from the truth in each frame. Positions are along the track's own
// line from its first point; the truth from the picture's centre.
TipErrors tipErrors(const nb::video::NeedleTrack& track)
{
    const QPointF centre(kWidth / 2.0, kHeight / 2.0), d = unit(track.axis);
    const double centreAt = dot(centre - track.axis.p1(), d);
    TipErrors e;
    for (int k = 0; k < kFrames && k < int(track.displacement_px.size()); ++k) {
        const double error = std::abs(track.displacement_px[std::size_t(k)] - centreAt - tipAt(k));
        if (!std::isfinite(error))
            continue;
        ++e.seen;
        e.close += error < 2.0;
        e.worst = std::max(e.worst, error);
    }
    return e;
}

}  // namespace

class TestNeedleAxis : public QObject {
    Q_OBJECT

private slots:
    void pointsFromShaftToTip_data()
    {
        QTest::addColumn<double>("towardsTip_deg");
        QTest::addColumn<bool>("clockOnShaft");
        QTest::addColumn<bool>("tissueCarried");
        for (double angle : {0.0, 70.0, 135.0, 180.0, 200.0, 270.0, 320.0})
            QTest::newRow(qPrintable(QStringLiteral("tip towards %1 deg").arg(angle))) << angle << false << false;
        // A clock laid along the line (the needle at 20 deg) hides the shaft so that its line is
        // found 4.5 px off; across it, as here, it does not.
        for (double angle : {160.0, 250.0})
            QTest::newRow(qPrintable(QStringLiteral("tip towards %1 deg, clock on the shaft").arg(angle))) << angle << true << false;
        // Tissue that moves with the needle is not what the strip showed ahead of the tip in
        // other frames: there the tip is left as the edge detector found it. That detector is
        // itself pulled by grain that moves (within 2 px in 77 and 66 of 90 frames); measured
        // against sides that do not hold, it was worse (58 of 90).
        for (double angle : {30.0, 225.0})
            QTest::newRow(qPrintable(QStringLiteral("tip towards %1 deg, tissue carried along").arg(angle))) << angle << false << true;
    }

    void pointsFromShaftToTip()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(double, towardsTip_deg);
        QFETCH(bool, clockOnShaft);
        QFETCH(bool, tissueCarried);
        const NeedleVideo v{towardsTip_deg, clockOnShaft, tissueCarried};
        QTemporaryDir dir;
        QString problem;
        const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
        QVERIFY2(index, qPrintable(problem));
        nb::video::FrameReader reader(*index);
        QCOMPARE(reader.index().size(), kFrames);
        const QPointF u = direction(v), centre(kWidth / 2.0, kHeight / 2.0);

        // Found in the picture (among the lines that look like a needle, which one is the
        // needle the recording decides): along the needle, from its shaft to its tip.
        const std::vector<nb::video::NeedleAxis> lines = nb::video::needleAxisCandidates(reader, {}, 16);
        std::vector<nb::video::NeedleAxis> onNeedle;
        for (const nb::video::NeedleAxis& a : lines) {
            const QPointF d = unit(a), n(-d.y(), d.x());
            if (std::abs(dot(d, u)) > 0.998 && std::abs(dot(centre - a.p1(), n)) < 2.0)
                onNeedle.push_back(a);
        }
        QVERIFY2(!onNeedle.empty(), qPrintable(QStringLiteral("none of %1 lines found is the needle").arg(lines.size())));

        // Drawn either way by the operator: turned to point the same way.
        const nb::video::NeedleAxis drawn(centre - u * 100.0, centre + u * 100.0), backwards(drawn.p2(), drawn.p1());
        QVERIFY(dot(unit(nb::video::trackNeedle(reader, drawn).axis), u) > 0.999);
        QVERIFY2(dot(unit(nb::video::trackNeedle(reader, backwards).axis), u) > 0.999, "a line drawn from the tip to the shaft stays so");

        // Along it the tip is seen in nearly every frame, where it is. A textured background
        // pulls an edge detector's peak to the grain's edges nearby (up to 6 px here, by
        // position); the tip is measured against what the strip shows on either side of it.
        // Several lines found may lie on the needle, a degree or so apart, and one of them may
        // lose the tip where the clock or the moving tissue crosses it (the clock at 160°: 34 of
        // 84 frames within 2 px on the line 0.1° off, all on the one 0.5° off); the sync tracks
        // them all and the recording picks the one that follows it, as the truth does here. That
        // one is measured from the shaft to the tip (a line turned the other way, its tip read
        // from the other end, would be far from the truth in every frame).
        std::vector<nb::video::NeedleTrack> tracks = nb::video::trackNeedles(reader, onNeedle);
        const auto best = std::max_element(tracks.begin(), tracks.end(), [](const auto& a, const auto& b) {
            return tipErrors(a).close - a.masked < tipErrors(b).close - b.masked;
        });
        for (const nb::video::NeedleTrack& t : tracks) {
            const TipErrors e = tipErrors(t);
            qInfo("line %.2f° off the needle: %d frames without a tip; of the rest %d within 2 px, the worst %.2f px off%s",
                  std::acos(std::min(1.0, dot(unit(t.axis), u))) * 180.0 / M_PI, t.masked, e.close, e.worst, &t == &*best ? " (kept)" : "");
        }
        const nb::video::NeedleTrack& track = *best;
        QVERIFY2(dot(unit(track.axis), u) > 0, "the line kept points from the tip to the shaft");
        QCOMPARE(int(track.displacement_px.size()), kFrames);
        const TipErrors e = tipErrors(track);
        const int seen = e.seen, close = e.close;
        QVERIFY2(track.masked <= kFrames / 10, qPrintable(QStringLiteral("%1 frames without a tip").arg(track.masked)));
        QVERIFY2(close >= (tissueCarried ? 2.0 / 3.0 : 0.95) * seen,
                 qPrintable(QStringLiteral("the tip is within 2 px in %1 of %2 frames").arg(close).arg(seen)));
    }

    // A faint needle (16 grey levels) on grain as strong as it and as fine (25, in 4 px
    // squares), under noise of 30 in each frame, in a 1024x768 picture: the ridge is the
    // grain's everywhere, and on the copy a third as wide that the ridge's lines are sought on,
    // no line of it is the needle's; in single frames the tip barely stands out. Along its
    // length the shaft stands out of the frames' mean (probe seed 246810 case 10: none of 14
    // lines found was the needle and the sync was 256 frames off; found, 0.5 frames). Here
    // the needle's line was found at 2 of these 8 angles before, and must be at 6.
    void findsAFaintShaftOnGrainAsFine()
    {
        const std::array angles{10.0, 35.0, 80.0, 122.0, 160.0, 205.0, 250.0, 300.0};
        int found = 0, ran = 0;
        QStringList missed;
        for (std::size_t i = 0; i < angles.size(); ++i) {
            if (!nb::test::caseInShare(i))
                continue;
            ++ran;
            const double angle = angles[i];
            NeedleVideo v{angle};
            v.contrast = 16.0;
            v.grain = 25.0;
            v.noise = 30.0;
            v.width = 1024;
            v.height = 768;
            QTemporaryDir dir;
            QString problem;
            const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
            QVERIFY2(index, qPrintable(problem));
            nb::video::FrameReader reader(*index);
            const QPointF u = direction(v), centre(v.width / 2.0, v.height / 2.0);
            const std::vector<nb::video::NeedleAxis> lines = nb::video::needleAxisCandidates(reader, {}, 16);
            const bool needle = std::any_of(lines.begin(), lines.end(), [&](const nb::video::NeedleAxis& a) {
                const QPointF d = unit(a), n(-d.y(), d.x());
                return std::abs(dot(d, u)) > 0.9995 && std::abs(dot(centre - a.p1(), n)) < 2.0;
            });
            found += needle;
            if (!needle)
                missed << QString::number(angle);
        }
        qInfo("the needle's line found at %d of %d angles; not at %s deg", found, ran, qPrintable(missed.join(QStringLiteral(", "))));
        // A share of the angles (under the sanitizers) says nothing of the whole's count.
        if (ran == int(angles.size()))
            QVERIFY2(found >= 6, qPrintable(QStringLiteral("the needle's line found at only %1 of 8 angles").arg(found)));
    }

    // The edge response needs 8 px beyond a sample: a tip closer than that to the picture's
    // edge has its edge cut off, and the response peaks on the last samples it reaches, short of
    // the tip. There no place is read (probe seed 187716 case 13: a stroke ending 6 px from the
    // picture's edge read 3.5 px short through its final rest, and the sync was 2.1 frames off;
    // here the tip read up to 6.3 px short, stuck 9.3 px from the edge).
    void readsNoTipCutOffByThePicturesEdge()
    {
        NeedleVideo v{0.0};
        v.travelCentre = kWidth / 2.0 - 50.0 - 4.0;  // the tip comes to 4 px from the right edge
        v.contrast = 86.0;
        v.noise = 18.0;
        QString problem;
        const std::optional<nb::video::NeedleTrack> found = trackedAcrossTheMiddle(v, &problem);
        QVERIFY2(found, qPrintable(problem));
        const nb::video::NeedleTrack& track = *found;
        QCOMPARE(int(track.displacement_px.size()), kFrames);
        QVERIFY(unit(track.axis).x() > 0.999);
        const double centreAt = kWidth / 2.0 - track.axis.x1();
        int nearEdge = 0, read = 0, wrongNearEdge = 0, close = 0;
        for (int k = 0; k < kFrames; ++k) {
            const double truth = kWidth / 2.0 + v.travelCentre + tipAt(k);
            const double at = track.displacement_px[std::size_t(k)] - centreAt + kWidth / 2.0;
            const bool near = truth > kWidth - 1.0 - 10.0;
            nearEdge += near;
            if (!std::isfinite(at))
                continue;
            ++read;
            close += std::abs(at - truth) <= 2.0;
            wrongNearEdge += near && std::abs(at - truth) > 2.0;
        }
        qInfo("the tip within 10 px of the edge in %d frames, read more than 2 px off in %d; %d of %d frames read within 2 px",
              nearEdge, wrongNearEdge, close, read);
        QVERIFY2(nearEdge >= 20, "the tip does not come close to the edge");
        QCOMPARE(wrongNearEdge, 0);
        QVERIFY2(read >= kFrames - nearEdge - 5, qPrintable(QStringLiteral("%1 frames without a tip").arg(kFrames - read)));
        QVERIFY2(close >= 0.9 * read, qPrintable(QStringLiteral("the tip within 2 px in %1 of %2 frames").arg(close).arg(read)));
    }

    // A tip that runs out of the picture: from 110 px inside the right edge to 30 px beyond it
    // and back, one and a half times. While it is out the shaft crosses the whole picture and
    // nothing along the line says where the tip is: such frames are not read (or read at the
    // edge), and the line still points from the shaft to the tip. Along the lines found on the
    // needle (which line is the needle, the recording decides) and one drawn backwards. With a
    // clock burnt in on the shaft, the tracker read the clock's digits where the tip was out
    // (19 of 38 frames) and, misled by them, lost the tip inside the picture (7 of 44 frames
    // within 2 px): the frames where the tip was beyond the edge had taught it the shaft there
    // as the strip's background.
    void leavesNoTipReadWhereItIsOutOfThePicture_data()
    {
        QTest::addColumn<bool>("clock");
        QTest::newRow("plain") << false;
        QTest::newRow("clock on the shaft") << true;
    }

    void leavesNoTipReadWhereItIsOutOfThePicture()
    {
        QFETCH(bool, clock);
        NeedleVideo v{0.0, clock, false};
        v.tip = [](int frame) { return 70.0 * std::sin(2.0 * kPi * frame / 60.0); };
        v.travelCentre = kWidth / 2.0 - 110.0 + 70.0;  // from 110 px inside the edge to 30 px beyond
        v.contrast = 60.0;
        v.noise = 8.0;
        QTemporaryDir dir;
        QString problem;
        const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
        QVERIFY2(index, qPrintable(problem));
        nb::video::FrameReader reader(*index);
        const QPointF centre(kWidth / 2.0, kHeight / 2.0);
        std::vector<std::pair<QString, nb::video::NeedleAxis>> lines;
        for (const nb::video::NeedleAxis& a : nb::video::needleAxisCandidates(reader, {}, 16)) {
            const QPointF d = unit(a), n(-d.y(), d.x());
            if (std::abs(d.x()) > 0.998 && std::abs(dot(centre - a.p1(), n)) < 2.0)
                lines.emplace_back(QStringLiteral("found"), a);
        }
        QVERIFY2(!lines.empty(), "no line found on the needle");
        lines.emplace_back(QStringLiteral("drawn backwards"), nb::video::NeedleAxis(centre + QPointF(100, 0), centre - QPointF(100, 0)));
        for (const auto& [how, line] : lines) {
            const bool found = how == QLatin1String("found");
            const nb::video::NeedleTrack track = nb::video::trackNeedle(reader, line);
            const QPointF d = unit(track.axis);
            const double centreAt = dot(centre - track.axis.p1(), d);
            int out = 0, outRead = 0, in = 0, inClose = 0;
            QStringList wrong;
            for (int k = 0; k < kFrames && k < int(track.displacement_px.size()); ++k) {
                const double truth = v.travelCentre + v.tip(k);  // from the centre, along +x
                const double at = (track.displacement_px[std::size_t(k)] - centreAt) * (d.x() > 0 ? 1.0 : -1.0);
                if (truth > kWidth / 2.0 - 1.0) {
                    ++out;
                    // Out of the picture: unread, or read at the edge.
                    if (std::isfinite(at) && at < kWidth / 2.0 - 4.0) {
                        ++outRead;
                        wrong << QStringLiteral("%1: %2 (out at %3)").arg(k).arg(at, 0, 'f', 1).arg(truth, 0, 'f', 1);
                    }
                } else if (truth < kWidth / 2.0 - 12.0) {
                    ++in;
                    inClose += std::isfinite(at) && std::abs(at - truth) <= 2.0;
                }
            }
            qInfo("%s: points %s; the tip out of the picture in %d frames, read inside it in %d; inside, %d of %d within 2 px. %s",
                  found ? "found" : "drawn backwards", d.x() > 0.999 ? "right" : "WRONG", out, outRead, inClose, in, qPrintable(wrong.join(QStringLiteral(", "))));
            QVERIFY2(d.x() > 0.999, found ? "the line found points from the tip to the shaft" : "the line drawn backwards is not turned");
            QVERIFY2(out >= 20, "the tip does not leave the picture");
            QCOMPARE(outRead, 0);
            QVERIFY2(inClose >= 0.9 * in, qPrintable(QStringLiteral("inside, the tip within 2 px in %1 of %2 frames").arg(inClose).arg(in)));
        }
    }

    // Digits that change on the needle's line every frame (a clock with milliseconds across the
    // shaft) differ from their mean in both signs by turns, and vote for either way the line
    // may point as much as the tip votes for one (probe seed 531911, case 9: 184 against 175,
    // the line left pointing from the tip, the tip lost and the sync 217 frames off). Then the
    // end of the line that shows the shaft in every frame is where the needle comes in.
    void turnsALineTheClockLeavesUndecided_data()
    {
        QTest::addColumn<double>("towardsTip_deg");
        QTest::addColumn<double>("clockScale");
        // A needle 80 grey levels bright under noise of 30, the clock in a large font laid
        // nearly along the line: the vote is 1.5:1 (at 20 deg, both sizes), where 2:1 decides.
        QTest::newRow("tip towards 20 deg, clock 1.6") << 20.0 << 1.6;
        QTest::newRow("tip towards 20 deg, clock 2.0") << 20.0 << 2.0;
        // Across the line the vote still decides.
        QTest::newRow("tip towards 160 deg, clock 1.6") << 160.0 << 1.6;
        QTest::newRow("tip towards 250 deg, clock 2.0") << 250.0 << 2.0;
    }

    void turnsALineTheClockLeavesUndecided()
    {
        NB_SKIP_OUTSIDE_CASE_SHARE();
        QFETCH(double, towardsTip_deg);
        QFETCH(double, clockScale);
        NeedleVideo v{towardsTip_deg, true, false};
        v.clockScale = clockScale;
        v.contrast = 80.0;
        v.noise = 30.0;
        QTemporaryDir dir;
        QString problem;
        const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
        QVERIFY2(index, qPrintable(problem));
        nb::video::FrameReader reader(*index);
        const QPointF u = direction(v), centre(kWidth / 2.0, kHeight / 2.0);
        const nb::video::NeedleAxis backwards(centre + u * 100.0, centre - u * 100.0);
        const nb::video::NeedleTrack track = nb::video::trackNeedle(reader, backwards);
        QVERIFY2(dot(unit(track.axis), u) > 0.999, "a line drawn from the tip to the shaft stays so");
    }

    // A line drawn by hand is a degree or two and a few pixels off the shaft; so is one found
    // from a short path of the tip. Far from where it was drawn it misses the shaft, and the
    // tip's course no longer fits the recording (probe seed 531911, case 6: a line 1.7° off,
    // the sync 17 s off at confidence 0). The tracker moves it onto the shaft its frames show.
    void settlesALineDrawnOffTheShaft_data()
    {
        QTest::addColumn<double>("towardsTip_deg");
        QTest::addColumn<double>("turn_deg");
        QTest::addColumn<double>("shift_px");
        QTest::newRow("tip towards 0 deg, drawn 2 deg and 3 px off") << 0.0 << 2.0 << 3.0;
        QTest::newRow("tip towards 135 deg, drawn -2.5 deg and -2 px off") << 135.0 << -2.5 << -2.0;
        QTest::newRow("tip towards 200 deg, drawn -1.5 deg and 3.5 px off") << 200.0 << -1.5 << 3.5;
        // Where a clock hides most of the shaft, too little of it shows to move the line by
        // (the clock rows above: 160 and 250 deg); the probe's clock lies across a longer shaft
        // (case 6 of seed 531911).
        QTest::newRow("tip towards 320 deg, drawn on the shaft") << 320.0 << 0.0 << 0.0;
    }

    void settlesALineDrawnOffTheShaft()
    {
        QFETCH(double, towardsTip_deg);
        QFETCH(double, turn_deg);
        QFETCH(double, shift_px);
        const NeedleVideo v{towardsTip_deg, false, false};
        QTemporaryDir dir;
        QString problem;
        const std::optional<nb::video::FrameIndex> index = writtenAndIndexed(dir, v, &problem);
        QVERIFY2(index, qPrintable(problem));
        nb::video::FrameReader reader(*index);
        const QPointF u = direction(v), centre(kWidth / 2.0, kHeight / 2.0);

        // Drawn over the tip's travel, 200 px long, turned and shifted off the needle.
        const double a = (towardsTip_deg + turn_deg) * kPi / 180.0;
        const QPointF w(std::cos(a), std::sin(a)), middle = centre + QPointF(-u.y(), u.x()) * shift_px;
        const nb::video::NeedleTrack track = nb::video::trackNeedle(reader, nb::video::NeedleAxis(middle - w * 100.0, middle + w * 100.0));
        const QPointF d = unit(track.axis), n(-d.y(), d.x());
        const double off_deg = std::acos(std::min(1.0, dot(d, u))) * 180.0 / kPi, off_px = std::abs(dot(centre - track.axis.p1(), n));
        const TipErrors e = tipErrors(track);
        qInfo("tracked along a line %.2f deg and %.2f px off the needle; %d frames without a tip, of the rest %d within 2 px, the worst %.2f px off",
              off_deg, off_px, track.masked, e.close, e.worst);
        QVERIFY2(off_deg < 0.3 && off_px < 0.75, qPrintable(QStringLiteral("the line is %1 deg and %2 px off the needle").arg(off_deg).arg(off_px)));
        QVERIFY2(track.masked <= kFrames / 10, qPrintable(QStringLiteral("%1 frames without a tip").arg(track.masked)));
        QVERIFY2(e.close >= 0.95 * e.seen, qPrintable(QStringLiteral("the tip is within 2 px in %1 of %2 frames").arg(e.close).arg(e.seen)));
    }
};

QTEST_GUILESS_MAIN(TestNeedleAxis)
#include "test_needle_axis.moc"
