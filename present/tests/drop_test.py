#!/usr/bin/env python3
"""Issue 21: a file dragged onto the viewer's window opens, with a real X drag (XDND)
under Xvfb. The drag source is a small GTK window offering the file as a text/uri-list;
xdotool presses the mouse on it, moves across to the viewer and lets go. The viewer's
window title then names the model (it is "Velocity - NAME").

    drop_test.py VELOCITY MODEL WORKDIR

Skipped (exit 77) without Xvfb, xdotool or GTK 3 for Python (scripts/deps.sh installs them).
"""
import os
import shutil
import subprocess
import sys
import time

SOURCE = r'''
import sys
import gi
gi.require_version("Gtk", "3.0")
from gi.repository import Gtk, Gdk
uri = sys.argv[1]
win = Gtk.Window(title="drag source")
win.set_default_size(200, 200)
win.move(700, 100)
box = Gtk.EventBox()
box.add(Gtk.Label(label="DRAG ME"))
win.add(box)
box.drag_source_set(Gdk.ModifierType.BUTTON1_MASK, [], Gdk.DragAction.COPY)
box.drag_source_add_uri_targets()
box.connect("drag-data-get", lambda w, ctx, data, info, t: data.set_uris([uri]))
win.connect("destroy", Gtk.main_quit)
win.show_all()
print("ready", flush=True)
Gtk.main()
'''


def main():
    velocity, model, work = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    if not shutil.which("Xvfb") or not shutil.which("xdotool"):
        print("skipped: needs Xvfb and xdotool")
        return 77
    probe = subprocess.run([sys.executable, "-c", "import gi; gi.require_version('Gtk', '3.0')"],
                           capture_output=True)
    if probe.returncode != 0:
        print("skipped: needs GTK 3 for Python (gir1.2-gtk-3.0)")
        return 77
    os.makedirs(work, exist_ok=True)
    display = ":%d" % (60 + os.getpid() % 30)
    xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "1024x768x24", "-nolisten", "tcp"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    procs = [xvfb]
    viewer = None
    env = dict(os.environ, DISPLAY=display, SDL_VIDEODRIVER="x11", SDL_RENDER_DRIVER="software",
               SDL_AUDIODRIVER="dummy", GDK_BACKEND="x11", NO_AT_BRIDGE="1")
    try:
        time.sleep(1.0)
        viewer = subprocess.Popen([velocity, "view", "--size", "640x480", "--scale", "1", "--window-at-origin",
                                   "--mute", "--no-vsync"], env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True)
        procs.append(viewer)
        source = subprocess.Popen([sys.executable, "-c", SOURCE, "file://" + model], env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        procs.append(source)
        assert source.stdout.readline().strip() == "ready", "the drag source did not start"

        def xdo(*args):
            return subprocess.run(["xdotool", *args], env=env, capture_output=True, text=True)

        def window_named(name):
            return xdo("search", "--name", name).stdout.split()

        deadline = time.time() + 20
        while time.time() < deadline and not (window_named("^Velocity - ") and window_named("drag source")):
            time.sleep(0.2)
        assert window_named("^Velocity - "), "the viewer's window did not appear"
        assert window_named("drag source"), "the drag source's window did not appear"
        time.sleep(0.5)
        name = os.path.basename(model)
        assert not window_named(name), "the model is open before the drop"

        # Press on the source, move past GTK's drag threshold, across to the viewer, let go.
        xdo("mousemove", "800", "200")
        time.sleep(0.3)
        xdo("mousedown", "1")
        for x, y in [(810, 205), (830, 210), (760, 220), (600, 240), (450, 240), (320, 240), (300, 250)]:
            time.sleep(0.15)
            xdo("mousemove", str(x), str(y))
        time.sleep(0.5)
        xdo("mouseup", "1")

        deadline = time.time() + 15
        while time.time() < deadline and not window_named(name):
            time.sleep(0.2)
        titles = [xdo("getwindowname", w).stdout.strip() for w in window_named("^Velocity - ")]
        print("viewer window titles after the drop:", titles)
        assert window_named(name), "the dropped model did not open (titles: %s)" % titles
        print("dropped and opened:", name)
        return 0
    finally:
        for p in reversed(procs):
            p.terminate()
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
        if viewer and viewer.stdout:
            out = viewer.stdout.read()
            if out.strip():
                print("viewer:", out.strip()[-2000:])


if __name__ == "__main__":
    sys.exit(main())
