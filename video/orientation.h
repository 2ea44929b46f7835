#pragma once
// A video's rotation tag (phones, some consoles' exports) turned as players turn it. OpenCV 4.6
// turns a 90° or 270° tag the wrong way round (opencv/opencv#22088): the capture's own turning
// is switched off and the picture turned here, the same in every OpenCV version.

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

namespace nb::video {

// Switches the opened capture's own turning off; the tag's rotation, 0, 90, 180 or 270.
int takeRotation(cv::VideoCapture& cap);
// `image` as players show it for a tag of `rotation_deg`.
void turnUpright(cv::Mat& image, int rotation_deg);
// Width and height as shown: swapped for a quarter turn.
inline bool quarterTurn(int rotation_deg) { return rotation_deg == 90 || rotation_deg == 270; }

}  // namespace nb::video
