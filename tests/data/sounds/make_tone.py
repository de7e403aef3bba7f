#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tests/data/sounds/tone.ogg, the OGG that tests/core/audio_test.cpp loads.

The output is checked in; neither the build nor the tests run this. It needs
`oggenc` (Debian: vorbis-tools). Run it from anywhere:
    python3 tests/data/sounds/make_tone.py
A 0.3 s 440 Hz sine, 22050 Hz mono, at oggenc's lowest quality: a few KB is
all a decoding test needs.
"""
import math
import os
import struct
import subprocess
import tempfile
import wave

RATE = 22050
SECONDS = 0.3
HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    n = int(RATE * SECONDS)
    samples = [int(8000 * math.sin(2 * math.pi * 440 * i / RATE)) for i in range(n)]
    with tempfile.TemporaryDirectory() as tmp:
        wav = os.path.join(tmp, "tone.wav")
        with wave.open(wav, "wb") as w:
            w.setnchannels(1)
            w.setsampwidth(2)
            w.setframerate(RATE)
            w.writeframes(struct.pack("<%dh" % n, *samples))
        out = os.path.join(HERE, "tone.ogg")
        # A fixed stream serial, so a rerun with the same oggenc gives the same bytes.
        subprocess.run(["oggenc", "--quiet", "-q", "-1", "--serial", "1", "-o", out, wav],
                       check=True)
    print("%s: %d bytes" % (out, os.path.getsize(out)))


if __name__ == "__main__":
    main()
