#pragma once
// Data values that files store in English (needle tips, simulated tissue presets, motions, the
// nominal calibration) said in the operator's language. The stored value never changes:
// "beveled" stays "beveled" in session.json and in every run file; only what is shown is
// translated.

#include <QString>

namespace nb {

// "beveled" → "beveled" / "abgeschrägt"; an unknown tip is shown as stored.
QString tipDisplayName(const QString& tip);
// "liver2" → "Liver 2" / "Leber 2", "prostate" → "Prostate" / "Prostata".
QString tissueDisplayName(const QString& tissue);

// "linear" → "linear", "sine" → "sine" / "Sinus".
QString motionDisplayName(const QString& motion);
// The name a run file gives the device's own calibration ("nominal (device)"), translated;
// a calibration of the operator's naming is shown as named.
QString calibrationDisplayName(const QString& calibration);
// A label track of the default label sets ("insertion" → "Einstich"); tracks the operator
// named are shown as named.
QString trackDisplayName(const QString& track);
// A plan factor or run setting by which runs are grouped ("frequency_hz" → "frequency [Hz]",
// "motion" → "motion" / "Bewegung"); a factor of the operator's naming as named.
QString factorDisplayName(const QString& factor);
// An event label of the default label sets ("contact" → "Kontakt"); phases (a, b1, b2, c) and
// labels the operator named are shown as named.
QString labelDisplayName(const QString& label);
// A run's protocol as plans and run files store it ("stiffness", "internal", "friction",
// "prostate"); others as stored.
QString protocolDisplayName(const QString& protocol);
// A plan template's title ("friction under imaging"), which a plan made from it keeps as its
// name; a plan the operator named is shown as named.
QString planTitleDisplayName(const QString& title);
// Where a friction fit took its static friction D from ("phase a", "velocity band", "none",
// as the fit's JSON and the exported tables store it).
QString staticSourceDisplayName(const QString& source);
// A word the fit tables hold as data ("pooled", "mean of runs", "not fitted", "yes", "mean",
// "std", "overall", "line", "peak speeds[, TISSUE]", "unknown"): the tables' CSV keeps it in
// English for scripts, the window and the LaTeX report say it in the operator's language.
QString tableValueDisplayName(const QString& value);
// A text cell of a fit table's column `key` as shown: tips and where D came from by their
// display names, the tables' own words by tableValueDisplayName.
QString tableCellDisplayName(const QString& key, const QString& value);
// What the acquisition engine stores as the calibration before one is chosen.
inline constexpr char kNominalCalibration[] = "nominal (device)";

}  // namespace nb
