"""Names from the project file are shown as they are: Rich markup in them is text, and control
characters never reach the terminal (they are shown as visible characters).  A project file
with raw control characters is refused by the schema (tests/test_bad_inputs.py), so the
end-to-end run here carries markup only and control characters are tested on the helpers."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from rich.text import Text
from textual.widgets import Input, TabbedContent

from frp_assess.config import load_project
from frp_assess.tui.app import FrpAssessApp
from frp_assess.tui.core.text import has_controls, printable
from frp_assess.tui.literal import literal, safe
from tests.tui.conftest import after_workers, run_async

SIZE = (120, 36)

#: markup that is not valid (``[/x]`` closes nothing: Rich raises on it) and markup that is
PROJECT = r"""
project: {name: "[bold]Wall[/x] red"}
wall: {thickness: 0.3, height: 3.0, length: 5.0, masonry: solid-brick-lime-mortar,
       mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    files:
      - {path: quake.txt, format: two-column, units: g, name: "rec[bold]"}
materials:
  "Mat[/x]": {elastic_modulus: 40, ultimate_strain: 0.02, density: 2000, price: 5,
              source: "[red]lab"}
interventions:
  - {material: "Mat[/x]", position: centred, ratio: 2.0, name: "opt[bold]"}
costs: {currency: "EU[/x]", installation_per_metre: 100.0}
"""

#: every control character but the line feed (an SVG screenshot has line feeds)
CONTROLS = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f]")


def write_project(tmp_path: Path) -> Path:
    lines = [f"{0.01 * i:.2f} {0.3 * math.sin(2 * math.pi * 0.01 * i):.6f}" for i in range(800)]
    (tmp_path / "quake.txt").write_text("\n".join(lines) + "\n", encoding="utf-8")
    path = tmp_path / "odd names.yaml"
    path.write_text(PROJECT, encoding="utf-8")
    return path


def test_printable_replaces_each_control_character_by_one_visible_one():
    text = "a\x1b[31mb\x07c\td\ne\x7ff\x9bg"
    shown = printable(text)
    assert shown == "a␛[31mb␇c␉d␊e␡f\ufffdg"
    assert len(shown) == len(text) and not CONTROLS.search(shown)
    assert printable(text, newlines=True).count("\n") == 1
    assert has_controls(text) and not has_controls("[bold]x[/x] ‰ €")


def test_literal_and_safe_never_read_markup_and_keep_styles():
    assert literal("[bold]x[/x]").plain == "[bold]x[/x]"
    styled = Text.assemble(("\x1b[2J", "red"), ("ok", "bold"))
    out = safe(styled)
    assert out.plain == "␛[2Jok"
    assert [(s.start, s.end, s.style) for s in out.spans] == [
        (s.start, s.end, s.style) for s in styled.spans
    ]


@pytest.mark.slow
def test_names_with_markup_show_literally(tmp_path: Path):
    path = write_project(tmp_path)
    project = load_project(path).project
    assert project.project.name == "[bold]Wall[/x] red"  # the file is valid
    seen: dict[str, str] = {}

    async def body() -> None:
        app = FrpAssessApp(path)
        async with app.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert app.problems == []
            name = app.query_one("#f-project-name-control", Input)
            assert name.value == "[bold]Wall[/x] red"
            assert not app.modified()  # shown visibly, kept as read
            await pilot.press("ctrl+r")
            await after_workers(pilot, lambda: not app.running and app.outcome is not None)
            tabs = app.query_one("#tabs", TabbedContent)
            results = app.query_one("#results-tabs", TabbedContent)
            for tab in ("wall", "materials", "retrofits", "records", "run", "results"):
                tabs.active = f"tab-{tab}"
                await pilot.pause()
                seen[tab] = app.export_screenshot()
            for sub in ("records", "plot", "design", "compliance"):
                results.active = f"res-{sub}"
                await pilot.pause()
                seen[f"results-{sub}"] = app.export_screenshot()
            tabs.active = "tab-history"
            await after_workers(pilot, lambda: "θ/α" in app.query_one("#hist-theta").render().plain)
            seen["history"] = app.export_screenshot()

    run_async(body)
    for where, svg in seen.items():
        assert not CONTROLS.search(svg), f"a control character reached the screen ({where})"
    shown = {k: svg.replace("&#160;", " ") for k, svg in seen.items()}
    assert "[bold]Wall[/x] red" in shown["wall"]
    assert "Mat[/x]" in shown["materials"]
    assert "opt[bold]" in shown["retrofits"] and "EU[/x]" in shown["retrofits"]
    assert "rec[bold]" in shown["records"]
    assert "opt[bold]" in shown["run"]
    assert "opt[bold]" in shown["results"] and "EU[/x]" in shown["results"]
    assert "rec[bold]" in shown["results-records"]
    assert "Mat[/x]" in shown["results-plot"]
    assert "opt[bold]" in shown["history"]
