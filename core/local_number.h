#pragma once
// A number as the operator's language writes it ("14,00" in German), with a fixed number of
// decimals and no group separator ("1001 ppm", not "1,001 ppm"); noise about zero reads 0, not
// -0. For what the window says; the command line's output stays in the C locale for scripts.

#include <QString>

namespace nb {

QString localNumber(double value, int decimals);

}  // namespace nb
