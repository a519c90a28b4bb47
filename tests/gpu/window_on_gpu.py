#!/usr/bin/env python3
"""Issue 19: view, fly and drive on the GPU backend in a real window (Xvfb with Mesa's
GLX), drawn in the window's own OpenGL context: what the X server's screen shows (its
framebuffer as an XWD file, Xvfb -fbdir) agrees with the CPU backend's frame of the same
run (PSNR >= 35 dB, the textured threshold of the parity tests), the 2D overlay shows,
resizing the window works (the frame following the window, and a fixed frame scaled to
fit), and each run says which path presented. Then the fallbacks: an X server without
GLX (read-back through EGL) and --backend auto (llvmpipe refused: the CPU draws).

    window_on_gpu.py VELOCITY WORKDIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "present", "tests"))
from window_test import read_png, read_xwd, start_xvfb  # noqa: E402

WINDOWED = "present=gpu, windowed (SDL GL context)"


def psnr(a, b):
    mse = np.mean((a.astype(np.float64) - b.astype(np.float64)) ** 2)
    return 99.0 if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


class Screen:
    """A private Xvfb and the programs run on it."""

    def __init__(self, work, name, size="1024x768", extra=()):
        self.fbdir = f"{work}/{name}"
        # -noreset: the server would otherwise reset when a program's last connection
        # closes, and the next program's could come while it does ("x11 not available").
        self.server, display = start_xvfb(shutil.which("Xvfb"), self.fbdir, size, ["-noreset", *extra])
        self.env = dict(os.environ, DISPLAY=":" + display, SDL_VIDEODRIVER="x11", SDL_AUDIODRIVER="dummy")

    def shot(self, w, h):
        return read_xwd(f"{self.fbdir}/Xvfb_screen0")[:h, :w]

    def start(self, velocity, args):
        return subprocess.Popen([velocity, *args, "--window-at-origin", "--mute"], env=self.env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)

    def wait_for(self, app, expect, what, seconds=90):
        """Polls the screen until it agrees with `expect` (>= 35 dB); returns the PSNR.
        (Each run starts on a screen that does not: see fresh().)"""
        h, w = expect.shape[:2]
        deadline, best = time.time() + seconds, 0.0
        while time.time() < deadline and app.poll() is None:
            best = max(best, psnr(self.shot(w, h), expect))
            if best >= 35:
                return best
            time.sleep(0.25)
        raise AssertionError(f"{what}: the window never agreed with the CPU frame (best {best:.2f} dB, "
                             f"exit {app.poll()})")

    def fresh(self, expect, what):
        """Before a run: what a window left there is gone (X repaints the root), so an
        agreement found next is the new window's."""
        h, w = expect.shape[:2]
        deadline = time.time() + 10
        while psnr(self.shot(w, h), expect) >= 35 and time.time() < deadline:
            time.sleep(0.2)
        assert psnr(self.shot(w, h), expect) < 35, f"{what}: the screen shows the expected frame before the run"

    def close(self):
        self.server.terminate()
        self.server.wait(timeout=10)


def stop(app):
    if app.poll() is None:
        app.send_signal(signal.SIGTERM)
    try:
        out, _ = app.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        app.kill()
        out, _ = app.communicate()
    return out


def cpu_frame(velocity, work, name, args, frames):
    """The CPU backend's last frame of a headless run."""
    out = f"{work}/cpu_{name}"
    subprocess.run([velocity, *args, "--headless", "--mute", "--frames", str(frames), "--record", out,
                    "--backend", "cpu"], check=True, stdout=subprocess.DEVNULL)
    return read_png(f"{out}/frame_{frames - 1:05d}.png")


def window_id(screen, app):
    """The program's window (SDL sets _NET_WM_PID; its title starts with "Velocity")."""
    deadline = time.time() + 60
    while time.time() < deadline and app.poll() is None:
        for how in (["--pid", str(app.pid)], ["--name", "^Velocity"]):
            ids = subprocess.run(["xdotool", "search", "--onlyvisible", *how], env=screen.env, capture_output=True,
                                 text=True).stdout.split()
            if ids:
                return ids[0]
        time.sleep(0.2)
    raise AssertionError(f"the window did not appear (exit {app.poll()}): {stop(app)}")


def main():
    velocity, work = sys.argv[1], os.path.abspath(sys.argv[2])
    if not shutil.which("Xvfb") or not shutil.which("xdotool"):
        print("SKIPPED: needs Xvfb and xdotool (scripts/deps.sh installs them)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(f"{work}/help.txt", "w") as f:
        f.write("0 press f1\n")  # the viewer's help box: a large overlay
    with open(f"{work}/start.txt", "w") as f:
        f.write("0.05 press enter\n")  # past fly's and drive's title menus
    frames = 5
    screen = Screen(work, "fb")
    try:
        # 1. view (with its help box), fly and drive: the same frames as the CPU's.
        for program in ["view", "fly", "drive"]:
            common = [program, "--size", "320x240", "--no-overlay", "--script",
                      f"{work}/help.txt" if program == "view" else f"{work}/start.txt"]
            frames = 5 if program == "view" else 20
            expect = cpu_frame(velocity, work, program, common, frames)
            assert expect.std() > 10, f"{program}: the CPU frame is blank: nothing to compare"
            screen.fresh(expect, program)
            app = screen.start(velocity, [*common, "--scale", "1", "--frames", str(frames), "--backend", "gpu",
                                          "--record", f"{work}/gpu_{program}", "--linger", "60"])
            try:
                db = screen.wait_for(app, expect, program)
                shown = screen.shot(320, 240)
            finally:
                out = stop(app)
            print(f"{program}: window {db:.2f} dB against the CPU frame")
            assert WINDOWED in out, f"{program} did not draw in the window's GL context:\n{out}"
            if program == "view":
                # The overlay is in the window: where the help box changes the CPU frame,
                # the screen shows the box, not the model under it.
                bare = cpu_frame(velocity, work, "view_bare", ["view", "--size", "320x240", "--no-overlay"], frames)
                box = np.abs(expect.astype(int) - bare.astype(int)).max(axis=2) > 40
                assert box.sum() > 5000, f"the help box changes only {box.sum()} pixels"
                to_box = np.abs(shown.astype(int) - expect.astype(int))[box].mean()
                to_bare = np.abs(shown.astype(int) - bare.astype(int))[box].mean()
                print(f"overlay: {box.sum()} pixels; mean difference {to_box:.2f} to the CPU frame with it, "
                      f"{to_bare:.2f} without")
                assert to_box < 3 and to_bare > 30, (to_box, to_bare)

        # 2. Resizing: the frame follows the window (--size window) ...
        app = screen.start(velocity, ["view", "--size", "window", "--no-overlay", "--backend", "gpu"])
        try:
            wid = window_id(screen, app)
            time.sleep(1.0)
            subprocess.run(["xdotool", "windowsize", wid, "400", "300"], env=screen.env, check=True)
            expect = cpu_frame(velocity, work, "view_400", ["view", "--size", "400x300", "--no-overlay"], 2)
            db = screen.wait_for(app, expect, "view resized to 400x300")
        finally:
            out = stop(app)
        print(f"resized to 400x300 (frame follows): {db:.2f} dB")
        assert WINDOWED in out and "size=400x300" in out, out

        # ... and a fixed frame is scaled to fit (nearest pixels): 320x240 in 640x480.
        app = screen.start(velocity, ["view", "--size", "320x240", "--scale", "1", "--no-overlay", "--backend", "gpu"])
        try:
            wid = window_id(screen, app)
            time.sleep(1.0)
            subprocess.run(["xdotool", "windowsize", wid, "640", "480"], env=screen.env, check=True)
            small = cpu_frame(velocity, work, "view_320", ["view", "--size", "320x240", "--no-overlay"], 2)
            db = screen.wait_for(app, small.repeat(2, axis=0).repeat(2, axis=1), "view scaled to 640x480")
        finally:
            out = stop(app)
        print(f"320x240 frame in a 640x480 window: {db:.2f} dB")
        assert WINDOWED in out, out

        # 3. --backend auto: the window's context is llvmpipe's, which auto refuses; the
        # CPU draws and the window shows its frames through SDL's renderer.
        frames = 5
        expect = cpu_frame(velocity, work, "view", ["view", "--size", "320x240", "--no-overlay"], frames)
        screen.fresh(expect, "auto")
        app = screen.start(velocity, ["view", "--size", "320x240", "--scale", "1", "--no-overlay", "--frames",
                                      str(frames), "--backend", "auto", "--linger", "60"])
        try:
            db = screen.wait_for(app, expect, "view --backend auto")
        finally:
            out = stop(app)
        print(f"auto: {db:.2f} dB; {out.splitlines()[:2]}")
        if "backend=cpu" in out:
            assert "auto: only a software OpenGL driver" in out and "present=cpu" in out, out
        # --no-gl-window: the read-back path in a GL-capable window (SDL's own renderer
        # holds a GLX context on the main thread; the GPU's EGL one lives on others).
        screen.fresh(expect, "--no-gl-window")
        app = screen.start(velocity, ["view", "--size", "320x240", "--scale", "1", "--no-overlay", "--frames",
                                      str(frames), "--backend", "gpu", "--no-gl-window", "--linger", "60"])
        try:
            db = screen.wait_for(app, expect, "view --no-gl-window")
        finally:
            out = stop(app)
        print(f"--no-gl-window: {db:.2f} dB")
        assert "backend=gpu" in out and "present=gpu, offscreen EGL + read-back" in out, out
    finally:
        screen.close()

    # 4. An X server without GLX: no GL context for the window; the GPU renders through
    # EGL, its frames read back and shown through SDL's renderer, and the run says why.
    screen = Screen(work, "fb_noglx", extra=["-extension", "GLX"])
    try:
        app = screen.start(velocity, ["view", "--size", "320x240", "--scale", "1", "--no-overlay", "--frames",
                                      str(frames), "--backend", "gpu", "--linger", "60"])
        try:
            db = screen.wait_for(app, expect, "view without GLX")
        finally:
            out = stop(app)
        print(f"without GLX: {db:.2f} dB")
        assert "backend=gpu" in out, out
        assert "present=gpu, offscreen EGL + read-back (no OpenGL" in out, out
        print([line for line in out.splitlines() if line.startswith("present=")][0])
    finally:
        screen.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
