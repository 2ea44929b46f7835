#pragma once
// The organ surface's displacement along the needle, frame by frame, for the relaxation
// (core/surface_relaxation.h), measured two ways:
// - its edges: the picture is summed across the needle's axis into a profile along it (a few
//   hundred pixels a bin, so a faint, noisy edge still stands out), what stays put over the
//   video (plates, overlays) is taken away, and the profile's gradient is matched from frame
//   to frame; the surface's edge, spanning the picture beside the needle, dominates it. What
//   stays put is what the profiles hold besides the surface moved as tracked (not their mean,
//   which holds the surface's edge where it rests long), found and tracked on in turn;
// - its texture: the tissue's shifts that video/tissue_tracker measures, added up and
//   projected on the direction the picture moves in most.
// Each fails on its own kind of picture (a faint texture under heavy noise; a surface whose
// edge is smeared); the suggestion fits both and keeps the larger believable spring-back.

#include "core/surface_relaxation.h"
#include "core/sync.h"
#include "frame_reader.h"
#include "tissue_tracker.h"

#include <QLineF>

namespace nb::video {

SurfaceTrace surfaceTraceFromShifts(const TissueShifts& shifts, const TimelineMapping& mapping);

// The edges' displacement along `axis` (video pixels, positive towards its p2). A picture
// shown again (a duplicate in the index, or decoded the same as the one before) is skipped.
// Throws VideoError.
SurfaceTrace trackSurfaceEdges(FrameReader& reader, const QLineF& axis, const TimelineMapping& mapping);

// Both traces for `reader`'s video, their sources named after `name` (the edges only when the
// needle's axis is found, video/needle_tracker.h). Throws VideoError.
std::vector<SurfaceTrace> surfaceTraces(FrameReader& reader, const TissueShifts& shifts, const TimelineMapping& mapping,
                                        const QString& name);

}  // namespace nb::video
