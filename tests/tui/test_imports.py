"""Textual stays in the UI: the numerics, ground motions and project file never import it."""

from __future__ import annotations

import subprocess
import sys

from tests.test_layering import PACKAGE, imported_modules


def test_core_packages_never_import_textual_at_runtime():
    code = (
        "import sys\n"
        "import frp_assess.config, frp_assess.dynamics, frp_assess.motions\n"
        "import frp_assess.api, frp_assess.assess.from_project\n"
        "bad = sorted(m for m in sys.modules if m == 'textual' or m.startswith('textual.'))\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_cli_imports_textual_only_for_the_tui_command():
    code = (
        "import sys\n"
        "from frp_assess.cli import build_parser\n"
        "build_parser()\n"
        "assert 'textual' not in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_core_sources_do_not_name_textual():
    for sub in ("dynamics", "motions", "config"):
        for path in sorted((PACKAGE / sub).glob("*.py")):
            bad = {m for m in imported_modules(path) if m.split(".")[0] == "textual"}
            bad |= {m for m in imported_modules(path) if m.startswith("frp_assess.tui")}
            assert not bad, f"{sub}/{path.name} imports {sorted(bad)}"


CORE = PACKAGE / "tui" / "core"


def test_the_tui_core_never_imports_textual_at_runtime():
    """The headless part of the TUI (session, model, progress...) runs without Textual."""
    modules = sorted(f"frp_assess.tui.core.{p.stem}" for p in CORE.glob("*.py"))
    assert {"frp_assess.tui.core.session", "frp_assess.tui.core.editor_state"} <= set(modules)
    code = (
        "import importlib, sys\n"
        f"for name in {modules!r}:\n"
        "    importlib.import_module(name)\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[0] == 'textual')\n"
        "bad += sorted(m for m in sys.modules if m.startswith('frp_assess.cli'))\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


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
