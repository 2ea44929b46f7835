#pragma once
// The tissue's velocity beside the needle as the imaging video shows it, on the recording's
// clock and in the needle's units (mm/s along the needle's axis, same sign as position_mm).
// Made by video/tissue_tracker from the picture; read by the phase suggestion, which then
// has the relative velocity of needle and tissue that defines the phases (models.md 5).

#include <QString>
#include <vector>

namespace nb {

struct TissueMotion {
    std::vector<double> time_s;          // recording time of each measurement
    std::vector<double> velocity_mm_s;   // NaN where the picture gave no measurement
    QString source;                      // what it came from, e.g. the video file's name
    double px_per_mm = 0.0;              // the picture's scale (0: unknown); below a pixel or so a
                                         // frame the measured speed reads short
};

}  // namespace nb
