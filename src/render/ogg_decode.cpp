// SPDX-License-Identifier: MIT
#include "ogg_decode.hpp"

#include <vorbis/vorbisfile.h>

#include <algorithm>
#include <cstring>

namespace ds::render {

namespace {

// libvorbisfile reads through these from the bytes already in memory.
struct Source {
    std::span<const uint8_t> bytes;
    size_t at = 0;
};

size_t read_source(void* buf, size_t size, size_t count, void* data) {
    auto* s = static_cast<Source*>(data);
    const size_t n = std::min(size * count, s->bytes.size() - s->at);
    std::memcpy(buf, s->bytes.data() + s->at, n);
    s->at += n;
    return size ? n / size : 0;
}

int seek_source(void* data, ogg_int64_t offset, int whence) {
    auto* s = static_cast<Source*>(data);
    const int64_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? int64_t(s->at) : int64_t(s->bytes.size());
    if (offset < -base || base + offset > int64_t(s->bytes.size())) return -1;
    s->at = size_t(base + offset);
    return 0;
}

long tell_source(void* data) { return long(static_cast<Source*>(data)->at); }

// libvorbisfile's error codes in words.
const char* vorbis_reason(long code) {
    switch (code) {
    case OV_EREAD: return "reading it failed";
    case OV_ENOTVORBIS: return "it is not Vorbis data";
    case OV_EVERSION: return "its Vorbis version is unknown";
    case OV_EBADHEADER: return "its Vorbis headers are corrupt";
    case OV_EBADLINK: return "its Ogg stream is corrupt";
    case OV_EFAULT: return "the Vorbis decoder failed";
    default: return "its Vorbis data is corrupt";
    }
}

bool fail(std::string& why, std::string text) {
    why = std::move(text);
    return false;
}

// Decodes from the opened `vf`; split from decode_ogg so ov_clear runs on
// every path.
bool decode_open(OggVorbis_File& vf, int64_t channels, int64_t rate, int64_t max_frames, DecodedOgg& out,
                 std::string& why) {
    if (ov_streams(&vf) != 1) return fail(why, "it chains several Ogg streams (only one is read)");
    const vorbis_info* info = ov_info(&vf, 0);
    if (!info || info->channels != channels || info->rate != rate)
        return fail(why, "its Vorbis headers disagree about its channels or rate");
    out.channels = info->channels;
    out.rate = info->rate;
    const size_t max_samples = size_t(max_frames) * size_t(channels);
    // A read asks for at most this: one Vorbis packet decodes to at most
    // 8192 samples a channel, so this is a few reads a packet.
    constexpr size_t kReadBytes = 16384;
    // Room for all the claim allows at once: the vector never doubles past it.
    out.samples.reserve(max_samples + kReadBytes / 2);
    for (;;) {
        const size_t had = out.samples.size();
        out.samples.resize(had + kReadBytes / 2);
        int section = 0;
        const long got = ov_read(&vf, reinterpret_cast<char*>(out.samples.data() + had), int(kReadBytes), 0, 2, 1,
                                 &section);
        if (got < 0) {
            if (got == OV_HOLE) {  // a gap in the data: skipped, as every player does
                out.samples.resize(had);
                continue;
            }
            return fail(why, vorbis_reason(got));
        }
        out.samples.resize(had + size_t(got) / 2);
        if (got == 0) return true;
        if (out.samples.size() > max_samples)
            return fail(why, "it decodes to more than the " + std::to_string(max_frames) +
                                 " samples its last Ogg page declares");
    }
}

}  // namespace

bool decode_ogg(std::span<const uint8_t> file, int64_t channels, int64_t rate, int64_t max_frames, DecodedOgg& out,
                std::string& why) {
    Source source{file};
    const ov_callbacks callbacks{read_source, seek_source, nullptr, tell_source};
    OggVorbis_File vf;
    if (const int rc = ov_open_callbacks(&source, &vf, nullptr, 0, callbacks); rc != 0) return fail(why, vorbis_reason(rc));
    const bool ok = decode_open(vf, channels, rate, max_frames, out, why);
    ov_clear(&vf);
    if (!ok) out.samples = {};
    return ok;
}

}  // namespace ds::render
