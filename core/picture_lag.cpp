#include "picture_lag.h"

#include <QStringList>
#include <algorithm>
#include <cmath>
#include <limits>

namespace nb {

MotionCoding motionCodingOf(const QString& codec)
{
    static const QStringList intra{QStringLiteral("mjpeg"), QStringLiteral("mjpg"), QStringLiteral("jpeg"), QStringLiteral("dvvideo"),
                                   QStringLiteral("dvsd"), QStringLiteral("dv25"), QStringLiteral("dv50"), QStringLiteral("rawvideo"),
                                   QStringLiteral("ffv1"), QStringLiteral("huffyuv"), QStringLiteral("hfyu"), QStringLiteral("png"),
                                   QStringLiteral("mpng"), QStringLiteral("prores"), QStringLiteral("apch"), QStringLiteral("apcn"),
                                   QStringLiteral("utvideo"), QStringLiteral("jpeg2000"), QStringLiteral("mjp2"), QStringLiteral("dnxhd"),
                                   QStringLiteral("avdn"), QStringLiteral("i420"), QStringLiteral("y800"), QStringLiteral("gray")};
    static const QStringList half{QStringLiteral("mpeg4"), QStringLiteral("fmp4"), QStringLiteral("xvid"), QStringLiteral("divx"),
                                  QStringLiteral("dx50"), QStringLiteral("mp4v"), QStringLiteral("mpeg2video"), QStringLiteral("mpg2"),
                                  QStringLiteral("mpeg1video"), QStringLiteral("mpg1"), QStringLiteral("h263"), QStringLiteral("msmpeg4v2"),
                                  QStringLiteral("msmpeg4v3"), QStringLiteral("div3"), QStringLiteral("mp42"), QStringLiteral("mp43")};
    static const QStringList quarter{QStringLiteral("h264"), QStringLiteral("avc1"), QStringLiteral("x264"), QStringLiteral("hevc"),
                                     QStringLiteral("hvc1"), QStringLiteral("hev1"), QStringLiteral("h265"), QStringLiteral("vp8"),
                                     QStringLiteral("vp80"), QStringLiteral("vp9"), QStringLiteral("vp90"), QStringLiteral("av1"),
                                     QStringLiteral("av01")};
    const QString name = codec.trimmed().toLower();
    if (intra.contains(name))
        return MotionCoding::Intra;
    if (half.contains(name))
        return MotionCoding::HalfPixel;
    if (quarter.contains(name))
        return MotionCoding::QuarterPixel;
    return MotionCoding::Unknown;
}

PictureTrail pictureTrail(const PictureCoding& c)
{
    // Nothing measured (too few pictures), or nothing carried over.
    if (c.motion == MotionCoding::Intra || !(c.noise_grey > 0.0) || !(c.memory >= 0.0))
        return {};
    constexpr double kInf = std::numeric_limits<double>::infinity();
    // With no edge measured, the most a faint edge trailed in the probes (1.08 px, coded twice).
    constexpr double kMostTrail_px = 1.5;
    const bool atTop = c.memory >= kMostMeasurableMemory;
    const double faint_px = 0.04 + 0.53 * std::min(c.memory, kMostMeasurableMemory);
    const bool edgeKnown = c.edgeSlope_grey_per_px > 0.0 && std::isfinite(c.edgeSlope_grey_per_px);
    // Half the quantiser's threshold over the edge's slope: 3.5 grey for a coder moving by half
    // pixels, 0.75 for one moving by quarters.
    const double halfPixel_px = edgeKnown ? 3.5 / c.edgeSlope_grey_per_px : kInf;
    const double quarterPixel_px = edgeKnown ? 0.75 / c.edgeSlope_grey_per_px : kInf;
    // A video whose coder moves by quarter pixels (or is not known) may have been coded by one
    // moving by halves first, unless the operator says it was coded once.
    const bool byHalves = c.motion == MotionCoding::HalfPixel;
    const bool once = byHalves || (c.codedOnce && c.motion == MotionCoding::QuarterPixel);
    const double own_px = byHalves ? halfPixel_px : quarterPixel_px;
    PictureTrail t;
    t.most_px = std::min({atTop ? kInf : faint_px, once ? own_px : halfPixel_px, kMostTrail_px});
    t.least_px = std::min({faint_px, own_px, t.most_px});
    // What the model left unexplained in the probes' strokes: coded once by halves, 0.06 px (root
    // mean square; at most 0.16); coded twice, 0.15 (0.29 below the meter's top).
    t.residual_px = once ? 0.10 : 0.15;
    t.narrowsIfCodedOnce = c.motion == MotionCoding::QuarterPixel && !c.codedOnce && t.most_px > t.least_px;
    return t;
}

}  // namespace nb
