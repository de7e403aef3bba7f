#!/usr/bin/env python3
# SPDX-License-Identifier: 0BSD
"""Regenerates the demos' sound effects: jump.wav, goal.wav, hit.wav, coin.wav,
and shmup's shot.wav and boom.wav.

The outputs are checked in; the build never runs this. Run it from anywhere:
    python3 demo/sounds/make_sounds.py
Square waves and LFSR noise, as an 8-bit console would make them: 22050 Hz
mono 16-bit, each at most 0.3 s. No randomness, so reruns give the same bytes.
"""
import math
import os
import struct
import wave

RATE = 22050  # half CD rate: plenty for square blips, and half the bytes
# Peak of 16-bit output: about a third of full scale, so several effects
# mixed at once do not clip.
VOLUME = 11000
# Fade-out over the last few ms of each sound: a square wave cut off
# mid-cycle clicks.
FADE_SECONDS = 0.006
HERE = os.path.dirname(os.path.abspath(__file__))


def square(freq, t, duty=0.5):
    """+1 or -1: a pulse of `freq` Hz at time t, high for `duty` of each cycle."""
    return 1.0 if (freq * t) % 1.0 < duty else -1.0


def noise_source():
    """The NES noise channel's 15-bit LFSR, as an endless stream of +1/-1."""
    state = 1
    while True:
        bit = (state ^ (state >> 1)) & 1
        state = (state >> 1) | (bit << 14)
        yield 1.0 if state & 1 else -1.0


def render(seconds, sample):
    """16-bit samples of `sample(t, frac)` (frac: 0 at the start, 1 at the end)."""
    n = int(seconds * RATE)
    fade = int(FADE_SECONDS * RATE)
    out = []
    for i in range(n):
        t = i / RATE
        gain = min(1.0, (n - i) / fade)
        out.append(int(VOLUME * gain * sample(t, i / n)))
    return out


def jump():
    """A rising pulse sweep, 0.15 s."""
    phase = [0.0]

    def sample(t, frac):
        freq = 300 * 2 ** (frac * 1.5)  # one and a half octaves up
        phase[0] += freq / RATE  # integrate, so the sweep has no jumps
        return (1.0 if phase[0] % 1.0 < 0.25 else -1.0) * (1 - 0.5 * frac)

    return render(0.15, sample)


def coin():
    """B5 then E6, the classic pick-up, 0.2 s."""

    def sample(t, frac):
        freq = 987.77 if t < 0.06 else 1318.51
        return square(freq, t) * (1 - frac)

    return render(0.2, sample)


def goal():
    """A C-major arpeggio up to the octave, 0.3 s."""
    notes = [523.25, 659.25, 783.99, 1046.50]
    step = 0.3 / len(notes)

    def sample(t, frac):
        freq = notes[min(int(t / step), len(notes) - 1)]
        return square(freq, t, 0.125 if frac > 0.75 else 0.5) * (1 - 0.4 * frac)

    return render(0.3, sample)


def hit():
    """A noise burst whose pitch falls, over a low thud, 0.18 s."""
    lfsr = noise_source()
    held = [0.0, 0.0]  # the current noise value, time until the next one

    def sample(t, frac):
        # Noise "pitch": how often the LFSR steps; slower is duller.
        rate = 8000 * (1 - frac) + 500
        held[1] -= 1 / RATE
        if held[1] <= 0:
            held[0] = next(lfsr)
            held[1] = 1 / rate
        thud = square(90, t)
        return (0.7 * held[0] + 0.3 * thud) * math.exp(-4 * frac)

    return render(0.18, sample)


def shot():
    """A laser blip: a narrow pulse sweeping down three octaves, 0.12 s."""
    phase = [0.0]

    def sample(t, frac):
        freq = 1600 * 2 ** (-3 * frac)
        phase[0] += freq / RATE
        return (1.0 if phase[0] % 1.0 < 0.125 else -1.0) * (1 - 0.7 * frac)

    return render(0.12, sample)


def boom():
    """An explosion: slow, dull noise over a falling low square, 0.3 s."""
    lfsr = noise_source()
    held = [0.0, 0.0]
    phase = [0.0]

    def sample(t, frac):
        rate = 3000 * (1 - frac) + 200
        held[1] -= 1 / RATE
        if held[1] <= 0:
            held[0] = next(lfsr)
            held[1] = 1 / rate
        phase[0] += (120 - 80 * frac) / RATE
        rumble = 1.0 if phase[0] % 1.0 < 0.5 else -1.0
        return (0.75 * held[0] + 0.25 * rumble) * math.exp(-3 * frac)

    return render(0.3, sample)


def write(name, samples):
    path = os.path.join(HERE, name)
    with wave.open(path, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(RATE)
        w.writeframes(struct.pack("<%dh" % len(samples), *samples))
    print("%s: %d samples, %d bytes" % (path, len(samples), os.path.getsize(path)))


if __name__ == "__main__":
    write("jump.wav", jump())
    write("coin.wav", coin())
    write("goal.wav", goal())
    write("hit.wav", hit())
    write("shot.wav", shot())
    write("boom.wav", boom())
