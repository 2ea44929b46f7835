#include "data_names.h"

#include "core/tr.h"

#include <QRegularExpression>

namespace nb {

QString tipDisplayName(const QString& tip)
{
    if (tip == QLatin1String("beveled"))
        return nb::TrViews::tr("beveled");
    if (tip == QLatin1String("diamond"))
        return nb::TrViews::tr("diamond");
    if (tip == QLatin1String("blunt"))
        return nb::TrViews::tr("blunt");
    return tip;
}

QString tissueDisplayName(const QString& tissue)
{
    static const QRegularExpression liver(QStringLiteral("^liver(\\d+)$"));
    if (const auto m = liver.match(tissue); m.hasMatch())
        return nb::TrViews::tr("Liver %1").arg(m.captured(1));
    if (tissue == QLatin1String("prostate"))
        return nb::TrViews::tr("Prostate");
    return tissue;
}

}  // namespace nb
