// SPDX-License-Identifier: MIT
// alsa-lib's own error lines, silenced. On Linux SDL opens the sound card
// through alsa-lib, whose default error handler writes every step of a
// failed open to stderr ("ALSA lib confmisc.c:855:(parse_card) cannot find
// card '0'", eight lines on a machine without a sound card). The engine
// already says the one thing that matters ("no audio device (…); sound is
// off", with SDL's reason), so those lines only bury it.
#pragma once

namespace ds::render {

// Gives alsa-lib a handler that drops its messages, for the rest of the
// process: SDL loads the same libasound.so.2 this is linked against, so
// the handler is the one its probe meets. Set before the device is first
// opened, and kept, as alsa-lib also prints when a device in use fails
// (an underrun): the game cannot act on those lines either. Does nothing
// on a build without alsa-lib (DOWNSTROKE_ALSA unset: not Linux).
void silence_alsa_messages();

}  // namespace ds::render
