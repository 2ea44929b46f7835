#include "surface_trace.h"

#include <algorithm>
#include <cmath>

namespace nb::video {

SurfaceTrace surfaceTraceFromShifts(const TissueShifts& s, const TimelineMapping& mapping)
{
    SurfaceTrace out;
    const std::size_t k = std::min({s.time_s.size(), s.dt_s.size(), s.dx_px.size(), s.dy_px.size()});
    if (k == 0)
        return out;
    // The principal axis of the shifts: the spring-back's few large steps and the carried
    // motion before it both lie along the needle.
    double sxx = 0, sxy = 0, syy = 0;
    for (std::size_t i = 0; i < k; ++i) {
        sxx += s.dx_px[i] * s.dx_px[i];
        sxy += s.dx_px[i] * s.dy_px[i];
        syy += s.dy_px[i] * s.dy_px[i];
    }
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    const double ux = std::cos(angle), uy = std::sin(angle);
    // Positions at the frames' own times: the first frame's, then each later frame's.
    double position = 0.0;
    out.time_s.push_back(mapping.toRecording(s.time_s[0] - 0.5 * s.dt_s[0]));
    out.displacement_px.push_back(position);
    for (std::size_t i = 0; i < k; ++i) {
        position += s.dx_px[i] * ux + s.dy_px[i] * uy;
        out.time_s.push_back(mapping.toRecording(s.time_s[i] + 0.5 * s.dt_s[i]));
        out.displacement_px.push_back(position);
    }
    return out;
}

}  // namespace nb::video
