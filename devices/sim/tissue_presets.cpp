#include "tissue_presets.h"

#include <QCoreApplication>

namespace nb::devices::sim {

QString tipName(Tip tip)
{
    switch (tip) {
    case Tip::Beveled: return QStringLiteral("beveled");
    case Tip::Diamond: return QStringLiteral("diamond");
    case Tip::Blunt: return QStringLiteral("blunt");
    }
    return {};
}

std::optional<Tip> tipFromName(const QString& name)
{
    for (Tip t : {Tip::Beveled, Tip::Diamond, Tip::Blunt})
        if (tipName(t) == name)
            return t;
    return std::nullopt;
}

KarnoppPerLength table5Friction()
{
    // Overall means of Table 5 (liver 7, under imaging).
    return {8.17918, 11.11063, 183.9548, 165.9895, 14.73542, -17.7954};
}

KarnoppPerLength table4Friction()
{
    // Table 4's overall row, except D_n: its overall value (+0.55) has the wrong sign for a
    // negative limit, so the mean of the per-frequency rows is used.
    return {2.821737, 9.977761, 556.4617, 294.0225, 10.39652, -31.5155};
}

Tip usualTip(const QString& tissue, bool internal)
{
    if (internal)
        return Tip::Blunt;
    const bool diamond = tissue == QLatin1String("liver5") || tissue == QLatin1String("liver7") || tissue == QLatin1String("prostate");
    return diamond ? Tip::Diamond : Tip::Beveled;
}

QString usualSetup(const QString& tissue)
{
    return tissue == QLatin1String("liver7") ? QStringLiteral("platform") : QStringLiteral("organ");
}

QStringList tissueNames()
{
    return {QStringLiteral("liver1"), QStringLiteral("liver2"), QStringLiteral("liver3"),
            QStringLiteral("liver5"), QStringLiteral("liver7"), QStringLiteral("prostate")};
}

std::optional<TissuePreset> tissuePreset(const QString& name, Tip tip)
{
    TissuePreset p;
    p.name = name;
    p.friction = table5Friction();
    // Table 2 rows.
    if (name == QLatin1String("liver1")) {
        p.stiffness = {0.0480, 0.0052};
        p.punctureDepth_mm = 16.5732;
        p.punctureForce_N = 2.3888;
    } else if (name == QLatin1String("liver2")) {
        p.stiffness = {0.0020, 0.0023};
        p.punctureDepth_mm = 22.3838;
        p.punctureForce_N = 1.2597;
    } else if (name == QLatin1String("liver3")) {
        p.stiffness = {0.0371, 0.0107};
        p.punctureDepth_mm = 8.9458;
        p.punctureForce_N = 1.4370;
        p.friction = table4Friction();
        p.tissueMass_kg = 0.258;  // the liver 3 slab
    } else if (name == QLatin1String("liver5")) {
        p.stiffness = {0.0204, 0.0008};
        p.punctureDepth_mm = 10.4022;
        p.punctureForce_N = 0.5352;
    } else if (name == QLatin1String("liver7")) {
        p.stiffness = {0.0042, 0.0133};
        p.punctureDepth_mm = 8.0068;
        p.punctureForce_N = 1.1283;
    } else if (name == QLatin1String("prostate")) {
        // Not tabulated in the thesis: a firmer, thinner capsule and many internal structures
        // (the canine prostate run showed many internal punctures).
        p.stiffness = {0.030, 0.0060};
        p.punctureDepth_mm = 6.0;
        p.punctureForce_N = 0.396;
        p.internalEvents_per_mm = 0.5;
        p.internalForceMean_N = 0.15;
        p.internalForceMax_N = 0.40;
    } else {
        return std::nullopt;
    }
    if (tip == Tip::Blunt) {
        // Table 3: capsule removed, blunt needle; the loading curve is that of the
        // internal structures, each giving at ~0.0858 N (at most 0.243 N).
        p.capsule = false;
        p.stiffness = {0.0056, 0.0024};
        p.internalForceMean_N = 0.0858;
        p.internalForceMax_N = 0.243;
    }
    return p;
}

}  // namespace nb::devices::sim
