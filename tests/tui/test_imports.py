"""Textual stays in the UI: the numerics, ground motions and project file never import it."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from tests.test_layering import PACKAGE, imported_modules

CORE = PACKAGE / "tui" / "core"
CORE_MODULES = sorted(f"frp_assess.tui.core.{p.stem}" for p in CORE.glob("*.py"))

#: One fresh interpreter answers the three run-time checks, in this order, each looking at
#: what the imports so far have loaded (so each is what it would be alone: the TUI's core
#: first, with nothing else loaded; then the numerics, on top of a core shown free of
#: Textual; then the CLI's parser, on top of both).  One start-up instead of three.
CHECKS = f"""
import importlib, json, sys

def loaded(*prefixes):
    return sorted(m for m in sys.modules if m.split('.')[0] == 'textual'
                  or any(m.startswith(p) for p in prefixes))

out = {{}}
for name in {CORE_MODULES!r}:
    importlib.import_module(name)
out['tui_core'] = loaded('frp_assess.cli')
import frp_assess.config, frp_assess.dynamics, frp_assess.motions
import frp_assess.api, frp_assess.assess.from_project
out['core_packages'] = loaded()
from frp_assess.cli import build_parser
build_parser()
out['cli_parser'] = loaded()
print(json.dumps(out))
"""


@pytest.fixture(scope="module")
def runtime_imports() -> dict[str, list[str]]:
    """What each step of :data:`CHECKS` found loaded that should not be (Textual, and for
    the TUI's core also the CLI)."""
    done = subprocess.run(
        [sys.executable, "-c", CHECKS], check=True, capture_output=True, text=True
    )
    result = json.loads(done.stdout)
    assert isinstance(result, dict)
    return result


def test_core_packages_never_import_textual_at_runtime(runtime_imports):
    """frp_assess.config, dynamics, motions, api and assess.from_project load no Textual."""
    assert runtime_imports["core_packages"] == []


def test_cli_imports_textual_only_for_the_tui_command(runtime_imports):
    """Building the CLI's parser (every command but running `tui`) loads no Textual."""
    assert runtime_imports["cli_parser"] == []


def test_core_sources_do_not_name_textual():
    for sub in ("dynamics", "motions", "config"):
        for path in sorted((PACKAGE / sub).glob("*.py")):
            bad = {m for m in imported_modules(path) if m.split(".")[0] == "textual"}
            bad |= {m for m in imported_modules(path) if m.startswith("frp_assess.tui")}
            assert not bad, f"{sub}/{path.name} imports {sorted(bad)}"


def test_the_tui_core_never_imports_textual_at_runtime(runtime_imports):
    """The headless part of the TUI (session, model, progress...) runs without Textual."""
    assert {"frp_assess.tui.core.session", "frp_assess.tui.core.editor_state"} <= set(CORE_MODULES)
    assert runtime_imports["tui_core"] == []


def test_the_tui_core_names_only_itself_and_the_layers_below():
    for path in sorted(CORE.glob("*.py")):
        names = imported_modules(path)
        bad = {m for m in names if m.split(".")[0] in ("textual", "rich")}
        bad |= {m for m in names if m.startswith("frp_assess.tui") and ".core" not in m}
        bad |= {m for m in names if m.startswith("frp_assess.cli")}
        assert not bad, f"tui/core/{path.name} imports {sorted(bad)}"


def test_the_tui_does_not_import_the_command_line_interface():
    for path in sorted((PACKAGE / "tui").rglob("*.py")):
        bad = {m for m in imported_modules(path) if m.startswith("frp_assess.cli")}
        assert not bad, f"{path.relative_to(PACKAGE)} imports {sorted(bad)}"
