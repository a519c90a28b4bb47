"""velocity.png.encode_png (libpng in the module): files that an independent decoder
(Pillow) reads back to the very pixels, for every kind, filter and layout; bad input is
a ValueError or TypeError naming what was expected."""
import io
import threading

import numpy as np
import pytest
from PIL import Image

import velocity
from velocity.png import decode_png, encode_png


def pillow(data):
    im = Image.open(io.BytesIO(data))
    return im, np.asarray(im)


def asymmetric(h, w, c, dtype=np.uint8, seed=0):
    """Noise over a gradient, no two rows or columns alike: a flipped or transposed
    image never matches."""
    rng = np.random.default_rng(seed)
    top = np.iinfo(dtype).max
    y, x = np.mgrid[0:h, 0:w]
    base = (y * 37 + x * 11) % (top + 1)
    shape = (h, w) if c == 1 else (h, w, c)
    noise = rng.integers(0, top // 8, size=shape)
    img = (base if c == 1 else base[:, :, None]) + noise
    return (img % (top + 1)).astype(dtype)


@pytest.mark.parametrize("c,mode", [(1, "L"), (3, "RGB"), (4, "RGBA")])
@pytest.mark.parametrize("filt", ["none", "sub", "up", "average", "paeth", "adaptive"])
def test_eight_bit_images_decode_to_the_same_pixels(c, mode, filt):
    img = asymmetric(23, 31, c)
    im, back = pillow(encode_png(img, 3, filt))
    assert im.mode == mode and im.size == (31, 23)
    np.testing.assert_array_equal(back, img)


def test_sixteen_bit_grey_keeps_every_bit_in_png_byte_order():
    mask = asymmetric(17, 29, 1, np.uint16)
    mask[0, 0], mask[0, 1] = 0x0102, 0xFF00  # the two bytes of a sample in PNG's order
    data = encode_png(mask)
    assert data[24] == 16 and data[25] == 0  # IHDR: bit depth 16, colour type grey
    np.testing.assert_array_equal(decode_png(data), mask)


def test_strided_and_non_contiguous_arrays():
    img = asymmetric(40, 50, 4)
    view = img[::-3, 5:45:2, :3]  # reversed rows, every other column, RGB of RGBA
    np.testing.assert_array_equal(pillow(encode_png(view))[1], view)
    np.testing.assert_array_equal(pillow(encode_png(img[:, :, :1]))[1], img[:, :, 0])
    one_row = img[7:8]
    np.testing.assert_array_equal(pillow(encode_png(one_row))[1], one_row)


def test_levels_trade_time_for_size():
    img = asymmetric(64, 64, 3)
    sizes = [len(encode_png(img, level)) for level in (0, 9)]
    assert sizes[0] > sizes[1]
    for level in (0, 1, 9):
        np.testing.assert_array_equal(pillow(encode_png(img, level))[1], img)


def test_a_rendered_frame_and_its_mask(tmp_path):
    scene = velocity.Scene(bg_color=(0.2, 0.3, 0.4, 1.0))
    scene.add(velocity.Mesh.sphere(24))
    scene.add(velocity.PerspectiveCamera(0.8), pose=velocity.look_at([0.3, 0.2, 3], [0, 0, 0]))
    scene.add(velocity.DirectionalLight(intensity=3.0))
    color, _, mask = velocity.OffscreenRenderer(64, 48).render(scene, velocity.RenderFlags.SEG)
    np.testing.assert_array_equal(pillow(encode_png(color))[1], color)
    np.testing.assert_array_equal(decode_png(encode_png(mask.astype(np.uint16))), mask)


@pytest.mark.parametrize("bad,kind,words", [
    (np.zeros((3, 4, 2), np.uint8), ValueError, "H x W x 3"),
    (np.zeros((3, 4, 3), np.uint16), ValueError, "16-bit images must be grey"),
    (np.zeros(5, np.uint8), ValueError, "got shape (5)"),
    (np.zeros((0, 4), np.uint8), ValueError, "empty"),
    (np.zeros((3, 4), np.float32), TypeError, "uint8 or uint16"),
    (np.zeros((3, 4), np.int16), TypeError, "got int16"),
])
def test_bad_images_are_value_or_type_errors(bad, kind, words):
    with pytest.raises(kind, match=None) as e:
        encode_png(bad)
    assert words in str(e.value) and isinstance(e.value, velocity.Error)


def test_bad_level_or_filter():
    img = np.zeros((2, 2), np.uint8)
    with pytest.raises(ValueError, match="level must be 0..9"):
        encode_png(img, 10)
    with pytest.raises(ValueError, match="filter must be"):
        encode_png(img, 3, "best")


def test_threads_encode_at_once():
    # The GIL is released while libpng works: threads share nothing but the input.
    img = asymmetric(128, 96, 3)
    want = encode_png(img)
    results = [None] * 4
    def work(i):
        results[i] = [encode_png(img) for _ in range(5)]
    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r == [want] * 5 for r in results)
