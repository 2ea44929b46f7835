#pragma once
// A spreadsheet set to a comma-decimal region (German, French) saves "CSV" with ';' (or a tab)
// between columns and ',' in numbers: every reader of NeedleBench's CSV files says so, not only
// that a column is missing.

#include <QString>

namespace nb {

// The message for a header line whose columns, split by ';' or a tab instead of ',', hold
// `column`; empty when the line is not such a header.
QString otherSeparatorProblem(const QString& headerLine, const QString& column);

}  // namespace nb
