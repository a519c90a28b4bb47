"""Headless Chromium driven over the DevTools protocol on a pipe, from the standard library.

Why the protocol rather than `chromium --dump-dom --virtual-time-budget`: with the
protocol we know when the page's promise has settled (virtual time can run out while
three.js still decodes a texture off the main thread), we get the page's own error
message back, and the pixels come back as data rather than through the DOM. Why a pipe
(--remote-debugging-pipe, fds 3 and 4, messages ending in NUL) rather than a WebSocket:
no port to pick or leak, and nothing outside Python's standard library (no puppeteer,
whose browser download is blocked here anyway).

Every wait is bounded by one deadline; on any failure the browser's process group is
killed, so nothing is left running.
"""
from __future__ import annotations

import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import tempfile
import time

# WebGL on the CPU: ANGLE on SwiftShader, which Chromium ships. Unsafe only in the sense
# that SwiftShader is not hardened against hostile shaders: we run only three.js's own.
# Pages from file:// may read other files (the model, its .bin and images, three.js).
FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--allow-file-access-from-files", "--no-first-run", "--no-default-browser-check",
         "--disable-extensions", "--disable-background-networking", "--mute-audio",
         "--remote-debugging-pipe"]


def _fd_above_9(fd: int) -> int:
    high = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return high


class ChromiumMissing(RuntimeError):
    pass


class PageError(RuntimeError):
    """The page or the browser failed; the message is one line a person can act on."""


class Timeout(PageError):
    """The deadline passed; the message says what was being waited for."""


def find_chromium() -> str:
    """The Chromium to run: $VELOCITY_CHROMIUM, else the first of chromium (Debian),
    chromium-browser, google-chrome on PATH. Raises ChromiumMissing."""
    explicit = os.environ.get("VELOCITY_CHROMIUM")
    if explicit:
        if shutil.which(explicit):
            return shutil.which(explicit)
        raise ChromiumMissing(f"VELOCITY_CHROMIUM={explicit} is not an executable")
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    raise ChromiumMissing("Chromium is not installed (Debian: apt-get install chromium; scripts/deps.sh does)")


class Browser:
    """One headless Chromium with one page; use as a context manager.

        with Browser(deadline=time.monotonic() + 60) as b:
            b.open("file:///.../oracle.html")
            value = b.evaluate("window.renderOracle({...})")
    """

    def __init__(self, deadline: float, chromium: str | None = None):
        self.deadline = deadline
        self.chromium = chromium or find_chromium()
        self._next_id = 0
        self._buffer = b""
        self._events: list[dict] = []
        self._session = None
        self._proc = None

    def __enter__(self) -> "Browser":
        self._profile = tempfile.TemporaryDirectory(prefix="velocity-chromium-")
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()
        # The child's ends numbered 10 or above, so that putting them on 3 and 4 below
        # cannot overwrite one with the other.
        to_browser_r, from_browser_w = (_fd_above_9(to_browser_r), _fd_above_9(from_browser_w))
        # $VELOCITY_CHROMIUM_FLAGS: more flags, to debug (--enable-logging=stderr) or to
        # check a failure (--disable-webgl).
        flags = FLAGS + os.environ.get("VELOCITY_CHROMIUM_FLAGS", "").split() + [f"--user-data-dir={self._profile.name}"]
        if os.geteuid() == 0:
            flags.append("--no-sandbox")  # Chromium refuses to start as root with its sandbox
        self._log = open(os.path.join(self._profile.name, "stderr.txt"), "wb")
        # bash (dash takes one-digit fds only) puts our pipe ends on the fds the protocol
        # uses (3: commands in, 4: replies out) and closes the originals, then runs Chromium.
        shell = f'exec "$0" "$@" 3<&{to_browser_r} 4>&{from_browser_w} {to_browser_r}<&- {from_browser_w}>&-'
        self._proc = subprocess.Popen(["/bin/bash", "-c", shell, self.chromium, *flags, "about:blank"],
                                      pass_fds=(to_browser_r, from_browser_w), stdin=subprocess.DEVNULL,
                                      stdout=self._log, stderr=self._log, start_new_session=True)
        os.close(to_browser_r)
        os.close(from_browser_w)
        try:
            target = self.call("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
            self._session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True},
                                      session=False)["sessionId"]
            self.call("Page.enable")
            self.call("Runtime.enable")
            self.call("Log.enable")  # a module script that failed to load is reported here
        except BaseException:
            self.__exit__(None, None, None)
            raise
        return self

    def __exit__(self, *exc) -> None:
        if self._proc and self._proc.poll() is None:
            try:
                os.killpg(self._proc.pid, signal.SIGKILL)  # the browser and its helpers
            except ProcessLookupError:
                pass
            self._proc.wait()
        for fd in (self._to_browser, self._from_browser):
            try:
                os.close(fd)
            except OSError:
                pass
        self._log.close()
        self._profile.cleanup()

    def open(self, url: str) -> None:
        """Navigates to url and waits for its load event (module scripts have run by then)."""
        self._events.clear()
        reply = self.call("Page.navigate", {"url": url})
        if reply.get("errorText"):
            raise PageError(f"cannot open {url}: {reply['errorText']}")
        self._wait_event("Page.loadEventFired", f"loading {url}")

    def evaluate(self, expression: str):
        """The value of a JavaScript expression, awaited if it is a promise. A thrown error
        becomes PageError with the error's message."""
        reply = self.call("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                               "returnByValue": True}, doing="waiting for the page's answer")
        if "exceptionDetails" in reply:
            details = reply["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text", "error")
            # The message without the stack ("    at ..." lines), on one line.
            lines = [l.strip() for l in text.splitlines() if not l.startswith("    at ")]
            raise PageError(" ".join(lines).removeprefix("Error: "))
        return reply["result"].get("value")

    def take_messages(self, levels: tuple[str, ...] = ("error",)) -> list[str]:
        """Uncaught exceptions, and console messages at these levels ("error", "warning"),
        since the last call, first lines only: a module that failed to load, GLTFLoader's
        warnings about what it ignored. Forgets every event seen so far."""
        out = []
        for e in self._events:
            method, params = e.get("method"), e.get("params", {})
            if method == "Runtime.exceptionThrown":
                d = params["exceptionDetails"]
                out.append(d.get("exception", {}).get("description") or d.get("text", ""))
            elif method == "Runtime.consoleAPICalled" and params["type"] in levels:
                out.append(" ".join(str(a.get("value", a.get("description", ""))) for a in params["args"]))
            elif method == "Log.entryAdded" and params["entry"]["level"] in levels:
                entry = params["entry"]
                out.append(entry["text"] + (f" ({entry['url']})" if entry.get("url") else ""))
        self._events.clear()
        return [line.splitlines()[0] for line in out if line]

    # --- the protocol: numbered commands, replies matched by id, events kept for later
    def call(self, method: str, params: dict | None = None, session: bool = True, doing: str = "") -> dict:
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = self._session
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self._to_browser, data):]
        while True:
            reply = self._read_message(doing or f"waiting for Chromium's reply to {method}")
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise PageError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            self._events.append(reply)

    def _wait_event(self, name: str, doing: str) -> None:
        while not any(e.get("method") == name for e in self._events):
            self._events.append(self._read_message(doing))

    def _read_message(self, doing: str) -> dict:
        while b"\0" not in self._buffer:
            left = self.deadline - time.monotonic()
            if left <= 0:
                raise Timeout(doing)
            ready, _, _ = select.select([self._from_browser], [], [], left)
            if not ready:
                continue
            chunk = os.read(self._from_browser, 1 << 20)
            if not chunk:
                raise PageError(f"Chromium exited while {doing}: {self._last_log_line()}")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        decoded = json.loads(message)
        if decoded.get("method") in ("Inspector.targetCrashed", "Target.targetCrashed"):
            raise PageError(f"the page crashed while {doing}")
        return decoded

    def _last_log_line(self) -> str:
        self._log.flush()
        with open(self._log.name, "rb") as f:
            lines = [l for l in f.read().decode(errors="replace").splitlines() if l.strip()]
        return lines[-1] if lines else "no message"
