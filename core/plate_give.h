#pragma once
// How far a slab gives against the plate it rests on, read where the needle carries it into
// that plate (models.md 5, phase a: needle and tissue move together until the tissue breaks
// away). While carried, the tissue moves as the needle does, so the force's rise with the
// needle's position is the contact's stiffness. In phase c the slab rests against the same
// contact, held there by the friction: as the friction changes (the needle slowing), it moves
// by ΔF/k, and the relative velocity is v - Ḟ/k, not v. Where the contact is soft (a slab
// resting on the soft part of its plate, whose friction is small: liver 3 moving in) that
// motion is a large share of the slow speeds that pin C, and a sliding line written in the
// needle's speed carries it into C (Cp 15-40 % high with the residual at the noise); the run's
// own sliding samples cannot tell it from C, their Ḟ barely changing through a slowing stroke.

#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace nb {

struct PlateGive {
    double stiffness_N_per_m = 0.0;  // the force's rise per metre of the needle's carried travel
    // The largest force the contact was seen to hold at that stiffness (N, a magnitude), its
    // losses at contact taken out: beyond it the rise steepened (the plate's stiff part) or the
    // tissue broke away, so a slab at rest beyond it is taken not to give.
    double upTo_N = 0.0;
    // The step the force takes as the moving tissue touches the plate, over the speed there
    // (N·s/m): the contact's losses, which lift the carried force above the one at rest.
    double losses_Ns_per_m = 0.0;
    std::size_t rises = 0;           // carried stretches it is read from
    // Each rise's break-away: where its stretch began (the tissue carried from there), the
    // sample where it let go, and how far into the contact it was then (m, a magnitude). Its
    // motion once it rests starts from there (restingTissueVelocity).
    struct BreakAway {
        std::size_t carriedFrom, at;
        double depth_m;
    };
    std::vector<BreakAway> breakAways;
};

// `x_m`, `v_m_s`: the needle's smoothed position and velocity; `force_N`: the force averaged over
// a few samples only, with the holder's inertia removed (a fast stroke crosses a soft contact
// within a few of the fit's smoothing windows), and `smooth_N` the same over `window` samples,
// which finds the rise. `carried`: [from, to) sample ranges in which the tissue is carried in
// the direction `sign` (+1, -1), each holding where it breaks away: the force's extreme that
// way, sought up to a few samples past `to`, which it must fall from. `noise_N`: `force_N`'s
// noise. nullopt where fewer than two stretches, or fewer than half of them, show a rise to a
// break-away.
std::optional<PlateGive> plateGive(std::span<const double> x_m, std::span<const double> v_m_s, std::span<const double> smooth_N,
                                   std::span<const double> force_N, std::span<const std::pair<std::size_t, std::size_t>> carried, int sign,
                                   double noise_N, std::size_t window);

// The tissue's velocity (m/s, signed as the needle's) from each break-away of `give` to the
// next turning point, NaN elsewhere: the contact as a spring k with its losses in parallel
// (Kelvin-Voigt), pressed by the friction `force_N` (as measured: the holder's inertia
// removed), k·s + c·ṡ = F, started where the rise left it and held at the depth of `upTo_N`
// (the plate's stiff part behind it). Without losses the slab follows the force at once (Ḟ/k).
std::vector<double> restingTissueVelocity(const PlateGive& give, std::span<const double> time_s, std::span<const double> v_m_s,
                                          std::span<const double> force_N, int sign);

// `rows` (sorted sliding samples) without those of each slide moving `sign`-wards that fall
// within the slab's settling after it lets go, where the slide starts on the contact's soft part
// or near it: its way there is not the contact's law (plate_give.cpp).
std::vector<std::size_t> withoutSettling(const std::vector<std::size_t>& rows, const PlateGive& give, std::span<const double> time_s,
                                         std::span<const double> v_m_s, std::span<const double> force_N, int sign);

// `rows` (sorted sliding samples) without those before a break-away the give was read from, in
// its stretch: there the tissue was still carried, however well the force there may pass for
// sliding (a carried rise at the needle's top speed can cross the sliding line).
std::vector<std::size_t> withoutCarried(const std::vector<std::size_t>& rows, const PlateGive& give);

}  // namespace nb
