#include "spreadsheet_separator.h"

#include "tr.h"

#include <QStringList>

namespace nb {

QString otherSeparatorProblem(const QString& headerLine, const QString& column)
{
    if (headerLine.split(QLatin1Char(',')).size() > 1)
        return {};
    for (const QChar separator : {QLatin1Char(';'), QLatin1Char('\t')}) {
        QStringList names = headerLine.split(separator);
        for (QString& n : names)
            n = n.trimmed().remove(QLatin1Char('"'));
        if (names.contains(column))
            return nb::TrCore::tr("the columns are separated by '%1', not by commas (a spreadsheet saving in a "
                                  "comma-decimal language?); save it as CSV with ',' between columns and '.' in numbers")
                .arg(separator == QLatin1Char(';') ? QStringLiteral(";") : nb::TrCore::tr("tab"));
    }
    return {};
}

}  // namespace nb
