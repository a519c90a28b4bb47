#!/usr/bin/env python3
"""Issue 10: through SDL's disk audio driver, the engine note of `velocity drive` rises
in pitch as the car speeds up. The pitch is measured here, independently of the
synthesiser, as the strongest frequency of the recorded samples (FFT).

    audio_test.py VELOCITY WORKDIR
"""
import os
import shutil
import subprocess
import sys

import numpy as np

RATE = 44100


def main():
    velocity, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    script = f"{work}/throttle.txt"
    with open(script, "w") as f:
        f.write("0 down up\n")  # flat out down the straight
    raw = f"{work}/engine.raw"
    env = dict(os.environ, SDL_AUDIODRIVER="disk", SDL_DISKAUDIOFILE=raw)
    run = subprocess.run([velocity, "drive", "--headless", "--skip-menu", "--size", "160x120", "--frames", "240",
                          "--script", script], env=env, stdout=subprocess.PIPE, text=True, check=True)
    print(run.stdout.strip())
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
