#include "tissue_trace.h"
#include "statistics.h"
#include "tr.h"

#include <Eigen/Dense>
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

namespace {

// The polynomial in x (T's columns) of the degree that minimises nf·ln(mean square) + cost·degree,
// fitted to the samples `use` marks, and evaluated at every sample.
SlideTissue smoothestExplaining(const Eigen::MatrixXd& T, const Eigen::VectorXd& u, const std::vector<bool>& use, double nf, double cost)
{
    const auto m = u.size();
    Eigen::Index kept = 0;
    for (bool b : use)
        kept += b;
    Eigen::MatrixXd A(kept, T.cols());
    Eigen::VectorXd y(kept);
    for (Eigen::Index r = 0, k = 0; r < m; ++r)
        if (use[std::size_t(r)])
            A.row(k) = T.row(r), y(k++) = u(r);
    const double floor = 1e-12 * (y.squaredNorm() / double(std::max<Eigen::Index>(1, kept)) + 1e-300);
    const int most = int(std::min<Eigen::Index>(T.cols(), std::max<Eigen::Index>(1, kept)));
    SlideTissue out;
    double bestScore = INFINITY;
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(T.cols());
    for (int terms = 1; terms <= most; ++terms) {
        const Eigen::VectorXd c = A.leftCols(terms).colPivHouseholderQr().solve(y);
        const double meanSquare = std::max(floor, (y - A.leftCols(terms) * c).squaredNorm() / double(kept));
        const double score = nf * std::log(meanSquare) + cost * (terms - 1);
        if (score < bestScore) {
            bestScore = score, out.degree = terms - 1;
            coefficients.setZero();
            coefficients.head(terms) = c;
        }
    }
    const Eigen::VectorXd fitted = T * coefficients;
    out.velocity.assign(fitted.data(), fitted.data() + m);
    return out;
}

}  // namespace

SlideTissue tissueOverSlide(std::span<const double> time_s, std::span<const double> velocity, double measurements)
{
    // Each term beyond the mean must explain the readings far beyond their scatter: the degree
    // taken minimises measurements·ln(mean square) + kTermCost·degree, about an F ratio of 10 a
    // term (p < 0.005 for a slide of 30 frames), so that noise does not pass for a change in the
    // creep while a clean trace keeps the shape it shows.
    constexpr double kTermCost = 10.0;
    constexpr int kMostTerms = 7;
    // A reading this many times the scatter (robustSigma) off the curve is
    // motion the curve cannot follow (the slab arriving at the plate as the slide begins: 4 to 9
    // mm/s over a few frames, liver 3) or a misreading: left out of the curve.
    constexpr double kBeyondScatter = 5.0;
    const auto m = Eigen::Index(std::min(time_s.size(), velocity.size()));
    if (m == 0)
        return {};
    const double nf = std::max(1.0, std::min(measurements, double(m)));
    const int most = int(std::clamp<double>(nf - 2.0, 1.0, kMostTerms));
    const double t0 = time_s[0], span = std::max(1e-9, time_s[std::size_t(m - 1)] - t0);
    const Eigen::Map<const Eigen::VectorXd> u(velocity.data(), m);
    Eigen::MatrixXd T(m, most);
    for (Eigen::Index r = 0; r < m; ++r) {
        const double x = 2.0 * (time_s[std::size_t(r)] - t0) / span - 1.0;
        for (int j = 0; j < most; ++j)
            T(r, j) = std::pow(x, j);
    }
    std::vector<bool> use(std::size_t(m), true);
    SlideTissue first = smoothestExplaining(T, u, use, nf, kTermCost);
    std::vector<double> away(static_cast<std::size_t>(m));
    for (Eigen::Index r = 0; r < m; ++r)
        away[std::size_t(r)] = std::fabs(u(r) - first.velocity[std::size_t(r)]);
    const double scatter = robustSigma(away);
    std::size_t beyond = 0;
    for (std::size_t r = 0; r < use.size(); ++r)
        if (away[r] > kBeyondScatter * scatter && away[r] > 1e-9 * (std::fabs(u(Eigen::Index(r))) + 1e-300))
            use[r] = false, ++beyond;
    SlideTissue out = beyond == 0 || 2 * beyond > use.size()
                          ? std::move(first)
                          : smoothestExplaining(T, u, use, nf * double(use.size() - beyond) / double(use.size()), kTermCost);
    // A clean trace (a tracker that reads the frames nearly without noise) may show motion no
    // smooth curve follows: the slab arriving, stopping at the slide's end. Where the readings'
    // scatter about the curve is far beyond their own noise (from their second differences frame
    // to frame; both robust, so that a misread frame does not move them), the readings are taken
    // as they are.
    constexpr double kCurveToNoise = 9.0;
    const auto stride = std::max<Eigen::Index>(1, Eigen::Index(double(m) / nf));
    std::vector<double> second;
    for (Eigen::Index r = 2 * stride; r < m; r += stride)
        second.push_back(std::fabs(u(r) - 2.0 * u(r - stride) + u(r - 2 * stride)));
    if (second.size() >= 3) {
        const double noise = noiseFromSecondDifferences(std::move(second));
        std::vector<double> left(static_cast<std::size_t>(m));
        for (Eigen::Index r = 0; r < m; ++r)
            left[std::size_t(r)] = std::fabs(u(r) - out.velocity[std::size_t(r)]);
        const double curveScatter = robustSigma(std::move(left));
        if (curveScatter * curveScatter > kCurveToNoise * noise * noise) {
            out.velocity.assign(velocity.begin(), velocity.begin() + m);
            out.degree = -1;
        }
    }
    return out;
}

}  // namespace nb
