"""Where a tree keeps its outline files, so every tool can be pointed at a fixture tree in tests."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Tree:
    root: Path
    features: Path
    registry: Path
    requirements: Path

    @classmethod
    def at(cls, root: str | Path, features: str | Path = "features") -> Tree:
        root = Path(root).resolve()
        feats = (root / features).resolve()
        return cls(root, feats, feats / "registry.yaml", root / "docs" / "requirements.md")

    def rel(self, path: str | Path) -> str:
        """Path as written in messages and in the registry: relative to the tree root, POSIX separators."""
        path = Path(path).resolve()
        try:
            return path.relative_to(self.root).as_posix()
        except ValueError:
            return path.as_posix()


REPO = Tree.at(Path(__file__).resolve().parents[2])
