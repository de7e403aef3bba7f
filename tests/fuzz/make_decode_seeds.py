#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes tests/fuzz/seeds/decode/: small sound and image files for the
differential target `decode` (fuzz_decode.cpp), one of each encoding its
checks count, so mutations start from files the decoders accept.

The output is checked in; neither the build nor the tests run this:
    python3 tests/fuzz/make_decode_seeds.py
The test data's PNGs and tone.ogg are added as seeds by CMake, not here.
"""
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds", "decode")


def riff(fmt, data, extra_chunks=b""):
    body = b"WAVE" + b"fmt " + struct.pack("<I", len(fmt)) + fmt + extra_chunks
    body += b"data" + struct.pack("<I", len(data)) + data + (b"\0" if len(data) % 2 else b"")
    return b"RIFF" + struct.pack("<I", len(body)) + body


def fmt(encoding, channels, rate, block, bits, extra=None):
    f = struct.pack("<HHIIHH", encoding, channels, rate, rate * block, block, bits)
    if extra is not None:
        f += struct.pack("<H", len(extra)) + extra
    return f


def wavs():
    square = b"".join(struct.pack("<h", 6000 if (i // 25) % 2 else -6000) for i in range(400))
    yield "pcm16-mono.wav", riff(fmt(1, 1, 22050, 2, 16), square)
    yield "pcm8-stereo.wav", riff(fmt(1, 2, 8000, 2, 8), bytes((i * 7) & 0xFF for i in range(600)))
    yield "pcm24-mono.wav", riff(fmt(1, 1, 44100, 3, 24), bytes(300))
    yield "float-stereo.wav", riff(fmt(3, 2, 48000, 8, 32), struct.pack("<200f", *([0.25, -0.25] * 100)))
    yield "alaw-mono.wav", riff(fmt(6, 1, 8000, 1, 8, b""), bytes(range(256)))
    yield "mulaw-mono.wav", riff(fmt(7, 1, 8000, 1, 8, b""), bytes(range(256)))
    # IMA ADPCM: 256-byte blocks of a 4-byte header per channel and 4-bit
    # samples: 505 frames a block mono, 249 stereo.
    yield "ima-mono.wav", riff(fmt(0x11, 1, 22050, 256, 4, struct.pack("<H", 505)), bytes(256 * 3))
    yield "ima-stereo.wav", riff(fmt(0x11, 2, 22050, 256, 4, struct.pack("<H", 249)), bytes(256 * 2 + 100))
    # MS ADPCM: a 7-byte header per channel, 500 frames in a 256-byte mono
    # block; the seven standard coefficient pairs.
    coefs = [(256, 0), (512, -256), (0, 0), (192, 64), (240, 0), (460, -208), (392, -232)]
    ms_extra = struct.pack("<HH", 500, len(coefs)) + b"".join(struct.pack("<hh", *c) for c in coefs)
    block = bytes([0]) + struct.pack("<hhh", 16, 0, 0) + bytes(249)
    yield "msadpcm-mono.wav", riff(fmt(2, 1, 22050, 256, 4, ms_extra), block * 2)
    # WAVE_FORMAT_EXTENSIBLE naming PCM.
    guid = struct.pack("<H", 1) + bytes.fromhex("000000001000800000aa00389b71")
    ext = struct.pack("<HI", 16, 4) + guid
    yield "extensible-pcm.wav", riff(fmt(0xFFFE, 1, 16000, 2, 16, ext), bytes(800))


def gifs():
    # 1 x 1, a two-colour global table, LZW data for one pixel.
    one = (b"GIF89a" + struct.pack("<HH", 1, 1) + b"\x80\x00\x00" + b"\xff\xff\xff\x00\x00\x00"
           + b"!\xf9\x04\x01\x00\x00\x00\x00" + b"," + struct.pack("<HHHH", 0, 0, 1, 1) + b"\x00"
           + b"\x02\x02\x44\x01\x00" + b";")
    yield "one-pixel.gif", one
    # A 2 x 2 screen whose first image is 1 x 1: SDL_image sizes the picture
    # by the image, not the screen.
    yield "offset-image.gif", one[:6] + struct.pack("<HH", 2, 2) + one[10:]


def main():
    os.makedirs(HERE, exist_ok=True)
    for name, data in list(wavs()) + list(gifs()):
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
