"""The habit of rules/ (docs/architecture.md, "Where each rule lives"): every public function
is small, its docstring cites its source (a clause, an equation, a table, or docs/model.md)
and states units in brackets; every public constant has a comment (that the package needs
only the standard library is checked with the results' contract, tests/results)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

import frp_assess.rules

RULES = Path(frp_assess.rules.__file__).parent
SOURCE = re.compile(r"§|[Ee]qs?\.|Tab\.|Table|docs/model\.md|paper|Housner|ISO|EN 1998")
#: the longest rule [lines], docstring included: one clause, one small function
MAX_RULE_LINES = 30
MODULES = sorted(RULES.glob("*.py"))
FUNCTIONS = [
    (path.name, node)
    for path in MODULES
    for node in ast.parse(path.read_text(encoding="utf-8")).body
    if isinstance(node, ast.FunctionDef) and not node.name.startswith("_")
]


@pytest.mark.parametrize("module,node", FUNCTIONS, ids=[f"{m}:{n.name}" for m, n in FUNCTIONS])
def test_each_rule_cites_its_source_and_units(module: str, node: ast.FunctionDef) -> None:
    doc = ast.get_docstring(node) or ""
    assert SOURCE.search(doc), f"{module}:{node.name}: no clause or source in the docstring"
    assert "[" in doc, f"{module}:{node.name}: no unit in brackets in the docstring"
    lines = (node.end_lineno or node.lineno) - node.lineno + 1
    assert lines <= MAX_RULE_LINES, f"{module}:{node.name} has {lines} lines"


def test_each_public_constant_says_what_it_is() -> None:
    """A module-level constant of rules/ has a ``#:`` comment above it (its clause, unit)."""
    for path in MODULES:
        lines = path.read_text(encoding="utf-8").splitlines()
        for node in ast.parse("\n".join(lines)).body:
            target = node.targets[0] if isinstance(node, ast.Assign) else None
            if isinstance(node, ast.AnnAssign):
                target = node.target
            if isinstance(target, ast.Name) and target.id.isupper():
                # the comment above it, or above the group of constants it closes
                row = node.lineno - 2
                while row > 0 and re.match(r"[A-Z_0-9]+ = ", lines[row]):
                    row -= 1
                commented = lines[row].strip().startswith("#") or "#" in lines[node.lineno - 1]
                assert commented, (path.name, target.id)
