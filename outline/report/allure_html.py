"""Post-process the generated Allure 3 report: `python -m outline.report.allure_html reports/html/index.html`.

Allure 3.18's awesome report always embeds a Google Analytics tag (no option turns it off; only the allure2
plugin honours ALLURE_NO_ANALYTICS). A conformance report is opened from disk, often offline, and should not
call out when it is; drop the tag. A later Allure whose markup differs is left untouched.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

_GTAG = re.compile(
    r"\s*<script async src=\"https://www\.googletagmanager\.com/gtag/js\?id=[^\"]*\"></script>"
    r"\s*<script>\s*window\.dataLayer.*?</script>",
    re.DOTALL,
)


def strip_analytics(index_html: str | Path) -> bool:
    """Remove the analytics tag in place; True if one was removed."""
    path = Path(index_html)
    text = path.read_text(encoding="utf-8")
    stripped, count = _GTAG.subn("", text, count=1)
    if count:
        path.write_text(stripped, encoding="utf-8")
    return bool(count)


if __name__ == "__main__":
    for arg in sys.argv[1:] or ["reports/html/index.html"]:
        strip_analytics(arg)
