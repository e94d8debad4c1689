"""Open a generated Allure report in headless Chromium and read what a reader would see.

`python -m outline.report_browser reports/html/index.html` prints the report's total, its tree sections and
every console error; exit 1 if the page did not render or logged an error. `tests/test_report_in_browser.py`
uses `load()` on a report it builds.

Chromium (Debian's `chromium` package, installed by `make test`) is driven over the DevTools protocol on
`--remote-debugging-pipe` (fd 3 in, fd 4 out, NUL-separated JSON): stdlib only, no websocket client. The page is
opened as file://, the way the report is meant to be read (allurerc.mjs builds one self-contained index.html).

What counts as an error, all from the page's own session:
- console.error() / console.assert() calls (Runtime.consoleAPICalled type error/assert);
- uncaught exceptions and unhandled promise rejections (Runtime.exceptionThrown);
- browser log entries of level error: failed resource loads ("Failed to load resource: net::ERR_..."),
  blocked requests, CSP violations (Log.entryAdded);
- requests that failed at the network layer (Network.loadingFailed), unless Chromium itself cancelled them
  (canceled=true: an aborted prefetch or a request dropped by navigation, not a missing resource);
- any request that leaves the machine (a scheme other than file:, data:, blob:, about:): the report is
  self-contained, and outline/allure_html.py strips Allure's analytics tag so that it does not call out;
- error text the report renders in the page instead of logging it ("Failed to fetch <data file>: data not
  found", Allure's message for a data file missing from the report).
Warnings, console.log/info and Chromium's process noise on stderr (D-Bus, VA-API, sandbox notices of a
container without a session bus or GPU) are not errors; stderr is shown only when Chromium dies.
"""
from __future__ import annotations

import fcntl
import json
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

CHROMIUM = "/usr/bin/chromium"
INSTALL_HINT = ("`make test` installs it (Debian package `chromium`: "
                "apt-get install -y --no-install-recommends chromium)")
# Headless as root in a container with a closed network: no sandbox (refused as root), no GPU, no QUIC,
# and none of the background calls home (component updates, sync, first-run pages).
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1280,900"]

# Read in the page once per poll: the report's own data-testid hooks (Allure 3 awesome plugin).
_STATE_JS = r"""(() => {
  const q = (s, root = document) => root.querySelector(s);
  const total = q('[data-testid="metadata-item-total"] [data-testid="metadata-value"]');
  const sections = {};
  for (const sec of document.querySelectorAll('[data-testid="tree-section"]')) {
    const title = q('[data-testid="tree-section-title"]', sec);
    if (!title) continue;
    let n = 0;
    for (const item of sec.querySelectorAll('[class*="tree-status-bar-item"]')) n += Number(item.textContent) || 0;
    sections[title.textContent.trim()] = n;
  }
  const app = document.getElementById('app');
  // A test result's description is rendered into an iframe (srcdoc, same origin): its text, if one is shown.
  const frame = q('[data-testid="test-result-description-frame"]');
  const frameBody = frame && frame.contentDocument && frame.contentDocument.body;
  return {
    description: frameBody ? frameBody.innerText : null,
    title: document.title.trim(),
    reportTitle: (q('[data-testid="report-title"]') || {}).textContent || null,
    appChildren: app ? app.childElementCount : -1,
    loaderShown: !!document.getElementById('allure-app-loader'),
    total: total ? total.textContent.trim() : null,
    sections,
    text: document.body ? document.body.innerText : '',
  };
})()"""


# Allure 3's awesome app catches a missing or unreadable data file and shows, with no console message,
# "Failed to fetch widgets/statistic.json: data not found" where the widget would be.
_SHOWN_ERROR = re.compile(r"Failed to fetch|data not found")


# A report opened from disk loads nothing from elsewhere (and must not call out, see outline/allure_html.py).
_LOCAL_SCHEMES = {"file", "data", "blob", "about"}


class BrowserError(RuntimeError):
    """Chromium is missing, crashed, or did not answer in time."""


@dataclass
class PageLoad:
    url: str
    title: str = ""
    report_title: str | None = None
    app_children: int = -1
    loader_shown: bool = False
    total: int | None = None
    sections: dict[str, int] = field(default_factory=dict)
    text: str = ""
    description: str | None = None      # a test result page's description, as shown in its frame
    errors: list[str] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def rendered(self) -> bool:
        """The app mounted, the loading screen is gone and the summary shows a total."""
        return self.app_children > 0 and not self.loader_shown and self.total is not None

    def excerpt(self, limit: int = 1500) -> str:
        text = " | ".join(line.strip() for line in self.text.splitlines() if line.strip())
        return text[:limit] + (" ..." if len(text) > limit else "")


class _Pipe:
    """The DevTools protocol over --remote-debugging-pipe."""

    def __init__(self, proc: subprocess.Popen, to_browser: int, from_browser: int, log):
        self.proc, self.wfd, self.rfd, self.log = proc, to_browser, from_browser, log
        self.buffer = b""
        self.next_id = 0
        self.events: list[dict] = []

    def send(self, method: str, params: dict | None = None, session: str | None = None) -> int:
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        data = json.dumps(msg).encode() + b"\0"
        while data:
            data = data[os.write(self.wfd, data):]
        return self.next_id

    def _read(self, deadline: float) -> dict | None:
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([self.rfd], [], [], min(left, 0.5))
            if not ready:
                if self.proc.poll() is not None:
                    raise BrowserError(f"chromium exited with {self.proc.returncode}\n{self.log()}")
                continue
            chunk = os.read(self.rfd, 1 << 20)
            if not chunk:
                raise BrowserError(f"chromium closed the DevTools pipe\n{self.log()}")
            self.buffer += chunk
        raw, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(raw)

    def call(self, method: str, params: dict | None = None, session: str | None = None,
             timeout: float = 15.0) -> dict:
        wanted = self.send(method, params, session)
        deadline = time.monotonic() + timeout
        while True:
            msg = self._read(deadline)
            if msg is None:
                raise BrowserError(f"no answer to {method} within {timeout:.0f} s\n{self.log()}")
            if msg.get("id") == wanted:
                if "error" in msg:
                    raise BrowserError(f"{method}: {msg['error']}")
                return msg.get("result", {})
            if "method" in msg:
                self.events.append(msg)

    def drain(self, seconds: float) -> None:
        deadline = time.monotonic() + seconds
        while (msg := self._read(deadline)) is not None:
            if "method" in msg:
                self.events.append(msg)


def _arg_text(arg: dict) -> str:
    if "value" in arg:
        return str(arg["value"])
    return arg.get("description") or arg.get("unserializableValue") or arg.get("type", "?")


def _errors(events: list[dict], session: str) -> list[str]:
    """The page's console errors, uncaught exceptions and failed loads, one line each (see module doc)."""
    urls: dict[str, str] = {}
    out: list[str] = []
    failed: list[tuple[str, str]] = []
    for ev in events:
        if ev.get("sessionId") != session:
            continue
        method, p = ev["method"], ev.get("params", {})
        if method == "Network.requestWillBeSent":
            urls[p["requestId"]] = url = p["request"]["url"]
            if url.split(":", 1)[0] not in _LOCAL_SCHEMES:
                out.append(f"external request: {url[:160]}")
        elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            frame = (p.get("stackTrace") or {}).get("callFrames") or [{}]
            where = f" ({frame[0].get('url', '')[-80:]}:{frame[0].get('lineNumber', '?')})" if frame[0] else ""
            out.append(f"console.{p['type']}: " + " ".join(_arg_text(a) for a in p.get("args", [])) + where)
        elif method == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            desc = (d.get("exception") or {}).get("description") or d.get("text", "")
            out.append(f"uncaught exception: {desc.splitlines()[0] if desc else d}"
                       f" ({d.get('url', '')[-80:]}:{d.get('lineNumber', '?')})")
        elif method == "Log.entryAdded" and p["entry"].get("level") == "error":
            e = p["entry"]
            out.append(f"log error [{e.get('source')}]: {e.get('text', '')} {e.get('url', '')[-120:]}".rstrip())
        elif method == "Network.loadingFailed" and not p.get("canceled"):
            failed.append((p.get("errorText", "?"), urls.get(p["requestId"], "?")))
    # A failed load usually also logs "Failed to load resource" with its URL: name it once.
    logged = {url for line in out for url in line.split() if "://" in url}
    out += [f"failed load: {err} {url[-120:]}" for err, url in failed if url[-120:] not in logged]
    return out


def _state(pipe: _Pipe, session: str) -> dict:
    answer = pipe.call("Runtime.evaluate", {"expression": _STATE_JS, "returnByValue": True}, session=session)
    return answer["result"].get("value") or {}


def _shown_errors(text: str) -> list[str]:
    """Errors the report renders as text instead of logging them (a data file it cannot load)."""
    return [f"shown in page: {line.strip()}" for line in text.splitlines() if _SHOWN_ERROR.search(line)]


def _above_4(fd: int) -> int:
    """The same pipe end on a descriptor > 4, so the shell's `3<&N 4>&M` cannot clobber it."""
    high = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return high


def load(target: str | Path, *, chromium: str = CHROMIUM, timeout: float = 30.0, settle: float = 0.5) -> PageLoad:
    """Open `target` (a file path or URL) and wait until the report shows its total, or a test result page its
    description (or `timeout` passes)."""
    url = target if isinstance(target, str) and "://" in target else Path(target).resolve().as_uri()
    exe = shutil.which(chromium) if os.sep not in chromium else chromium
    if not exe or not os.access(exe, os.X_OK):
        raise BrowserError(f"{chromium} not found: {INSTALL_HINT}")
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="report-browser-") as profile, \
            tempfile.TemporaryFile() as stderr:
        cmd_r, cmd_w = os.pipe()    # we write commands, chromium reads fd 3
        res_r, res_w = os.pipe()    # chromium writes fd 4, we read
        cmd_r, res_w = _above_4(cmd_r), _above_4(res_w)
        # Place the pipe ends on fd 3 and 4 in the child without preexec_fn (unsafe with threads);
        # bash, not sh: dash takes single-digit descriptors only.
        shell = f'exec "$0" "$@" 3<&{cmd_r} 4>&{res_w} {cmd_r}<&- {res_w}>&-'
        proc = subprocess.Popen(["bash", "-c", shell, exe, *FLAGS, f"--user-data-dir={profile}",
                                 "--remote-debugging-pipe", "about:blank"],
                                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=stderr,
                                pass_fds=(cmd_r, res_w), start_new_session=True)
        os.close(cmd_r)
        os.close(res_w)

        def log() -> str:
            stderr.seek(0)
            lines = stderr.read().decode(errors="replace").splitlines()
            return "chromium stderr (last lines):\n" + "\n".join(lines[-15:])

        pipe = _Pipe(proc, cmd_w, res_r, log)
        page = PageLoad(url=url)
        try:
            target_id = pipe.call("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = pipe.call("Target.attachToTarget", {"targetId": target_id, "flatten": True})["sessionId"]
            for domain in ("Runtime", "Log", "Network", "Page"):
                pipe.call(f"{domain}.enable", session=session)
            nav = pipe.call("Page.navigate", {"url": url}, session=session)
            if nav.get("errorText"):
                page.errors.append(f"navigation failed: {nav['errorText']}")
            deadline = time.monotonic() + timeout
            while True:
                state = _state(pipe, session)
                shown = state.get("total") is not None or state.get("description") is not None   # overview, result
                done = shown and not state.get("loaderShown")
                if done or _shown_errors(state.get("text", "")) or time.monotonic() > deadline:
                    break
                pipe.drain(0.2)
            pipe.drain(settle)  # what goes wrong right after the first render
            state = _state(pipe, session)
            page.title = state.get("title", "")
            page.report_title = state.get("reportTitle")
            page.app_children = state.get("appChildren", -1)
            page.loader_shown = bool(state.get("loaderShown"))
            total = state.get("total")
            page.total = int(total) if total and total.isdigit() else None
            page.sections = state.get("sections") or {}
            page.text = state.get("text", "")
            page.description = state.get("description")
            page.errors += _errors(pipe.events, session) + _shown_errors(page.text)
            try:
                pipe.call("Browser.close", timeout=5)
            except BrowserError:
                pass
        finally:
            os.close(cmd_w)
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:  # its own process group: renderer and GPU processes too
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
            os.close(res_r)
    page.seconds = time.monotonic() - started
    return page


def main(argv: list[str]) -> int:
    status = 0
    for arg in argv or ["reports/html/index.html"]:
        page = load(arg)
        print(f"{page.url}: {'rendered' if page.rendered else 'NOT rendered'} in {page.seconds:.1f} s, "
              f"title {page.title!r}, total {page.total}, sections {page.sections}")
        for line in page.errors:
            print(f"  {line}")
        status |= int(not page.rendered or bool(page.errors))
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
