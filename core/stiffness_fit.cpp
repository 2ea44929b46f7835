#include "stiffness_fit.h"

#include "core/run_plausibility.h"
#include "core/tr.h"

#include "fit_error.h"
#include "statistics.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {

// Polynomial without constant term, x^1..x^degree, by QR.
Eigen::VectorXd polyFit(const StiffnessSegment& s, int degree, std::vector<double>* residuals)
{
    const auto n = Eigen::Index(s.depth_mm.size());
    Eigen::MatrixXd A(n, degree);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        double p = 1.0;
        for (int k = 0; k < degree; ++k) {
            p *= s.depth_mm[std::size_t(i)];
            A(i, k) = p;
        }
        y(i) = s.force_N[std::size_t(i)];
    }
    const Eigen::VectorXd c = A.colPivHouseholderQr().solve(y);
    const Eigen::VectorXd r = y - A * c;
    residuals->assign(r.data(), r.data() + r.size());
    return c;
}

bool springValid(double a, double b, double xMax)
{
    return b > 0.0 && a * xMax + b > 0.0 && std::isfinite(a) && std::isfinite(b);
}

double springSse(const StiffnessSegment& s, double a, double b)
{
    double sse = 0.0;
    for (std::size_t i = 0; i < s.depth_mm.size(); ++i) {
        const double x = s.depth_mm[i];
        const double r = s.force_N[i] - x / (a * x + b);
        sse += r * r;
    }
    return sse;
}

SpringStiffnessFit fitSpring(const StiffnessSegment& s)
{
    SpringStiffnessFit fit;
    const std::size_t n = s.depth_mm.size();
    const double xMax = *std::max_element(s.depth_mm.begin(), s.depth_mm.end());
    const double fMax = *std::max_element(s.force_N.begin(), s.force_N.end());
    // Start from x/f = a·x + b, which is linear, on the points well above the noise.
    Eigen::MatrixXd A(Eigen::Index(n), 2);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(Eigen::Index(n));
    Eigen::Index m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (s.force_N[i] > 0.2 * fMax && s.depth_mm[i] > 0.0) {
            A(m, 0) = s.depth_mm[i];
            A(m, 1) = 1.0;
            y(m) = s.depth_mm[i] / s.force_N[i];
            ++m;
        }
    }
    double a = 0.0, b = fMax > 0.0 ? xMax / fMax : 1.0;
    if (m >= 2) {
        const Eigen::Vector2d p = A.topRows(m).colPivHouseholderQr().solve(y.head(m));
        if (springValid(p(0), p(1), xMax)) {
            a = p(0);
            b = p(1);
        }
    }
    if (!springValid(a, b, xMax))
        return fit;
    // Levenberg-Marquardt on the force residuals; steps that would put the spring's pole
    // inside the data range are rejected like steps that increase the error.
    double sse = springSse(s, a, b);
    double lambda = 1e-3;
    for (int it = 0; it < 100; ++it) {
        Eigen::Matrix2d JtJ = Eigen::Matrix2d::Zero();
        Eigen::Vector2d Jtr = Eigen::Vector2d::Zero();
        for (std::size_t i = 0; i < n; ++i) {
            const double x = s.depth_mm[i];
            const double den = a * x + b;
            const Eigen::Vector2d j(-x * x / (den * den), -x / (den * den));
            const double r = s.force_N[i] - x / den;
            JtJ.noalias() += j * j.transpose();
            Jtr.noalias() += j * r;
        }
        bool improved = false;
        for (int tries = 0; tries < 20 && !improved; ++tries) {
            Eigen::Matrix2d M = JtJ;
            M.diagonal() *= 1.0 + lambda;
            const Eigen::Vector2d step = M.ldlt().solve(-Jtr);
            const double na = a + step(0), nb = b + step(1);
            if (springValid(na, nb, xMax)) {
                const double nsse = springSse(s, na, nb);
                if (nsse < sse) {
                    const double gain = sse - nsse;
                    a = na;
                    b = nb;
                    sse = nsse;
                    lambda = std::max(lambda / 10.0, 1e-12);
                    improved = true;
                    if (gain < 1e-12 * std::max(sse, 1e-30)) {
                        fit.converged = true;
                        it = 100;
                    }
                    break;
                }
            }
            lambda *= 10.0;
        }
        if (!improved) {
            fit.converged = true;  // no step reduces the error: a minimum
            break;
        }
    }
    fit.a_per_N = a;
    fit.b_mm_per_N = b;
    std::vector<double> res(n);
    for (std::size_t i = 0; i < n; ++i)
        res[i] = s.force_N[i] - s.depth_mm[i] / (a * s.depth_mm[i] + b);
    fit.rms_N = rms(res);
    fit.r2 = rSquared(s.force_N, res);
    return fit;
}

}  // namespace

StiffnessSegment stiffnessSegment(const Run& run, const InsertionEvents& events)
{
    StiffnessSegment s;
    const std::size_t end = std::min(events.puncture.index + 1, run.size());
    for (std::size_t i = 0; i < end; ++i) {
        const double d = run.position_mm[i] - events.contact.position_mm;
        if (d < 0.0)
            continue;
        s.depth_mm.push_back(d);
        s.force_N.push_back(run.force_N[i] - events.zeroOffset_N);
    }
    return s;
}

StiffnessFit fitStiffness(const StiffnessSegment& segment)
{
    const std::size_t n = std::min(segment.depth_mm.size(), segment.force_N.size());
    if (n < 4 || segment.depth_mm.size() != segment.force_N.size())
        throw FitError(nb::TrCore::tr("too few samples (%1) between contact and puncture").arg(n));
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(segment.depth_mm[i]) || !std::isfinite(segment.force_N[i]))
            throw FitError(nb::TrCore::tr("stiffness sample %1 is not a finite number").arg(i + 1));
        else if (std::abs(segment.force_N[i]) > kNoLoadCellReads_N)  // one such sample is the whole fit
            throw FitError(nb::TrCore::tr("stiffness sample %1 is %2 N: a corrupt sample")
                               .arg(i + 1)
                               .arg(segment.force_N[i], 0, 'g', 4));
    if (*std::max_element(segment.depth_mm.begin(), segment.depth_mm.end()) <= 0.0)
        throw FitError(nb::TrCore::tr("no depth past the contact point"));

    StiffnessFit fit;
    fit.samples = n;
    std::vector<double> res;
    const Eigen::VectorXd q = polyFit(segment, 2, &res);
    fit.quadratic.model = {q(0), q(1)};
    fit.quadratic.rms_N = rms(res);
    fit.quadratic.r2 = rSquared(segment.force_N, res);
    const Eigen::VectorXd c = polyFit(segment, 3, &res);
    fit.cubic = {c(0), c(1), c(2), rms(res), rSquared(segment.force_N, res)};
    fit.spring = fitSpring(segment);
    return fit;
}

StiffnessSummary fitStiffnessRuns(std::span<const StiffnessSegment> segments)
{
    if (segments.empty())
        throw FitError(nb::TrCore::tr("no runs to fit"));
    StiffnessSummary sum;
    StiffnessSegment all;
    std::vector<double> a1, a2;
    for (const StiffnessSegment& s : segments) {
        sum.runs.push_back(fitStiffness(s));
        a1.push_back(sum.runs.back().quadratic.model.a1_N_per_mm);
        a2.push_back(sum.runs.back().quadratic.model.a2_N_per_mm2);
        all.depth_mm.insert(all.depth_mm.end(), s.depth_mm.begin(), s.depth_mm.end());
        all.force_N.insert(all.force_N.end(), s.force_N.begin(), s.force_N.end());
    }
    sum.pooled = fitStiffness(all);
    sum.meanOfRuns = {mean(a1), mean(a2)};
    sum.stdDevOfRuns = {sampleStdDev(a1), sampleStdDev(a2)};
    return sum;
}

}  // namespace nb
