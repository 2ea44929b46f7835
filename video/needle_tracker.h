#pragma once
// The needle's signed displacement along its own axis, frame by frame: what the picture measures,
// in pixels, for synchronisation and for the friction phases.
//
// The axis is a line the operator gives or one found in the picture (needle_axis_finder.h). Either
// is first moved onto the shaft the video shows, when it shows one over a good stretch (a line
// drawn by hand, or found from a short path of the tip, is a degree or two off it). Along it a
// strip a few pixels wide is sampled into a profile (needle_strip.h); what stays put in the profile
// (plates, overlays crossing the strip, the shaft's own texture) is removed by subtracting the low
// percentile of the gradient over the video, and the moving edge that is left is the tip. Where the
// shaft shows against the picture either side of it, an edge is the tip only where the shaft ends:
// the changing digits of a clock or counter that the line crosses are not. Its position is found in
// every frame on its own (no accumulated drift), and measured again against what each sample of the
// strip shows behind a tip and ahead of one (learnt from the sampled frames), so that a still
// textured background does not pull it to the texture's edges; a track keeps that measure where it
// scatters clearly less while the tip moves. Where a frame alone does not show the tip clearly (a
// faint needle in heavy noise), the tip's likeliest course through the frames (TipPath) says where
// to look for it in that frame. Frames where no edge stands out of the noise there are masked
// (NaN), never guessed.

#include "core/picture_lag.h"
#include "frame_samples.h"
#include "needle_axis.h"

#include <QRect>
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

namespace nb::video {

struct NeedleTrack {
    std::vector<double> time_s;           // video time of each frame
    std::vector<double> displacement_px;  // tip position along the axis; NaN when masked
    NeedleAxis axis;
    bool axisDetected = false;            // false: the caller gave the axis
    // The sign of the tip's edge along the axis (0: not read), and whether a shaft's sign told it;
    // where none stood out it is the sign of the stronger edges, a coin toss for a faint needle at
    // rest half the time.
    int tipPolarity = 0;
    bool shaftSeen = false;
    double edgeSnr = 0.0;                 // median tip edge strength over the gradient noise
    int masked = 0;                       // frames without a usable tip (duplicates included)
    int damaged = 0;                      // frames left out: in a damaged stretch of the file, not decodable
    // How the video's coder carried pictures over, and the tip's edge (core/picture_lag.h).
    PictureCoding coding;
};

// For each of `axes`, the line of a shaft too faint to settle it on (trackNeedles moves a line
// only onto a shaft that stands 4 σ out of the grain in enough of its segments): the shaft read
// where it stands 3 σ out; nothing where that leaves the line as it is, or the shaft is clear
// enough to settle it anyway. Read at 3 σ, the grain beside a faint shaft pulls the line too (on
// a needle drawn exactly along its line, 0.44° off it), so it is a line to track beside `axes`,
// not instead of them.
std::vector<std::optional<NeedleAxis>> settledOnFaintShafts(const FrameSamples& samples, const std::vector<NeedleAxis>& axes);

// A stretch along an axis, in pixels from its p1 (as a track's displacements are).
struct AxisStretch {
    double from_px = 0.0, to_px = 0.0;
};

// How to read an axis where the caller knows better than the frames.
struct AxisReading {
    bool asPointed = false;  // tracked the way it points, never turned round
    int shaftSign = 0;       // +1 a shaft brighter than beside it, −1 darker; 0: as the frames show
};

// Tracks the tip along each axis in every frame, in one pass over the video. Each axis is
// first moved (within 3° and 4 px) onto the shaft the video shows, and turned round when its
// needle's shaft lies towards p2: an operator may draw the line roughly and either way. The
// track's `axis` is the line measured along. `notRead` (empty, or one per axis): a stretch of
// the axis where no tip is read, as far around it as a tip's edge reaches; give the axis as a
// track measured along it, so that the stretch stays where it was. `within` (empty: the whole
// picture): the region in which the tip is read; the line beyond it is not read at all (the
// operator's region that leaves out a clock or counter the line runs through). Throws VideoError.
std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress = {},
                                      const std::atomic_bool* cancel = nullptr,
                                      const std::vector<std::optional<AxisStretch>>& notRead = {}, QRect within = {});
// The same, learning from `samples` (sampleFrames of this reader) instead of sampling again.
// `readings` (empty, or one per axis): how to read each, where the caller knows.
std::vector<NeedleTrack> trackNeedles(FrameReader& reader, const FrameSamples& samples, const std::vector<NeedleAxis>& axes,
                                      const std::function<void(int, int)>& progress = {},
                                      const std::atomic_bool* cancel = nullptr,
                                      const std::vector<std::optional<AxisStretch>>& notRead = {}, QRect within = {},
                                      const std::vector<AxisReading>& readings = {});

// Tracks the tip along `axis` in every frame. Throws VideoError.
NeedleTrack trackNeedle(FrameReader& reader, const NeedleAxis& axis,
                        const std::function<void(int, int)>& progress = {},
                        const std::atomic_bool* cancel = nullptr);

}  // namespace nb::video
