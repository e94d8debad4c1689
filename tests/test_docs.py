"""The README and the guides in docs/ name only what exists: every repository path in backticks or a link, every
`python -m` module and every `make` target; and every make target is documented somewhere."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
TOP = ("features/", "steps/", "sut/", "outline/", "tests/", "bench/", "docs/", ".ci/")
GENERATED = ("reports/", "mutants/", ".venv", "node_modules")      # made by a run, not kept in the repository
_TICKED = re.compile(r"`([^`\n]+)`")
_LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")
_MODULE = re.compile(r"python -m ([\w.]+)")
_MAKE = re.compile(r"\bmake ([a-z][\w-]*)")


def _code(text: str) -> str:
    """The code a page shows: fenced blocks and `spans` (prose such as "make one" is not a command)."""
    fenced = re.findall(r"(?ms)^```[^\n]*\n(.*?)^```", text)
    return "\n".join([*fenced, *_TICKED.findall(re.sub(r"(?ms)^```.*?^```", "", text))])


def _targets() -> set[str]:
    text = (ROOT / "Makefile").read_text(encoding="utf-8")
    return set(re.findall(r"(?m)^([a-z][\w-]*):", text))


def _paths(text: str) -> set[str]:
    found = set()
    for token in _TICKED.findall(text):
        for word in token.split():
            word = word.strip("(),;:'\"").split("::")[0]
            word = re.sub(r"@.*$", "", word)        # steps/x.py@<digest>
            if word.startswith(TOP) and not re.search(r"[<>{}*$|\[\]]", word) and ":" not in word:
                found.add(word)
    return found


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_path_a_page_names_exists(page: Path) -> None:
    text = page.read_text(encoding="utf-8")
    missing = sorted(p for p in _paths(text) if not (ROOT / p).exists())
    for link in _LINK.findall(text):
        if link.startswith(("http:", "https:", "mailto:")) or link.startswith(GENERATED):
            continue
        target = (page.parent / link).resolve()
        if not target.exists() and not str(target.relative_to(ROOT) if ROOT in target.parents else target) \
                .startswith(GENERATED):
            missing.append(link)
    assert not missing, f"{page.relative_to(ROOT)} names what does not exist: {missing}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_command_a_page_names_exists(page: Path) -> None:
    text = _code(page.read_text(encoding="utf-8"))
    modules = sorted({m.rstrip(".") for m in _MODULE.findall(text)})
    unknown = [m for m in modules if importlib.util.find_spec(m) is None]
    targets = _targets()
    unknown += [f"make {t}" for t in sorted(set(_MAKE.findall(text))) if t not in targets]
    assert not unknown, f"{page.relative_to(ROOT)} names commands that do not exist: {unknown}"


def test_every_make_target_is_documented() -> None:
    said = " ".join(_code(page.read_text(encoding="utf-8")) for page in PAGES)
    undocumented = sorted(t for t in _targets() if t != "help" and not re.search(rf"\bmake {re.escape(t)}\b", said))
    assert not undocumented, f"make targets no page describes: {undocumented}"



def test_the_readme_is_a_front_door() -> None:
    # The README says what the suite is and where each guide is; the stories themselves live in docs/ (issue 32).
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 220, f"README.md has {len(lines)} lines: move the story into a guide in docs/"
    linked = set(_LINK.findall("\n".join(lines)))
    guides = {f"docs/{p.name}" for p in (ROOT / "docs").glob("*.md")}
    assert not guides - linked, f"guides the README does not point to: {sorted(guides - linked)}"


@pytest.mark.parametrize("page", sorted((ROOT / "docs").glob("*.md")), ids=lambda p: p.name)
def test_every_guide_opens_with_a_title(page: Path) -> None:
    first = page.read_text(encoding="utf-8").lstrip().splitlines()[0]
    assert first.startswith("# ") or first.startswith("<!--"), f"{page.name} opens with {first!r}, not a title"
