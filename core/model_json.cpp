#include "model_json.h"

#include "core/stiffness_fit.h"

namespace nb {

QJsonObject toJson(const StiffnessModel& m)
{
    return {{QStringLiteral("a1_N_per_mm"), m.a1_N_per_mm}, {QStringLiteral("a2_N_per_mm2"), m.a2_N_per_mm2}};
}

QJsonObject toJson(const QuadraticStiffnessFit& q)
{
    QJsonObject o = toJson(q.model);
    o.insert(QStringLiteral("rms_N"), q.rms_N);
    o.insert(QStringLiteral("r2"), q.r2);
    return o;
}

QJsonObject toJson(const KarnoppPerLength& p)
{
    return {{QStringLiteral("Cp_N_per_m"), p.Cp_N_per_m},     {QStringLiteral("Cn_N_per_m"), p.Cn_N_per_m},
            {QStringLiteral("bp_Ns_per_m2"), p.bp_Ns_per_m2}, {QStringLiteral("bn_Ns_per_m2"), p.bn_Ns_per_m2},
            {QStringLiteral("Dp_N_per_m"), p.Dp_N_per_m},     {QStringLiteral("Dn_N_per_m"), p.Dn_N_per_m}};
}

}  // namespace nb
