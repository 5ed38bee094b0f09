"""Tie-rods as retrofit options (``interventions: - {type: tie, ...}`` and a bars option with a
``tie:`` block; docs/model.md §12): what the project file accepts, how the options are named
and deduplicated, and the one located line (file:line: key: message, exit 2) it refuses."""

from __future__ import annotations

from pathlib import Path

import pytest

from frp_assess.config.loader import load_project_text
from frp_assess.config.schema import Intervention, Project, TieOption
from tests.config.located import assert_one_located_line, validate_text

BASE = """\
project: {name: Tie options}
wall:
  thickness: 0.4
  height: 6.0
  unit_weight: 18
  mechanism: one-sided
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}
interventions:
  - {type: tie, height: 5.5, diameter: 20, spacing: 3.0, length: 8.0}
  - {material: GFRP, position: centred, ratio: 1}
  - material: GFRP
    position: external
    ratio: 1
    tie: {height: 5.5, area: 314, spacing: 3.0, length: 8.0, anchorage: 40}
costs: {tie_steel_per_kg: 2.5, tie_plate: 60, tie_installation: 300}
"""


def _sub(old: str, new: str) -> str:
    assert old in BASE, old
    return BASE.replace(old, new, 1)


def _project(text: str) -> Project:
    return load_project_text(text, "p.yaml").project


#: (id, project text, expected fragment, line, key)
REFUSED: list[tuple[str, str, str, int, str]] = [
    (
        "tie-option-above-the-wall",
        _sub("{type: tie, height: 5.5,", "{type: tie, height: 6.5,"),
        "expected a tie on the wall, 0 < height <= H = 6 m, found 6.5",
        12,
        "interventions[0].height",
    ),
    (
        "bars-and-tie-above-the-wall",
        _sub("tie: {height: 5.5,", "tie: {height: 7,"),
        "expected a tie on the wall, 0 < height <= H = 6 m, found 7",
        17,
        "interventions[2].tie.height",
    ),
    (
        "tie-option-without-a-size",
        _sub("height: 5.5, diameter: 20, ", "height: 5.5, "),
        "give the tie's 'diameter' [mm] or its 'area' [mm2], exactly one; found neither",
        12,
        "interventions[0]",
    ),
    (
        "unknown-option-type",
        _sub("{type: tie,", "{type: anchor,"),
        "expected one of tie, found 'anchor'",
        12,
        "interventions[0].type",
    ),
    (
        "spacing-out-of-range",
        _sub("diameter: 20, spacing: 3.0", "diameter: 20, spacing: 0.1"),
        "0.2",
        12,
        "interventions[0].spacing",
    ),
    (
        "bars-field-on-a-tie",
        _sub("{type: tie, height: 5.5,", "{type: tie, ratio: 1, height: 5.5,"),
        "ratio",
        12,
        "interventions[0]",
    ),
    (
        "negative-plate-price",
        _sub("tie_plate: 60", "tie_plate: -1"),
        "0",
        18,
        "costs.tie_plate",
    ),
]


@pytest.mark.parametrize(("text", "fragment", "line", "key"), [r[1:] for r in REFUSED],
                         ids=[r[0] for r in REFUSED])  # fmt: skip
def test_refused_with_one_located_line(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    text: str,
    fragment: str,
    line: int,
    key: str,
) -> None:
    code, err = validate_text(tmp_path, text, capsys)
    assert_one_located_line(code, err, line, key, fragment)


def test_tie_options_are_valid_and_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The three kinds validate without a warning (the time histories model the tie,
    docs/model.md §12), each named by default from its bars and tie."""
    code, err = validate_text(tmp_path, BASE, capsys)
    assert code == 0, err
    assert "interventions[" not in err
    options = _project(BASE).expand_interventions()
    assert [o.name for o in options] == [
        "Tie Ø20 @ 3.0 m at 5.5 m",
        "GFRP centred 1‰",
        "GFRP external 1‰ + tie A 314 mm² @ 3.0 m at 5.5 m",
    ]
    assert isinstance(options[0], TieOption)
    assert options[0].yield_strength == 235 and options[0].elastic_modulus == 210
    assert isinstance(options[2], Intervention) and options[2].tie is not None
    assert options[2].tie.anchorage == 40


def test_bars_options_without_type_are_read_as_before() -> None:
    """An option without ``type`` stays FRP bars with no tie (the golden projects' options)."""
    option = _project(BASE).expand_interventions()[1]
    assert isinstance(option, Intervention)
    assert option.tie is None
    assert option.model_dump(exclude_none=True) == {
        "name": "GFRP centred 1‰",
        "material": "GFRP",
        "position": "centred",
        "ratio": 1,
    }


def test_the_same_tie_twice_is_one_option_and_two_ties_under_one_name_are_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A repeated tie (whatever its name) is dropped like a repeated bars option; two
    different ties under one name are refused, located at the second."""
    text = _sub(
        "  - {material: GFRP, position: centred, ratio: 1}\n",
        "  - {type: tie, name: catena, height: 5.5, diameter: 20, spacing: 3.0, length: 8.0}\n",
    )
    names = [o.name for o in _project(text).expand_interventions()]
    assert names == [
        "Tie Ø20 @ 3.0 m at 5.5 m",
        "GFRP external 1‰ + tie A 314 mm² @ 3.0 m at 5.5 m",
    ]
    clash = text.replace("name: catena, height: 5.5,", "name: Tie Ø20 @ 3.0 m at 5.5 m, height: 5,")
    code, err = validate_text(tmp_path, clash, capsys)
    assert code == 2
    assert "p.yaml:13: interventions[1]: two different options are named" in err


def test_json_schema_and_template_document_the_tie_option() -> None:
    """The JSON Schema lists ``type: tie`` with the tie's fields and the tie's prices in
    ``costs``; the template shows a tie option and the prices."""
    schema = str(Project.model_json_schema())
    for key in ("TieOption", "tie_steel_per_kg", "tie_steel_per_metre", "tie_plate",
                "tie_installation", "anchorage"):  # fmt: skip
        assert key in schema, key
    root = Path(__file__).resolve().parents[2]
    for template in (root / "templates" / "wall.yaml", root / "frp_assess/templates/wall.yaml"):
        text = template.read_text(encoding="utf-8")
        assert "type: tie" in text and "tie_plate" in text, template
