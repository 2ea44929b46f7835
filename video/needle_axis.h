#pragma once

#include <QLineF>

namespace nb::video {

// A needle's line in video pixels, from its shaft towards its tip once the tracker has turned
// it so. Displacements along it are positive towards `p2()`.
using NeedleAxis = QLineF;

}  // namespace nb::video
