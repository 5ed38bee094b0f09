"""Import rules as one table: what each package of frp_assess may import (docs/architecture.md).

Checked on the source (import statements of every module, sub-packages included), not on
``sys.modules``: numba itself imports PyYAML.  Dependencies point one way: the numerical core
(``dynamics``, ``motions``) knows nothing of files, schemas or screens; ``config`` turns
files into checked values; ``assess`` runs them; ``api`` is the application; ``cli``, ``tui``
and ``report`` are thin layers over it.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import frp_assess

PACKAGE = Path(frp_assess.__file__).parent

#: package -> the frp_assess packages it may import ("" is frp_assess itself, for __version__)
INTERNAL: dict[str, set[str]] = {
    "errors": set(),
    "rules": set(),  # pure engineering formulas: nothing of frp_assess below them
    "results": {"errors"},  # the typed results (stdlib dataclasses): no numerics, no files
    "numbers": {"results"},
    "text_safety": set(),
    "io_utils": {"errors"},
    "output_set": {"errors", "io_utils"},
    "dynamics": {"errors", "motions", "rules"},
    "motions": {"errors", "io_utils"},
    "config": {"errors", "io_utils", "rules", "dynamics", "motions"},
    "assess": {
        "", "errors", "io_utils", "numbers", "text_safety", "rules", "dynamics", "motions",
        "config", "results",
    },  # fmt: skip
    "report": {"errors", "io_utils", "numbers", "text_safety", "results"},
    "study": {
        "", "errors", "io_utils", "dynamics", "motions", "config", "assess", "report", "results",
    },  # fmt: skip
    "app": {
        "", "errors", "io_utils", "output_set", "text_safety", "dynamics", "motions", "config",
        "assess", "report", "study", "results",
    },  # fmt: skip
    "api": {"app"},  # the former application API: a re-export of app, kept for old imports
    "tui": {
        "", "errors", "io_utils", "numbers", "text_safety", "dynamics", "motions", "config",
        "assess", "api", "app", "results",
    },  # fmt: skip
    "cli": {
        "", "errors", "io_utils", "numbers", "text_safety", "output_set", "dynamics", "motions",
        "config", "assess", "report", "study", "api", "app", "tui", "results",
    },  # fmt: skip
    "__main__": {"cli"},
    "__init__": set(),
}
#: (report reads nothing but results.json: tests/report/test_report.py checks it further)
#: third-party libraries that only some packages may use
RESTRICTED = {
    "textual": {"tui"},
    "rich": {"cli", "tui", "text_safety"},
    "reportlab": {"report", "study"},
    "pydantic": {"config", "study", "tui"},
    "pydantic_core": {"config", "tui"},
    "yaml": {"config", "study"},
    "ruamel": {"config"},
    "dask": {"study"},
}


def imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
    return names


def package_of(path: Path) -> str:
    parts = path.relative_to(PACKAGE).parts
    return parts[0].removesuffix(".py")


MODULES = sorted(PACKAGE.rglob("*.py"))


def test_every_package_has_a_rule() -> None:
    assert {package_of(p) for p in MODULES} <= set(INTERNAL)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_follow_the_table(path: Path) -> None:
    own = package_of(path)
    bad = []
    for name in imported_modules(path):
        parts = name.split(".")
        if parts[0] == "frp_assess":
            target = parts[1] if len(parts) > 1 else ""
            if target != own and target not in INTERNAL[own]:
                bad.append(name)
        elif parts[0] in RESTRICTED and own not in RESTRICTED[parts[0]]:
            bad.append(name)
    assert not bad, f"{own} may not import {sorted(bad)}"
