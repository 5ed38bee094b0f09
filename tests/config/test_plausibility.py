"""Legal but implausible values (issue 25, class 6): a warning, not an error — printed once by
``validate`` and ``run``, stored in results.json's ``input_warnings``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from frp_assess.cli import main
from frp_assess.config import load_project_text
from frp_assess.config.plausibility import RATIO, WALL_HEIGHT, project_warnings

BASE = """\
project: {name: Plausible}
wall: {thickness: 0.3, height: 3.0, masonry: rubble-stone, mechanism: one-sided}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}
interventions:
  - {material: GFRP, position: centred, ratio: 1}
"""
#: the issue's example: a wall 32 m high, bars at 0.0015 ‰
IMPLAUSIBLE = BASE.replace("height: 3.0", "height: 32.0").replace("ratio: 1}", "ratio: 0.0015}")
#: the bars of 0.0015 ‰ on a wall 0.3 m x 1 m: one Ø6 bar (π·6²/4 = 28.27 mm²), the fewest
#: whole bars, 28.27/(300·1000) = 0.0942 ‰ (62.8 times the ratio asked)
AS_BUILT_0_0015 = (
    "GFRP centred 0.0015‰: 0.0015 ‰ is built as 1 bar Ø6 per line at 1 m, 0.0942 ‰ (62.8 "
    "times the ratio asked, more than 25% off; governed by the area of whole bars); the model "
    "uses it: check the ratio, the diameter and bars.max_spacing"
)


def _texts(text: str) -> list[str]:
    return [w.text() for w in project_warnings(load_project_text(text, "p.yaml").project)]


def test_a_project_of_practice_has_no_warning() -> None:
    assert _texts(BASE) == []


def test_the_issues_example_gives_one_warning_per_value() -> None:
    texts = _texts(IMPLAUSIBLE)
    assert len(texts) == 2
    assert texts[0].startswith("wall.height: 32 m is above the range of practice 1-15 m")
    assert texts[1].startswith(
        "interventions[0].ratio: 0.0015 ‰ is below the range of practice 0.1-10 ‰"
    )


@pytest.mark.parametrize(
    ("old", "new", "key"),
    [
        ("thickness: 0.3", "thickness: 2.0", "wall.thickness"),
        ("masonry: rubble-stone", "unit_weight: 29", "wall.unit_weight"),
        ("{type: preset, name: A2}", "{type: ec8, ag: 1.2, ground: B}", "seismic.spectrum.ag"),
        ("  records:", "  t1: 8\n  records:", "seismic.t1"),
        ("ratio: 1}", "ratio: 15}", "interventions[0].ratio"),
    ],
)
def test_each_checked_key_warns_outside_its_range(old: str, new: str, key: str) -> None:
    assert old in BASE
    texts = _texts(BASE.replace(old, new, 1))
    assert [t.split(":")[0] for t in texts] == [key]


def test_the_bounds_themselves_are_of_practice() -> None:
    text = BASE.replace("height: 3.0", f"height: {WALL_HEIGHT.high}").replace(
        "ratio: 1}", f"ratio: {RATIO.low}}}"
    )
    assert _texts(text) == []


def test_validate_prints_each_warning_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(IMPLAUSIBLE, encoding="utf-8")
    assert main(["validate", str(path)]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [
        f"frp-assess: warning: {path}:2: wall.height: 32 m is above the range of practice "
        "1-15 m (a wall panel between restraints is 1-15 m high); check the value and its units",
        f"frp-assess: warning: {path}:8: interventions[0].ratio: 0.0015 ‰ is below the range "
        "of practice 0.1-10 ‰ (vertical FRP bars are designed at 0.5-5 ‰); check the value and "
        "its units",
        # the bars as built (assess/bars_as_built.py): the fewest Ø6 bars at bars.max_spacing
        f"frp-assess: warning: {path}:8: interventions[0].ratio: {AS_BUILT_0_0015}",
    ]


def test_run_prints_them_once_and_stores_them(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(IMPLAUSIBLE, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out), "--no-pdf"]) in (0, 1)
    err = capsys.readouterr().err
    assert err.count("wall.height: 32 m is above") == 1
    assert err.count("interventions[0].ratio: 0.0015 ‰ is below") == 1
    stored = json.loads((out / "results.json").read_text(encoding="utf-8"))["input_warnings"]
    assert stored == [*_texts(IMPLAUSIBLE), f"interventions[0].ratio: {AS_BUILT_0_0015}"]
