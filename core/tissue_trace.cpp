#include "tissue_trace.h"
#include "tr.h"

#include <QFile>
#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <limits>

namespace nb {

TissueMotion readTissueTrace(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        throw TissueTraceError(path, nb::TrCore::tr("cannot be read: %1").arg(file.errorString()));
    if (file.readLine().trimmed() != QByteArray(kTissueTraceHeader))
        throw TissueTraceError(path, nb::TrCore::tr("is not a tissue trace: its first line must be '%1' (as labels suggest --tissue-trace writes it)")
                                         .arg(QString::fromLatin1(kTissueTraceHeader)));
    TissueMotion trace;
    trace.source = QFileInfo(path).fileName();
    for (int line = 2; !file.atEnd(); ++line) {
        const QByteArray text = file.readLine().trimmed();
        if (text.isEmpty())
            continue;
        const QList<QByteArray> cells = text.split(',');
        bool okTime = false, okVelocity = false;
        const double t = cells.size() == 2 ? cells[0].toDouble(&okTime) : 0.0;
        double velocity = std::numeric_limits<double>::quiet_NaN();
        if (cells.size() == 2 && !cells[1].trimmed().isEmpty())
            velocity = cells[1].toDouble(&okVelocity);
        else
            okVelocity = cells.size() == 2;  // an empty cell: no measurement in that frame
        if (!okTime || !okVelocity || !std::isfinite(t) || (!std::isnan(velocity) && !std::isfinite(velocity)))
            throw TissueTraceError(path, nb::TrCore::tr("line %1 is not a time and a velocity: '%2'").arg(line).arg(QString::fromUtf8(text)));
        if (!trace.time_s.empty() && !(t > trace.time_s.back()))
            throw TissueTraceError(path, nb::TrCore::tr("line %1: the time %2 s does not follow %3 s").arg(line).arg(t).arg(trace.time_s.back()));
        trace.time_s.push_back(t);
        trace.velocity_mm_s.push_back(velocity);
    }
    if (trace.time_s.size() < 2)
        throw TissueTraceError(path, nb::TrCore::tr("holds fewer than two measurements"));
    return trace;
}

std::vector<double> tissueVelocityAt(const TissueMotion& trace, const std::vector<double>& time_s)
{
    std::vector<double> out(time_s.size(), std::numeric_limits<double>::quiet_NaN());
    const std::vector<double>& t = trace.time_s;
    const std::vector<double>& v = trace.velocity_mm_s;
    const std::size_t m = std::min(t.size(), v.size());
    if (m < 2)
        return out;
    for (std::size_t i = 0; i < time_s.size(); ++i) {
        const double x = time_s[i];
        if (!(x >= t[0] && x <= t[m - 1]))
            continue;
        const std::size_t hi = std::max<std::size_t>(1, std::size_t(std::lower_bound(t.begin(), t.begin() + std::ptrdiff_t(m), x) - t.begin()));
        const std::size_t lo = hi - 1;
        const double w = (x - t[lo]) / (t[hi] - t[lo]);
        out[i] = v[lo] + w * (v[hi] - v[lo]);  // NaN when either is missing
    }
    return out;
}

}  // namespace nb
