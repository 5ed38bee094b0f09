"""The TUI uses Textual's public API only: no widget overrides or calls a private Textual
method, and no module reads another object's private attribute (these change between
Textual releases without notice; an override of one caused a tab to switch back)."""

from __future__ import annotations

import ast
import importlib
import inspect
import re
import textwrap
import tomllib
from importlib.metadata import version
from pathlib import Path

from textual.widgets import TabbedContent

import frp_assess.tui

TUI = Path(frp_assess.tui.__file__).parent


def tui_modules() -> list[Path]:
    return sorted(TUI.rglob("*.py"))


def is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def test_no_private_attribute_of_another_object_is_read():
    found = []
    for path in tui_modules():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, ast.Attribute) or not is_private(node.attr):
                continue
            if isinstance(node.value, ast.Name) and node.value.id in ("self", "cls"):
                continue  # the object's own (checked against Textual's names below)
            found.append(f"{path.relative_to(TUI)}:{node.lineno}: {ast.unparse(node)}")
    assert found == []


def private_textual_names(cls: type) -> list[str]:
    """The private names of Textual's base classes that ``cls`` defines or uses on self."""
    textual_bases = [b for b in cls.__mro__[1:] if b.__module__.startswith("textual.")]
    if not textual_bases:
        return []
    theirs: set[str] = set().union(*(vars(b) for b in textual_bases))
    tree = ast.parse(textwrap.dedent(inspect.getsource(cls)))
    ours = {
        n.name
        for n in ast.walk(tree)
        if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef) and is_private(n.name)
    }
    ours |= {
        n.attr
        for n in ast.walk(tree)
        if isinstance(n, ast.Attribute)
        and isinstance(n.value, ast.Name)
        and n.value.id == "self"
        and is_private(n.attr)
    }
    return sorted(ours & theirs)


def test_no_widget_defines_or_calls_a_private_textual_name():
    found = []
    for path in tui_modules():
        name = ".".join(path.relative_to(TUI.parent.parent).with_suffix("").parts)
        module = importlib.import_module(name)
        for cls in vars(module).values():
            if inspect.isclass(cls) and cls.__module__ == module.__name__:
                found += [f"{name}.{cls.__name__}.{a}" for a in private_textual_names(cls)]
    assert found == []


class Overriding(TabbedContent):
    def _on_tab_pane_focused(self, event: object) -> None:
        self._own_state = 1


def test_the_check_finds_an_override():
    assert private_textual_names(Overriding) == ["_on_tab_pane_focused"]


def test_textual_is_pinned_to_the_major_version_tested():
    """pyproject.toml allows one major version of Textual, the one installed here (Textual
    changes its API between major versions)."""
    pyproject = Path(__file__).resolve().parents[2] / "pyproject.toml"
    deps = tomllib.loads(pyproject.read_text(encoding="utf-8"))["project"]["dependencies"]
    spec = next(d for d in deps if re.match(r"textual\b", d))
    m = re.fullmatch(r"textual>=(\d+)\.(\d+),<(\d+)", spec.replace(" ", ""))
    assert m is not None, spec
    low, high = (int(m[1]), int(m[2])), int(m[3])
    assert high == low[0] + 1
    installed = tuple(int(x) for x in version("textual").split(".")[:2])
    assert low <= installed and installed[0] < high
