#!/usr/bin/env python3
"""Issue 10: under Xvfb the window opens, and what it shows (read from the X server's
own framebuffer, an XWD file that Xvfb -fbdir keeps up to date) is exactly the frame the
headless run of the same command renders.

    window_test.py VELOCITY WORKDIR
"""
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

import numpy as np


def read_png(path):
    """8-bit RGB or RGBA, non-interlaced (what Velocity writes) -> HxWx3 uint8."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    assert depth == 8 and colour in (2, 6) and interlace == 0
    bpp = 4 if colour == 6 else 3
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + w * bpp)
    out = np.zeros((h, w * bpp), np.int32)
    prev = np.zeros(w * bpp, np.int32)
    for y in range(h):
        f, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        if f == 0:
            cur = line
        elif f == 2:
            cur = (line + prev) & 255
        else:  # filters that depend on the pixel to the left: one pixel at a time
            cur = line.copy()
            for x in range(w * bpp):
                a = cur[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                if f == 1:
                    p = a
                elif f == 3:
                    p = (a + b) >> 1
                else:
                    pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                    p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[x] = (cur[x] + p) & 255
        out[y] = cur
        prev = cur
    return out.reshape(h, w, bpp)[:, :, :3].astype(np.uint8)


def read_xwd(path):
    """Xvfb's screen (XWD, ZPixmap, 24/32 bits a pixel) -> HxWx3 uint8."""
    d = open(path, "rb").read()
    f = struct.unpack(">25I", d[:100])
    header_size, fmt, width, height, byte_order, bpp, bpl = f[0], f[2], f[4], f[5], f[7], f[11], f[12]
    rmask, gmask, bmask, ncolors = f[14], f[15], f[16], f[19]
    assert fmt == 2 and bpp == 32, (fmt, bpp)
    off = header_size + ncolors * 12
    rows = np.frombuffer(d, np.uint8, count=bpl * height, offset=off).reshape(height, bpl)
    v = rows[:, :width * 4].copy().view("<u4" if byte_order == 0 else ">u4").reshape(height, width)

    def channel(mask):
        shift = (mask & -mask).bit_length() - 1
        return ((v & mask) >> shift).astype(np.uint8)

    return np.dstack([channel(rmask), channel(gmask), channel(bmask)])


def start_xvfb(xvfb, fbdir, size="640x480", extra=()):
    """A private X server (SIZE x 24 bits) whose screen is the file FBDIR/Xvfb_screen0.
    Returns the server's process and its display number."""
    os.makedirs(fbdir)
    r, w = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", size + "x24", "-fbdir", fbdir,
                               "-nolisten", "tcp", *extra], pass_fds=[w])
    os.close(w)
    display = b""
    while not display.endswith(b"\n"):
        chunk = os.read(r, 16)
        if not chunk:
            break
        display += chunk
    os.close(r)
    display = display.decode().strip()
    assert display, "Xvfb did not start"
    for _ in range(100):  # the screen file appears once the server is up
        if os.path.exists(f"{fbdir}/Xvfb_screen0"):
            break
        time.sleep(0.1)
    return server, display


def main():
    velocity, work = sys.argv[1], sys.argv[2]
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        print("SKIPPED: Xvfb is not installed (Debian's xvfb; scripts/deps.sh installs it)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    common = ["view", "--size", "320x240", "--no-overlay", "--frames", "3", "--mute"]

    # The headless frame.
    subprocess.run([velocity, *common, "--headless", "--record", f"{work}/headless"], check=True)
    expect = read_png(f"{work}/headless/frame_00002.png")
    assert expect.std() > 10, "the headless frame is blank: nothing to compare"

    # The window, on a private X server whose screen is a file.
    fbdir = f"{work}/fb"
    server, display = start_xvfb(xvfb, fbdir)
    env = dict(os.environ, DISPLAY=":" + display, SDL_VIDEODRIVER="x11", SDL_AUDIODRIVER="dummy",
               SDL_RENDER_DRIVER="software", SDL_FRAMEBUFFER_ACCELERATION="0")
    # (The software renderer straight onto X11: no OpenGL driver is loaded.)
    app = subprocess.Popen([velocity, *common, "--scale", "1", "--window-at-origin", "--record", f"{work}/window",
                            "--linger", "60"], env=env, stdout=subprocess.PIPE, text=True)
    try:
        deadline = time.time() + 60
        last = None
        matched = False
        while time.time() < deadline and app.poll() is None:
            time.sleep(0.25)
            if not os.path.exists(f"{work}/window/frame_00002.png"):
                continue
            screen = read_xwd(f"{fbdir}/Xvfb_screen0")[:240, :320]
            last = np.abs(screen.astype(int) - expect.astype(int))
            if last.max() <= 2:
                matched = True
                break
        assert app.poll() is None, "velocity exited before its window was seen"
        app.send_signal(signal.SIGTERM)  # ends the run cleanly, exit status 128 + 15
        out, _ = app.communicate(timeout=30)
    finally:
        if app.poll() is None:
            app.kill()
        server.terminate()
        server.wait(timeout=10)
    print(out.strip())
    assert app.returncode == 128 + signal.SIGTERM, f"velocity exited with {app.returncode}"
    assert "frames=3 size=320x240 median_ms=" in out
    # The window run rendered the same frame as the headless one...
    np.testing.assert_array_equal(read_png(f"{work}/window/frame_00002.png"), expect)
    # ... and the screen showed it.
    if last is None:
        raise AssertionError("the window's frame was never recorded")
    assert matched, f"the window differs from the headless frame: max {last.max()}, {np.count_nonzero(last.max(axis=2) > 2)} pixels"
    print("window matches the headless frame (320x240, every channel within 2)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
