#pragma once
// Relaxation from the imaging video (models.md 4): until the capsule gives, the needle pushes
// the organ's surface down with it (x_s1 → x_s2); after the puncture the surface springs back
// towards x_s3, and relaxation is the moment it has come to rest. The force cannot show that
// moment; the picture can.
//
// The surface's displacement along the needle (pixels, one value a frame, on the recording's
// clock) is fitted around the puncture with the motion the thesis describes: carried at a
// steady speed before the spring-back's onset t0, then an exponential settling
// d(t) = A + (d0 − A)·exp(−(t − t0)/τ). Relaxation is 4 τ after the puncture: 98 % of the
// spring-back done, the remainder (under 2 %) well below what an operator can see move.
// A fit over all the frames is what makes it robust: a single frame's noise does not decide
// when the motion stopped, as it would for a threshold on the last frames' motion.

#include <QString>

#include <optional>
#include <vector>

namespace nb {

struct SurfaceTrace {
    std::vector<double> time_s;           // recording time of each frame
    std::vector<double> displacement_px;  // along the main direction of the picture's motion
    QString source;                       // what it came from, e.g. the video file's name
};

struct SpringBack {
    double onset_s = 0.0;       // fitted start of the spring-back (recording time)
    double tau_s = 0.0;         // its time constant
    double amplitude_px = 0.0;  // |d0 − A|: how far the surface sprang back
    double noise_px = 0.0;      // the trace's frame-to-frame noise
    double carried_px = 0.0;    // how far the surface was carried from the contact to the onset
    double relaxed_s = 0.0;     // puncture + 4 τ
};

// The spring-back after the puncture at `puncture_s` (from the force). Its onset is looked for
// within `search_s` of the puncture (the clocks' agreement). With the contact's time (NaN:
// unknown) the surface must have been carried down at least as far as it springs back (it
// cannot spring back past where it was touched): a trace that lost the surface and reads
// short before the puncture is not believed. Nothing (and `problem` says why) when the trace
// does not show it: too few frames, a motion within the noise, a fit that does not explain
// the motion, or a video that ends before the surface has come to rest.
std::optional<SpringBack> fitSpringBack(const SurfaceTrace& trace, double puncture_s, double contact_s, QString* problem = nullptr,
                                        double search_s = 0.5);

}  // namespace nb
