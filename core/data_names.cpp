#include "data_names.h"

#include "core/tr.h"

#include <QRegularExpression>

namespace nb {

QString tipDisplayName(const QString& tip)
{
    if (tip == QLatin1String("beveled"))
        return nb::TrCore::tr("beveled");
    if (tip == QLatin1String("diamond"))
        return nb::TrCore::tr("diamond");
    if (tip == QLatin1String("blunt"))
        return nb::TrCore::tr("blunt");
    return tip;
}

QString tissueDisplayName(const QString& tissue)
{
    static const QRegularExpression liver(QStringLiteral("^liver(\\d+)$"));
    if (const auto m = liver.match(tissue); m.hasMatch())
        return nb::TrCore::tr("Liver %1").arg(m.captured(1));
    if (tissue == QLatin1String("prostate"))
        return nb::TrCore::tr("Prostate");
    return tissue;
}

QString motionDisplayName(const QString& motion)
{
    if (motion == QLatin1String("linear"))
        return nb::TrCore::tr("linear");
    if (motion == QLatin1String("sine"))
        return nb::TrCore::tr("sine");
    return motion;
}

QString trackDisplayName(const QString& track)
{
    if (track == QLatin1String("insertion"))
        return nb::TrCore::tr("insertion");
    if (track == QLatin1String("withdrawal"))
        return nb::TrCore::tr("withdrawal");
    if (track == QLatin1String("events"))
        return nb::TrCore::tr("events");
    return track;
}

QString factorDisplayName(const QString& factor)
{
    if (factor == QLatin1String("tissue"))
        return nb::TrCore::tr("tissue");
    if (factor == QLatin1String("tip"))
        return nb::TrCore::tr("tip");
    if (factor == QLatin1String("motion"))
        return nb::TrCore::tr("motion");
    if (factor == QLatin1String("site"))
        return nb::TrCore::tr("site");
    if (factor == QLatin1String("repeat"))
        return nb::TrCore::tr("repeat");
    if (factor == QLatin1String("cycles"))
        return nb::TrCore::tr("cycles");
    if (factor == QLatin1String("velocity_mm_s"))
        return nb::TrCore::tr("velocity [mm/s]");
    if (factor == QLatin1String("frequency_hz"))
        return nb::TrCore::tr("frequency [Hz]");
    if (factor == QLatin1String("amplitude_mm"))
        return nb::TrCore::tr("amplitude [mm]");
    if (factor == QLatin1String("depth_mm"))
        return nb::TrCore::tr("depth [mm]");
    if (factor == QLatin1String("thickness_mm"))
        return nb::TrCore::tr("slab thickness [mm]");
    return factor;
}

QString labelDisplayName(const QString& label)
{
    if (label == QLatin1String("contact"))
        return nb::TrCore::tr("contact");
    if (label == QLatin1String("puncture"))
        return nb::TrCore::tr("puncture");
    if (label == QLatin1String("relaxation"))
        return nb::TrCore::tr("relaxation");
    if (label == QLatin1String("internal puncture"))
        return nb::TrCore::tr("internal puncture");
    return label;
}

QString tableValueDisplayName(const QString& value)
{
    static const QLatin1String peakSpeeds("peak speeds, ");
    if (value.startsWith(peakSpeeds))
        return nb::TrCore::tr("peak speeds, %1").arg(tissueDisplayName(value.mid(peakSpeeds.size())));
    if (value == QLatin1String("pooled"))
        return nb::TrCore::tr("pooled");
    if (value == QLatin1String("mean of runs"))
        return nb::TrCore::tr("mean of runs");
    if (value == QLatin1String("not fitted"))
        return nb::TrCore::tr("not fitted");
    if (value == QLatin1String("yes"))
        return nb::TrCore::tr("yes");
    if (value == QLatin1String("mean"))
        return nb::TrCore::tr("mean");
    if (value == QLatin1String("std"))
        return nb::TrCore::tr("std");
    if (value == QLatin1String("overall"))
        return nb::TrCore::tr("overall");
    if (value == QLatin1String("line"))
        return nb::TrCore::tr("line");
    if (value == QLatin1String("peak speeds"))
        return nb::TrCore::tr("peak speeds");
    if (value == QLatin1String("unknown"))
        return nb::TrCore::tr("unknown");
    if (value == QLatin1String("all"))
        return nb::TrCore::tr("all");
    return value;
}

QString tableCellDisplayName(const QString& key, const QString& value)
{
    if (key == QLatin1String("tip"))
        return tipDisplayName(value);
    if (key == QLatin1String("static_from"))
        return staticSourceDisplayName(value);
    return tableValueDisplayName(value);
}

QString protocolDisplayName(const QString& protocol)
{
    if (protocol == QLatin1String("stiffness"))
        return nb::TrCore::tr("stiffness");
    if (protocol == QLatin1String("internal"))
        return nb::TrCore::tr("internal stiffness");
    if (protocol == QLatin1String("friction"))
        return nb::TrCore::tr("friction");
    if (protocol == QLatin1String("prostate"))
        return nb::TrCore::tr("prostate");
    return protocol;
}

QString planTitleDisplayName(const QString& title)
{
    if (title == QLatin1String("overall stiffness"))
        return nb::TrCore::tr("overall stiffness");
    if (title == QLatin1String("internal stiffness"))
        return nb::TrCore::tr("internal stiffness");
    if (title == QLatin1String("friction"))
        return nb::TrCore::tr("friction");
    if (title == QLatin1String("stiffness under imaging"))
        return nb::TrCore::tr("stiffness under imaging");
    if (title == QLatin1String("friction under imaging"))
        return nb::TrCore::tr("friction under imaging");
    if (title == QLatin1String("prostate"))
        return nb::TrCore::tr("prostate");
    return title;
}

QString staticSourceDisplayName(const QString& source)
{
    if (source == QLatin1String("phase a"))
        return nb::TrCore::tr("phase a");
    if (source == QLatin1String("velocity band"))
        return nb::TrCore::tr("velocity band");
    if (source == QLatin1String("none"))
        return nb::TrCore::tr("none");
    return source;
}

QString calibrationDisplayName(const QString& calibration)
{
    return calibration == QLatin1String(kNominalCalibration) ? nb::TrCore::tr("nominal (device)") : calibration;
}

}  // namespace nb
