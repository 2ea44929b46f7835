#pragma once
// The tissues the simulated rig can hold, with the thesis's numbers (Tables 2-5,
// models.md): capsule stiffness, puncture scatter, relaxation, cutting, friction per length,
// internal structures. One preset per tissue; the needle tip changes the puncture behaviour.

#include "core/models.h"

#include <QString>
#include <QStringList>
#include <optional>

namespace nb::devices::sim {

enum class Tip { Beveled, Diamond, Blunt };
QString tipName(Tip tip);
std::optional<Tip> tipFromName(const QString& name);
// The tip the thesis used with a preset: blunt for internal insertions, diamond for livers 5
// and 7 and the prostate, beveled otherwise.
Tip usualTip(const QString& tissue, bool internal);
// "platform" for the friction slab (liver7), "organ" otherwise.
QString usualSetup(const QString& tissue);

struct TissuePreset {
    QString name;                    // liver1 ... liver7, prostate
    bool capsule = true;             // false: capsule removed (Table 3), no main puncture
    StiffnessModel stiffness;        // pre-puncture a1 x + a2 x^2, x in mm past contact
    double punctureDepth_mm = 10.0;  // mean depth past contact at puncture (Table 2)
    double punctureDepthSd = 0.08;   // relative spread of puncture depth over a specimen's sites
    double punctureForce_N = 1.0;    // Table 2's mean, for reference in the truth file
    double relaxFraction = 0.35;     // x_s3 - x_s1 = fraction * (x_s2 - x_s1) after puncture
    double relaxTime_s = 0.08;       // surface spring-back time constant
    double cutting_N = 0.0858;       // eq. 27, Table 3
    KarnoppPerLength friction;       // per metre of needle in tissue (Table 5)
    double internalEvents_per_mm = 0.15;   // small internal punctures (vessels, triads)
    double internalForceMean_N = 0.0858;   // Table 3
    double internalForceMax_N = 0.243;
    double internalStiffness_N_per_mm = 0.08; // local build-up before an internal structure gives
    double tissueMass_kg = 0.6905;   // the slab on the friction platform (liver 7: 690.5 g)
};

// Presets by name; `tip` Blunt turns a liver into the capsule-removed preparation (Table 3).
std::optional<TissuePreset> tissuePreset(const QString& name, Tip tip);
QStringList tissueNames();

// Table 5 overall means (liver 7, per length) and Table 4's (liver 3); what the friction
// platform simulates.
KarnoppPerLength table5Friction();
KarnoppPerLength table4Friction();

}  // namespace nb::devices::sim
