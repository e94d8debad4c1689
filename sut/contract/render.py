"""docs/implementing-a-sut.md from the catalogue and the declaration form (`python -m sut.contract render`)."""
from __future__ import annotations

from pathlib import Path

import jinja2

from sut.contract.catalogue import HERE, TRACE_CHECK_PER_KIND, load
from sut.contract.declaration import form

GUIDE = HERE.parents[1] / "docs" / "implementing-a-sut.md"
PROFILE_ORDER = ("crh2", "metro-tcn", "atp", "atp-crh2", "vdx")


def _oneline(text: object) -> str:
    return " ".join(str(text or "").split()).replace("|", "\\|")


def _words(values: object) -> str:
    return ", ".join(f"`{v}`" for v in values) if isinstance(values, list) else ""


def _range(value: object) -> str:
    return f"{value[0]} .. {value[1]}" if isinstance(value, list) and len(value) == 2 else (str(value) if value else "")


def render() -> str:
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(HERE)), trim_blocks=True, lstrip_blocks=True,
                             keep_trailing_newline=True, undefined=jinja2.StrictUndefined)
    env.filters.update(oneline=_oneline, words=_words, range_of=_range)
    profiles = [p for p in PROFILE_ORDER if (HERE / f"{p}.yaml").exists()]
    profiles += sorted(p.stem for p in HERE.glob("*.yaml") if p.stem not in profiles and p.stem != "form")
    text = env.get_template("guide.md.j2").render(form=form(), contracts=[load(p) for p in profiles],
                                                       per_kind=TRACE_CHECK_PER_KIND)
    while "\n\n\n" in text:
        text = text.replace("\n\n\n", "\n\n")
    return text


def write(path: Path = GUIDE) -> Path:
    path.write_text(render(), encoding="utf-8")
    return path
