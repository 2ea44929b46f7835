#include "local_number.h"

#include <QLocale>
#include <cmath>

namespace nb {

QString localNumber(double value, int decimals)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    const double scale = std::pow(10.0, decimals);
    return locale.toString(std::round(value * scale) == 0.0 ? 0.0 : value, 'f', decimals);
}

}  // namespace nb
