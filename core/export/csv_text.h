#pragma once
// Small text helpers the CSV writers share.

#include <QByteArray>
#include <QFileDevice>
#include <QString>

namespace nb {

// A CSV field, quoted ("...", "" for a quote) only when it holds a comma, quote or line break.
QByteArray csvField(const QString& text);

// A number with `decimals` places, trailing zeros kept for aligned columns; empty for NaN.
QByteArray csvNumber(double value, int decimals);

// Why writing `path` through `file` failed, for the user: "no space left on the disk" when
// that is the cause (QSaveFile itself says only "Unknown error").
QString writeFailure(const QFileDevice& file, const QString& path);

// Writes `bytes` to `path` through a temporary renamed on success. Throws ExportError.
void writeFileAtomically(const QString& path, const QByteArray& bytes);

}  // namespace nb
