"""PNG files of numpy images, to bytes (so that the batch runners write them
atomically), through Pillow (Debian's python3-pil): 8-bit grey, RGB and RGBA, and
16-bit grey (segmentation masks)."""
from __future__ import annotations

import io

import numpy as np
from PIL import Image

_MODES = {1: "L", 3: "RGB", 4: "RGBA"}  # channels -> Pillow's mode for uint8


def encode_png(image: np.ndarray, level: int = 3) -> bytes:
    """PNG bytes of `image`: H x W (grey), H x W x 3 (RGB) or H x W x 4 (RGBA) uint8, or
    H x W uint16 (grey, 16 bits). Rows top first. `level` is zlib's, 0..9."""
    image = np.asarray(image)
    if image.ndim == 3 and image.shape[2] == 1:
        image = image[:, :, 0]
    channels = 1 if image.ndim == 2 else image.shape[2] if image.ndim == 3 else 0
    if channels not in _MODES or image.shape[0] < 1 or image.shape[1] < 1:
        raise ValueError(f"encode_png: expected H x W, H x W x 3 or H x W x 4, got shape {image.shape}")
    if image.dtype == np.uint16:
        if channels != 1:
            raise ValueError("encode_png: 16-bit images must be grey (H x W)")
        im = Image.frombuffer("I;16", (image.shape[1], image.shape[0]), np.ascontiguousarray(image, "<u2"),
                              "raw", "I;16", 0, 1)
    elif image.dtype == np.uint8:
        im = Image.fromarray(np.ascontiguousarray(image), _MODES[channels])
    else:
        raise ValueError(f"encode_png: expected uint8 or uint16, got {image.dtype}")
    out = io.BytesIO()
    im.save(out, "PNG", compress_level=level)
    return out.getvalue()


def decode_png(data: bytes) -> np.ndarray:
    """The image in PNG bytes, as encode_png takes it (16-bit grey as uint16)."""
    im = Image.open(io.BytesIO(data))
    if im.mode in ("I;16", "I;16B", "I"):
        return np.asarray(im, dtype=np.uint32).astype(np.uint16) if im.mode == "I" else \
            np.asarray(im).astype(np.uint16)
    return np.asarray(im)
