"""A project full of markup runs to the end; every output shows the text as typed: the
terminal (rich markup literal) and the PDF (no image, no link, no markup).  Raw control
characters (terminal escape sequences) are refused by the project schema with key and line
(tests/test_bad_inputs.py); results.json edited by hand can still carry them to the PDF, which
shows a placeholder (tests/report/test_escaping.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.report import build_story
from frp_assess.results.json_io import from_json
from tests.report.test_report import story_text

HOSTILE = r"""
project:
  name: "Hostile <b>wall [/x]"
  engineer: "[red]red[/red] <font color=red>"
  location: "<a href=\"x\">here</a>"
  notes: "[bold]notes[/bold] <img src=\"/etc/passwd\"/>"
wall: {thickness: 0.3, height: 3.0, length: 5.0, unit_weight: 18.0, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 2, seed: 7, duration: 15.0, dt: 0.01}
materials:
  "CFRP-HM <i>": {elastic_modulus: 200, ultimate_strain: 0.01, density: 1600, price: 40}
interventions:
  - {name: "[/x] opt <b>", material: GFRP, position: external, ratio: 1.0}
  - {material: "CFRP-HM <i>", position: external, ratio: 2.0}
costs: {currency: "<b>EUR [/x]", installation_per_metre: 100.0}
"""


def test_hostile_project_runs_and_shows_text_as_typed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    project = tmp_path / "hostile.yaml"
    project.write_text(HOSTILE, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(project), "--out", str(out), "--jobs", "2"]) == 0
    cap = capsys.readouterr()
    assert "\x1b" not in cap.out + cap.err
    assert "[/x] opt <b>" in cap.out and "<b>EUR [/x]" in cap.out
    pdf = (out / "report.pdf").read_bytes()
    assert b"/XObject" not in pdf and b"/URI" not in pdf and b"/Annot" not in pdf
    results = from_json((out / "results.json").read_text(encoding="utf-8"))
    text = story_text(build_story(results))
    for typed in ("Hostile <b>wall [/x]", '<a href="x">here</a>', "[/x] opt <b>", "<b>EUR [/x]"):
        assert typed in text
    assert "[red]red[/red] <font color=red>" in text and "\x1b" not in text
