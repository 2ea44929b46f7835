#pragma once
// What a lab has of a simulated run: force and position. The simulator's true phase and the
// tissue's position are removed before anything is suggested or fitted from the run.

#include "core/run.h"

#include <algorithm>

namespace nbtest {

inline nb::Run withoutTruthColumns(nb::Run run)
{
    std::erase_if(run.text, [](const auto& column) { return column.first == QLatin1String("phase"); });
    std::erase_if(run.numeric, [](const auto& column) { return column.first == QLatin1String("tissue_position_mm"); });
    return run;
}

}  // namespace nbtest
