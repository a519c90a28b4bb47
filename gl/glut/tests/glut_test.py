#!/usr/bin/env python3
"""GLUT for pGL, driven as a person would drive a GLUT program.

    glut_test.py callbacks GLUT_DEMO WORKDIR   SDL's dummy video driver, a script of key
                                              presses and clicks: every callback gets
                                              them, the timer fires, frames are recorded
    glut_test.py window GLUT_DEMO WORKDIR      under Xvfb: the window shows exactly the
                                              frame the program rendered (glReadPixels)
    glut_test.py stops GLUT_LOOP WORKDIR       a program looping in its display callback
                                              ends after VELOCITY_GLUT_FRAMES, records at
                                              most its bound, ends on SIGTERM and SIGINT
    glut_test.py menus GLUT_MENUS WORKDIR      a script opens the right button's menu,
                                              drags to an entry, clicks one, reaches into a
                                              sub-menu, lets go outside: the callbacks and
                                              the recorded frames show each
"""
import os
import signal
import shutil
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "present", "tests"))
from window_test import read_png, read_xwd, start_xvfb  # noqa: E402  (the real-time tests' helpers)


def read_ppm(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    assert parts[0] == b"P6" and parts[2] == b"255", path
    w, h = map(int, parts[1].split())
    return np.frombuffer(parts[3], np.uint8, count=w * h * 3).reshape(h, w, 3)


def callbacks(demo, work):
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    script = os.path.join(work, "script.txt")
    with open(script, "w") as f:
        f.write("# keys, a special key, a click, then close the window\n"
                "0.15 press a\n0.25 press left\n0.35 click 100 50 left\n0.45 press p\n0.9 quit\n")
    out = subprocess.run([demo], env=dict(env, VELOCITY_GLUT_SCRIPT=script), capture_output=True, text=True, timeout=60)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, f"glut_demo exited with {out.returncode}"
    lines = out.stdout.splitlines()
    assert lines[0] == "reshape 320 240", "the reshape callback comes first, with the window's size"
    assert any(l.startswith("key 97 ") for l in lines), "'a' reached the keyboard callback"
    assert any(l.startswith("special 100 ") for l in lines), "the left arrow reached the special callback (GLUT_KEY_LEFT)"
    assert "mouse 0 0 100 50" in lines and "mouse 0 1 100 50" in lines, "the click reached the mouse callback, down then up"
    assert any(l.startswith("key 112 ") for l in lines), "'p' reached the keyboard callback"
    timers = [l for l in lines if l.startswith("timer 7 after ")]
    assert len(timers) == 1 and int(timers[0].split()[3]) >= 100, "the timer fired once, not before its 100 ms"
    order = [l.split()[0] for l in lines if l.split()[0] in ("key", "special", "mouse")]
    assert order == ["key", "special", "mouse", "mouse", "key"], f"events in the script's order: {order}"

    # VELOCITY_GLUT_FRAMES leaves the main loop; VELOCITY_GLUT_RECORD keeps every frame.
    rec = os.path.join(work, "frames")
    out = subprocess.run([demo], env=dict(env, VELOCITY_GLUT_FRAMES="4", VELOCITY_GLUT_RECORD=rec),
                         capture_output=True, text=True, timeout=60)
    print(out.stdout, out.stderr)
    assert out.returncode == 0 and "main loop left after 4 frames" in out.stdout
    frames = [read_png(os.path.join(rec, f"frame_{i:05d}.png")) for i in range(4)]
    assert not os.path.exists(os.path.join(rec, "frame_00004.png"))
    for f in frames:
        assert f.shape == (240, 320, 3)
        lit = np.count_nonzero(np.abs(f.astype(int) - [26, 26, 38]).max(axis=2) > 8)  # not the clear colour
        assert 5000 < lit < 40000, f"the cube covers part of the window: {lit} pixels"
    assert np.any(frames[0] != frames[3]), "the idle callback spins the cube between frames"
    print("callbacks, timer, frames and recording: as GLUT defines them")


def window(demo, work):
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        print("SKIPPED: Xvfb is not installed (Debian's xvfb; scripts/deps.sh installs it)")
        return 77
    fbdir = os.path.join(work, "fb")
    server, display = start_xvfb(xvfb, fbdir)
    dump = os.path.join(work, "frame.ppm")
    env = dict(os.environ, DISPLAY=":" + display, SDL_VIDEODRIVER="x11", SDL_AUDIODRIVER="dummy",
               SDL_RENDER_DRIVER="software")
    app = subprocess.Popen([demo, dump, "10"], env=env, stdout=subprocess.PIPE, text=True)
    try:
        deadline = time.time() + 60
        matched, last = False, None
        while time.time() < deadline and app.poll() is None:
            time.sleep(0.25)
            if not os.path.exists(dump) or os.path.getsize(dump) < 320 * 240 * 3:
                continue
            expect = read_ppm(dump)
            screen = read_xwd(f"{fbdir}/Xvfb_screen0")[:240, :320]
            last = np.abs(screen.astype(int) - expect.astype(int))
            if last.max() <= 2:
                matched = True
                break
        assert app.poll() is None, "glut_demo exited before its window was seen"
        app.send_signal(signal.SIGTERM)  # ends the program by the signal, as freeglut's
        out, _ = app.communicate(timeout=30)
    finally:
        if app.poll() is None:
            app.kill()
        server.terminate()
        server.wait(timeout=10)
    print(out)
    assert app.returncode == -signal.SIGTERM, f"glut_demo exited with {app.returncode}, not by SIGTERM"
    assert last is not None, "the frame was never dumped"
    assert expect.std() > 10, "the dumped frame is blank: nothing to compare"
    assert matched, f"the window differs from the GL frame: max {last.max()}, {np.count_nonzero(last.max(axis=2) > 2)} pixels"
    print("the window shows the frame pGL rendered (320x240, every channel within 2)")
    return 0


def stops(loop, work):
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    # VELOCITY_GLUT_FRAMES counts the swaps made inside the display callback, and the
    # single-buffered loop's repeated glutPostRedisplay; recording stops with it.
    rec = os.path.join(work, "frames")
    out = subprocess.run([loop, "swap"], env=dict(env, VELOCITY_GLUT_FRAMES="5", VELOCITY_GLUT_RECORD=rec),
                         capture_output=True, text=True, timeout=30)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, f"glut_loop swap with 5 frames exited with {out.returncode}"
    assert "looping" in out.stdout and "main loop left" not in out.stdout
    assert sorted(os.listdir(rec)) == [f"frame_{i:05d}.png" for i in range(5)], sorted(os.listdir(rec))
    out = subprocess.run([loop, "post"], env=dict(env, VELOCITY_GLUT_FRAMES="5"), capture_output=True, text=True,
                         timeout=30)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, f"glut_loop post with 5 frames exited with {out.returncode}"

    # Without a frame limit, the recorder keeps its bound (1000 frames) and says so.
    rec = os.path.join(work, "unbounded")
    app = subprocess.Popen([loop, "swap"], env=dict(env, VELOCITY_GLUT_RECORD=rec), stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    try:
        deadline, count, steady = time.time() + 120, -1, 0
        while time.time() < deadline and steady < 4:
            time.sleep(0.25)
            n = len(os.listdir(rec)) if os.path.isdir(rec) else 0
            steady = steady + 1 if n == count and n >= 1000 else 0
            count = n
        assert app.poll() is None, f"the program ended by itself: {app.returncode}, {app.stderr.read()}"
        app.send_signal(signal.SIGTERM)
        _, err = app.communicate(timeout=5)
    finally:
        if app.poll() is None:
            app.kill()
    print(err)
    assert count == 1000, f"{count} frames recorded: the bound is 1000"
    assert "1000 frames recorded, no more" in err

    # SIGTERM and SIGINT end it, by the signal, as they end freeglut's programs.
    for sig in (signal.SIGTERM, signal.SIGINT):
        # (with the signal's default action, whatever this test inherited: a background
        # shell's children ignore SIGINT, and GLUT keeps what it finds, as freeglut)
        app = subprocess.Popen([loop, "swap"], env=env, stdout=subprocess.PIPE, text=True,
                               preexec_fn=lambda s=sig: signal.signal(s, signal.SIG_DFL))
        try:
            assert app.stdout.readline().strip() == "looping"
            time.sleep(0.3)
            sent = time.time()
            app.send_signal(sig)
            app.wait(timeout=5)
            took = time.time() - sent
        finally:
            if app.poll() is None:
                app.kill()
        print(f"{sig.name}: ended {took:.3f} s after it was sent, status {app.returncode}")
        assert app.returncode == -sig, f"{sig.name}: exit status {app.returncode}, not killed by the signal"
        assert took < 1, f"{sig.name}: took {took:.2f} s to end"
    print("a program looping in its display callback: stopped by the frame limit, the recorder's bound, "
          "SIGTERM and SIGINT")
    return 0


def menus(program, work):
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    first = subprocess.run([program], env=dict(env, VELOCITY_GLUT_FRAMES="1"), capture_output=True, text=True, timeout=60)
    print(first.stdout, first.stderr)
    assert first.returncode == 0
    lines = first.stdout.splitlines()
    assert lines[0] == "items 3" and lines[1] == "items 3 current 1", "removed, changed and added entries counted"
    root_width = int(lines[2].split()[1])
    # The root menu opens at (20, 20): entries 18 pixels high from row 21, its sub-menu
    # (opened from the third, "More") at x = 20 + width - 2, level with that entry.
    sub_x, sub_y = 20 + root_width - 2, 20 + 2 * 18
    script = os.path.join(work, "script.txt")
    with open(script, "w") as f:
        f.write("# drag to Green; click-open then click Red; drag into More > Blue; let go outside\n"
                "0.2 mousedown right 20 20\n0.35 move 40 47\n0.5 mouseup right 40 47\n"
                "0.7 click 30 30 right\n0.9 click 40 40 left\n"
                f"1.1 mousedown right 20 20\n1.2 move 40 65\n1.3 move {sub_x + 10} {sub_y + 9}\n"
                f"1.45 mouseup right {sub_x + 10} {sub_y + 9}\n"
                "1.6 mousedown right 20 20\n1.7 move 5 140\n1.8 mouseup right 5 140\n"
                "2.0 click 100 100 left\n2.3 quit\n")
    rec = os.path.join(work, "frames")
    out = subprocess.run([program], env=dict(env, VELOCITY_GLUT_SCRIPT=script, VELOCITY_GLUT_RECORD=rec),
                         capture_output=True, text=True, timeout=60)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, f"menus exited with {out.returncode}"
    got = [l for l in out.stdout.splitlines() if l.startswith(("menu", "mouse"))]
    assert got == ["menu 2 current root items 3", "menu 1 current root items 3", "menu 3 current more items 1",
                   "mouse 0 0 100 100", "mouse 0 1 100 100"], f"the choices and the program's own clicks: {got}"
    frames = sorted(os.listdir(rec))
    images = [read_png(os.path.join(rec, n)) for n in frames]
    grey = [i for i, im in enumerate(images) if tuple(im[25, 60]) == (224, 224, 224)]
    green = [i for i, im in enumerate(images) if tuple(im[100, 150]) == (0, 255, 0)]
    blue = [i for i, im in enumerate(images) if tuple(im[100, 150]) == (0, 0, 255)]
    assert grey, "a frame shows the open menu's face"
    assert green and blue and green[0] < blue[0], "choosing Green, then Blue, changed what the program drew"
    assert tuple(images[-1][25, 60]) != (224, 224, 224), "the menu is closed at the end"
    # The labels are drawn: dark text pixels inside the open menu's first entry.
    im = images[grey[0]]
    assert (im[22:38, 22:20 + root_width - 2].max(axis=2) < 100).any(), "the entries' labels are drawn"
    return 0


def main():
    mode, demo, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if mode == "callbacks":
        return callbacks(demo, work) or 0
    if mode == "stops":
        return stops(demo, work)
    if mode == "menus":
        return menus(demo, work)
    return window(demo, work)


if __name__ == "__main__":
    sys.exit(main())
