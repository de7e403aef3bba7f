// SPDX-License-Identifier: MIT
#include "sound_header.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace ds::render {

namespace {

uint32_t le16(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8; }
uint32_t le32(const uint8_t* p) { return le16(p) | le16(p + 2) << 16; }
uint64_t le64(const uint8_t* p) { return uint64_t(le32(p)) | uint64_t(le32(p + 4)) << 32; }

bool fail(std::string& why, std::string text) {
    why = std::move(text);
    return false;
}

bool plausible(SoundHeader& h, std::string& why) {
    if (h.channels < 1 || h.channels > kMaxSoundChannels)
        return fail(why, std::string("its ") + h.format + " header declares " + std::to_string(h.channels) +
                             " channels (at most " + std::to_string(kMaxSoundChannels) + ")");
    if (h.rate < 1 || h.rate > kMaxSoundRate)
        return fail(why, std::string("its ") + h.format + " header declares a rate of " + std::to_string(h.rate) +
                             " Hz (at most " + std::to_string(kMaxSoundRate) + ")");
    return true;
}

// The WAV encodings SDL_LoadWAV decodes (a WAVE_FORMAT_EXTENSIBLE file names
// one of them in the first two bytes of its sub-format).
enum : uint32_t { kPcm = 1, kMsAdpcm = 2, kFloat = 3, kALaw = 6, kMuLaw = 7, kImaAdpcm = 0x11, kExtensible = 0xFFFE };

// The most frames `size` bytes of data chunk decode to under `encoding`, and
// the bytes a decoded sample takes; false with `why` for an encoding that is
// not counted. ADPCM comes in blocks of `block` bytes, each a header per
// channel (MS: 7 bytes, IMA: 4) and 4-bit samples after it (plus the
// header's own samples: MS 2, IMA 1); the last block may be cut short, and
// counts as a whole one, so the claim is never below what SDL decodes.
bool wav_frames(uint32_t encoding, int64_t channels, int64_t bits, int64_t block, uint64_t size, SoundHeader& h,
                std::string& why) {
    switch (encoding) {
    case kPcm:
    case kFloat:
    case kALaw:
    case kMuLaw: {
        if (bits < 1 || bits > 64) return fail(why, "its WAV header declares " + std::to_string(bits) + " bits a sample");
        const int64_t sample = (bits + 7) / 8;
        // SDL counts frames by the block alignment, even one smaller than a
        // frame (it then decodes more frames than the data holds): the
        // smaller of the two divides.
        const int64_t frame = block > 0 ? std::min(block, channels * sample) : channels * sample;
        h.frames = int64_t(size / uint64_t(frame));
        h.decoded_sample_bytes = encoding == kALaw || encoding == kMuLaw ? 2 : sample == 3 ? 4 : sample;
        return true;
    }
    case kMsAdpcm:
    case kImaAdpcm: {
        const int64_t header = (encoding == kMsAdpcm ? 7 : 4) * channels, extra = encoding == kMsAdpcm ? 2 : 1;
        if (bits != 4 || block <= header)
            return fail(why, "its ADPCM WAV header declares " + std::to_string(bits) + " bits a sample in blocks of " +
                                 std::to_string(block) + " bytes");
        const int64_t per_block = (block - header) * 8 / (4 * channels) + extra;
        h.frames = int64_t((size + uint64_t(block) - 1) / uint64_t(block)) * per_block;
        h.decoded_sample_bytes = 2;
        return true;
    }
    default:
        return fail(why, "its WAV encoding " + std::to_string(encoding) +
                             " is none the loader counts (PCM, float, A-law, µ-law, MS and IMA ADPCM)");
    }
}

// RIFF "WAVE": chunks of a 4-byte id and a little-endian size, padded to
// even sizes; "fmt " (encoding, channels, rate, …, bits per sample) comes
// before "data", whose size must fit in the file.
bool wav(std::span<const uint8_t> b, SoundHeader& h, std::string& why) {
    h.format = "WAV";
    uint64_t at = 12;
    uint32_t encoding = 0;
    int64_t bits = 0, block = 0;
    bool have_fmt = false;
    while (at + 8 <= b.size()) {
        const uint8_t* c = b.data() + at;
        const uint64_t size = le32(c + 4);
        if (std::memcmp(c, "fmt ", 4) == 0) {
            if (size < 16 || at + 8 + 16 > b.size()) return fail(why, "its WAV fmt chunk is cut short");
            encoding = le16(c + 8);
            h.channels = le16(c + 10);
            h.rate = le32(c + 12);
            block = le16(c + 20);
            bits = le16(c + 22);
            if (encoding == kExtensible) {
                if (size < 40 || at + 8 + 40 > b.size()) return fail(why, "its WAV fmt chunk is cut short");
                encoding = le16(c + 8 + 24);  // the sub-format's first two bytes
            }
            have_fmt = true;
        } else if (std::memcmp(c, "data", 4) == 0) {
            if (!have_fmt) return fail(why, "its WAV data chunk comes before its fmt chunk");
            if (at + 8 + size > b.size())
                return fail(why, "its WAV data chunk declares " + std::to_string(size) + " bytes, but the file holds " +
                                     std::to_string(b.size() > at + 8 ? b.size() - at - 8 : 0) + " after it");
            if (!plausible(h, why)) return false;
            return wav_frames(encoding, h.channels, bits, block, size, h, why);
        }
        at += 8 + size + (size & 1);
    }
    return fail(why, have_fmt ? "its WAV data chunk is missing" : "its WAV header is cut short");
}

// The Ogg page CRC: polynomial 0x04C11DB7, not reflected, starting from 0,
// over the page with its CRC field read as zero.
uint32_t ogg_crc(std::span<const uint8_t> page) {
    static const std::array<uint32_t, 256> table = [] {
        std::array<uint32_t, 256> t{};
        for (uint32_t i = 0; i < 256; ++i) {
            uint32_t r = i << 24;
            for (int k = 0; k < 8; ++k) r = r & 0x80000000u ? r << 1 ^ 0x04C11DB7u : r << 1;
            t[i] = r;
        }
        return t;
    }();
    uint32_t crc = 0;
    for (size_t i = 0; i < page.size(); ++i)
        crc = crc << 8 ^ table[(crc >> 24 ^ (i >= 22 && i < 26 ? 0 : page[i])) & 0xff];
    return crc;
}

// The length of the Ogg page at the start of `b`, or 0 when it is not a
// whole page there with a right CRC.
size_t ogg_page(std::span<const uint8_t> b) {
    if (b.size() < 27 || std::memcmp(b.data(), "OggS", 4) != 0 || b[4] != 0) return 0;
    size_t size = 27 + b[26];
    if (b.size() < size) return 0;
    for (size_t i = 0; i < b[26]; ++i) size += b[27 + i];
    if (b.size() < size || ogg_crc(b.first(size)) != le32(b.data() + 22)) return 0;
    return size;
}

// Ogg: pages start "OggS"; the first page's packet is Vorbis's
// identification header ("\x01vorbis", version, channels, rate); a page's
// granule position (bytes 6–13) counts the samples up to its end, so the
// last page's is the stream's length. That page must end the file, carry
// the end-of-stream flag and the first page's serial number, and pass its
// CRC: bytes appended to a file, or a second stream chained after the
// first, do not get to say how long it is. The decoder is capped at this
// claim all the same (ogg_decode.hpp), as a page can be forged whole.
bool ogg(std::span<const uint8_t> b, SoundHeader& h, std::string& why) {
    h.format = "OGG";
    if (b.size() < 27) return fail(why, "its Ogg page header is cut short");
    const size_t segments = b[26], packet = 27 + segments;
    if (b.size() < packet + 16 || std::memcmp(b.data() + packet, "\x01vorbis", 7) != 0)
        return fail(why, "its first Ogg packet is not a Vorbis identification header");
    h.channels = b[packet + 11];
    h.rate = le32(b.data() + packet + 12);
    h.decoded_sample_bytes = 2;
    if (!plausible(h, why)) return false;
    const uint32_t serial = le32(b.data() + 14);
    const size_t from = b.size() > kOggMaxPageBytes ? b.size() - kOggMaxPageBytes : 0;
    for (size_t i = b.size() >= 27 ? b.size() - 27 + 1 : 0; i-- > from;) {
        if (b[i] != 'O' || ogg_page(b.subspan(i)) != b.size() - i) continue;
        const uint8_t* page = b.data() + i;
        if (le32(page + 14) != serial)
            return fail(why, "its last Ogg page belongs to another stream (chained Ogg files are not read)");
        if (!(page[5] & 4)) return fail(why, "its last Ogg page does not end the stream (the file is cut short)");
        const uint64_t granule = le64(page + 6);
        if (granule > (uint64_t(1) << 40))
            return fail(why, "its last Ogg page declares " + std::to_string(granule) + " samples");
        h.frames = int64_t(granule);
        return true;
    }
    return fail(why, "its last Ogg page is missing or corrupt (the file is cut short or has bytes after its end)");
}

}  // namespace

bool read_sound_header(std::span<const uint8_t> file, SoundHeader& out, std::string& why) {
    if (file.size() >= 12 && std::memcmp(file.data(), "RIFF", 4) == 0 && std::memcmp(file.data() + 8, "WAVE", 4) == 0)
        return wav(file, out, why);
    if (file.size() >= 4 && std::memcmp(file.data(), "OggS", 4) == 0) return ogg(file, out, why);
    return fail(why, file.empty() ? "it is empty" : "it is not a WAV or Ogg Vorbis file");
}

}  // namespace ds::render
