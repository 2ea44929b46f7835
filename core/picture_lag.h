#pragma once
// How late a coded video shows a slow, faint motion. An inter-frame coder (H.264, MPEG-4 part 2)
// codes each picture as the one before plus the changes worth their bits; a change smaller than
// what its quantiser drops is carried on from picture to picture until it adds up. Noise fresh
// in every camera frame comes out of such a coder correlated from one picture to the next, and
// how much says how much of a picture is the one before it. A needle's edge that changes its
// pixels by less than the noise is coded like the noise and shows as late; a bold edge, or a
// fast one, changes them by far more than the coder drops and is shown on time. (Probe seed
// 417293, slow faint sines: the tip read in the decoded pictures of MPEG-4 was 0.77 frames late
// against the pictures drawn, of MJPEG 0.1; the sync 1.04 frames late and 0.15.)
//
// The model: the coder passes a pixel's difference from what it last showed when, with the
// camera's noise on it, it is beyond a threshold, and keeps the pixel otherwise. Fresh noise
// passes at a rate of 1 − memory, which sets the threshold; a motion not yet shown differs by
// more each frame, and is shown within a few frames however faint.

namespace nb {

struct PictureCoding {
    // Lag-one correlation of the picture's noise from one frame to the next: 0 when every picture
    // is coded afresh (MJPEG, DV, uncoded), towards 1 when the coder drops the noise.
    double memory = 0.0;
    double noise_grey = 0.0;             // the noise per pixel in the pictures as decoded (σ), taken
                                         // for the camera's: a coder that holds a pixel shows it whole
    double edgeSlope_grey_per_px = 0.0;  // the tip's edge along the needle: how much a pixel changes
                                         // as the tip moves a pixel
};

// The most memory the pictures' noise can show (video/picture_memory): beyond it a coder has
// dropped nearly all of the camera's noise, and with it what the lag's model reads its threshold
// from. A video measured there shows the motion late by an amount the model does not know.
inline constexpr double kMostMeasurableMemory = 0.95;
// The most memory the lag's model takes: a coder holding more would never show a faint change.
inline constexpr double kMostModelledMemory = 0.99;

// Frames by which a picture shows late a change of `change_grey` a frame in a pixel; 0 when the
// coding carries nothing over (or is not known). At most 10.
double pictureLag_frames(const PictureCoding& coding, double change_grey);

}  // namespace nb
