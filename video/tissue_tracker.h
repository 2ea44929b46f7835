#pragma once
#include <utility>
// The tissue's motion in the imaging video, for the friction phases (models.md 5: the
// operator reads a, b1, b2, c off how the tissue moves against the needle).
//
// The tissue fills most of the picture with its texture; phase correlation of the whole
// picture (or the operator's region) against a reference picture finds the displacement of
// that texture, sub-pixel and without adding up frame-to-frame errors. Static
// parts (plates, burnt-in clocks, the black surround) add a peak at zero shift; the texture's
// shift wins where it covers more of the picture. The shifts are then put on the recording's
// clock, projected on the direction the tissue moves in (any angle in the picture), and
// scaled to millimetres against the needle: while the tissue is carried (phase a) it moves
// exactly as the needle does, and it never moves faster, so the upper cluster of the ratio of
// tissue to needle displacement is the picture's scale.

#include "core/run.h"
#include "core/sync.h"
#include "core/tissue_motion.h"
#include "frame_reader.h"

#include <QRect>
#include <atomic>
#include <functional>

namespace nb::video {

struct TissueShifts {
    std::vector<double> time_s;  // video time, midway between the two frames compared
    std::vector<double> dt_s;    // time between them
    std::vector<double> dx_px, dy_px;
    std::vector<double> response;  // phase correlation peak (0..1): how sure the match is
};

// Frame-to-frame shifts of the picture inside `roi` (empty: everywhere), as differences of
// the displacement measured against a reference picture, so that they add up to it. A picture
// shown again (the index calls it a duplicate, it decodes the same as the one before, or, coded
// again by an inter-frame coder, nearly the same) is skipped: the next is compared with the last
// distinct picture. Throws VideoError.
TissueShifts trackTissueShifts(FrameReader& reader, QRect roi = {}, const std::function<void(int, int)>& progress = {},
                               const std::atomic_bool* cancel = nullptr);

// The direction the picture moves in: the principal axis of the first `count` shifts (unit vector).
std::pair<double, double> principalShiftAxis(const TissueShifts& shifts, std::size_t count);

// The shifts as the tissue's velocity along the needle, on the recording's clock, in mm/s.
// `problem` (may be null) says why the result is empty: too little motion in the picture or
// no motion of the needle to scale it by.
TissueMotion tissueMotionFromShifts(const TissueShifts& shifts, const Run& run, const TimelineMapping& mapping,
                                    QString* problem = nullptr);

}  // namespace nb::video
