"""What the package and its documents cite must be in the hands of a user: the repository's
own model description (docs/model.md), never the team's specification (MODEL.md) nor
anything outside the repository (../shared)."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = sorted(
    p
    for folder in ("frp_assess", "docs", "projects")
    for p in (ROOT / folder).rglob("*")
    if p.suffix in {".py", ".json", ".yaml", ".md", ".tcss"}
) + [ROOT / "README.md"]


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_citation_a_user_cannot_open(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    for banned in ("MODEL.md", "../shared", "shared/reference"):
        assert banned not in text, f"{path.relative_to(ROOT)} cites {banned}"
