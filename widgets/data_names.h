#pragma once
// Data values that files store in English (needle tips, simulated tissue presets) said in the
// operator's language. The stored value never changes: "beveled" stays "beveled" in
// session.json and in every run file; only what a widget shows is translated.

#include <QString>

namespace nb {

// "beveled" → "beveled" / "abgeschrägt"; an unknown tip is shown as stored.
QString tipDisplayName(const QString& tip);
// "liver2" → "Liver 2" / "Leber 2", "prostate" → "Prostate" / "Prostata".
QString tissueDisplayName(const QString& tissue);

}  // namespace nb
