// SPDX-License-Identifier: MIT
// Canvas::blit copies opaque pictures and blends per-pixel-alpha ones itself
// (canvas.cpp says why): a copy must come out as SDL_BlitSurface would have
// put it, a blend as the exactly rounded "over" of each pixel, both clipped
// at every edge; faded and colour-keyed pictures still go to SDL.
#include <doctest/doctest.h>

#include <SDL.h>

#include <cstdint>

#include "canvas.hpp"

using ds::render::Canvas;

namespace {

constexpr int kW = 40, kH = 24;  // small, so pictures cross every edge

SDL_Surface* picture(int w, int h, SDL_BlendMode mode) {
    SDL_Surface* s = SDL_CreateRGBSurfaceWithFormat(0, w, h, 32, SDL_PIXELFORMAT_ARGB8888);
    SDL_SetSurfaceBlendMode(s, mode);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            static_cast<uint32_t*>(s->pixels)[y * s->pitch / 4 + x] =
                uint32_t(0x80 + x * 7) << 24 | uint32_t(x * 13) << 16 | uint32_t(y * 11) << 8 | 0x5a;
    return s;
}

// The exactly rounded "over" of ARGB8888 pixel s onto opaque d.
uint32_t over(uint32_t s, uint32_t d) {
    const uint32_t a = s >> 24;
    auto ch = [&](int k) { return (((s >> k) & 0xff) * a + ((d >> k) & 0xff) * (255 - a) + 127) / 255; };
    return 0xff000000u | ch(16) << 16 | ch(8) << 8 | ch(0);
}

// Canvas::blit of a per-pixel-alpha picture at (x, y), against over().
void check_over(SDL_Surface* pic, int x, int y) {
    Canvas c(kW, kH);
    c.clear({10, 20, 30, 255});
    c.blit(pic, x, y);
    int wrong = 0;
    for (int py = 0; py < kH; ++py)
        for (int px = 0; px < kW; ++px) {
            const bool inside = px >= x && px < x + pic->w && py >= y && py < y + pic->h;
            const uint32_t want =
                inside ? over(static_cast<const uint32_t*>(pic->pixels)[(py - y) * pic->pitch / 4 + (px - x)], 0xff0a141e)
                       : 0xff0a141e;
            const ds::render::Rgba got = c.pixel(px, py);
            wrong += (uint32_t(got.a) << 24 | uint32_t(got.r) << 16 | uint32_t(got.g) << 8 | got.b) != want;
        }
    CHECK_MESSAGE(wrong == 0, "at (" << x << ", " << y << ")");
}

// Canvas::blit at (x, y), against SDL_BlitSurface onto a surface like the canvas.
void check(SDL_Surface* pic, int x, int y, uint8_t alpha) {
    Canvas c(kW, kH);
    c.clear({10, 20, 30, 255});
    SDL_Surface* ref = SDL_CreateRGBSurfaceWithFormat(0, kW, kH, 32, SDL_PIXELFORMAT_ARGB8888);
    SDL_SetSurfaceBlendMode(ref, SDL_BLENDMODE_NONE);
    SDL_FillRect(ref, nullptr, 0xff0a141e);
    c.blit(pic, x, y, alpha);
    SDL_Rect r{x, y, pic->w, pic->h};
    SDL_SetSurfaceAlphaMod(pic, alpha);
    SDL_BlitSurface(pic, nullptr, ref, &r);
    SDL_SetSurfaceAlphaMod(pic, 255);
    int wrong = 0;
    for (int py = 0; py < kH; ++py)
        for (int px = 0; px < kW; ++px) {
            const uint32_t want = static_cast<const uint32_t*>(ref->pixels)[py * ref->pitch / 4 + px];
            const ds::render::Rgba got = c.pixel(px, py);
            const uint32_t g = uint32_t(got.a) << 24 | uint32_t(got.r) << 16 | uint32_t(got.g) << 8 | got.b;
            wrong += g != want;
        }
    CHECK_MESSAGE(wrong == 0, "at (" << x << ", " << y << ") alpha " << int(alpha));
    SDL_FreeSurface(ref);
}

}  // namespace

TEST_SUITE("render") {

TEST_CASE("an opaque picture is copied as SDL would, clipped at every edge") {
    SDL_Surface* pic = picture(16, 16, SDL_BLENDMODE_NONE);
    for (int y : {-20, -16, -15, -3, 0, 5, kH - 16, kH - 1, kH, 1 << 30})
        for (int x : {-(1 << 30), -16, -15, -1, 0, 1, 2, 3, 4, kW - 16, kW - 5, kW - 1, kW}) check(pic, x, y, 255);
    SDL_FreeSurface(pic);
}

TEST_CASE("a picture with alpha blends each pixel exactly, clipped at every edge") {
    SDL_Surface* blended = picture(16, 16, SDL_BLENDMODE_BLEND);
    auto* px = static_cast<uint32_t*>(blended->pixels);
    px[0] = 0x00ffffffu;  // fully clear: leaves the canvas
    px[1] = 0xff123456u;  // fully opaque: replaces it
    for (int y : {-20, -15, 0, 4, kH - 1, kH})
        for (int x : {-16, -3, 0, 7, kW - 9, kW}) check_over(blended, x, y);
    SDL_FreeSurface(blended);
}

TEST_CASE("faded and colour-keyed pictures still blend as SDL does") {
    SDL_Surface* blended = picture(16, 16, SDL_BLENDMODE_BLEND);
    SDL_Surface* opaque = picture(16, 16, SDL_BLENDMODE_NONE);
    SDL_Surface* keyed = picture(16, 16, SDL_BLENDMODE_NONE);
    SDL_SetColorKey(keyed, SDL_TRUE, static_cast<const uint32_t*>(keyed->pixels)[0]);
    for (int x : {-3, 0, 7, kW - 9}) {
        check(blended, x, 4, 128);
        check(opaque, x, 4, 128);
        check(keyed, x, 4, 255);
    }
    SDL_FreeSurface(blended);
    SDL_FreeSurface(opaque);
    SDL_FreeSurface(keyed);
}

}  // TEST_SUITE
