#include "orientation.h"
#include "core/tr.h"
#include "frame_index.h"

#include <cmath>
#include <utility>

namespace nb::video {

int takeRotation(cv::VideoCapture& cap)
{
    cap.set(cv::CAP_PROP_ORIENTATION_AUTO, 0.0);
    const int deg = int(std::lround(cap.get(cv::CAP_PROP_ORIENTATION_META)));
    const int turned = ((deg % 360) + 360) % 360;
    return turned == 90 || turned == 180 || turned == 270 ? turned : 0;
}

void turnIndexUpright(FrameIndex& index, int rotation_deg)
{
    if (rotation_deg == 0)
        return;
    if (rotation_deg == 90 || rotation_deg == 270)
        std::swap(index.width, index.height);
    index.rotation_deg = rotation_deg;
}

void turnUpright(cv::Mat& image, int rotation_deg)
{
    // ffmpeg and players show a tag of 90° as the coded picture turned counter-clockwise.
    if (image.empty() || rotation_deg == 0)
        return;
    cv::Mat turned;
    cv::rotate(image, turned,
               rotation_deg == 90    ? cv::ROTATE_90_COUNTERCLOCKWISE
               : rotation_deg == 180 ? cv::ROTATE_180
                                     : cv::ROTATE_90_CLOCKWISE);
    image = turned;
}

}  // namespace nb::video
