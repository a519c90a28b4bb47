"""The pinned three.js (package.json, package-lock.json) installed next to this file with
`npm ci`, only when node_modules is missing or was installed from another lock file: a
stamp in node_modules holds the SHA-256 of the lock file it came from. So a checkout that
has run once works offline, and concurrent tests (ctest -j) do not install twice: the
check and the install hold an exclusive lock on package.json."""
from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
STAMP = os.path.join(HERE, "node_modules", ".velocity-lock-sha256")


class InstallError(RuntimeError):
    pass


def _lock_digest() -> str:
    with open(os.path.join(HERE, "package-lock.json"), "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def ensure_three(timeout: float = 300) -> None:
    """Runs `npm ci` here unless node_modules matches package-lock.json. Raises InstallError."""
    with open(os.path.join(HERE, "package.json"), "rb") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        digest = _lock_digest()
        try:
            with open(STAMP) as f:
                if f.read().strip() == digest:
                    return
        except FileNotFoundError:
            pass
        npm = shutil.which("npm")
        if not npm:
            raise InstallError("npm is not installed (Debian: apt-get install npm; scripts/deps.sh does)")
        try:
            run = subprocess.run([npm, "ci", "--no-audit", "--no-fund", "--loglevel=error"], cwd=HERE,
                                 stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            raise InstallError(f"npm ci timed out after {timeout:.0f} s in {HERE}") from None
        if run.returncode != 0:
            lines = [l for l in (run.stderr + run.stdout).splitlines() if l.strip()]
            raise InstallError(f"npm ci failed in {HERE}: {lines[0] if lines else 'exit ' + str(run.returncode)}")
        with open(STAMP, "w") as f:
            f.write(digest + "\n")
