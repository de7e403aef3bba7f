// SPDX-License-Identifier: MIT
#include "alsa_quiet.hpp"

#ifdef DOWNSTROKE_ALSA
#include <alsa/asoundlib.h>
#endif

namespace ds::render {

#ifdef DOWNSTROKE_ALSA
namespace {

// snd_lib_error_handler_t: alsa-lib's file, line, function, error and
// printf-style message, all dropped.
void drop_message(const char*, int, const char*, int, const char*, ...) {}

}  // namespace

// Rather than a probe of /proc/asound or /dev/snd before SDL opens ALSA
// (which would guess wrong where sound goes through PulseAudio or PipeWire
// without either) or fd 2 redirected around the open (which would swallow
// other threads' messages too): alsa-lib's own switch for its own lines.
void silence_alsa_messages() { snd_lib_error_set_handler(drop_message); }
#else
void silence_alsa_messages() {}
#endif

}  // namespace ds::render
