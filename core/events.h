#pragma once
// Events of a constant-velocity insertion (models.md section 4): contact with the capsule
// (x_s1), the main puncture (x_s2), later internal punctures, and the end of the
// post-puncture drop (relaxation, where the surface has sprung back to x_s3 < x_s2).

#include "labels.h"
#include "models.h"
#include "run.h"

#include <cstddef>
#include <span>
#include <optional>
#include <vector>

namespace nb {

struct RunEvent {
    std::size_t index = 0;     // nearest sample
    double time_s = 0.0;
    double position_mm = 0.0;
    double force_N = 0.0;      // zeroed force (offset removed)
};

struct EventOptions {
    // A drop counts as the main puncture when the force falls by at least this fraction of
    // the peak (zeroed) force and by at least `minPunctureDrop_N`.
    double punctureDropFraction = 0.2;
    double minPunctureDrop_N = 0.05;
    // Later drops of at least this much (and of 8 noise sigmas) are internal punctures.
    double minInternalDrop_N = 0.02;
    // Smoothing used to find peaks, as travel of the needle [mm].
    double smoothing_mm = 0.1;
};

struct InsertionEvents {
    double zeroOffset_N = 0.0;   // mean force before contact, subtracted from every force here
    double noise_N = 0.0;        // estimated sample noise (standard deviation)
    RunEvent contact;            // position_mm is the fitted x_s1 (between samples)
    RunEvent puncture;           // force peak before the first sharp drop (x_s2)
    std::vector<RunEvent> internalPunctures;
    std::optional<RunEvent> relaxation;  // end of the drop after the main puncture
    // The piecewise model fitted with the contact point: 0 before x_s1, a1·d + a2·d² after.
    StiffnessModel stiffness;
    double stiffnessRms_N = 0.0;

    double punctureDepth_mm() const { return puncture.position_mm - contact.position_mm; }
};

// Uses the forward stroke (samples up to the deepest position). Throws FitError for too few
// samples, no forward motion or no puncture.
InsertionEvents detectEvents(const Run& run, const EventOptions& options = {});

// The contact search on its own: samples (position, raw force) up to the puncture; finds
// x_s1, the offset and a1, a2 of  offset + [x >= x_s1]·(a1 d + a2 d²)  by a 1-D search over
// x_s1 with a linear least-squares solve inside.
struct ContactFit {
    double contact_mm = 0.0;
    double offset_N = 0.0;
    StiffnessModel stiffness;
    double rms_N = 0.0;
};
ContactFit fitContact(std::span<const double> position_mm, std::span<const double> force_N);

// The operator's point labels override what detection found. "contact" sets x_s1 (the
// position at the label's time) and the zero offset (the mean force before it, as the thesis
// zeroed its forces); "puncture" sets x_s2 at the force peak within ±window_s of the label
// (a label placed on a video frame is known to a frame). Other labels are ignored. Throws
// FitError for a label outside the run or a puncture not past the contact.
void applyEventLabels(InsertionEvents& events, const Run& run, const Labels& labels, double window_s = 0.05);

// The events detected, with the operator's labels applied. Where detection finds none (a
// puncture too soft for it, say) and the labels mark both the contact and the puncture, the
// events are the labels' alone, as the thesis read them off the video; else detection's error.
InsertionEvents eventsWithLabels(const Run& run, const Labels& labels);

}  // namespace nb
