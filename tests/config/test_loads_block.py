"""The ``wall.loads`` block (docs/model.md §12): what the project file accepts and the one
located line (file:line: key: message, exit 2) for what it refuses."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.config.located import assert_one_located_line, validate_text

BASE = """\
project: {name: Loads}
wall:
  thickness: 0.4
  height: 6.0
  unit_weight: 18
  mechanism: one-sided
  loads:
    top:
      - {name: first floor, load: 10.0, distance: 0.3}
      - {name: roof, load: 4.0, distance: 0.2, inertia: restrained}
    thrust:
      - {name: rafters, force: 1.0, height: 5.5}
    ties:
      - {name: catena, height: 5.8, diameter: 20, spacing: 3.0, length: 8.0}
seismic:
  spectrum: {type: preset, name: A2}
  records:
    artificial: {count: 1, seed: 1, duration: 13.5, dt: 0.05}
interventions:
  - {material: GFRP, position: centred, ratio: 1}
"""


def _sub(old: str, new: str) -> str:
    assert old in BASE, old
    return BASE.replace(old, new, 1)


#: (id, project text, expected fragment, line, key)
REFUSED: list[tuple[str, str, str, int, str]] = [
    (
        "line-of-action-outside-the-wall",
        _sub("load: 10.0, distance: 0.3}", "load: 10.0, distance: 0.45}"),
        "expected 0 <= distance <= B = 0.4 m",
        9,
        "wall.loads.top[0].distance",
    ),
    (
        "tie-above-the-wall",
        _sub("height: 5.8,", "height: 6.5,"),
        "expected a tie on the wall, 0 < height <= H = 6 m, found 6.5",
        14,
        "wall.loads.ties[0].height",
    ),
    (
        "thrust-above-the-wall",
        _sub("height: 5.5}", "height: 7}"),
        "expected 0 <= height <= H = 6 m, found 7",
        12,
        "wall.loads.thrust[0].height",
    ),
    (
        # W·B/2 + Σ P·d = 43.2·0.2 + 10·0.3 + 4·0.2 = 12.44 kNm/m < 3·5.5 = 16.5
        "thrust-tips-the-wall-at-rest",
        _sub("force: 1.0, height: 5.5", "force: 3.0, height: 5.5"),
        "found sum(F*h) = 16.5 kNm/m against W*B/2 + sum(P*d) = 12.44 kNm/m",
        11,
        "wall.loads.thrust",
    ),
    (
        "tie-without-a-size",
        _sub("diameter: 20, ", ""),
        "give the tie's 'diameter' [mm] or its 'area' [mm2], exactly one; found neither",
        14,
        "wall.loads.ties[0]",
    ),
    (
        # the time histories hold two tie levels: a third height is refused
        "three-tie-levels",
        _sub(
            "length: 8.0}\n",
            "length: 8.0}\n"
            + "".join(
                f"      - {{name: t{h}, height: {h}, diameter: 20, spacing: 3.0, length: 8.0}}\n"
                for h in (2.0, 3.0)
            ),
        ),
        "the time histories model at most 2 tie levels; ties at the same height",
        16,
        "wall.loads.ties[2]",
    ),
    (
        "inertia-unknown",
        _sub("inertia: restrained", "inertia: floating"),
        "wall.loads.top[1].inertia",
        10,
        "wall.loads.top[1].inertia",
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


def test_a_facade_with_a_floor_and_a_thrust_is_valid(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    no_tie = BASE.replace(
        "    ties:\n      - {name: catena, height: 5.8, diameter: 20, spacing: 3.0, length: 8.0}\n",
        "",
    )
    assert no_tie != BASE
    code, err = validate_text(tmp_path, no_tie, capsys)
    assert code == 0, err


def test_ties_are_in_the_time_histories_without_a_warning(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The time histories model the tie (docs/model.md §12): validate accepts it silently,
    two rows of the same tie at the same height (one level) too, and a floor tie below the
    eaves tie (a second level)."""
    doubled = _sub(
        "length: 8.0}\n",
        "length: 8.0}\n      - {name: second row, height: 5.8, diameter: 16, spacing: 2.0, "
        "length: 8.0}\n",
    )
    floor_tie = _sub(
        "length: 8.0}\n",
        "length: 8.0}\n      - {name: floor tie, height: 3.0, diameter: 20, spacing: 3.0, "
        "length: 8.0}\n",
    )
    for text in (BASE, doubled, floor_tie):
        code, err = validate_text(tmp_path, text, capsys)
        assert code == 0, err
        assert "tie" not in err and "time histories" not in err, err
