#pragma once
// How far behind the needle's tip a coded video shows it. An inter-frame coder (H.264, MPEG-4
// part 2) codes each picture as the one before, moved and mended where the change is worth its
// bits; a change smaller than what its quantiser drops is carried on until it adds up. A slowly
// moving tip is shown where it was a moment ago: behind it by a trail that holds steady in
// pixels whatever the speed, so its lag in time is the trail over the speed.
//
// What sets the trail (picture_lag_probe on 116 slow strokes of the sync probes: faint needles
// coded once and twice, bold needles on quiet cameras coded MPEG-4, H.264 and twice):
//  - a faint edge, whose change is coded like the noise: about 0.04 + 0.53 × memory px, with the
//    memory the noise's correlation from picture to picture (residuals within ±0.26 px);
//  - a bold edge is passed once it has moved far enough for its change to beat the quantiser's
//    threshold: about half that threshold over the edge's slope. MPEG-4 part 2 (half-pixel
//    motion) trailed 3.5 grey / slope (0.15 to 0.41 px at slopes 21 to 5, ±0.16 px); H.264
//    (quarter-pixel motion, x264's psychovisual tuning) 0.00 to 0.16 px at slopes 6 to 20;
//  - the smaller of the two; and the first coder's, when the video was coded twice (a console's
//    MPEG-4 made H.264 by the lab trailed as MPEG-4 does), which no container tells.

#include <QString>

namespace nb {

// How finely a video's coder follows motion from one picture to the next.
enum class MotionCoding {
    Unknown,       // not said: as finely as any, or coded twice
    Intra,         // every picture coded afresh (MJPEG, DV, uncompressed, lossless): no trail
    HalfPixel,     // MPEG-1/2, MPEG-4 part 2, H.263
    QuarterPixel,  // H.264, HEVC, VP8/9, AV1
};

// From a codec's name as FFmpeg gives it ("h264", "mpeg4") or the container's four-character
// code ("avc1", "FMP4", "MJPG"); Unknown for a name it does not know.
MotionCoding motionCodingOf(const QString& codec);

struct PictureCoding {
    // Lag-one correlation of the picture's noise from one frame to the next: 0 when every picture
    // is coded afresh (MJPEG, DV, uncoded), towards 1 when the coder drops the noise.
    double memory = 0.0;
    double noise_grey = 0.0;             // the noise per pixel in the pictures as decoded (σ)
    double edgeSlope_grey_per_px = 0.0;  // the tip's edge along the needle: how much a pixel changes
                                         // as the tip moves a pixel; 0 when not measured
    MotionCoding motion = MotionCoding::Unknown;
    // The operator says the file was coded once, by the coder its container names (the console
    // or camera wrote it so, nobody converted it): a video whose coder moves by quarter pixels
    // then trails as that coder does, not anywhere down to a first coder's trail.
    bool codedOnce = false;
};

// The most memory the pictures' noise can show (video/picture_memory): beyond it a coder has
// dropped nearly all of the camera's noise, and with it what the faint edge's trail is read from.
// A video measured there may trail by more than the memory says.
inline constexpr double kMostMeasurableMemory = 0.95;

// How far behind the tip the pictures show it, in pixels along the needle: between `least_px`
// and `most_px` for what is known of the coding (the second coder of a video coded twice shows
// the first one's trail), give or take `residual_px`, what the model left unexplained in the
// probes' strokes (less for a video known to be coded once than for one that may be coded twice).
struct PictureTrail {
    double least_px = 0.0;
    double most_px = 0.0;
    double residual_px = 0.0;
    // The range is a first coder's that may hide behind a coder moving by quarter pixels: an
    // operator who knows the file was never converted narrows it (PictureCoding::codedOnce).
    bool narrowsIfCodedOnce = false;
    double likely_px() const { return 0.5 * (least_px + most_px); }
    double uncertainty_px() const { return 0.5 * (most_px - least_px) + residual_px; }
};

PictureTrail pictureTrail(const PictureCoding& coding);

}  // namespace nb
