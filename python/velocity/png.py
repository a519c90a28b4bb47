"""PNG encoding of numpy images, to bytes (so that the batch runners write them atomically).

8-bit grey, RGB and RGBA, and 16-bit grey (segmentation masks). zlib from the standard
library does the compression; each row is filtered with PNG's "Up" filter, which
costs one numpy subtraction and helps rendered images compress.
"""
from __future__ import annotations

import struct
import zlib

import numpy as np

_COLOR_TYPES = {1: 0, 3: 2, 4: 6}  # channels -> PNG colour type (grey, RGB, RGBA)


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def encode_png(image: np.ndarray, level: int = 3) -> bytes:
    """PNG bytes of `image`: H x W (grey), H x W x 3 (RGB) or H x W x 4 (RGBA) uint8, or
    H x W uint16 (grey, 16 bits). Rows top first. `level` is zlib's, 0..9."""
    image = np.asarray(image)
    if image.ndim == 2:
        image = image[:, :, None]
    if image.ndim != 3 or image.shape[2] not in _COLOR_TYPES or image.shape[0] < 1 or image.shape[1] < 1:
        raise ValueError(f"encode_png: expected H x W, H x W x 3 or H x W x 4, got shape {image.shape}")
    if image.dtype == np.uint16:
        if image.shape[2] != 1:
            raise ValueError("encode_png: 16-bit images must be grey (H x W)")
        depth, rows = 16, image[:, :, 0].astype(">u2").view(np.uint8)
    elif image.dtype == np.uint8:
        depth, rows = 8, image.reshape(image.shape[0], -1)
    else:
        raise ValueError(f"encode_png: expected uint8 or uint16, got {image.dtype}")
    h, w, c = image.shape
    # Filter "Up" (2): each byte minus the byte above it, modulo 256; the first row is
    # taken as if a row of zeros were above it.
    up = np.empty((h, rows.shape[1] + 1), np.uint8)
    up[:, 0] = 2
    up[0, 1:] = rows[0]
    np.subtract(rows[1:], rows[:-1], out=up[1:, 1:], dtype=np.uint8, casting="unsafe")
    header = struct.pack(">IIBBBBB", w, h, depth, _COLOR_TYPES[c], 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(up.tobytes(), level)) +
            _chunk(b"IEND", b""))


def decode_png(data: bytes) -> np.ndarray:
    """Decodes what encode_png writes (non-interlaced 8-bit grey/RGB/RGBA or 16-bit grey,
    any filter): for reading the batch runners' outputs back in tests and scripts."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("decode_png: not a PNG file")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        (length,), kind = struct.unpack(">I", data[pos:pos + 4]), data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    if header is None:
        raise ValueError("decode_png: no IHDR chunk")
    w, h, depth, color_type, _, _, interlace = header
    channels = {0: 1, 2: 3, 6: 4}.get(color_type)
    if channels is None or depth not in (8, 16) or interlace or (depth == 16 and channels != 1):
        raise ValueError(f"decode_png: unsupported PNG (depth {depth}, colour type {color_type})")
    bpp = channels * depth // 8
    raw = np.frombuffer(zlib.decompress(b"".join(idat)), np.uint8).reshape(h, 1 + w * bpp)
    out = np.zeros((h, w * bpp), np.int32)
    for y in range(h):
        f, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        prev = out[y - 1] if y else np.zeros(w * bpp, np.int32)
        if f == 0:
            cur = line
        elif f == 1:
            cur = line.copy()
            for x in range(bpp, w * bpp):
                cur[x] = (cur[x] + cur[x - bpp]) & 255
        elif f == 2:
            cur = (line + prev) & 255
        elif f == 3:
            cur = line.copy()
            for x in range(w * bpp):
                left = cur[x - bpp] if x >= bpp else 0
                cur[x] = (cur[x] + (left + prev[x]) // 2) & 255
        elif f == 4:
            cur = line.copy()
            for x in range(w * bpp):
                a = cur[x - bpp] if x >= bpp else 0
                b, c = prev[x], prev[x - bpp] if x >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                cur[x] = (cur[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        else:
            raise ValueError(f"decode_png: bad filter {f} in row {y}")
        out[y] = cur
    pixels = out.astype(np.uint8)
    if depth == 16:
        return pixels.reshape(h, w, 2).astype(np.uint16)[:, :, 0] * 256 + pixels.reshape(h, w, 2)[:, :, 1]
    return pixels.reshape(h, w, channels) if channels > 1 else pixels.reshape(h, w)
