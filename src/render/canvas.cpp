// SPDX-License-Identifier: MIT
#include "canvas.hpp"

#include <SDL_image.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "font.hpp"
#include "render_error.hpp"

namespace ds::render {

namespace {

// ARGB8888: one uint32 per pixel, alpha in the top byte.
uint32_t pack(Rgba c) {
    return uint32_t(c.a) << 24 | uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b;
}

uint8_t mix(uint8_t src, uint8_t dst, uint8_t a) {
    return static_cast<uint8_t>((src * a + dst * (255 - a) + 127) / 255);
}

// Whether SDL would blit `p` onto the canvas as a plain copy of its pixels
// (opaque, same format, nothing modulated). SDL 2's copy uses non-temporal
// stores for 16-byte-aligned rows, made for large blits: they push the
// canvas out of the cache, and a frame of 16×16 tiles and sprites then goes
// to memory (a 16×16 blit to an x divisible by 4 took ~290 ns, ~60 ns at
// other x; SDL 2.26). Such pictures are copied row by row here instead.
// How blit() may draw a picture itself rather than through SDL: a plain
// copy (opaque, as every tile of an RGB image), a blend by each pixel's
// alpha (a sprite sheet: through SDL it took 5.0 ms for 10k sprites in
// view, against 2.9 ms here), or neither (any other setting: SDL does it).
enum class Fast { No, Copy, Blend };
Fast fast_kind(SDL_Surface* p, uint8_t alpha) {
    SDL_BlendMode mode;
    Uint8 a, r, g, b;
    if (p->format->format != SDL_PIXELFORMAT_ARGB8888 || SDL_MUSTLOCK(p) || SDL_HasColorKey(p) ||
        SDL_GetSurfaceBlendMode(p, &mode) != 0 || SDL_GetSurfaceAlphaMod(p, &a) != 0 || a != 255 ||
        SDL_GetSurfaceColorMod(p, &r, &g, &b) != 0 || r != 255 || g != 255 || b != 255)
        return Fast::No;
    if (mode == SDL_BLENDMODE_NONE) return alpha == 255 ? Fast::Copy : Fast::No;
    // Faded (a layer's opacity), SDL blends by another rule: leave it to SDL.
    return mode == SDL_BLENDMODE_BLEND && alpha == 255 ? Fast::Blend : Fast::No;
}

// One row of pixels, in 16-byte pieces the compiler inlines: a call to
// memcpy for each 64-byte row of a tile costs more than the copy itself.
void copy_row(uint8_t* to, const uint8_t* from, size_t bytes) {
    size_t i = 0;
    for (; i + 16 <= bytes; i += 16) std::memcpy(to + i, from + i, 16);
    for (; i < bytes; i += 4) std::memcpy(to + i, from + i, 4);
}

// One row blended by each source pixel's alpha onto the opaque canvas:
// "over", rounded to the nearest value as fill_rect rounds (SDL's blitter
// approximates / 255 by shifts and is off by one in about half the cases).
// Sprite pixels are mostly fully clear or fully opaque, which skip the
// arithmetic.
void blend_row(uint32_t* to, const uint32_t* from, int n) {
    for (int i = 0; i < n; ++i) {
        const uint32_t s = from[i], a = s >> 24;
        if (a == 0) continue;
        if (a == 255) {
            to[i] = s;
            continue;
        }
        const uint32_t d = to[i];
        const auto ch = [&](int shift) {
            return ((s >> shift & 0xff) * a + (d >> shift & 0xff) * (255 - a) + 127) / 255;
        };
        to[i] = 0xff000000u | ch(16) << 16 | ch(8) << 8 | ch(0);
    }
}

}  // namespace

Canvas::Canvas(int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxCanvasSide || height > kMaxCanvasSide)
        throw RenderError("canvas size " + std::to_string(width) + "x" + std::to_string(height) +
                          " is not between 1 and " + std::to_string(kMaxCanvasSide));
    if (int64_t(width) * height > kMaxCanvasPixels)
        throw RenderError("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " is more than " +
                          std::to_string(kMaxCanvasPixels) + " pixels");
    surface_ = SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_ARGB8888);
    if (!surface_) throw RenderError(std::string("cannot make a canvas: ") + SDL_GetError());
    SDL_SetSurfaceBlendMode(surface_, SDL_BLENDMODE_NONE);
}

Canvas::~Canvas() { SDL_FreeSurface(surface_); }

// With ordinary stores: SDL_FillRect streams past the cache like SDL's copy
// (plain_copy), and every tile drawn after it would then miss on its canvas
// line. In 16-byte pieces, as copy_row: a loop of 4-byte stores is not
// vectorised.
void Canvas::clear(Rgba c) {
    const uint32_t p = pack({c.r, c.g, c.b, 255});
    const uint32_t four[4] = {p, p, p, p};
    const size_t bytes = size_t(width()) * 4;
    for (int y = 0; y < height(); ++y) {
        uint8_t* row = static_cast<uint8_t*>(surface_->pixels) + y * surface_->pitch;
        size_t i = 0;
        for (; i + 16 <= bytes; i += 16) std::memcpy(row + i, four, 16);
        for (; i < bytes; i += 4) std::memcpy(row + i, &p, 4);
    }
}

void Canvas::blend(int x, int y, Rgba c) {
    auto* row = reinterpret_cast<uint32_t*>(static_cast<uint8_t*>(surface_->pixels) + y * surface_->pitch);
    if (c.a == 255) {
        row[x] = pack(c);
        return;
    }
    const uint32_t d = row[x];
    row[x] = pack({mix(c.r, d >> 16 & 0xff, c.a), mix(c.g, d >> 8 & 0xff, c.a),
                   mix(c.b, d & 0xff, c.a), 255});
}

void Canvas::fill_rect(int x, int y, int w, int h, Rgba c) {
    const int x0 = std::max(x, 0), y0 = std::max(y, 0);
    const int x1 = static_cast<int>(std::min<long>(long(x) + w, width()));
    const int y1 = static_cast<int>(std::min<long>(long(y) + h, height()));
    if (c.a == 255 && x0 < x1 && y0 < y1) {
        SDL_Rect r{x0, y0, x1 - x0, y1 - y0};
        SDL_FillRect(surface_, &r, pack(c));
        return;
    }
    for (int py = y0; py < y1; ++py)
        for (int px = x0; px < x1; ++px) blend(px, py, c);
}

void Canvas::outline_rect(int x, int y, int w, int h, Rgba c) {
    if (w <= 0 || h <= 0) return;
    fill_rect(x, y, w, 1, c);
    if (h > 1) fill_rect(x, y + h - 1, w, 1, c);
    if (h > 2) {
        fill_rect(x, y + 1, 1, h - 2, c);
        if (w > 1) fill_rect(x + w - 1, y + 1, 1, h - 2, c);
    }
}

namespace {

// Liang–Barsky: the part of the segment inside [0, w) × [0, h), false when
// none is. Only lines with an end off the canvas are clipped, so a line on
// the canvas keeps exactly its Bresenham pixels.
bool clip_segment(int& x0, int& y0, int& x1, int& y1, int w, int h) {
    const double dx = double(x1) - x0, dy = double(y1) - y0;
    double t0 = 0, t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {double(x0), w - 1.0 - x0, double(y0), h - 1.0 - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
    const double ox = x0, oy = y0;
    x0 = int(std::lround(ox + t0 * dx));
    y0 = int(std::lround(oy + t0 * dy));
    x1 = int(std::lround(ox + t1 * dx));
    y1 = int(std::lround(oy + t1 * dy));
    return true;
}

}  // namespace

void Canvas::line(int x0, int y0, int x1, int y1, Rgba c) {
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < width() && y < height(); };
    if (!(inside(x0, y0) && inside(x1, y1)) && !clip_segment(x0, y0, x1, y1, width(), height()))
        return;
    // Bresenham, every pixel once (a translucent line does not darken where
    // it would cross itself).
    const long dx = std::labs(long(x1) - x0), dy = -std::labs(long(y1) - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    long err = dx + dy;
    for (;;) {
        if (inside(x0, y0)) blend(x0, y0, c);
        if (x0 == x1 && y0 == y1) break;
        const long e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            err += dx;
            y0 += sy;
        }
    }
}

void Canvas::text(int x, int y, std::string_view s, Rgba c, int scale) {
    scale = std::max(scale, 1);
    int pen = x;
    for (unsigned char ch : s) {
        if (ch == '\n') {
            pen = x;
            y += kLineHeight * scale;
            continue;
        }
        for (int row = 0; row < kGlyphHeight; ++row) {
            const uint8_t bits = glyph_row(ch, row);
            for (int col = 0; col < kGlyphWidth; ++col)
                if (bits >> (kGlyphWidth - 1 - col) & 1)
                    fill_rect(pen + col * scale, y + row * scale, scale, scale, c);
        }
        pen += kGlyphAdvance * scale;
    }
}

void Canvas::blit(SDL_Surface* picture, int x, int y, uint8_t alpha) {
    if (!picture) return;
    const Fast fast = fast_kind(picture, alpha);
    if (fast != Fast::No) {
        const int x0 = std::max(x, 0), y0 = std::max(y, 0);
        const int x1 = static_cast<int>(std::min<long>(long(x) + picture->w, width()));
        const int y1 = static_cast<int>(std::min<long>(long(y) + picture->h, height()));
        for (int py = y0; py < y1 && x0 < x1; ++py) {
            uint8_t* to = static_cast<uint8_t*>(surface_->pixels) + py * surface_->pitch + x0 * 4;
            const uint8_t* from =
                static_cast<const uint8_t*>(picture->pixels) + (py - y) * picture->pitch + (x0 - x) * 4;
            if (fast == Fast::Copy) copy_row(to, from, size_t(x1 - x0) * 4);
            else blend_row(reinterpret_cast<uint32_t*>(to), reinterpret_cast<const uint32_t*>(from), x1 - x0);
        }
        return;
    }
    SDL_Rect dst{x, y, picture->w, picture->h};
    if (alpha != 255) SDL_SetSurfaceAlphaMod(picture, alpha);
    SDL_BlitSurface(picture, nullptr, surface_, &dst);
    if (alpha != 255) SDL_SetSurfaceAlphaMod(picture, 255);
}

namespace {

// Where a picture pixel edge falls exactly on a canvas pixel centre (a
// scale of 3/4 puts every fourth there), the source image's pixel before it
// is taken, as Qt's fixed-point sampling does: Tiled's pictures match ours
// then, flipped tiles too (PictureBox::reversed_x/y).
constexpr double kTie = 1.0 / 65536;

// The canvas pixels a turned box can touch: its corners' bounds, clipped.
struct PixelSpan {
    int x0, y0, x1, y1;
};
PixelSpan touched(const PictureBox& b, double cos_t, double sin_t, int width, int height) {
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (const auto& [dx, dy] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}}) {
        const double x = b.cx + dx * b.w - b.pivot_x, y = b.cy + dy * b.h - b.pivot_y;
        const double tx = b.pivot_x + x * cos_t - y * sin_t, ty = b.pivot_y + x * sin_t + y * cos_t;
        lo_x = std::min(lo_x, tx), hi_x = std::max(hi_x, tx);
        lo_y = std::min(lo_y, ty), hi_y = std::max(hi_y, ty);
    }
    const auto clip = [](double v, int hi) { return int(std::clamp(v, 0.0, double(hi))); };
    return {clip(std::floor(lo_x), width), clip(std::floor(lo_y), height), clip(std::ceil(hi_x), width),
            clip(std::ceil(hi_y), height)};
}

// Qt's rounding to whole px: half up.
int64_t q_round(double v) { return int64_t(std::floor(v + 0.5)); }

// For each canvas pixel t in [first, first + size) along one axis, the
// source pixel a picture n px long, drawn over [a0, a0 + len), shows there,
// or -1: exactly as Qt 5's scaled blit picks it (qt_scale_image_* in
// qblendfunctions: 16.16 fixed point from the first pixel drawn, the step
// truncated), so that a stretched tile matches Tiled's picture pixel for
// pixel. `reversed`: the picture runs against its source (a flip), which Qt
// draws with a negative step from the source's far end (rounded as the
// forward case is: Tiled 1.8 on Debian's Qt 5.15 draws it so).
struct AxisMap {
    int64_t first = 0, last = 0;  // canvas px drawn: [first, last)
    std::vector<int> source;
};
AxisMap qt_axis(double a0, double len, int n, bool reversed, int canvas) {
    AxisMap m;
    m.first = std::max<int64_t>(q_round(a0), 0);
    m.last = std::min<int64_t>(q_round(a0 + len), canvas);
    if (m.first >= m.last) return m;
    const double s = (reversed ? -n : n) / len;
    const auto step = int64_t(65536 * s);  // truncated toward zero, as Qt's int conversion
    const double from = (double(m.first) + 0.5 - a0) * s * 65536;
    int64_t at = (reversed ? int64_t(n) * 65536 : 0) + int64_t(std::ceil(from)) - 1;
    m.source.resize(size_t(m.last - m.first));
    for (int& v : m.source) {
        const int64_t i = at >> 16;  // arithmetic: a negative stays out of range
        v = i >= 0 && i < n ? int(reversed ? n - 1 - i : i) : -1;
        at += step;
    }
    return m;
}

// Picture pixel `s` (ARGB; its alpha ignored when the picture is opaque)
// tinted (each channel × tint / 255) and faded by `alpha`.
Rgba tinted(uint32_t s, bool opaque, uint8_t alpha, Rgba tint) {
    return {mul255(s >> 16 & 0xff, tint.r), mul255(s >> 8 & 0xff, tint.g), mul255(s & 0xff, tint.b),
            mul255(mul255(opaque ? 255 : s >> 24, tint.a), alpha)};
}

}  // namespace

void Canvas::draw_picture(SDL_Surface* pic, const PictureBox& b, uint8_t alpha, Rgba tint) {
    if (!pic || pic->w <= 0 || pic->h <= 0 || !(b.w > 0) || !(b.h > 0) || alpha == 0) return;
    if (pic->format->format != SDL_PIXELFORMAT_ARGB8888 || SDL_MUSTLOCK(pic)) return;
    if (!(std::fabs(b.cx) < 1e9 && std::fabs(b.cy) < 1e9 && b.w < 1e9 && b.h < 1e9)) return;
    SDL_BlendMode mode;
    SDL_GetSurfaceBlendMode(pic, &mode);
    const bool opaque = mode == SDL_BLENDMODE_NONE;
    const double left = b.cx - b.w / 2, top = b.cy - b.h / 2;
    const auto sample = [&](int u, int v) {
        return reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(pic->pixels) + v * pic->pitch)[u];
    };
    if (b.degrees == 0 && !b.transposed) {  // stretched, maybe flipped: Qt's scaled blit
        const AxisMap xs = qt_axis(left, b.w, pic->w, b.reversed_x, width());
        const AxisMap ys = qt_axis(top, b.h, pic->h, b.reversed_y, height());
        for (int64_t y = ys.first; y < ys.last; ++y) {
            const int v = ys.source[size_t(y - ys.first)];
            if (v < 0) continue;
            for (int64_t x = xs.first; x < xs.last; ++x)
                if (const int u = xs.source[size_t(x - xs.first)]; u >= 0)
                    if (const Rgba c = tinted(sample(u, v), opaque, alpha, tint); c.a) blend(int(x), int(y), c);
        }
        return;
    }
    const double rad = b.degrees * (3.14159265358979323846 / 180.0);
    const double cos_t = b.degrees == 0 ? 1 : std::cos(rad), sin_t = b.degrees == 0 ? 0 : std::sin(rad);
    const PixelSpan span = touched(b, cos_t, sin_t, width(), height());
    const double to_u = pic->w / b.w, to_v = pic->h / b.h;
    const double tie_x = b.reversed_x ? kTie : -kTie, tie_y = b.reversed_y ? kTie : -kTie;
    for (int y = span.y0; y < span.y1; ++y) {
        for (int x = span.x0; x < span.x1; ++x) {
            // The pixel's centre, turned back about the pivot into the box.
            const double px = x + 0.5 - b.pivot_x, py = y + 0.5 - b.pivot_y;
            const double bx = b.pivot_x + px * cos_t + py * sin_t, by = b.pivot_y - px * sin_t + py * cos_t;
            const double u = std::floor((bx - left) * to_u + tie_x), v = std::floor((by - top) * to_v + tie_y);
            if (!(u >= 0 && u < pic->w && v >= 0 && v < pic->h)) continue;
            if (const Rgba c = tinted(sample(int(u), int(v)), opaque, alpha, tint); c.a) blend(x, y, c);
        }
    }
}

Rgba Canvas::pixel(int x, int y) const {
    if (x < 0 || y < 0 || x >= width() || y >= height()) return {0, 0, 0, 0};
    const auto* row = reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(surface_->pixels) +
                                                        y * surface_->pitch);
    const uint32_t p = row[x];
    return {uint8_t(p >> 16), uint8_t(p >> 8), uint8_t(p), uint8_t(p >> 24)};
}

namespace {

// Where save_png's PNG goes: a descriptor, with the first write error kept.
// SDL's own file stream (IMG_SavePNG) lets a failed write pass unnoticed —
// a full disk gave a truncated or empty picture and no error.
struct PngSink {
    int fd = -1;
    int error = 0;  // errno of the first failed write
};

PngSink& sink_of(SDL_RWops* rw) { return *static_cast<PngSink*>(rw->hidden.unknown.data1); }

size_t SDLCALL sink_write(SDL_RWops* rw, const void* data, size_t size, size_t count) {
    PngSink& sink = sink_of(rw);
    if (sink.error) return 0;
    const char* p = static_cast<const char*>(data);
    for (size_t left = size * count; left > 0;) {
        const ssize_t n = ::write(sink.fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            sink.error = n < 0 ? errno : EIO;
            return 0;
        }
        p += n;
        left -= size_t(n);
    }
    return count;
}

Sint64 SDLCALL sink_seek(SDL_RWops* rw, Sint64 offset, int whence) {
    const int how = whence == RW_SEEK_SET ? SEEK_SET : whence == RW_SEEK_CUR ? SEEK_CUR : SEEK_END;
    const off_t at = ::lseek(sink_of(rw).fd, off_t(offset), how);
    return at < 0 ? SDL_SetError("seek failed") : Sint64(at);
}

Sint64 SDLCALL sink_size(SDL_RWops*) { return -1; }
size_t SDLCALL sink_read(SDL_RWops*, void*, size_t, size_t) { return 0; }
int SDLCALL sink_close(SDL_RWops*) { return 0; }  // save_png closes the descriptor itself

std::string errno_text(int e) { return std::strerror(e); }

// A new file beside `path` (O_EXCL, so never one that is there, never a FIFO
// or a device; the umask applies, as to any file the game writes), and its
// name; -1 with errno when none can be made.
int open_beside(const std::string& path, std::string& temp) {
    static unsigned serial = 0;
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp = path + ".part-" + std::to_string(::getpid()) + "-" + std::to_string(serial++);
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    return -1;
}

}  // namespace

void Canvas::save_png(const std::string& path) const {
    const auto refuse = [&](const std::string& why) { throw RenderError("cannot write '" + path + "': " + why); };
    // Only a regular file (new, or replaced): a FIFO would block the game
    // until a reader came, and a device or a directory is no picture.
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) refuse("not a regular file");
    // Written beside it and renamed over it only once whole, so a failed
    // write (a full disk) leaves the file that was there as it was.
    std::string temp;
    const int fd = open_beside(path, temp);
    if (fd < 0) refuse(errno_text(errno));
    PngSink sink{fd};
    int saved = -1;
    if (SDL_RWops* rw = SDL_AllocRW()) {
        rw->size = sink_size;
        rw->seek = sink_seek;
        rw->read = sink_read;
        rw->write = sink_write;
        rw->close = sink_close;
        rw->type = SDL_RWOPS_UNKNOWN;
        rw->hidden.unknown.data1 = &sink;
        saved = IMG_SavePNG_RW(surface_, rw, 0);
        SDL_FreeRW(rw);
    }
    const std::string sdl_error = saved != 0 ? IMG_GetError() : "";
    // close reports what the writes could not (a delayed write on NFS).
    const int close_error = ::close(fd) != 0 ? errno : 0;
    int error = sink.error ? sink.error : close_error;
    if (!error && saved == 0 && ::rename(temp.c_str(), path.c_str()) != 0) error = errno;
    if (error || saved != 0) {
        ::unlink(temp.c_str());  // a partial picture is no frame
        refuse(error ? errno_text(error) : sdl_error);
    }
}

}  // namespace ds::render
