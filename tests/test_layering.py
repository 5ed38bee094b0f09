"""The numerical core never imports UI, YAML or schema libraries (ARCHITECTURE.md).

Checked on the source (import statements), not on ``sys.modules``: numba itself imports PyYAML.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import frp_assess

FORBIDDEN = {
    "textual",
    "rich",
    "yaml",
    "pydantic",
    "reportlab",
    "frp_assess.config",
    "frp_assess.cli",
    "frp_assess.report",
    "frp_assess.tui",
}
PACKAGE = Path(frp_assess.__file__).parent


def imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
    return names


@pytest.mark.parametrize("subpackage", ["dynamics", "motions"])
def test_core_imports_no_ui_or_io_libraries(subpackage):
    files = sorted((PACKAGE / subpackage).glob("*.py"))
    assert files
    for path in files:
        bad = {
            m
            for m in imported_modules(path)
            if any(m == f or m.startswith(f + ".") for f in FORBIDDEN)
        }
        assert not bad, f"{path.name} imports {sorted(bad)}"
