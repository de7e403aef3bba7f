// SPDX-License-Identifier: MIT
#include "ease.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace ds {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kBack = 5, kElastic = 6;  // family indexes, in kFamilies order

// The eased "in" curve of each family; "out" and "in-out" derive from it.
double in_curve(int family, double t) {
    switch (family) {
        case 0: return t * t;
        case 1: return t * t * t;
        case 2: return t * t * t * t;
        case 3: return 1 - std::cos(t * kPi / 2);
        case 4: return t == 0 ? 0 : std::pow(2, 10 * t - 10);
        case kBack: {
            constexpr double c1 = 1.70158, c3 = c1 + 1;
            return c3 * t * t * t - c1 * t * t;
        }
        case kElastic: {
            constexpr double c4 = 2 * kPi / 3;
            if (t == 0 || t == 1) return t;
            return -std::pow(2, 10 * t - 10) * std::sin((t * 10 - 10.75) * c4);
        }
        default: {  // bounce: the mirror of the out curve
            double u = 1 - t;
            constexpr double n1 = 7.5625, d1 = 2.75;
            double out;
            if (u < 1 / d1) out = n1 * u * u;
            else if (u < 2 / d1) { u -= 1.5 / d1; out = n1 * u * u + 0.75; }
            else if (u < 2.5 / d1) { u -= 2.25 / d1; out = n1 * u * u + 0.9375; }
            else { u -= 2.625 / d1; out = n1 * u * u + 0.984375; }
            return 1 - out;
        }
    }
}

// easings.net's in-out for back and elastic are not mirrored in curves: they
// overshoot by their own constants.
double back_in_out(double t) {
    constexpr double c2 = 1.70158 * 1.525;
    // u * u rather than pow(u, 2): the same value, and the Scheme reference
    // can write it the same way.
    if (t < 0.5) {
        const double u = 2 * t;
        return (u * u * ((c2 + 1) * 2 * t - c2)) / 2;
    }
    const double u = 2 * t - 2;
    return (u * u * ((c2 + 1) * (t * 2 - 2) + c2) + 2) / 2;
}

double elastic_in_out(double t) {
    constexpr double c5 = 2 * kPi / 4.5;
    if (t == 0 || t == 1) return t;
    return t < 0.5 ? -(std::pow(2, 20 * t - 10) * std::sin((20 * t - 11.125) * c5)) / 2
                   : (std::pow(2, -20 * t + 10) * std::sin((20 * t - 11.125) * c5)) / 2 + 1;
}

constexpr std::array<std::string_view, 8> kFamilies = {"quad", "cubic", "quart", "sine",
                                                      "expo", "back",  "elastic", "bounce"};
constexpr std::array<std::string_view, 3> kVariants = {"in", "out", "in-out"};

}  // namespace

bool ease_from_name(std::string_view name, Ease& out) {
    if (name == "linear") {
        out = Ease::Linear;
        return true;
    }
    for (size_t f = 0; f < kFamilies.size(); ++f) {
        const auto& fam = kFamilies[f];
        if (name.size() <= fam.size() + 1 || name.substr(0, fam.size()) != fam ||
            name[fam.size()] != '-')
            continue;
        const auto rest = name.substr(fam.size() + 1);
        for (size_t v = 0; v < kVariants.size(); ++v)
            if (rest == kVariants[v]) {
                out = static_cast<Ease>(1 + 3 * f + v);
                return true;
            }
    }
    return false;
}

std::string_view ease_name(Ease e) {
    static const auto names = [] {
        std::array<std::string, 26> n;
        n[0] = "linear";
        for (size_t f = 0; f < kFamilies.size(); ++f)
            for (size_t v = 0; v < kVariants.size(); ++v)
                n[1 + 3 * f + v] = std::string(kFamilies[f]) + "-" + std::string(kVariants[v]);
        n[25] = "custom";
        return n;
    }();
    return names[static_cast<size_t>(e)];
}

double ease(Ease e, double t) {
    // The ends are pinned: sin/cos round off, and a tween must start and stop
    // exactly where it was told to.
    if (!(t > 0)) return 0;
    if (t >= 1) return 1;
    if (e == Ease::Linear || e == Ease::Custom) return t;
    const int index = static_cast<int>(e) - 1;
    const int family = index / 3, variant = index % 3;
    switch (variant) {
        case 0: return in_curve(family, t);
        case 1: return 1 - in_curve(family, 1 - t);
        default:
            if (family == kBack) return back_in_out(t);
            if (family == kElastic) return elastic_in_out(t);
            return t < 0.5 ? in_curve(family, 2 * t) / 2 : 1 - in_curve(family, 2 - 2 * t) / 2;
    }
}

}  // namespace ds
