// The renderer as Scheme sees it: a display per game (an off-screen canvas,
// the tile pictures, the render hook's draw list, and optionally a window
// with its input), the draw-* commands, frame capture, and sounds. Built only
// with SDL2 (render_missing.cpp stands in without it).
#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "contacts.hpp"
#include "convert.hpp"
#include "failure.hpp"
#include "keys.hpp"
#include "plist.hpp"
#include "pushed_pairs.hpp"
#include "registry.hpp"
#include "detail/stopwatch.hpp"
#include "tilemap_type.hpp"

#include "audio.hpp"
#include "render/constants.hpp"
#include "canvas.hpp"
#include "draw_list.hpp"
#include "input.hpp"
#include "interpolate.hpp"
#include "frame_compare.hpp"
#include "scene_draw.hpp"
#include "tile_animation.hpp"
#include "tile_art.hpp"
#include "window.hpp"

namespace ds::guile {

namespace {

using namespace ds::render;

// Everything one game draws with. Plain C++: no SCM is kept here.
struct Display {
    int width = 0, height = 0;
    std::unique_ptr<Canvas> canvas;  // made when first drawn
    TileArt art;
    DrawList commands;
    std::unique_ptr<Window> window;
    bool fullscreen = false;  // asked for (--fullscreen, game-fullscreen-set!), also before a window opens
    InputState input;
    std::vector<std::string> actions;  // by action number
    // Per-frame scratch, kept so a frame does not allocate.
    std::vector<EntityView> entities;
    std::vector<EntityView> before;             // the step before, when drawing between two
    std::vector<int64_t> now_ids, before_ids;   // their #:id tags
    std::vector<Trail> trails;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    std::vector<AnimationFrame> frames;  // an #:animation list's, while it is read
    DrawCounts counts;
    size_t culled = 0;
    double ms = 0;
    std::optional<Rgba> background;  // make-game's background:, else the map's
    std::vector<std::string> warnings;  // drawing's, until written to the warning port
};

SCM display_type = SCM_BOOL_F;
SCM sym_world, sym_screen;
SCM key_sprite, key_flip_x, key_visible, key_color, key_sprite_offset, key_sprite_scale, key_rotation,
    key_animation, key_animation_start;

void finalize_display(SCM obj) {
    delete static_cast<Display*>(scm_foreign_object_ref(obj, 0));
    scm_foreign_object_set_x(obj, 0, nullptr);
}

Display* display_of(SCM obj, const char* proc, Failure& f) {
    f.proc = proc;
    if (SCM_IS_A_P(obj, display_type)) {
        if (auto* d = static_cast<Display*>(scm_foreign_object_ref(obj, 0))) return d;
    }
    fail(f, "wrong-type-arg", scm_list_1(obj), "expected a display, got ~S");
    return nullptr;
}

// ---------------------------------------------------------------- arguments

// kNamedColors' names as symbols, interned once (register_render_procedures).
SCM named_color_symbols[std::size(kNamedColors)];

// "white black … gray", for messages.
std::string color_names() {
    std::string names;
    for (const NamedColor& c : kNamedColors) (names += names.empty() ? "" : " ") += c.name;
    return names;
}

// (r g b) or (r g b a), each an exact integer 0–255, or a colour's name.
bool color_arg(SCM v, Rgba& out, Failure& f, Arg what = "color") {
    if (scm_is_symbol(v)) {
        for (size_t i = 0; i < std::size(kNamedColors); ++i)
            if (scm_is_eq(v, named_color_symbols[i])) {
                out = kNamedColors[i].rgba;
                return true;
            }
    }
    uint8_t c[4] = {0, 0, 0, 255};
    const long n = scm_ilength(v);
    bool ok = n == 3 || n == 4;
    SCM p = v;
    for (long i = 0; ok && i < n; ++i, p = SCM_CDR(p)) {
        ok = scm_is_unsigned_integer(SCM_CAR(p), 0, 255);
        if (ok) c[i] = static_cast<uint8_t>(scm_to_uint(SCM_CAR(p)));
    }
    if (!ok) {
        fail_arg(f, what, v, "(r g b) or (r g b a) of integers 0–255, or one of the names %s", color_names().c_str());
        return false;
    }
    out = {c[0], c[1], c[2], c[3]};
    return true;
}

bool space_arg(SCM v, Space& out, Failure& f) {
    if (scm_is_eq(v, sym_world)) out = Space::World;
    else if (scm_is_eq(v, sym_screen)) out = Space::Screen;
    else {
        fail_arg(f, "space", v, "world or screen");
        return false;
    }
    return true;
}

bool gid_arg(SCM v, const char* what, uint32_t& out, Failure& f) {
    return from_scm(v, out, what, f, "a gid (an exact integer ≥ 0, flip bits allowed)");
}

// A symbol's name.
bool symbol_arg(SCM v, const char* what, std::string& out, Failure& f) {
    if (scm_is_symbol(v)) return from_scm(scm_symbol_to_string(v), out, what, f);
    fail_arg(f, what, v, "a symbol");
    return false;
}

// ---------------------------------------------------------------- displays

SCM make_display(SCM width, SCM height) {
    Failure f{"make-display"};
    int w = 0, h = 0;
    Display* d = nullptr;
    if (from_scm(width, w, "width", f, 1, kMaxCanvasSide) && from_scm(height, h, "height", f, 1, kMaxCanvasSide) &&
        int64_t(w) * h > kMaxCanvasPixels)
        fail(f, "wrong-type-arg", scm_list_3(width, height, scm_from_int64(kMaxCanvasPixels)),
             "width × height: ~S × ~S is more than ~S pixels (256 MiB a frame)");
    if (!f)
        guarded(f, nullptr, [&] {
            d = new Display;
            d->width = w;
            d->height = h;
        });
    if (f) raise(f);
    return scm_make_foreign_object_1(display_type, d);
}

Canvas& canvas_of(Display& d) {
    if (!d.canvas) d.canvas = std::make_unique<Canvas>(d.width, d.height);
    return *d.canvas;
}

SCM open_window(SCM display, SCM title, SCM scale) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    std::string t;
    int s = 0;
    if (d)
        guarded(f, nullptr, [&] {
            if (!from_scm(title, t, "title", f) || !from_scm(scale, s, "scale", f, 0, 64)) return;
            d->window = std::make_unique<Window>(t, d->width, d->height, s, d->fullscreen);
            s = d->window->scale();
        });
    if (f) raise(f);
    return scm_from_int(s);
}

// Fullscreen on or off: now in an open window, and for a window opened later.
// Returns whether the window (or the wish, without one) is fullscreen.
SCM set_fullscreen(SCM display, SCM on) {
    Failure f;
    Display* d = display_of(display, "game-fullscreen-set!", f);
    bool now = false;
    if (d)
        guarded(f, nullptr, [&] {
            d->fullscreen = scm_is_true(on);
            if (d->window) d->window->set_fullscreen(d->fullscreen);
            now = d->window ? d->window->fullscreen() : d->fullscreen;
        });
    if (f) raise(f);
    return scm_from_bool(now);
}

SCM fullscreen_p(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-fullscreen?", f);
    if (f) raise(f);
    return scm_from_bool(d->window ? d->window->fullscreen() : d->fullscreen);
}

SCM refresh_rate(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    if (f) raise(f);
    return scm_from_int(d->window ? d->window->refresh_hz() : kDefaultRefreshHz);
}

SCM vsync_p(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    if (f) raise(f);
    return scm_from_bool(d->window && d->window->vsync());
}

SCM close_window(SCM display) {
    Failure f;
    if (Display* d = display_of(display, "game-run!", f)) guarded(f, nullptr, [&] { d->window.reset(); });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

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

SCM display_stats(SCM display) {
    Failure f;
    Display* d = display_of(display, "engine-stats", f);
    if (f) raise(f);
    const DrawCounts& c = d->counts;
    return scm_list_4(scm_from_utf8_symbol("render"), scm_from_size_t(c.tiles + c.sprites + c.boxes + c.commands),
                      scm_from_size_t(d->culled), scm_from_double(d->ms));
}

SCM display_save_png(SCM display, SCM path) {
    Failure f;
    Display* d = display_of(display, "game-capture", f);
    std::string p;
    if (d)
        guarded(f, nullptr, [&] {
            if (from_scm(path, p, "file", f)) canvas_of(*d).save_png(p);
        });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM rgba_list(Rgba c) {
    return scm_list_4(scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b), scm_from_uint8(c.a));
}

// The last frame drawn against a golden PNG: #f when they are the same;
// (size W H) when the golden picture is another size; else (count x y
// expected actual) for the pixels that differ, the first of them named.
// Either way that differs, writes the frame and a diff picture.
SCM display_compare_png(SCM display, SCM golden, SCM actual, SCM diff) {
    Failure f;
    Display* d = display_of(display, "check-frame", f);
    std::string g, a, df;
    FrameDiff r;
    if (d && from_scm(golden, g, "golden", f) && from_scm(actual, a, "actual", f) && from_scm(diff, df, "diff", f))
        guarded(f, nullptr, [&] { r = compare_with_png(canvas_of(*d), g, a, df); });
    if (f) raise(f);
    if (!r.same_size)
        return scm_list_3(scm_from_utf8_symbol("size"), scm_from_int(r.golden_width), scm_from_int(r.golden_height));
    if (r.differing == 0) return SCM_BOOL_F;
    return scm_list_5(scm_from_int64(r.differing), scm_from_int(r.first_x), scm_from_int(r.first_y),
                      rgba_list(r.expected), rgba_list(r.actual));
}

SCM display_pixel(SCM display, SCM x, SCM y) {
    Failure f;
    Display* d = display_of(display, "game-pixel", f);
    int px = 0, py = 0;
    Rgba c;
    if (d && from_scm(x, px, "x", f, 0, d->width - 1) && from_scm(y, py, "y", f, 0, d->height - 1))
        guarded(f, nullptr, [&] { c = canvas_of(*d).pixel(px, py); });
    if (f) raise(f);
    return scm_list_4(scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b), scm_from_uint8(c.a));
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

// ---------------------------------------------------------------- input

// ((action name …) …): the actions, each with the inputs that hold it.
SCM set_background(SCM display, SCM color) {
    Failure f;
    Display* d = display_of(display, "make-game", f);
    Rgba c;
    if (d && scm_is_false(color)) {
        d->background.reset();
    } else if (d) {
        Failure quiet;  // color_arg names the argument "color": make-game's is background
        if (color_arg(color, c, quiet)) d->background = Rgba{c.r, c.g, c.b, 255};  // a clear colour is opaque
        else fail_arg(f, "background", color, "(r g b) or (r g b a) of integers 0–255, or #f");
    }
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM set_input_map(SCM display, SCM map) {
    Failure f;
    Display* d = display_of(display, "make-game", f);
    std::vector<std::string> actions;
    std::vector<Binding> bindings;
    const long n = d ? scm_ilength(map) : 0;
    if (d && (n < 0 || n > kMaxActions))
        fail_arg(f, "input-map", map, "a list of at most %d (action name …)", kMaxActions);
    if (d && !f)
        guarded(f, nullptr, [&] {
            SCM p = map;
            for (long i = 0; !f && i < n; ++i, p = SCM_CDR(p)) {
                SCM entry = SCM_CAR(p);
                if (scm_ilength(entry) < 1 || !scm_is_symbol(SCM_CAR(entry))) {
                    fail_arg(f, "input-map", entry, "(action name …) with a symbol action");
                    break;
                }
                std::string action;
                symbol_arg(SCM_CAR(entry), "action", action, f);
                actions.push_back(action);
                for (SCM q = SCM_CDR(entry); scm_is_pair(q) && !f; q = SCM_CDR(q)) {
                    std::string name;
                    Binding b;
                    if (!from_scm(SCM_CAR(q), name, "input-map key", f)) break;
                    if (!parse_binding(name, static_cast<uint8_t>(i), b))
                        fail(f, "wrong-type-arg", scm_list_2(SCM_CAR(q), SCM_CAR(entry)),
                             "input-map: no key or controller input is named ~S (for ~S)");
                    else
                        bindings.push_back(b);
                }
            }
            if (f) return;
            d->actions = std::move(actions);
            d->input.set_bindings(std::move(bindings));
        });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM default_map() {
    SCM out = SCM_EOL;
    const auto& map = default_input_map();
    for (auto it = map.rbegin(); it != map.rend(); ++it) {
        SCM names = SCM_EOL;
        for (auto n = it->names.rbegin(); n != it->names.rend(); ++n) names = scm_cons(scm_from_utf8_string(*n), names);
        out = scm_cons(scm_cons(scm_from_utf8_symbol(it->action), names), out);
    }
    return out;
}

// → (held-actions quit? debug-toggles): what the window's events say now.
SCM poll_input(SCM display) {
    Failure f;
    Display* d = display_of(display, "game-run!", f);
    uint64_t held = 0;
    bool quit = false, focused = true;
    int toggles = 0;
    MouseState mouse;
    if (d && d->window) {
        guarded(f, nullptr, [&] { d->window->poll(d->input); });
        held = d->input.take_held();
        quit = d->input.quit_requested();
        toggles = d->input.take_debug_toggles();
        mouse = d->input.take_mouse();
        focused = d->input.focused();
        d->fullscreen = d->window->fullscreen();  // F11 may have toggled it
    }
    if (f) raise(f);
    SCM list = SCM_EOL;
    for (size_t a = d->actions.size(); a-- > 0;)
        if (held >> a & 1) list = scm_cons(scm_from_utf8_symbol(d->actions[a].c_str()), list);
    SCM pointer = SCM_BOOL_F;
    if (mouse.inside) {
        static const char* const kButtons[] = {"left", "middle", "right"};
        SCM buttons = SCM_EOL;
        for (int b = 2; b >= 0; --b)
            if (mouse.buttons >> b & 1) buttons = scm_cons(scm_from_utf8_symbol(kButtons[b]), buttons);
        pointer = scm_list_3(scm_from_int(mouse.x), scm_from_int(mouse.y), buttons);
    }
    return scm_list_5(list, scm_from_bool(quit), scm_from_int(toggles), pointer, scm_from_bool(focused));
}

// ---------------------------------------------------------------- sound

std::unique_ptr<SoundBank> bank;  // one per process: there is one audio device
// What was loaded under each name, so a bank reopened on the real device
// (a window opening after the script loaded its sounds) has them all again.
std::unordered_map<std::string, std::string> sound_files;
std::unordered_map<std::string, std::string> music_files;  // likewise for music
double music_volume = 1, sound_volume = 1;                  // and the volumes set

SCM open_audio(SCM audible) {
    Failure f{"load-sound"};
    guarded(f, nullptr, [&] {
        if (!bank || (scm_is_true(audible) && !bank->audible())) {
            bank.reset();
            bank = std::make_unique<SoundBank>(scm_is_true(audible));
            for (const auto& [name, path] : sound_files) bank->load(name, path);
            for (const auto& [name, path] : music_files) bank->load_music(name, path);
            bank->set_music_volume(music_volume);
            bank->set_sound_volume(sound_volume);
        }
    });
    if (f) raise(f);
    return scm_from_bool(bank->audible());
}

// load-sound and load-music: NAME's file loaded by `load` into the bank
// (made silent if none is open yet) and remembered in `files`, so that a
// bank opened later loads it again.
SCM load_named(const char* who, SCM name, SCM path, void (SoundBank::*load)(const std::string&, const std::string&),
               std::unordered_map<std::string, std::string>& files) {
    Failure f{who};
    std::string n, p;
    guarded(f, nullptr, [&] {
        if (!symbol_arg(name, "name", n, f) || !from_scm(path, p, "file", f)) return;
        if (!bank) bank = std::make_unique<SoundBank>(false);
        (bank.get()->*load)(n, p);
        files[n] = p;
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

SCM load_sound(SCM name, SCM path) { return load_named("load-sound", name, path, &SoundBank::load, sound_files); }

SCM play_sound(SCM name) {
    Failure f{"play-sound"};
    std::string n;
    bool known = false;
    guarded(f, nullptr, [&] {
        if (symbol_arg(name, "name", n, f)) known = bank && bank->play(n);
    });
    if (f) raise(f);
    return scm_from_bool(known);
}

SCM load_music(SCM name, SCM path) {
    return load_named("load-music", name, path, &SoundBank::load_music, music_files);
}

// Milliseconds of a fade: the engine has checked them (a real from 0 to
// kMaxFadeMs); here they are rounded to SDL_mixer's int.
int fade_ms(SCM ms) { return int(std::lround(scm_to_double(ms))); }

SCM play_music(SCM name, SCM loop, SCM fade_in) {
    Failure f{"play-music"};
    std::string n;
    bool known = false;
    guarded(f, nullptr, [&] {
        if (symbol_arg(name, "name", n, f)) known = bank && bank->play_music(n, scm_is_true(loop), fade_ms(fade_in));
    });
    if (f) raise(f);
    return scm_from_bool(known);
}

SCM stop_music(SCM fade_out) {
    Failure f{"stop-music"};
    guarded(f, nullptr, [&] {
        if (bank) bank->stop_music(fade_ms(fade_out));
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

// Volumes (checked by the engine: reals from 0 to 1), kept for a reopened bank.
SCM set_volume(SCM which, SCM volume) {
    const bool music = scm_is_eq(which, scm_from_utf8_symbol("music"));
    Failure f{music ? "music-volume-set!" : "sound-volume-set!"};
    const double v = scm_to_double(volume);
    (music ? music_volume : sound_volume) = v;
    guarded(f, nullptr, [&] {
        if (bank) music ? bank->set_music_volume(v) : bank->set_sound_volume(v);
    });
    if (f) raise(f);
    return SCM_UNSPECIFIED;
}

// ---------------------------------------------------------------- pushed pairs

thread_local PairLog pushed_log;

SCM note_pushed_pairs(SCM on) {
    pushed_pairs() = scm_is_true(on) ? &pushed_log : nullptr;
    if (scm_is_false(on)) pushed_log.clear();
    return SCM_UNSPECIFIED;
}

SCM renderer_p() { return SCM_BOOL_T; }

// ((name r g b) …): kNamedColors for (downstroke render)'s color-rgba.
SCM named_colors() {
    SCM out = SCM_EOL;
    for (size_t i = std::size(kNamedColors); i-- > 0;) {
        const Rgba c = kNamedColors[i].rgba;
        out = scm_cons(scm_list_4(named_color_symbols[i], scm_from_uint8(c.r), scm_from_uint8(c.g), scm_from_uint8(c.b)),
                       out);
    }
    return out;
}

}  // namespace

void register_render_procedures() {
    display_type = scm_make_foreign_object_type(scm_from_utf8_symbol("display"),
                                                scm_list_1(scm_from_utf8_symbol("data")), finalize_display);
    scm_permanent_object(display_type);
    sym_world = scm_permanent_object(scm_from_utf8_symbol("world"));
    sym_screen = scm_permanent_object(scm_from_utf8_symbol("screen"));
    for (size_t i = 0; i < std::size(kNamedColors); ++i)
        named_color_symbols[i] = scm_permanent_object(
            scm_from_utf8_symboln(kNamedColors[i].name.data(), kNamedColors[i].name.size()));
    key_sprite = scm_permanent_object(scm_from_utf8_keyword("sprite"));
    key_flip_x = scm_permanent_object(scm_from_utf8_keyword("flip-x?"));
    key_visible = scm_permanent_object(scm_from_utf8_keyword("visible?"));
    key_color = scm_permanent_object(scm_from_utf8_keyword("color"));
    key_sprite_offset = scm_permanent_object(scm_from_utf8_keyword("sprite-offset"));
    key_sprite_scale = scm_permanent_object(scm_from_utf8_keyword("sprite-scale"));
    key_rotation = scm_permanent_object(scm_from_utf8_keyword("rotation"));
    key_animation = scm_permanent_object(scm_from_utf8_keyword("animation"));
    key_animation_start = scm_permanent_object(scm_from_utf8_keyword("animation-start"));

    // The native code of (downstroke render)'s and (downstroke engine)'s
    // procedures, documented there; then the game loop's building blocks.
    constexpr const char* render = "(downstroke render)";
    constexpr const char* engine = "(downstroke engine)";
    define_procedure<0, 0, 0, renderer_p>("%renderer?", WrapperDoc{"()", "renderer-available?", render});
    define_procedure<0, 0, 0, default_map>("%default-input-map", WrapperDoc{"()", "default-input-map", render});
    define_procedure<0, 0, 0, named_colors>("%named-colors", WrapperDoc{"()", "color-rgba", render});
    define_procedure<8, 0, 0, draw_rect>("%draw-rect!",
        WrapperDoc{"(display x y w h color fill? space)", "draw-rect", render});
    define_procedure<7, 0, 0, draw_line>("%draw-line!",
        WrapperDoc{"(display x0 y0 x1 y1 color space)", "draw-line", render});
    define_procedure<5, 0, 0, draw_sprite>("%draw-sprite!",
        WrapperDoc{"(display gid x y space)", "draw-sprite", render});
    define_procedure<7, 0, 0, draw_text>("%draw-text!",
        WrapperDoc{"(display text x y color scale space)", "draw-text", render});
    define_procedure<2, 0, 0, load_sound>("%load-sound", WrapperDoc{"(name file)", "load-sound", render});
    define_procedure<2, 0, 0, load_music>("%load-music", WrapperDoc{"(name file)", "load-music", render});
    define_procedure<3, 0, 0, play_music>("%play-music", WrapperDoc{"(name loop? fade-in-ms)", "play-music", engine});
    define_procedure<1, 0, 0, stop_music>("%stop-music", WrapperDoc{"(fade-out-ms)", "stop-music", engine});
    define_procedure<2, 0, 0, set_volume>("%set-volume!", WrapperDoc{"(which volume)", "music-volume-set!", engine});
    define_procedure<1, 0, 0, display_stats>("%display-stats",
        WrapperDoc{"(display) → (render drawn culled ms)", "engine-stats", engine});
    define_procedure<3, 0, 0, display_pixel>("%display-pixel", WrapperDoc{"(display x y)", "game-pixel", engine});
    define_procedure<2, 0, 0, make_display>("%make-display",
        "(width height): a display: an off-screen canvas of that size, made when first drawn.");
    define_procedure<3, 0, 0, open_window>("%display-open-window!",
        "(display title scale): opens a window showing the display at SCALE (0: fit the screen); returns the scale.");
    define_procedure<1, 0, 0, close_window>("%display-close-window!", "(display): closes its window.");
    define_procedure<2, 0, 0, set_fullscreen>("%display-set-fullscreen!",
        WrapperDoc{"(display on?)", "game-fullscreen-set!", engine});
    define_procedure<1, 0, 0, fullscreen_p>("%display-fullscreen?", WrapperDoc{"(display)", "game-fullscreen?", engine});
    define_procedure<1, 0, 0, vsync_p>("%display-vsync?",
        "(display): whether its window presents on the display's vertical blank.");
    define_procedure<1, 0, 0, refresh_rate>("%display-refresh-rate",
        "(display): the refresh rate, in Hz, of the display its window is on (60 when unknown).");
    define_procedure<7, 3, 0, display_draw>("%display-draw!",
        "(display tilemap camera-x camera-y entities debug? history [time-ms between frame-ms]): draws a frame "
        "(and shows it in the window); time-ms, the game's clock, picks each animated tile's frame; between, "
        "(previous-entities alpha camera-x camera-y) of the step before, draws each entity and the camera "
        "alpha of the way from then to now; frame-ms, the frame delay, turns #:animation-start into ms.");
    define_procedure<4, 0, 0, display_compare_png>("%display-compare-png",
        "(display golden actual diff): the last frame drawn against the golden PNG: #f when the same, (size w h) "
        "or (count x y expected actual) when not (then writing the frame to ACTUAL and a diff picture to DIFF).");
    define_procedure<2, 0, 0, display_save_png>("%display-save-png",
        "(display file): writes the last frame drawn as a PNG.");
    define_procedure<1, 0, 0, clear_commands>("%display-clear-commands!",
        "(display): forgets the draw commands of the last frame.");
    define_procedure<2, 0, 0, set_background>("%display-set-background!",
                                               "(display color): the clear colour, (r g b) or #f (the map's).");
    define_procedure<2, 0, 0, set_input_map>("%display-set-input-map!",
        "(display map): binds keys and controller inputs to actions: ((action name …) …).");
    define_procedure<1, 0, 0, poll_input>("%display-poll!",
        "(display): (held-actions quit? debug-toggles mouse focused?) from the window's events; mouse is "
        "(x y buttons) in the picture's pixels, or #f when the pointer is not over the picture.");
    define_procedure<1, 0, 0, open_audio>("%open-audio!",
        "(audible?): opens the audio device (silent when not AUDIBLE?); returns whether it plays.");
    define_procedure<1, 0, 0, play_sound>("%play-sound",
        "(name): plays a loaded sound; #f when none has that name.");
    define_procedure<1, 0, 0, note_pushed_pairs>("%note-pushed-pairs!",
        "(on?): whether step-scene notes the pairs it pushes apart, for the overlay.");
}

}  // namespace ds::guile
