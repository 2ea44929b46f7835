#include "events.h"
#include "core/tr.h"

#include "fit_error.h"
#include "signal.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {

struct Peak {
    std::size_t peak = 0, trough = 0;
    double drop = 0.0;
};

// Hysteresis ("zigzag") peak finder: a peak is confirmed once the signal falls `h` below
// it, its trough once the signal rises `h` above that. Noise smaller than h never
// confirms anything, so no derivative thresholds are needed.
std::vector<Peak> findDrops(const std::vector<double>& f, double h)
{
    std::vector<Peak> peaks;
    if (f.empty())
        return peaks;
    bool falling = false;
    std::size_t maxI = 0, minI = 0;
    for (std::size_t i = 1; i < f.size(); ++i) {
        if (!falling) {
            if (f[i] > f[maxI])
                maxI = i;
            else if (f[maxI] - f[i] >= h) {
                falling = true;
                minI = i;
            }
        } else {
            if (f[i] < f[minI])
                minI = i;
            else if (f[i] - f[minI] >= h) {
                peaks.push_back({maxI, minI, f[maxI] - f[minI]});
                falling = false;
                maxI = i;
            }
        }
    }
    if (falling)
        peaks.push_back({maxI, minI, f[maxI] - f[minI]});
    return peaks;
}

// Sample noise from first differences (robust to the slow trend of the force).
double noiseFromDifferences(std::span<const double> f)
{
    if (f.size() < 3)
        return 0.0;
    std::vector<double> d;
    d.reserve(f.size() - 1);
    for (std::size_t i = 1; i < f.size(); ++i)
        d.push_back(std::fabs(f[i] - f[i - 1]));
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    return d[d.size() / 2] / (0.6745 * std::sqrt(2.0));
}

// The sharp peak sits between samples of the smoothed signal; look for it in the raw
// force near there, averaging a few samples before it so noise does not pick the maximum.
std::size_t refinePeak(std::span<const double> f, std::size_t around, std::size_t radius)
{
    const std::size_t lo = around > radius ? around - radius : 0;
    const std::size_t hi = std::min(f.size() - 1, around + radius);
    constexpr std::size_t k = 5;
    std::size_t best = around;
    double bestValue = -INFINITY;
    for (std::size_t i = lo; i <= hi; ++i) {
        const std::size_t from = i >= k - 1 ? i - (k - 1) : 0;
        double s = 0.0;
        for (std::size_t j = from; j <= i; ++j)
            s += f[j];
        s /= double(i - from + 1);
        if (s > bestValue) {
            bestValue = s;
            best = i;
        }
    }
    return best;
}

double trailingMean(std::span<const double> f, std::size_t i, std::size_t k)
{
    const std::size_t from = i + 1 >= k ? i + 1 - k : 0;
    double s = 0.0;
    for (std::size_t j = from; j <= i; ++j)
        s += f[j];
    return s / double(i - from + 1);
}

struct ContactTrial {
    double sse = INFINITY;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
};

// Each trial contact x_c needs the normal equations of  f ≈ o + a1·d + a2·d²,  d = max(0, x - x_c):
// sums of d^0..d^4 and f·d^0..d^2. Only samples past x_c have d > 0, a suffix once sorted by
// position, and Σ(x - x_c)^k expands into suffix sums of x^j; so after an O(n log n) set-up
// every trial is a binary search and a 3x3 solve instead of a pass over the samples.
// Positions are taken about the middle of the stroke so the expanded powers stay small
// (mm, a few tens) and the cancellation in the binomial sums is harmless.
class ContactMoments {
public:
    ContactMoments(std::span<const double> pos, std::span<const double> force)
        : n_(pos.size())
    {
        const auto [lo, hi] = std::minmax_element(pos.begin(), pos.end());
        origin_ = (*lo + *hi) / 2.0;
        std::vector<std::size_t> order(n_);
        for (std::size_t i = 0; i < n_; ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) { return pos[l] < pos[r]; });
        sorted_.resize(n_);
        for (auto& m : xPow_)
            m.assign(n_ + 1, 0.0);
        for (auto& m : fxPow_)
            m.assign(n_ + 1, 0.0);
        for (std::size_t r = n_; r-- > 0;) {
            const std::size_t i = order[r];
            const double u = pos[i] - origin_;
            sorted_[r] = u;
            double p = 1.0;
            for (int k = 0; k < 5; ++k) {
                xPow_[k][r] = xPow_[k][r + 1] + p;
                if (k < 3)
                    fxPow_[k][r] = fxPow_[k][r + 1] + force[i] * p;
                p *= u;
            }
        }
        for (double f : force) {
            sumF_ += f;
            sumSquares_ += f * f;
        }
    }

    ContactTrial trial(double xc) const
    {
        const double c = xc - origin_;
        const std::size_t r = std::size_t(std::upper_bound(sorted_.begin(), sorted_.end(), c) - sorted_.begin());
        // Σ_{x > x_c} (u - c)^k from the suffix sums of u^j (binomial expansion).
        double d[5], fd[3];
        const double m = -c;
        const double mp[5] = {1.0, m, m * m, m * m * m, m * m * m * m};
        constexpr double binom[5][5] = {{1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
        for (int k = 0; k < 5; ++k) {
            d[k] = 0.0;
            for (int j = 0; j <= k; ++j)
                d[k] += binom[k][j] * xPow_[j][r] * mp[k - j];
            if (k < 3) {
                fd[k] = 0.0;
                for (int j = 0; j <= k; ++j)
                    fd[k] += binom[k][j] * fxPow_[j][r] * mp[k - j];
            }
        }
        Eigen::Matrix3d S;
        S << double(n_), d[1], d[2],
             d[1], d[2], d[3],
             d[2], d[3], d[4];
        const Eigen::Vector3d b(sumF_, fd[1], fd[2]);
        ContactTrial t;
        // Columns 1, d, d² with d in mm: the normal equations are well enough conditioned.
        const Eigen::LDLT<Eigen::Matrix3d> ldlt(S);
        if (ldlt.info() != Eigen::Success || r + 3 > n_)
            return t;
        t.x = ldlt.solve(b);
        // The capsule only pushes back: a1 < 0 would make the force dip below the offset
        // just past contact. Where noise hides the first ~0.2 mm of a mostly quadratic
        // force, that dip lets an early contact with a1 < 0 fit as well as the true one
        // (liver 2), so the bound a1 >= 0 is active then: solve for offset and a2 alone.
        if (t.x(1) < 0.0) {
            Eigen::Matrix2d S2;
            S2 << double(n_), d[2], d[2], d[4];
            const Eigen::Vector2d b2(sumF_, fd[2]);
            const Eigen::LDLT<Eigen::Matrix2d> l2(S2);
            if (l2.info() != Eigen::Success)
                return t;
            const Eigen::Vector2d x2 = l2.solve(b2);
            t.x = Eigen::Vector3d(x2(0), 0.0, x2(1));
        }
        // At the least-squares solution SSE = Σf² - bᵀx (also with a1 held at 0: b(1) is
        // then multiplied by 0).
        const double sse = std::max(0.0, sumSquares_ - b.dot(t.x));
        t.sse = std::isfinite(sse) ? sse : INFINITY;
        return t;
    }

private:
    std::size_t n_;
    double origin_ = 0.0, sumF_ = 0.0, sumSquares_ = 0.0;
    std::vector<double> sorted_;
    std::vector<double> xPow_[5];   // suffix sums of u^k over the sorted samples
    std::vector<double> fxPow_[3];  // suffix sums of f·u^k
};

RunEvent eventAt(const Run& run, std::size_t i, double offset)
{
    return {i, run.time_s[i], run.position_mm[i], run.force_N[i] - offset};
}

// Share of the loading (contact to puncture) the contact fit uses.
constexpr double kContactFitSpan = 0.55;

}  // namespace

ContactFit fitContact(std::span<const double> pos, std::span<const double> force)
{
    const std::size_t n = std::min(pos.size(), force.size());
    if (n < 8)
        throw FitError(nb::TrCore::tr("too few samples before the puncture (%1) to fit the contact")
                           .arg(n));
    pos = pos.first(n);
    force = force.first(n);
    const double lo = *std::min_element(pos.begin(), pos.end());
    // At least a few samples must lie past the contact for a1, a2 to be defined.
    std::vector<double> sorted(pos.begin(), pos.end());
    std::sort(sorted.begin(), sorted.end());
    const double hi = sorted[n - 4];
    if (!(hi > lo))
        throw FitError(nb::TrCore::tr("the needle does not move before the puncture"));
    const ContactMoments moments(pos, force);
    auto tryContact = [&](double xc) { return moments.trial(xc); };

    // Coarse grid, then golden section around the best cell: the error is smooth between
    // samples but not convex over the whole stroke.
    constexpr int grid = 200;
    const double step = (hi - lo) / grid;
    int best = 0;
    double bestSse = INFINITY;
    for (int k = 0; k <= grid; ++k) {
        const double s = tryContact(lo + k * step).sse;
        if (s < bestSse) {
            bestSse = s;
            best = k;
        }
    }
    double a = lo + std::max(0, best - 1) * step;
    double b = lo + std::min(grid, best + 1) * step;
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = tryContact(c).sse, fd = tryContact(d).sse;
    for (int it = 0; it < 40 && (b - a) > 1e-6; ++it) {
        if (fc < fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = tryContact(c).sse;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = tryContact(d).sse;
        }
    }
    double xc = (a + b) / 2.0;
    ContactTrial t = tryContact(xc);
    if (const double gridX = lo + best * step; bestSse < t.sse) {
        xc = gridX;
        t = tryContact(xc);
    }
    if (!std::isfinite(t.sse))
        throw FitError(nb::TrCore::tr("the contact fit failed (degenerate samples)"));
    ContactFit fit;
    fit.contact_mm = xc;
    fit.offset_N = t.x(0);
    fit.stiffness = {t.x(1), t.x(2)};
    double sse = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = std::max(0.0, pos[i] - xc);
        const double r = force[i] - (t.x(0) + t.x(1) * d + t.x(2) * d * d);
        sse += r * r;
    }
    fit.rms_N = std::sqrt(sse / double(n));
    return fit;
}

InsertionEvents detectEvents(const Run& run, const EventOptions& options)
{
    const std::size_t total = run.size();
    if (total < 20)
        throw FitError(nb::TrCore::tr("too few samples (%1) for event detection").arg(total));
    for (std::size_t i = 0; i < total; ++i)
        if (!std::isfinite(run.position_mm[i]) || !std::isfinite(run.force_N[i]) || !std::isfinite(run.time_s[i]))
            throw FitError(nb::TrCore::tr("sample %1 is not a finite number").arg(i + 1));
    const std::size_t end =
        std::size_t(std::max_element(run.position_mm.begin(), run.position_mm.end()) - run.position_mm.begin()) + 1;
    const double travel = run.position_mm[end - 1] - run.position_mm[0];
    const double duration = run.time_s[end - 1] - run.time_s[0];
    if (end < 20 || !(travel > 0.0) || !(duration > 0.0))
        throw FitError(nb::TrCore::tr("the needle does not move forward"));

    const std::span<const double> force(run.force_N.data(), end);
    const std::span<const double> pos(run.position_mm.data(), end);
    const std::span<const double> time(run.time_s.data(), end);
    const double speed = travel / duration;
    const int window = std::max(1, windowForDuration(time, options.smoothing_mm / speed) | 1);
    const std::vector<double> smooth = movingAverage(force, window);

    InsertionEvents ev;
    ev.noise_N = noiseFromDifferences(force);
    const double smoothNoise = ev.noise_N / std::sqrt(double(window));
    const double h = std::max(options.minInternalDrop_N, 8.0 * smoothNoise);
    const std::vector<Peak> drops = findDrops(smooth, h);

    // The first sharp drop after a rise is the puncture, provided the force before it
    // really rose from the contact (checked against the fitted offset, which a rough
    // baseline cannot give). Only the first few candidates are tried: each costs a fit.
    std::optional<Peak> main;
    std::size_t mainNo = 0, punctureIdx = 0;
    ContactFit contact;
    const std::size_t radius = std::size_t(window);
    int tried = 0;
    for (std::size_t k = 0; k < drops.size() && !main && tried < 5; ++k) {
        const double base = *std::min_element(smooth.begin(), smooth.begin() + std::ptrdiff_t(drops[k].peak) + 1);
        const double rise = smooth[drops[k].peak] - base;
        if (drops[k].drop < std::max(options.minPunctureDrop_N, options.punctureDropFraction * rise))
            continue;
        ++tried;
        const std::size_t idx = refinePeak(force, drops[k].peak, radius);
        if (idx < 8)
            continue;
        ContactFit c = fitContact(pos.first(idx + 1), force.first(idx + 1));
        // The capsule tents over the tip just before it tears and the force rises faster
        // than the quadratic there; fitting the contact to the loading before that keeps the
        // tenting from pulling x_s1 (and a1 with it) off.
        if (pos[idx] > c.contact_mm) {
            const double limit = c.contact_mm + kContactFitSpan * (pos[idx] - c.contact_mm);
            std::size_t m = 0;
            while (m <= idx && pos[m] <= limit)
                ++m;
            if (m >= 8 && m < idx)
                c = fitContact(pos.first(m), force.first(m));
        }
        const double peakForce = trailingMean(force, idx, 5) - c.offset_N;
        if (peakForce < std::max(options.minPunctureDrop_N, 0.5 * drops[k].drop) || !(pos[idx] > c.contact_mm))
            continue;
        main = drops[k];
        mainNo = k;
        punctureIdx = idx;
        contact = c;
    }
    if (!main)
        throw FitError(nb::TrCore::tr("no puncture: the force never rises from contact and then "
                                                               "drops sharply (by %1 N or %2 % of its peak)")
                           .arg(options.minPunctureDrop_N)
                           .arg(options.punctureDropFraction * 100.0));
    ev.zeroOffset_N = contact.offset_N;
    ev.stiffness = contact.stiffness;
    ev.stiffnessRms_N = contact.rms_N;

    std::size_t ci = 0;
    while (ci < punctureIdx && pos[ci] < contact.contact_mm)
        ++ci;
    ev.contact = eventAt(run, ci, ev.zeroOffset_N);
    ev.contact.position_mm = contact.contact_mm;
    ev.contact.force_N = smooth[ci] - ev.zeroOffset_N;
    if (ci > 0 && pos[ci] > pos[ci - 1]) {
        const double u = (contact.contact_mm - pos[ci - 1]) / (pos[ci] - pos[ci - 1]);
        ev.contact.time_s = time[ci - 1] + std::clamp(u, 0.0, 1.0) * (time[ci] - time[ci - 1]);
    }

    ev.puncture = eventAt(run, punctureIdx, ev.zeroOffset_N);
    ev.puncture.force_N = trailingMean(force, punctureIdx, 5) - ev.zeroOffset_N;

    // The drop ends where the smoothed force first comes within noise of its trough.
    std::size_t relax = main->trough;
    for (std::size_t i = main->peak; i < main->trough; ++i) {
        if (smooth[i] <= smooth[main->trough] + 2.0 * smoothNoise) {
            relax = i;
            break;
        }
    }
    ev.relaxation = eventAt(run, relax, ev.zeroOffset_N);
    ev.relaxation->force_N = smooth[relax] - ev.zeroOffset_N;

    for (std::size_t k = mainNo + 1; k < drops.size(); ++k) {
        const std::size_t i = refinePeak(force, drops[k].peak, radius);
        RunEvent e = eventAt(run, i, ev.zeroOffset_N);
        e.force_N = trailingMean(force, i, 5) - ev.zeroOffset_N;
        ev.internalPunctures.push_back(e);
    }
    return ev;
}

void applyEventLabels(InsertionEvents& ev, const Run& run, const Labels& labels, double window_s)
{
    auto find = [&](const QString& name) -> const Label* {
        for (const Label& l : labels)
            if (l.isPoint() && l.label.compare(name, Qt::CaseInsensitive) == 0)
                return &l;
        return nullptr;
    };
    const std::size_t n = run.size();
    if (n == 0)
        return;
    auto nearest = [&](double t) {
        const auto it = std::lower_bound(run.time_s.begin(), run.time_s.end(), t);
        std::size_t i = std::size_t(it - run.time_s.begin());
        if (i >= n)
            return n - 1;
        if (i > 0 && t - run.time_s[i - 1] < run.time_s[i] - t)
            --i;
        return i;
    };
    auto outside = [&](const Label& l) {
        return l.start_s < run.time_s.front() || l.start_s > run.time_s.back();
    };

    if (const Label* c = find(QStringLiteral("contact"))) {
        if (outside(*c))
            throw FitError(nb::TrCore::tr("the contact label at %1 s is outside the run (%2 to %3 s)")
                               .arg(c->start_s).arg(run.time_s.front()).arg(run.time_s.back()));
        const double t = c->start_s;
        const std::size_t hi = std::size_t(std::lower_bound(run.time_s.begin(), run.time_s.end(), t) - run.time_s.begin());
        double x = run.position_mm[std::min(hi, n - 1)];
        if (hi > 0 && hi < n && run.time_s[hi] > run.time_s[hi - 1]) {
            const double u = (t - run.time_s[hi - 1]) / (run.time_s[hi] - run.time_s[hi - 1]);
            x = run.position_mm[hi - 1] + u * (run.position_mm[hi] - run.position_mm[hi - 1]);
        }
        // As the thesis zeroed its forces: the mean of everything before the contact.
        const double oldOffset = ev.zeroOffset_N;
        if (hi > 0) {
            double sum = 0.0;
            for (std::size_t i = 0; i < hi; ++i)
                sum += run.force_N[i];
            ev.zeroOffset_N = sum / double(hi);
        }
        const double shift = oldOffset - ev.zeroOffset_N;
        for (RunEvent* e : {&ev.contact, &ev.puncture})
            e->force_N += shift;
        if (ev.relaxation)
            ev.relaxation->force_N += shift;
        for (RunEvent& e : ev.internalPunctures)
            e.force_N += shift;
        ev.contact.index = nearest(t);
        ev.contact.time_s = t;
        ev.contact.position_mm = x;
        ev.contact.force_N = run.force_N[ev.contact.index] - ev.zeroOffset_N;
    }
    if (const Label* p = find(QStringLiteral("puncture"))) {
        if (outside(*p))
            throw FitError(nb::TrCore::tr("the puncture label at %1 s is outside the run (%2 to %3 s)")
                               .arg(p->start_s).arg(run.time_s.front()).arg(run.time_s.back()));
        // A label placed on a video frame is known to a frame; the force peak near it is the puncture.
        const std::size_t lo = nearest(p->start_s - window_s), hi = nearest(p->start_s + window_s);
        std::size_t best = nearest(p->start_s);
        for (std::size_t i = lo; i <= hi; ++i)
            if (run.force_N[i] > run.force_N[best])
                best = i;
        ev.puncture.index = best;
        ev.puncture.time_s = run.time_s[best];
        ev.puncture.position_mm = run.position_mm[best];
        ev.puncture.force_N = trailingMean(run.force_N, best, 5) - ev.zeroOffset_N;  // as detection measures it
    }
    if (!(ev.puncture.position_mm > ev.contact.position_mm))
        throw FitError(nb::TrCore::tr("the puncture (%1 mm) is not past the contact (%2 mm)")
                           .arg(ev.puncture.position_mm).arg(ev.contact.position_mm));
}

InsertionEvents eventsWithLabels(const Run& run, const Labels& labels)
{
    InsertionEvents ev;
    try {
        ev = detectEvents(run);
    } catch (const FitError&) {
        if (!marksEvent(labels, QStringLiteral("contact")) || !marksEvent(labels, QStringLiteral("puncture")))
            throw;
    }
    applyEventLabels(ev, run, labels);
    return ev;
}

}  // namespace nb
