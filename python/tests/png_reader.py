"""Reads the PNG files canopy writes (8-bit RGB, filter "Sub" on every row, render/image.h)
with zlib alone, for comparing frames without an imaging library."""
import struct
import zlib

import numpy as np


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    pos, idat, size = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
    width, height = size
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, 1 + 3 * width)
    assert (raw[:, 0] == 1).all(), "expected filter Sub on every row"
    # Sub: each byte is stored minus the byte 3 to its left (one pixel), modulo 256.
    deltas = raw[:, 1:].reshape(height, width, 3).astype(np.uint32)
    return (np.cumsum(deltas, axis=1) % 256).astype(np.uint8)
