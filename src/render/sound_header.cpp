#include "sound_header.hpp"

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

// RIFF "WAVE": chunks of a 4-byte id and a little-endian size, padded to
// even sizes; "fmt " (format, channels, rate, …, bits per sample) comes
// before "data", whose size must fit in the file.
bool wav(std::span<const uint8_t> b, uint64_t file_size, SoundHeader& h, std::string& why) {
    h.format = "WAV";
    uint64_t at = 12;
    int64_t bits = 0, block = 0;
    bool have_fmt = false;
    while (at + 8 <= b.size()) {
        const uint8_t* c = b.data() + at;
        const uint64_t size = le32(c + 4);
        if (std::memcmp(c, "fmt ", 4) == 0) {
            if (size < 16 || at + 8 + 16 > b.size()) return fail(why, "its WAV fmt chunk is cut short");
            h.channels = le16(c + 10);
            h.rate = le32(c + 12);
            block = le16(c + 20);
            bits = le16(c + 22);
            have_fmt = true;
        } else if (std::memcmp(c, "data", 4) == 0) {
            if (!have_fmt) return fail(why, "its WAV data chunk comes before its fmt chunk");
            if (at + 8 + size > file_size)
                return fail(why, "its WAV data chunk declares " + std::to_string(size) + " bytes, but the file holds " +
                                     std::to_string(file_size > at + 8 ? file_size - at - 8 : 0) + " after it");
            if (!plausible(h, why)) return false;
            if (bits < 1 || bits > 64) return fail(why, "its WAV header declares " + std::to_string(bits) + " bits a sample");
            const int64_t frame_bytes = block > 0 ? block : h.channels * ((bits + 7) / 8);
            h.frames = int64_t(size) / frame_bytes;
            return true;
        }
        at += 8 + size + (size & 1);
    }
    return fail(why, have_fmt ? "its WAV data chunk is missing or past the first 64 KiB" : "its WAV header is cut short");
}

// Ogg: pages start "OggS"; the first page's packet is Vorbis's
// identification header ("\x01vorbis", version, channels, rate); a page's
// granule position (bytes 6–13) counts the samples up to its end, so the
// last page's is the stream's length.
bool ogg(std::span<const uint8_t> head, std::span<const uint8_t> tail, SoundHeader& h, std::string& why) {
    h.format = "OGG";
    if (head.size() < 27) return fail(why, "its Ogg page header is cut short");
    const size_t segments = head[26], packet = 27 + segments;
    if (head.size() < packet + 16 || std::memcmp(head.data() + packet, "\x01vorbis", 7) != 0)
        return fail(why, "its first Ogg packet is not a Vorbis identification header");
    h.channels = head[packet + 11];
    h.rate = le32(head.data() + packet + 12);
    if (!plausible(h, why)) return false;
    for (size_t i = tail.size() >= 27 ? tail.size() - 27 + 1 : 0; i-- > 0;)
        if (std::memcmp(tail.data() + i, "OggS", 4) == 0 && i + 14 <= tail.size()) {
            const uint64_t granule = le64(tail.data() + i + 6);
            if (granule > (uint64_t(1) << 40))
                return fail(why, "its last Ogg page declares " + std::to_string(granule) + " samples");
            h.frames = int64_t(granule);
            return true;
        }
    return fail(why, "its last Ogg page is missing (the file is cut short)");
}

}  // namespace

bool read_sound_header(std::span<const uint8_t> head, std::span<const uint8_t> tail, uint64_t file_size,
                       SoundHeader& out, std::string& why) {
    if (head.size() >= 12 && std::memcmp(head.data(), "RIFF", 4) == 0 && std::memcmp(head.data() + 8, "WAVE", 4) == 0)
        return wav(head, file_size, out, why);
    if (head.size() >= 4 && std::memcmp(head.data(), "OggS", 4) == 0) return ogg(head, tail, out, why);
    return fail(why, head.empty() ? "it is empty" : "it is not a WAV or Ogg Vorbis file");
}

}  // namespace ds::render
