#!/usr/bin/env python3
"""The GLX vendor library (libGLX_velocity.so.0) under Xvfb, chosen as any program
chooses it: __GLX_VENDOR_LIBRARY_NAME=velocity, the library on LD_LIBRARY_PATH.

    glx_test.py api GLX_CHECK LIBDIR WORKDIR   glx_check.c, with MIT-SHM and with
                                              VELOCITY_GLX_SHM=0 (XPutImage)
    glx_test.py installed BUILD GLX_CHECK WORKDIR   the same checks on the copy
                                              `cmake --install BUILD --prefix` installs
    glx_test.py gears LIBDIR WORKDIR           Debian's glxgears, unmodified: it says it
                                              runs on Velocity, counts frames, and its
                                              window shows the three gears (the screen
                                              is saved as WORKDIR/glxgears.png)
Exit 77 (skipped) without Xvfb, glxgears or libglvnd's libGL.
"""
import ctypes.util
import os
import shutil
import struct
import subprocess
import sys
import time
import zlib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "present", "tests"))
from window_test import read_xwd, start_xvfb  # noqa: E402  (the real-time tests' helpers)


def write_png(path, rgb):
    h, w, _ = rgb.shape
    raw = b"".join(b"\0" + rgb[y].tobytes() for y in range(h))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def environment(libdir, display):
    return dict(os.environ, DISPLAY=":" + display, __GLX_VENDOR_LIBRARY_NAME="velocity",
                LD_LIBRARY_PATH=libdir + os.pathsep + os.environ.get("LD_LIBRARY_PATH", ""))


def api(check, libdir, work):
    server, display = start_xvfb(shutil.which("Xvfb"), os.path.join(work, "fb"))
    try:
        for shm in ("1", "0"):
            env = dict(environment(libdir, display), VELOCITY_GLX_SHM=shm)
            run = subprocess.run([check], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                 timeout=120)
            print(f"--- VELOCITY_GLX_SHM={shm}\n{run.stdout}")
            assert run.returncode == 0, f"glx_check failed (exit {run.returncode})"
    finally:
        server.terminate()
        server.wait(timeout=10)
    return 0


def installed(build, check, work):
    prefix = os.path.join(work, "prefix")
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
    found = [d for d, _, files in os.walk(prefix) if "libGLX_velocity.so.0" in files]
    assert found, "cmake --install did not install libGLX_velocity.so.0"
    print(f"installed: {found[0]}/libGLX_velocity.so.0")
    return api(check, found[0], work)


def gears(libdir, work):
    glxgears = shutil.which("glxgears")
    if not glxgears:
        print("SKIPPED: glxgears is not installed (Debian's mesa-utils)")
        return 77
    fbdir = os.path.join(work, "fb")
    server, display = start_xvfb(shutil.which("Xvfb"), fbdir)
    try:
        app = subprocess.Popen([glxgears, "-info"], env=environment(libdir, display), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
        time.sleep(6)  # glxgears reports its frame rate every 5 seconds
        screen = read_xwd(f"{fbdir}/Xvfb_screen0")[:300, :300]  # its 300x300 window, at 0,0
        running = app.poll() is None
        app.terminate()
        out, _ = app.communicate(timeout=30)
    finally:
        server.terminate()
        server.wait(timeout=10)
    print(out)
    write_png(os.path.join(work, "glxgears.png"), screen)
    assert running, "glxgears ended by itself"
    assert "GL_RENDERER   = Velocity" in out, "glxgears is not running on Velocity"
    assert " frames in " in out, "glxgears counted no frames"
    r, g, b = (screen[..., i].astype(int) for i in range(3))
    red = np.count_nonzero((r > 100) & (r > 3 * g) & (r > 3 * b))
    green = np.count_nonzero((g > 100) & (g > 2 * r) & (g > 2 * b))
    blue = np.count_nonzero((b > 100) & (b > 2 * r) & (b > 2 * g))
    black = np.count_nonzero(screen.max(axis=2) < 10)
    print(f"glxgears' window: {red} red, {green} green, {blue} blue, {black} black pixels of 90000")
    # The gears cover about a third of the window, the red one the most.
    assert red > 8000 and green > 3000 and blue > 1000, "the gears are not in the window"
    assert black > 30000, "the background is not black"
    return 0


def main():
    if not shutil.which("Xvfb"):
        print("SKIPPED: Xvfb is not installed (Debian's xvfb; scripts/deps.sh installs it)")
        return 77
    if not ctypes.util.find_library("GLX"):
        print("SKIPPED: libglvnd's libGLX is not installed (Debian's libglx0)")
        return 77
    mode = sys.argv[1]
    work = sys.argv[-1]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if mode == "api":
        return api(sys.argv[2], sys.argv[3], work)
    if mode == "installed":
        return installed(sys.argv[2], sys.argv[3], work)
    return gears(sys.argv[2], work)


if __name__ == "__main__":
    sys.exit(main())
