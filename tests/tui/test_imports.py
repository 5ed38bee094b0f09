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
