#pragma once
// Small text helpers the CSV writers share.

#include <QByteArray>
#include <QString>

namespace nb {

// A CSV field, quoted ("...", "" for a quote) only when it holds a comma, quote or line break.
QByteArray csvField(const QString& text);

// A number with `decimals` places, trailing zeros kept for aligned columns; empty for NaN.
QByteArray csvNumber(double value, int decimals);

// Writes `bytes` to `path` through a temporary renamed on success. Throws ExportError.
void writeFileAtomically(const QString& path, const QByteArray& bytes);

}  // namespace nb
