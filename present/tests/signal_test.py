#!/usr/bin/env python3
"""Issue 21: SIGTERM and SIGINT end every program cleanly. Each run records frames to a
folder; once a few are written it gets the signal, and must exit within 2 s with the
shell's status for that signal (128 + N), print its statistics, and leave only whole
PNGs (every chunk's CRC right, the image data the size the header says) and no
half-written ".part" file. The kernel may run the handler on any of the program's
threads: one run sends the signal to a thread other than the main one (tgkill), where
stop 29's volatile flag was a data race (ThreadSanitizer).

    signal_test.py VELOCITY WORKDIR
"""
import ctypes
import errno
import glob
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib


def check_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    pos, idat, size, ended = 8, b"", None, False
    while pos < len(data):
        assert pos + 12 <= len(data), f"{path}: cut inside a chunk"
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length].rjust(4, b"\0"))
        assert len(body) == length and zlib.crc32(kind + body) == crc, f"{path}: bad {kind} chunk"
        pos += 12 + length
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            size = h * (1 + w * (4 if colour == 6 else 3))
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            ended = True
    assert ended, f"{path}: no IEND"
    assert len(zlib.decompress(idat)) == size, f"{path}: image data of the wrong size"


def signal_other_thread(proc, sig):
    """Sends `sig` to one of proc's threads other than its main one that is running at
    that moment (ThreadSanitizer holds a signal back while its thread sleeps); False if
    none is (or each ended before it could be sent)."""
    libc = ctypes.CDLL(None, use_errno=True)
    for tid in sorted(int(t) for t in os.listdir(f"/proc/{proc.pid}/task")):
        try:
            with open(f"/proc/{proc.pid}/task/{tid}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if tid == proc.pid or state != "R":
            continue
        if libc.tgkill(proc.pid, tid, int(sig)) == 0:
            return True
        assert ctypes.get_errno() == errno.ESRCH, f"tgkill: {os.strerror(ctypes.get_errno())}"
    return False


def run(velocity, work, name, args, sig, env=None, other_thread=False):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    cmd = [velocity] + args + ["--frames", "1000000", "--size", "160x120", "--mute", "--record", out]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            env=dict(os.environ, **(env or {})))
    deadline = time.monotonic() + 60
    while len(glob.glob(os.path.join(out, "*.png"))) < 5:
        assert proc.poll() is None, f"{name}: ended early: {proc.stdout.read()}"
        assert time.monotonic() < deadline, f"{name}: no frames recorded"
        time.sleep(0.02)
    sent = time.monotonic()
    if other_thread:
        while not signal_other_thread(proc, sig):
            assert proc.poll() is None and time.monotonic() < deadline, f"{name}: no thread but the main one"
            time.sleep(0.001)
    else:
        proc.send_signal(sig)
    try:
        output, _ = proc.communicate(timeout=2)
    except subprocess.TimeoutExpired:
        proc.kill()
        raise AssertionError(f"{name}: still running 2 s after {sig.name}")
    took = time.monotonic() - sent
    assert proc.returncode == 128 + sig, f"{name}: exit status {proc.returncode}, not {128 + sig}: {output}"
    assert "frames=" in output, f"{name}: no statistics line: {output}"
    pngs = sorted(glob.glob(os.path.join(out, "*.png")))
    leftovers = [p for p in os.listdir(out) if not p.endswith(".png")]
    assert not leftovers, f"{name}: left {leftovers}"
    for p in pngs:
        check_png(p)
    print(f"{name}: {sig.name}{' to another thread' if other_thread else ''} -> exit {proc.returncode} in {took:.2f} s, {len(pngs)} whole PNGs")


def main():
    velocity, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    run(velocity, work, "drive_term", ["drive", "--headless", "--skip-menu"], signal.SIGTERM)
    run(velocity, work, "fly_int", ["fly", "--headless"], signal.SIGINT)
    run(velocity, work, "fly_int_other_thread", ["fly", "--headless"], signal.SIGINT, other_thread=True)
    # The window code too, on SDL's dummy video driver (SDL must not take the signal).
    run(velocity, work, "view_dummy_term", ["view"], signal.SIGTERM, {"SDL_VIDEODRIVER": "dummy"})
    print("ok")


if __name__ == "__main__":
    main()
