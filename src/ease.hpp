// Easing curves for tweens: the usual families, each in, out and in-out.
#pragma once
#include <cstdint>
#include <string_view>

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
bool ease_from_name(std::string_view name, Ease& out);
std::string_view ease_name(Ease e);
// ease(0) = 0 and ease(1) = 1 for every curve; t outside [0,1] is clamped (semantics §6).
double ease(Ease e, double t);

}  // namespace ds
