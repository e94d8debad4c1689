"""One-way layers (issue 14, issue 32): no module of the project (sut/, steps/, outline/, bench/, tests/)
imports another that imports it back, relative, function-level and type-only imports (under TYPE_CHECKING)
included; a CRH2 part never imports the train that assembles it."""
from __future__ import annotations

import ast
from pathlib import Path

from tests.helpers import REPO

SUT = REPO / "sut"


def _module_name(path: Path) -> str:
    rel = path.relative_to(REPO).with_suffix("")
    parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
    return ".".join(parts)


PACKAGES = ("sut", "steps", "outline", "bench", "tests")


def _imports(packages: tuple[str, ...] = ("sut",)) -> dict[str, set[str]]:
    modules = {_module_name(p): p for package in packages for p in (REPO / package).rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        deps: set[str] = set()
        here = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:                # from .x import y, from .. import z
                    base = ".".join(here[:len(here) - node.level + 1] + ([node.module] if node.module else []))
                targets = [f"{base}.{alias.name}" for alias in node.names] + [base]
                deps.update(t for t in targets if t in modules)
            elif isinstance(node, ast.Import):
                deps.update(alias.name for alias in node.names if alias.name in modules)
        # a package's __init__ is imported on the way to any of its modules: not a dependency of interest
        graph[name] = {d for d in deps if d != name and not name.startswith(d + ".")}
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_module_of_the_sut_imports_itself_through_others() -> None:
    graph = _imports()
    assert len(graph) > 30
    assert _cycles(graph) == []


def test_no_module_of_the_project_imports_itself_through_others() -> None:
    graph = _imports(PACKAGES)
    assert len(graph) > 150 and "outline.tracing.render" in graph and "outline.tracing.trace" in graph["outline.tracing.render"]
    assert _cycles(graph) == []


def test_the_crh2_parts_know_the_train_only_as_its_context() -> None:
    graph = _imports()
    importers = sorted(name for name, deps in graph.items() if "sut.reference.crh2.train" in deps)
    assert importers == ["sut.reference.crh2.backend"]


def test_three_trains_at_a_glance() -> None:
    packages = sorted(p.name for p in (SUT / "reference").iterdir() if (p / "__init__.py").exists())
    assert packages == ["atp", "crh2", "metro"]


# Who may import whom (docs/architecture.md): the steps reach a SUT only through the driver interface and the
# contract, never the reference implementation; the reference and the driver know nothing of the suite.
FORBIDDEN = {
    "steps": ("sut.reference", "tests", "bench"),
    "sut": ("steps", "outline", "tests", "bench"),
}


def test_each_layer_imports_only_what_it_may() -> None:
    graph = _imports(PACKAGES)
    wrong = [f"{module} imports {dep}" for module, deps in sorted(graph.items()) for dep in sorted(deps)
             for layer, banned in FORBIDDEN.items() if module.split(".")[0] == layer
             and any(dep == b or dep.startswith(b + ".") for b in banned)]
    assert wrong == []


def test_outline_is_split_by_concern() -> None:
    # issue 32: outline/ holds its command line and one subpackage per concern, each saying what it owns.
    top = REPO / "outline"
    modules = sorted(p.name for p in top.glob("*.py"))
    assert modules == ["__init__.py", "__main__.py"], f"outline/ modules outside a subpackage: {modules}"
    for package in sorted(p for p in top.iterdir() if (p / "__init__.py").exists()):
        doc = ast.get_docstring(ast.parse((package / "__init__.py").read_text(encoding="utf-8")))
        assert doc and len(doc.splitlines()) <= 3, f"outline/{package.name}/__init__.py: say what it owns, briefly"
        assert f"   {package.name}/" in (REPO / "docs" / "architecture.md").read_text(encoding="utf-8"), \
            f"docs/architecture.md does not place outline/{package.name}/"
