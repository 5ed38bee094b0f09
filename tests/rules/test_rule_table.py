"""docs/architecture.md, "Where each rule lives": the rule → function table is true.

Each row names a function (or a constant) by its dotted path; it must exist there, and no
other module of the package may define one of that name at its top level (a module that
needs the rule imports it, and may re-export it: an import is not a definition).
"""

from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

import pytest

import frp_assess

PACKAGE = Path(frp_assess.__file__).parent
DOC = PACKAGE.parent / "docs" / "architecture.md"
SECTION = "## Where each rule lives"
ROW = re.compile(r"^\|(?P<rule>[^|]+)\|(?P<clause>[^|]+)\|\s*`(?P<path>frp_assess\.[\w.]+)`\s*\|$")


def table_rows(text: str) -> list[tuple[str, str]]:
    """(rule, dotted path) of every row of the section's tables."""
    section = text.split(SECTION, 1)[1].split("\n## ", 1)[0]
    return [
        (m["rule"].strip(), m["path"])
        for line in section.splitlines()
        if (m := ROW.match(line.strip()))
    ]


ROWS = table_rows(DOC.read_text(encoding="utf-8"))

#: (name, module) defining a row's name for something else, each with why; each must still be
#: there (the entry goes with the clash)
SAME_NAME_ELSEWHERE: dict[tuple[str, str], str] = {}


def module_level_definitions(path: Path) -> set[str]:
    """The names ``path`` defines at its top level: functions, classes, assignments (not
    imports)."""
    names: set[str] = set()
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            names.add(node.name)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


DEFINITIONS = {
    ".".join(["frp_assess", *p.relative_to(PACKAGE).with_suffix("").parts]): (
        module_level_definitions(p)
    )
    for p in sorted(PACKAGE.rglob("*.py"))
}


def test_the_table_is_there() -> None:
    """The section holds the table (a parse that finds nothing would pass every row test)."""
    assert len(ROWS) >= 40
    assert any(path.startswith("frp_assess.rules.record_sets.") for _, path in ROWS)


@pytest.mark.parametrize("rule,path", ROWS, ids=[p for _, p in ROWS])
def test_each_row_names_the_one_definition(rule: str, path: str) -> None:
    module, _, name = path.rpartition(".")
    assert hasattr(importlib.import_module(module), name), f"{rule}: no {path}"
    assert name in DEFINITIONS[module], f"{rule}: {module} imports {name}, not defines it"
    elsewhere = sorted(
        m
        for m, names in DEFINITIONS.items()
        if name in names and m != module and (name, m) not in SAME_NAME_ELSEWHERE
    )
    assert not elsewhere, f"{rule}: {name} is also defined in {elsewhere}"


def test_every_allowed_clash_is_still_there() -> None:
    for name, module in SAME_NAME_ELSEWHERE:
        assert name in DEFINITIONS[module], (name, module)


def test_the_check_bites() -> None:
    """A row whose name is defined twice, or not at all, is found."""
    text = (
        f"{SECTION}\n\n| a | b | `frp_assess.rules.masonry.nothing_here` |\n"
        "| c | d | `frp_assess.rules.geometry.slenderness` |\n## Next\n| e | f | `frp_assess.x` |\n"
    )
    assert table_rows(text) == [
        ("a", "frp_assess.rules.masonry.nothing_here"),
        ("c", "frp_assess.rules.geometry.slenderness"),
    ]
    assert "nothing_here" not in DEFINITIONS["frp_assess.rules.masonry"]
    # two top-level definitions of one name are seen as two
    assert "slenderness" in DEFINITIONS["frp_assess.rules.geometry"]
    assert "slenderness" not in DEFINITIONS["frp_assess.dynamics.wall"]  # imported there
