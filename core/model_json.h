#pragma once
// The thesis's models as JSON objects, with units in the keys (`a1_N_per_mm`, `Cp_N_per_m`).
// Every command that prints a model and the simulator's truth file write them from here, so a
// script reads the same keys wherever a model appears.

#include "core/models.h"

#include <QJsonObject>

namespace nb {

struct QuadraticStiffnessFit;

// {a1_N_per_mm, a2_N_per_mm2}
QJsonObject toJson(const StiffnessModel& model);
// {a1_N_per_mm, a2_N_per_mm2, rms_N, r2}
QJsonObject toJson(const QuadraticStiffnessFit& fit);
// {Cp_N_per_m, Cn_N_per_m, bp_Ns_per_m2, bn_Ns_per_m2, Dp_N_per_m, Dn_N_per_m}
QJsonObject toJson(const KarnoppPerLength& model);

}  // namespace nb
