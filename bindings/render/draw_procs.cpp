// SPDX-License-Identifier: MIT
// Drawing a frame (the map, the entities as their keys say they look, the
// debug overlay, the step before when drawing between two) and the render
// hook's draw commands.
#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

#include "arguments.hpp"
#include "convert.hpp"
#include "display.hpp"
#include "failure.hpp"
#include "keys.hpp"
#include "plist.hpp"
#include "pushed_pairs.hpp"
#include "registry.hpp"
#include "detail/stopwatch.hpp"
#include "tilemap_type.hpp"

#include "render/constants.hpp"

namespace ds::guile {

namespace {

using namespace ds::render;

SCM key_sprite, key_flip_x, key_visible, key_color, key_sprite_offset, key_sprite_scale, key_rotation,
    key_animation, key_animation_start;

// ---------------------------------------------------------------- entities

bool proper_list(SCM v, const char* what, Failure& f) {
    if (scm_ilength(v) >= 0) return true;
    fail_arg(f, what, v, "a proper list");
    return false;
}

// The game's clock as drawing reads it: the frame's ms (frame number ×
// frame delay) and the frame delay, which turns an #:animation-start frame
// into ms.
struct SpriteClock {
    double time_ms = 0, frame_ms = 0;
};

// A real in (0, kMaxSpriteScale].
bool scale_factor(SCM v, double& out) {
    Failure quiet;
    return from_scm(v, out, "#:sprite-scale", quiet) && out > 0 && out <= kMaxSpriteScale;
}

// #:animation's picture at `ms` of the entity's own clock: a gid (its
// tile's Tiled animation plays, as a map cell's does), or a list of
// (gid . ms) played in order and over again.
bool animation_gid(SCM v, double ms, EntityView& out, std::vector<AnimationFrame>& frames, Failure& f) {
    if (!scm_is_pair(v) && !scm_is_null(v)) {
        out.sprite_ms = ms;
        return gid_arg(v, "#:animation", out.sprite, f);
    }
    const long n = scm_ilength(v);
    if (n < 1 || n > kMaxAnimationFrames) {
        fail_arg(f, "#:animation", v, "a gid or a list of 1 to %d (gid . ms)", int(kMaxAnimationFrames));
        return false;
    }
    frames.clear();
    for (SCM p = v; scm_is_pair(p); p = SCM_CDR(p)) {
        SCM entry = SCM_CAR(p);
        AnimationFrame a;
        Failure quiet;
        if (!scm_is_pair(entry) || !from_scm(SCM_CAR(entry), a.tile_id, "gid", quiet) ||
            !from_scm(SCM_CDR(entry), a.duration_ms, "ms", quiet, 0, INT_MAX)) {
            fail_arg(f, "#:animation", entry, "a frame (gid . ms): a gid and an exact integer of ms ≥ 0");
            return false;
        }
        frames.push_back(a);
    }
    // The listed gids may be animated tiles themselves: they play by the
    // same clock.
    out.sprite_ms = ms;
    out.sprite = animation_frame(frames, ms, frames.front().tile_id);
    return true;
}

// The keys that say how an entity looks, read in one walk of its plist
// (the first of a repeated key counts, as entity-ref reads it), so an
// entity costs one walk whichever of them it has.
bool entity_looks(SCM e, const SpriteClock& clock, EntityView& out, std::vector<AnimationFrame>& frames, Failure& f) {
    SCM sprite = SCM_UNDEFINED, flip = SCM_UNDEFINED, visible = SCM_UNDEFINED, color = SCM_UNDEFINED,
        offset = SCM_UNDEFINED, scale = SCM_UNDEFINED, rotation = SCM_UNDEFINED, animation = SCM_UNDEFINED,
        start = SCM_UNDEFINED;
    const std::pair<SCM, SCM*> wanted[] = {{key_sprite, &sprite},       {key_flip_x, &flip},
                                           {key_visible, &visible},     {key_color, &color},
                                           {key_sprite_offset, &offset}, {key_sprite_scale, &scale},
                                           {key_rotation, &rotation},   {key_animation, &animation},
                                           {key_animation_start, &start}};
    for (SCM p = e; scm_is_pair(p) && scm_is_pair(SCM_CDR(p)); p = SCM_CDR(SCM_CDR(p))) {
        SCM k = SCM_CAR(p);
        if (!scm_is_keyword(k)) continue;
        for (const auto& [key, slot] : wanted)
            if (scm_is_eq(k, key)) {
                if (SCM_UNBNDP(*slot)) *slot = SCM_CADR(p);
                break;
            }
    }
    const auto given = [](SCM v) { return !SCM_UNBNDP(v) && scm_is_true(v); };
    out.visible = SCM_UNBNDP(visible) || scm_is_true(visible);
    out.flip_x = given(flip);
    if (given(sprite) && !gid_arg(sprite, "#:sprite", out.sprite, f)) return false;
    if (given(color)) {
        Rgba c;
        if (!color_arg(color, c, f, "#:color")) return false;
        out.color = c;
    }
    if (given(offset)) {
        Failure quiet;  // one message for the pair, whichever half is bad
        if (!(scm_is_pair(offset) && from_scm(SCM_CAR(offset), out.sprite_dx, "dx", quiet) &&
              from_scm(SCM_CDR(offset), out.sprite_dy, "dy", quiet))) {
            fail_arg(f, "#:sprite-offset", offset, "(dx . dy) of finite reals, in px");
            return false;
        }
    }
    if (given(scale)) {
        const bool pair = scm_is_pair(scale);
        if (!(pair ? scale_factor(SCM_CAR(scale), out.scale_x) && scale_factor(SCM_CDR(scale), out.scale_y)
                   : scale_factor(scale, out.scale_x))) {
            fail_arg(f, "#:sprite-scale", scale, "a real > 0 and at most %d, or a pair (sx . sy) of them",
                     int(kMaxSpriteScale));
            return false;
        }
        if (!pair) out.scale_y = out.scale_x;
    }
    if (given(rotation)) {
        if (!from_scm(rotation, out.degrees, "#:rotation", f, "a finite real number of degrees")) return false;
        out.degrees = std::fmod(out.degrees, 360.0);  // a whole turn is none: 360 draws as 0 does, a copy
    }
    if (given(animation)) {
        int64_t first = 0;
        if (given(start)) {
            if (!scm_is_signed_integer(start, -kMaxAnimationStart, kMaxAnimationStart)) {
                fail_arg(f, "#:animation-start", start, "a frame number: an exact integer from %lld to %lld",
                         -(long long)kMaxAnimationStart, (long long)kMaxAnimationStart);
                return false;
            }
            first = scm_to_int64(start);
        }
        if (!animation_gid(animation, clock.time_ms - double(first) * clock.frame_ms, out, frames, f)) return false;
    }
    return true;
}

// An entity's body, and with a clock how it looks; without one (the
// overlay's trails, the step before) only the body is wanted.
bool entity_view(SCM e, size_t index, EntityView& out, Failure& f, const SpriteClock* clock = nullptr,
                 std::vector<AnimationFrame>* frames = nullptr) {
    if (scm_ilength(e) < 0) {
        fail(f, "wrong-type-arg", scm_list_1(scm_from_size_t(index)),
             "entity ~S: expected a keyword plist, got a circular or improper list");
        return false;
    }
    Decoded dec;
    if (!decode_entity(e, dec, f)) return false;
    const Body& b = dec.body;
    out = EntityView{};
    out.x = b.x.v, out.y = b.y.v, out.w = b.w.v, out.h = b.h.v, out.vx = b.vx.v, out.vy = b.vy.v;
    out.solid = b.solid, out.immovable = b.immovable, out.ghost = b.skips(kSkipEntityCollisions);
    out.on_ground = b.on_ground, out.sensor = b.sensor;
    return !clock || entity_looks(e, *clock, out, *frames, f);
}

// The entities' bodies, and with a clock how each looks.
bool entity_views(SCM entities, std::vector<EntityView>& out, Failure& f, const SpriteClock* clock = nullptr,
                  std::vector<AnimationFrame>* frames = nullptr) {
    out.clear();
    if (!proper_list(entities, "entities", f)) return false;
    size_t i = 0;
    for (SCM p = entities; scm_is_pair(p); p = SCM_CDR(p), ++i) {
        out.emplace_back();
        if (!entity_view(SCM_CAR(p), i, out.back(), f, clock, frames)) return false;
    }
    return true;
}

// Matches each entity to its past selves by #:id, or by position when it
// has none, and collects their centres, oldest first, ending where it is now.
bool trails_of(SCM current, const std::vector<EntityView>& now, SCM past_lists, std::vector<Trail>& out,
               Failure& f) {
    out.clear();
    if (!proper_list(past_lists, "history", f)) return false;
    std::vector<int64_t> tags;
    for (SCM p = current; scm_is_pair(p); p = SCM_CDR(p))
        tags.push_back(identity_tag(plist_get(SCM_CAR(p), keys->key[kId], SCM_BOOL_F)));
    out.resize(tags.size());
    std::unordered_map<int64_t, size_t> by_tag;
    for (size_t i = 0; i < tags.size(); ++i)
        if (tags[i] != 0) by_tag.emplace(tags[i], i);
    for (SCM l = past_lists; scm_is_pair(l); l = SCM_CDR(l)) {
        SCM list = SCM_CAR(l);
        if (!proper_list(list, "history entities", f)) return false;
        size_t i = 0;
        for (SCM p = list; scm_is_pair(p); p = SCM_CDR(p), ++i) {
            EntityView v;
            if (!entity_view(SCM_CAR(p), i, v, f)) return false;
            const int64_t tag = identity_tag(plist_get(SCM_CAR(p), keys->key[kId], SCM_BOOL_F));
            size_t who = i;
            if (tag != 0) {
                auto it = by_tag.find(tag);
                if (it == by_tag.end()) continue;
                who = it->second;
            } else if (i >= tags.size() || tags[i] != 0) {
                continue;
            }
            out[who].emplace_back(v.x + v.w / 2, v.y + v.h / 2);
        }
    }
    for (size_t i = 0; i < out.size() && i < now.size(); ++i)
        if (!out[i].empty()) out[i].emplace_back(now[i].x + now[i].w / 2, now[i].y + now[i].h / 2);
    return true;
}

// The map property entity-layer names the object layer the entities are
// drawn in (the layers after it draw over them); a name no object layer has
// is an error, not a silent "on top".
void entity_layer_of(const Tilemap& map, SceneView& view, Failure& f) {
    const Property* p = find_property(map.properties, "entity-layer");
    if (!p) return;
    for (const ObjectLayer& l : map.object_layers)
        if (l.name == p->value) {
            view.entity_layer = p->value;
            return;
        }
    fail(f, "misc-error", scm_list_2(scm_from_utf8_string(p->value.c_str()), scm_from_utf8_string(map.path.c_str())),
         "map property entity-layer is ~S, which names no object layer of ~S");
}

// Writes drawing's warnings to (current-warning-port), as load-tilemap
// writes its own. Only Display-owned strings are alive while Guile runs.
void warn_all(Display& d) {
    SCM port = scm_current_warning_port();
    for (size_t i = 0; i < d.warnings.size(); ++i) {
        scm_puts("game-draw: warning: ", port);
        scm_display(scm_from_utf8_string(d.warnings[i].c_str()), port);
        scm_newline(port);
    }
    d.warnings.clear();
}

// The #:id tag of each entity of a validated list.
void id_tags(SCM entities, std::vector<int64_t>& out) {
    out.clear();
    for (SCM p = entities; scm_is_pair(p); p = SCM_CDR(p))
        out.push_back(identity_tag(plist_get(SCM_CAR(p), keys->key[kId], SCM_BOOL_F)));
}

// Drawing between two steps (interpolate.hpp): `between` is #f, or
// (previous alpha camera-x camera-y): the list and the camera the step
// before left, and how far past it the clock is.
bool between_steps(Display& d, SceneView& view, SCM entities, SCM between, Failure& f) {
    if (SCM_UNBNDP(between) || scm_is_false(between)) return true;
    if (scm_ilength(between) != 4) {
        fail_arg(f, "between", between, "#f or (previous-entities alpha camera-x camera-y)");
        return false;
    }
    const SCM previous = scm_list_ref(between, scm_from_int(0)), alpha = scm_list_ref(between, scm_from_int(1));
    double a = 0, px = 0, py = 0;
    if (!from_scm(alpha, a, "alpha", f) || !from_scm(scm_list_ref(between, scm_from_int(2)), px, "camera x then", f) ||
        !from_scm(scm_list_ref(between, scm_from_int(3)), py, "camera y then", f))
        return false;
    if (!(a >= 0 && a <= 1)) {
        fail_arg(f, "alpha", alpha, "a number from 0 to 1");
        return false;
    }
    if (!entity_views(previous, d.before, f)) return false;
    id_tags(entities, d.now_ids);
    id_tags(previous, d.before_ids);
    interpolate_views(d.entities, d.now_ids, d.before, d.before_ids, a);
    view.camera_x = interpolated(px, view.camera_x, a);
    view.camera_y = interpolated(py, view.camera_y, a);
    return true;
}

SCM display_draw(SCM display, SCM tilemap, SCM cam_x, SCM cam_y, SCM entities, SCM debug, SCM history,
                 SCM time_ms, SCM between, SCM frame_ms) {
    Failure f;
    Display* d = display_of(display, "game-draw", f);
    SceneView view;
    if (d && scm_is_true(tilemap)) {
        if (is_tilemap(tilemap)) view.map = &tilemap_handle(tilemap).map;
        else fail_arg(f, "tilemap", tilemap, "a tilemap or #f");
    }
    if (d && !f && view.map) entity_layer_of(*view.map, view, f);
    if (d) view.background = d->background;
    if (d && !f && !SCM_UNBNDP(time_ms)) from_scm(time_ms, view.time_ms, "time-ms", f);
    SpriteClock clock{view.time_ms, 0};
    if (d && !f && !SCM_UNBNDP(frame_ms)) from_scm(frame_ms, clock.frame_ms, "frame-ms", f);
    if (d && !f && from_scm(cam_x, view.camera_x, "camera x", f) && from_scm(cam_y, view.camera_y, "camera y", f))
        guarded(f, nullptr, [&] {  // decoding the entities fills C++ vectors too
            if (!entity_views(entities, d->entities, f, &clock, &d->frames)) return;
            if (!between_steps(*d, view, entities, between, f)) return;
            view.debug = scm_is_true(debug);
            d->trails.clear();
            d->pairs.clear();
            if (view.debug) {
                if (PairLog* log = pushed_pairs()) d->pairs = *log;
                std::sort(d->pairs.begin(), d->pairs.end());
                d->pairs.erase(std::unique(d->pairs.begin(), d->pairs.end()), d->pairs.end());
                if (!trails_of(entities, d->entities, history, d->trails, f)) return;
            }
            view.entities = d->entities;
            view.commands = &d->commands;
            view.pushed_pairs = d->pairs;
            view.trails = d->trails;
            const auto t0 = Clock::now();
            d->counts = draw_scene(canvas_of(*d), d->art, view);
            d->warnings = d->art.take_warnings();
            d->culled = d->entities.size() - d->counts.sprites - d->counts.boxes;
            if (d->window) d->window->present(*d->canvas);
            d->ms = ms_since(t0);
        });
    if (d) warn_all(*d);
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

// ---------------------------------------------------------------- draw commands

SCM clear_commands(SCM display) {
    Failure f;
    if (Display* d = display_of(display, "render", f)) d->commands.clear();
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

// Appends a command once every argument has converted; `fill` converts the rest.
template <class Fill>
SCM push_command(const char* proc, SCM display, SCM color, SCM space, Fill fill) {
    Failure f;
    Display* d = display_of(display, proc, f);
    DrawCommand c;
    if (d && d->commands.commands.size() >= size_t(kMaxDrawCommands))
        fail(f, "misc-error", scm_list_1(scm_from_int64(kMaxDrawCommands)),
             "more than ~S drawings queued in one frame: a render: loop that never ends?");
    else if (d && (scm_is_false(color) || color_arg(color, c.color, f)) && space_arg(space, c.space, f))
        guarded(f, nullptr, [&] {  // fill may copy a string
            if (fill(c, f)) d->commands.commands.push_back(std::move(c));
        });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM draw_rect(SCM display, SCM x, SCM y, SCM w, SCM h, SCM color, SCM filled, SCM space) {
    return push_command("draw-rect", display, color, space, [&](DrawCommand& c, Failure& f) {
        c.kind = scm_is_true(filled) ? DrawCommand::Kind::FilledRect : DrawCommand::Kind::Rect;
        return from_scm(x, c.x, "x", f) && from_scm(y, c.y, "y", f) && from_scm(w, c.x2, "width", f) &&
               from_scm(h, c.y2, "height", f);
    });
}

SCM draw_line(SCM display, SCM x0, SCM y0, SCM x1, SCM y1, SCM color, SCM space) {
    return push_command("draw-line", display, color, space, [&](DrawCommand& c, Failure& f) {
        c.kind = DrawCommand::Kind::Line;
        return from_scm(x0, c.x, "x0", f) && from_scm(y0, c.y, "y0", f) && from_scm(x1, c.x2, "x1", f) &&
               from_scm(y1, c.y2, "y1", f);
    });
}

SCM draw_sprite(SCM display, SCM gid, SCM x, SCM y, SCM space) {
    return push_command("draw-sprite", display, SCM_BOOL_F, space, [&](DrawCommand& c, Failure& f) {
        c.kind = DrawCommand::Kind::Sprite;
        return gid_arg(gid, "gid", c.gid, f) && from_scm(x, c.x, "x", f) && from_scm(y, c.y, "y", f);
    });
}

SCM draw_text(SCM display, SCM text, SCM x, SCM y, SCM color, SCM scale, SCM space) {
    return push_command("draw-text", display, color, space, [&](DrawCommand& c, Failure& f) {
        c.kind = DrawCommand::Kind::Text;
        return from_scm(text, c.text, "text", f) && from_scm(x, c.x, "x", f) && from_scm(y, c.y, "y", f) &&
               from_scm(scale, c.scale, "scale", f, 1, 64);
    });
}

// ---------------------------------------------------------------- pushed pairs

thread_local PairLog pushed_log;

SCM note_pushed_pairs(SCM on) {
    pushed_pairs() = scm_is_true(on) ? &pushed_log : nullptr;
    if (scm_is_false(on)) pushed_log.clear();
    return SCM_UNSPECIFIED;
}

// ((name r g b) …): kNamedColors for (downstroke render)'s color-rgba.
SCM named_colors() {
    SCM out = SCM_EOL;
    for (size_t i = std::size(kNamedColors); i-- > 0;) {
        const Rgba c = kNamedColors[i].rgba;
        out = scm_cons(
            scm_list_4(named_color_symbol(i), scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b)), out);
    }
    return out;
}

}  // namespace

void register_draw_procedures() {
    key_sprite = scm_permanent_object(scm_from_utf8_keyword("sprite"));
    key_flip_x = scm_permanent_object(scm_from_utf8_keyword("flip-x?"));
    key_visible = scm_permanent_object(scm_from_utf8_keyword("visible?"));
    key_color = scm_permanent_object(scm_from_utf8_keyword("color"));
    key_sprite_offset = scm_permanent_object(scm_from_utf8_keyword("sprite-offset"));
    key_sprite_scale = scm_permanent_object(scm_from_utf8_keyword("sprite-scale"));
    key_rotation = scm_permanent_object(scm_from_utf8_keyword("rotation"));
    key_animation = scm_permanent_object(scm_from_utf8_keyword("animation"));
    key_animation_start = scm_permanent_object(scm_from_utf8_keyword("animation-start"));

#define DS_NATIVE DS_DEFINE_NATIVE
#define DS_RENDER_NATIVE DS_DEFINE_NATIVE
#include "draw.def"
#undef DS_NATIVE
#undef DS_RENDER_NATIVE
}

}  // namespace ds::guile
