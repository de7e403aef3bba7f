// SPDX-License-Identifier: MIT
// Every tunable of the renderer, each with the reason for its value.
#pragma once
#include <cstdint>

#include "color.hpp"

namespace ds::render {

// Cleared to before the map: a dark blue-grey, so an empty cell reads as
// "sky" and black tiles or text still show against it.
constexpr Rgba kBackground{24, 28, 40, 255};


// The largest image the renderer decodes (tilesets, image collections, image
// layers), checked from the file's header before a pixel is allocated: a
// side of 16384 px is the largest texture side common GPUs take, and 256 MiB
// decoded (8192 × 8192 at 4 bytes a pixel) is far past any tileset or
// backdrop while a machine can hold several; a 3.5 MB PNG declaring
// 30000 × 30000 px would otherwise decode to 3.6 GB.
constexpr int64_t kMaxImageSidePx = 16384;
constexpr int64_t kMaxImageDecodedBytes = int64_t(256) << 20;
// The largest image file read (whole, before decoding): the decoded bound
// and 1 MiB more. No format taken stores a picture in more bytes than it
// decodes to (a BMP, at most 4 bytes a pixel, is the largest) beyond its
// headers and metadata (EXIF, ICC: a JPEG's frame header may follow up to
// a MiB of them), so a larger file is padding or a lie.
constexpr int64_t kMaxImageFileBytes = kMaxImageDecodedBytes + (int64_t(1) << 20);

// The most a sound may take decoded, at the mixer's 44.1 kHz, stereo, 16
// bits: 64 MiB is about six minutes, where a sound effect lasts seconds; a
// WAV or OGG header can claim any length, and SDL_mixer decodes a sound
// whole, so the claim is checked (sound_header.hpp) before it is believed.
constexpr int64_t kMaxSoundDecodedBytes = int64_t(64) << 20;
// The largest sound file read (whole, before decoding): as much as a sound
// may decode to. An effect's file is KBs; one this large is a master
// recording (384 kHz, 8 channels) to be converted first, and reading it
// whole beside its decoded copy doubles what a sound may cost.
constexpr int64_t kMaxSoundFileBytes = kMaxSoundDecodedBytes;

// Music is read whole into memory when loaded and decoded from there as it
// plays, so no decoder can read past what was checked; each format's file
// is bounded by what that format holds (music_format.hpp tells them apart
// by content). A 2.1 GB sparse MOD or MIDI file (4 KB on disk) used to
// crash the decoder, and a 1 GB MIDI took 2 GB.
// Streamed (Ogg Vorbis, WAV, FLAC, MP3), decoded a little at a time: 64 MiB
// is about an hour of Ogg at 160 kb/s and six minutes of CD-quality WAV,
// and is what a loaded track costs while it stays loaded.
constexpr int64_t kMaxStreamedMusicBytes = int64_t(64) << 20;
// Tracker modules (MOD, XM, S3M, IT): the patterns and samples of a real
// one are KBs to a few MB; libmodplug copies the file and unpacks its
// samples, so a module costs a few times its size, and 32 MiB keeps that
// far below the machine while past any module released.
constexpr int64_t kMaxModuleFileBytes = int64_t(32) << 20;
// MIDI holds notes, not sound: a whole symphony is about 100 KB. Each event
// becomes a decoder structure several times its size, which is how 1 GB of
// MIDI took 2 GB; 4 MiB is forty symphonies.
constexpr int64_t kMaxMidiFileBytes = int64_t(4) << 20;

// The most draw-* calls one frame may queue: 262 144 is hundreds of times
// what a 640 × 360 picture can show (a 16 px sprite on every cell is 900),
// and at about 80 bytes a call it keeps a runaway render: loop to about
// 20 MB instead of growing until the machine runs out.
constexpr int64_t kMaxDrawCommands = int64_t(1) << 18;

// The largest #:sprite-scale: 64 makes a 16 px sprite 1024 px, past any
// game's screen; a larger factor is a typo (a size given for a factor). A
// drawn sprite costs at most the canvas's pixels whatever its scale.
constexpr double kMaxSpriteScale = 64;
// The most frames an #:animation list holds: every entity's list is read
// each frame it is drawn, so its length is that entity's cost; a sprite
// sheet's run of frames is a few to a few dozen, and 256 is ten seconds of
// distinct pictures at 25 a second.
constexpr long kMaxAnimationFrames = 256;
// The largest #:animation-start, either side of 0: 2^53, where a frame
// number stops being exact as a double (the clock is frame × delay, in ms).
constexpr int64_t kMaxAnimationStart = int64_t(1) << 53;

// The largest window scale tried when fitting the screen: beyond this a
// pixel-art game is already huge, and a 64× surface blit would be wasteful.
constexpr int kMaxScale = 16;
// The rate a window presents at when SDL cannot tell the display's: the
// commonest refresh rate, and what Xvfb's displays are paced as.
constexpr int kDefaultRefreshHz = 60;

// The overlay's boxes, by role: hues far apart so a glance tells them apart.
constexpr Rgba kSolidColor{80, 220, 100, 255};      // solid: takes part in push-apart
constexpr Rgba kImmovableColor{80, 150, 255, 255};  // solid and never pushed
constexpr Rgba kGhostColor{200, 110, 230, 255};     // solid but skips entity collisions
constexpr Rgba kPlainColor{170, 170, 170, 255};     // not solid: moves through entities
constexpr Rgba kRestingColor{250, 210, 70, 255};    // on the ground and not moving
constexpr Rgba kSensorColor{90, 225, 225, 255};     // a sensor: notices overlaps, pushes nothing

// A cell whose gid no tileset holds: magenta, the colour no tileset uses
// and every artist reads as "texture missing"; filled faintly and outlined
// so the tiles behind it still show.
constexpr Rgba kMissingTileColor{255, 0, 255, 255};
constexpr uint8_t kMissingTileFillAlpha = 96;

// Overlay marks.
constexpr Rgba kVelocityColor{255, 240, 120, 255};
constexpr Rgba kGroundMarkColor{255, 140, 40, 255};
constexpr Rgba kPushedPairColor{255, 70, 70, 255};
constexpr Rgba kTrailColor{120, 230, 255, 255};
// Behind the overlay's legend: dark enough for its colours to read over grass.
constexpr Rgba kLegendPlate{0, 0, 0, 170};
// A velocity in px/frame is drawn this many frames long: a body moving one
// pixel a frame would otherwise get a vector no longer than a pixel.
constexpr double kVelocityScale = 4.0;
// The on-ground mark: a bar this many px tall under the feet.
constexpr int kGroundMarkHeight = 2;

}  // namespace ds::render
