#!/usr/bin/env python3
"""GLUT's shapes (or fonts: any program written for both) against freeglut's.

    shapes_test.py VELOCITY_EXE FREEGLUT_EXE COMPARE WORKDIR [NAME]

shapes.c built against Velocity's GLUT runs on SDL's dummy video driver; built against
freeglut and the system's libGL it runs in a window of a private Xvfb, drawn by Mesa
(llvmpipe). Each writes its frames into a folder; velocity_gl_compare compares them
(PSNR >= 35 dB a frame). Exit 77 (skipped) without Xvfb.
"""
import os
import shutil
import subprocess
import sys


def start_xvfb(xvfb):
    """A private X server; returns it and its display name."""
    r, w = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", "640x480x24", "-nolisten", "tcp"],
                              pass_fds=[w], stderr=subprocess.DEVNULL)
    os.close(w)
    display = b""
    while not display.endswith(b"\n"):
        chunk = os.read(r, 16)
        if not chunk:
            break
        display += chunk
    os.close(r)
    display = display.decode().strip()
    if not display:
        server.kill()
        raise SystemExit("shapes_test: Xvfb did not start")
    return server, ":" + display


def main():
    velocity, freeglut, compare, work = sys.argv[1:5]
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        print("SKIPPED: Xvfb is not installed (Debian's xvfb; scripts/deps.sh installs it)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    out_v, out_m = os.path.join(work, "velocity"), os.path.join(work, "mesa")
    os.makedirs(out_v), os.makedirs(out_m)
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    subprocess.run([velocity, out_v], env=env, check=True, timeout=120)
    server, display = start_xvfb(xvfb)
    try:
        env = dict(os.environ, DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1", LP_NUM_THREADS="1",
                   __GLX_VENDOR_LIBRARY_NAME="mesa")
        subprocess.run([freeglut, out_m], env=env, check=True, timeout=120)
    finally:
        server.terminate()
        server.wait(timeout=30)
    name = sys.argv[5] if len(sys.argv) > 5 else "glut_shapes"
    return subprocess.run([compare, name, out_v, out_m, "35"]).returncode


if __name__ == "__main__":
    sys.exit(main())
