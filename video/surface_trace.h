#pragma once
// The organ surface's displacement along the needle, frame by frame, for the relaxation
// (core/surface_relaxation.h). The tissue's texture and its surface move together (they are
// the same organ), so the picture's shifts that video/tissue_tracker measures, added up,
// give where the surface is; projected on the direction the picture moves in most (the
// needle's axis, whatever its angle in the picture), and put on the recording's clock.

#include "core/surface_relaxation.h"
#include "core/sync.h"
#include "tissue_tracker.h"

namespace nb::video {

SurfaceTrace surfaceTraceFromShifts(const TissueShifts& shifts, const TimelineMapping& mapping);

}  // namespace nb::video
