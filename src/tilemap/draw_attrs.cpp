// SPDX-License-Identifier: MIT
#include "draw_attrs.hpp"

#include <array>
#include <utility>

namespace ds {

namespace {

template <typename T, size_t N>
std::optional<T> lookup(const std::array<std::pair<std::string_view, T>, N>& names, std::string_view text) {
    for (const auto& [name, v] : names)
        if (name == text) return v;
    return std::nullopt;
}

}  // namespace

std::optional<ObjectAlignment> parse_object_alignment(std::string_view text) {
    using A = ObjectAlignment;
    static constexpr std::array<std::pair<std::string_view, A>, 10> names{{
        {"unspecified", A::Unspecified}, {"topleft", A::TopLeft}, {"top", A::Top},
        {"topright", A::TopRight}, {"left", A::Left}, {"center", A::Center}, {"right", A::Right},
        {"bottomleft", A::BottomLeft}, {"bottom", A::Bottom}, {"bottomright", A::BottomRight}}};
    return lookup(names, text);
}

std::optional<TileRenderSize> parse_tile_render_size(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, TileRenderSize>, 2> names{
        {{"tile", TileRenderSize::Tile}, {"grid", TileRenderSize::Grid}}};
    return lookup(names, text);
}

std::optional<FillMode> parse_fill_mode(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, FillMode>, 2> names{
        {{"stretch", FillMode::Stretch}, {"preserve-aspect-fit", FillMode::PreserveAspectFit}}};
    return lookup(names, text);
}

std::optional<RenderOrder> parse_render_order(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, RenderOrder>, 4> names{
        {{"right-down", RenderOrder::RightDown}, {"right-up", RenderOrder::RightUp},
         {"left-down", RenderOrder::LeftDown}, {"left-up", RenderOrder::LeftUp}}};
    return lookup(names, text);
}

std::optional<bool> parse_draw_order(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, bool>, 2> names{{{"index", false}, {"topdown", true}}};
    return lookup(names, text);
}

}  // namespace ds
