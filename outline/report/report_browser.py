"""Open a generated Allure report in headless Chromium and read what a reader would see.

`python -m outline.report.report_browser reports/html/index.html` prints the report's total, its tree sections and
every console error; exit 1 if the page did not render or logged an error. `tests/test_report_in_browser.py`
uses `load()` on a report it builds.

Chromium (Debian's `chromium` package, installed by `make test`) is driven by Playwright for Python
(playwright-core's driver, which ships in the wheel; no browser download: `executable_path` is Debian's
Chromium). The page is opened as file://, the way the report is meant to be read (allurerc.mjs builds one
self-contained index.html).

What counts as an error, all from the page's own session:
- console.error() / console.assert() calls, and the browser's own error entries that Playwright reports as
  console errors: failed resource loads ("Failed to load resource: net::ERR_..."), blocked requests, CSP
  violations;
- uncaught exceptions and unhandled promise rejections (Playwright's "pageerror");
- requests that failed at the network layer ("requestfailed"), unless Chromium itself cancelled them
  (net::ERR_ABORTED: an aborted prefetch or a request dropped by navigation, not a missing resource);
- any request that leaves the machine (a scheme other than file:, data:, blob:, about:): the report is
  self-contained, and outline/report/allure_html.py strips Allure's analytics tag so that it does not call out;
- error text the report renders in the page instead of logging it ("Failed to fetch <data file>: data not
  found", Allure's message for a data file missing from the report).
Warnings, console.log/info and Chromium's process noise on stderr (D-Bus, VA-API, sandbox notices of a
container without a session bus or GPU) are not errors.
"""
from __future__ import annotations

import os
import re
import shutil
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

CHROMIUM = "/usr/bin/chromium"
INSTALL_HINT = ("`make test` installs it (Debian package `chromium`: "
                "apt-get install -y --no-install-recommends chromium)")
# Headless as root in a container with a closed network: no sandbox (refused as root), no GPU, no QUIC,
# and none of the background calls home (component updates, sync, first-run pages).
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
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


# A report opened from disk loads nothing from elsewhere (and must not call out, see outline/report/allure_html.py).
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


def _shown_errors(text: str) -> list[str]:
    """Errors the report renders as text instead of logging them (a data file it cannot load)."""
    return [f"shown in page: {line.strip()}" for line in text.splitlines() if _SHOWN_ERROR.search(line)]


def _listen(page, errors: list[str]) -> None:
    """Every error of the page's own session, one line each, in the order they happen (see module doc)."""
    def console(msg) -> None:
        if msg.type in ("error", "assert"):
            where = msg.location or {}
            at = f" ({where.get('url', '')[-80:]}:{where.get('lineNumber', '?')})" if where.get("url") else ""
            errors.append(f"console.{msg.type}: {msg.text}{at}")

    def request(req) -> None:
        if req.url.split(":", 1)[0] not in _LOCAL_SCHEMES:
            errors.append(f"external request: {req.url[:160]}")

    def failed(req) -> None:
        failure = req.failure or "?"
        if "ERR_ABORTED" not in failure and not any(req.url[-120:] in line for line in errors):
            errors.append(f"failed load: {failure} {req.url[-120:]}")

    page.on("console", console)
    page.on("pageerror", lambda exc: errors.append(
        f"uncaught exception: {exc.name}: {(exc.message or '').splitlines()[0] if exc.message else exc}"))
    page.on("request", request)
    page.on("requestfailed", failed)


def load(target: str | Path, *, chromium: str = CHROMIUM, timeout: float = 30.0, settle: float = 0.5) -> PageLoad:
    """Open `target` (a file path or URL) and wait until the report shows its total, or a test result page its
    description (or `timeout` passes)."""
    from playwright.sync_api import Error as PlaywrightError, sync_playwright

    url = target if isinstance(target, str) and "://" in target else Path(target).resolve().as_uri()
    exe = shutil.which(chromium) if os.sep not in chromium else chromium
    if not exe or not os.access(exe, os.X_OK):
        raise BrowserError(f"{chromium} not found: {INSTALL_HINT}")
    started = time.monotonic()
    page = PageLoad(url=url)
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=exe, headless=True, args=FLAGS,
                                                 timeout=timeout * 1000)
            try:
                tab = browser.new_page(viewport={"width": 1280, "height": 900})
                _listen(tab, page.errors)
                try:
                    tab.goto(url, wait_until="load", timeout=timeout * 1000)
                except PlaywrightError as exc:
                    page.errors.append(f"navigation failed: {str(exc).splitlines()[0]}")
                deadline = time.monotonic() + timeout
                while True:
                    state = tab.evaluate(_STATE_JS)
                    shown = state.get("total") is not None or state.get("description") is not None
                    if (shown and not state.get("loaderShown")) or _shown_errors(state.get("text", "")) \
                            or time.monotonic() > deadline:
                        break
                    tab.wait_for_timeout(200)
                tab.wait_for_timeout(settle * 1000)   # what goes wrong right after the first render
                state = tab.evaluate(_STATE_JS)
            finally:
                browser.close()
    except PlaywrightError as exc:
        raise BrowserError(f"chromium via playwright: {exc}") from None
    page.title = state.get("title", "")
    page.report_title = state.get("reportTitle")
    page.app_children = state.get("appChildren", -1)
    page.loader_shown = bool(state.get("loaderShown"))
    total = state.get("total")
    page.total = int(total) if total and total.isdigit() else None
    page.sections = state.get("sections") or {}
    page.text = state.get("text", "")
    page.description = state.get("description")
    page.errors += _shown_errors(page.text)
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
