#pragma once
// Fit results as a table (rows of text and numbers) written to CSV for scripts and to a
// LaTeX tabular (booktabs) for the thesis-style report.

#include <QByteArray>
#include <QString>
#include <variant>
#include <vector>

namespace nb {

struct TableColumn {
    QString key;          // CSV header, e.g. "a1_N_per_mm"
    QString title;        // LaTeX header text (escaped), e.g. "a1"
    QString unit;         // unit shown as "[unit]" under the title (typeset by latexUnit); may be empty
    int decimals = 4;     // for numbers
    QString latexTitle;   // raw LaTeX header overriding `title` (e.g. "$a_1$"); optional
};

using TableCell = std::variant<QString, double>;

struct FitTable {
    QString caption;  // LaTeX caption
    QString label;    // LaTeX \label, e.g. "tab:stiffness"
    std::vector<TableColumn> columns;
    std::vector<std::vector<TableCell>> rows;  // each as long as `columns`; NaN prints empty / "--"
};

QByteArray fitTableCsv(const FitTable& table);
QByteArray fitTableLatex(const FitTable& table);

// Escapes LaTeX's special characters in plain text.
QString latexEscaped(const QString& text);

// A unit typeset in math mode: "N/mm^2" -> "$\mathrm{N}/\mathrm{mm}^{2}$", "N s/m^2" with a
// thin space; no package needed beyond LaTeX itself.
QString latexUnit(const QString& unit);

// Atomic writes. Throw ExportError.
void writeFitTableCsv(const QString& path, const FitTable& table);
void writeFitTableLatex(const QString& path, const FitTable& table);

}  // namespace nb
