#!/usr/bin/env python3
# SPDX-License-Identifier: 0BSD
"""Regenerates the demos' music: theme.ogg, a short chiptune loop.

The output is checked in; the build never runs this. It needs `oggenc`
(Debian: vorbis-tools). Run it from anywhere:
    python3 demo/sounds/make_music.py
Two square-wave voices and a noise hat, as the sound effects are made
(make_sounds.py), 8 bars of 4 beats at 120 bpm: 16 s, looping seamlessly
(every note ends before the bar line). 22050 Hz mono at oggenc's lowest
quality keeps it near 60 KB. No randomness: reruns give the same samples.
"""
import os
import struct
import subprocess
import tempfile
import wave

RATE = 22050
BEAT = 0.5  # seconds: 120 bpm
HERE = os.path.dirname(os.path.abspath(__file__))
# Peaks that leave room for the effects played over the music.
LEAD, BASS, HAT = 3000, 3200, 900

# A minor, then F, C, G: (root of the bass, lead notes as MIDI numbers per half beat).
BARS = [
    (45, [69, 72, 76, 72, 74, 72, 71, 72]),
    (41, [69, 72, 77, 76, 74, 72, 74, 76]),
    (48, [76, 79, 84, 79, 81, 79, 77, 76]),
    (43, [74, 71, 67, 71, 74, 76, 74, 71]),
    (45, [69, 72, 76, 79, 81, 79, 76, 72]),
    (41, [77, 76, 74, 72, 74, 76, 77, 79]),
    (48, [79, 76, 72, 76, 79, 84, 81, 79]),
    (43, [74, 76, 74, 71, 67, 71, 74, 0]),
]


def freq(midi):
    return 440.0 * 2 ** ((midi - 69) / 12)


def square(f, t, duty=0.5):
    return 1.0 if (f * t) % 1.0 < duty else -1.0


def samples():
    out = []
    lfsr = 1
    step = BEAT / 2
    for root, lead in BARS:
        for k in range(8):  # half beats
            n = int(step * RATE)
            for i in range(n):
                t = i / RATE
                gate = 1.0 - i / n  # each note decays to nothing before the next
                v = 0.0
                if lead[k]:
                    v += LEAD * gate * square(freq(lead[k]), t, 0.25)
                bass = root if k % 2 == 0 else root + 12
                v += BASS * (1.0 - 0.5 * i / n) * square(freq(bass), t)
                if k % 2 == 1 and i < n // 6:  # the hat on the off beats
                    bit = (lfsr ^ (lfsr >> 1)) & 1
                    lfsr = (lfsr >> 1) | (bit << 14)
                    v += HAT * (1 if lfsr & 1 else -1) * (1 - 6 * i / n)
                out.append(max(-32767, min(32767, int(v))))
    return out


def main():
    data = samples()
    with tempfile.TemporaryDirectory() as tmp:
        wav = os.path.join(tmp, "theme.wav")
        with wave.open(wav, "wb") as w:
            w.setnchannels(1)
            w.setsampwidth(2)
            w.setframerate(RATE)
            w.writeframes(struct.pack("<%dh" % len(data), *data))
        subprocess.run(["oggenc", "-Q", "-q", "0", "-o", os.path.join(HERE, "theme.ogg"), wav], check=True)
    print("theme.ogg: %d samples, %.1f s" % (len(data), len(data) / RATE))


if __name__ == "__main__":
    main()
