#!/usr/bin/env python3
"""The EGL vendor library (libEGL_velocity.so.0) chosen as any headless program chooses an
EGL vendor: libglvnd's libEGL reads the JSON file __EGL_VENDOR_LIBRARY_FILENAMES names.

    egl_test.py api EGL_CHECK JSON             egl_check.c through the build tree's JSON
    egl_test.py installed BUILD EGL_CHECK WORKDIR   the same on the copy
                                              `cmake --install BUILD --prefix` installs,
                                              found through its installed JSON file
    egl_test.py eglinfo JSON                   Debian's eglinfo (mesa-utils), unmodified:
                                              it finds the surfaceless platform, says the
                                              display is Velocity's and lists its five
                                              configurations
Exit 77 (skipped) without eglinfo.
"""
import os
import shutil
import subprocess
import sys


def environment(json):
    # Only Velocity's vendor: Mesa's, if installed, is not loaded.
    return dict(os.environ, __EGL_VENDOR_LIBRARY_FILENAMES=json)


def run(command, json):
    result = subprocess.run(command, env=environment(json), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=120)
    print(result.stdout)
    return result


def api(check, json):
    result = run([check], json)
    assert result.returncode == 0, f"egl_check failed (exit {result.returncode})"
    assert "all EGL checks passed" in result.stdout
    return 0


def installed(build, check, work):
    prefix = os.path.join(work, "prefix")
    shutil.rmtree(prefix, ignore_errors=True)
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, stdout=subprocess.DEVNULL)
    json = os.path.join(prefix, "share", "glvnd", "egl_vendor.d", "60_velocity.json")
    assert os.path.isfile(json), "cmake --install did not install share/glvnd/egl_vendor.d/60_velocity.json"
    libraries = [d for d, _, files in os.walk(prefix) if "libEGL_velocity.so.0" in files]
    assert libraries, "cmake --install did not install libEGL_velocity.so.0"
    print(f"installed: {json} -> {libraries[0]}/libEGL_velocity.so.0")
    return api(check, json)


def eglinfo(json):
    program = shutil.which("eglinfo")
    if not program:
        print("SKIPPED: eglinfo is not installed (Debian's mesa-utils)")
        return 77
    result = run([program], json)
    assert result.returncode == 0, f"eglinfo failed (exit {result.returncode})"
    out = result.stdout
    section = out[out.index("Surfaceless platform:"):]
    assert "EGL vendor string: Velocity" in section, "the surfaceless display is not Velocity's"
    assert "EGL client APIs: OpenGL" in section
    # Its configuration table: one row per configuration, ids 0x01 to 0x05.
    rows = [line for line in section.splitlines() if line.strip().startswith("0x0")]
    assert len(rows) == 5, f"{len(rows)} configurations listed"
    return 0


def main(argv):
    mode = argv[1]
    if mode == "api":
        return api(argv[2], argv[3])
    if mode == "installed":
        return installed(argv[2], argv[3], argv[4])
    if mode == "eglinfo":
        return eglinfo(argv[2])
    raise SystemExit(f"unknown mode {mode}")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
