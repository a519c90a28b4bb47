#!/usr/bin/env python3
"""Issue 10: through SDL's disk audio driver, the engine note of `velocity drive` rises
in pitch as the car speeds up, and SDL's audio thread runs at a normal priority (a raised
one starved the frame on a loaded machine). The pitch is measured here, independently of the
synthesiser, as the strongest frequency of the recorded samples (FFT).

    audio_test.py VELOCITY WORKDIR
"""
import os
import shutil
import subprocess
import sys
import time

import numpy as np

RATE = 44100


def audio_thread_nice(proc):
    """The nice values SDL's audio thread had while `proc` ran (after its first buffer)."""
    seen = set()
    first = None
    while proc.poll() is None:
        try:
            for tid in os.listdir(f"/proc/{proc.pid}/task"):
                with open(f"/proc/{proc.pid}/task/{tid}/comm") as f:
                    if not f.read().startswith("SDLAudio"):
                        continue
                with open(f"/proc/{proc.pid}/task/{tid}/stat") as f:
                    nice = int(f.read().rsplit(")", 1)[1].split()[16])  # field 19
                first = first or time.monotonic()
                if time.monotonic() - first > 0.2:  # the callback has run by then
                    seen.add(nice)
        except (FileNotFoundError, ProcessLookupError, IndexError, ValueError):
            pass
        time.sleep(0.05)
    return seen


def main():
    velocity, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    script = f"{work}/throttle.txt"
    with open(script, "w") as f:
        f.write("0 down up\n")  # flat out down the straight
    raw = f"{work}/engine.raw"
    env = dict(os.environ, SDL_AUDIODRIVER="disk", SDL_DISKAUDIOFILE=raw)
    run = subprocess.Popen([velocity, "drive", "--headless", "--skip-menu", "--size", "160x120", "--frames", "240",
                            "--script", script], env=env, stdout=subprocess.PIPE, text=True)
    nices = audio_thread_nice(run)
    out, _ = run.communicate()
    print(out.strip())
    assert run.returncode == 0, f"velocity drive exited with {run.returncode}"
    # SDL raises its audio thread to nice -20 where it may; that thread then drew the
    # process's share of the processors to itself and the frame stalled under load.
    print(f"audio thread nice values seen: {sorted(nices)}")
    assert nices, "no SDL audio thread was seen"
    assert all(n == 0 for n in nices), "the audio thread runs at a raised priority"
    samples = np.fromfile(raw, dtype=np.int16).astype(np.float64)  # mono, native order, as opened
    seconds = len(samples) / RATE
    print(f"recorded {seconds:.2f} s of sound")
    assert seconds > 2.5, "the disk driver recorded too little sound"

    def pitch(t):
        window = samples[int(t * RATE):int(t * RATE) + RATE // 2] * np.hanning(RATE // 2)
        spectrum = np.abs(np.fft.rfft(window))
        freqs = np.fft.rfftfreq(len(window), 1 / RATE)
        spectrum[freqs < 30] = 0
        return freqs[np.argmax(spectrum)]

    times = np.arange(0.5, seconds - 0.5, 0.5)
    pitches = [pitch(t) for t in times]
    print("pitch (Hz) at " + ", ".join(f"{t:.1f} s: {p:.0f}" for t, p in zip(times, pitches)))
    assert all(b >= a - 2 for a, b in zip(pitches, pitches[1:])), "the engine note fell while accelerating"
    assert pitches[-1] > pitches[0] * 1.4, "the engine note did not rise"
    assert 40 < pitches[0] < 200 and pitches[-1] < 600, "implausible engine pitch"
    return 0


if __name__ == "__main__":
    sys.exit(main())
