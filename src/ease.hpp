// SPDX-License-Identifier: MIT
// Easing curves for tweens: the usual families, each in, out and in-out.
#pragma once
#include <cstdint>
#include <string_view>
#include "export.hpp"

namespace ds {

enum class Ease : uint8_t {
    Linear,
    QuadIn, QuadOut, QuadInOut,
    CubicIn, CubicOut, CubicInOut,
    QuartIn, QuartOut, QuartInOut,
    SineIn, SineOut, SineInOut,
    ExpoIn, ExpoOut, ExpoInOut,
    BackIn, BackOut, BackInOut,
    ElasticIn, ElasticOut, ElasticInOut,
    BounceIn, BounceOut, BounceInOut,
    Custom,  // a caller-supplied function of t
};

// 'linear, 'quad-in, 'bounce-in-out, … → Ease; false for an unknown name.
DOWNSTROKE_API bool ease_from_name(std::string_view name, Ease& out);
DOWNSTROKE_API std::string_view ease_name(Ease e);
// ease(0) = 0 and ease(1) = 1 for every curve; t outside [0,1] is clamped (semantics §6).
DOWNSTROKE_API double ease(Ease e, double t);

}  // namespace ds
