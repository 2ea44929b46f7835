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
struct FrameIndex;
// The index's width and height as shown (swapped for a quarter turn), and the tag said in its
// warnings; nothing for 0.
void turnIndexUpright(FrameIndex& index, int rotation_deg);

}  // namespace nb::video
