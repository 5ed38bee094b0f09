"""results.json read back as strictly as the project file (issue 36 item 6): a file edited by
hand is refused with one line naming the file and the key, and every file frp-assess wrote
still reads.

References: the golden results.json of ``tests/golden/expected/small`` (written by a run),
edited here as a user would edit it with a text editor; the ranges are the project file's
(config.schema's fields), the words of each expectation typed here.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, get_args

import pytest

from frp_assess.config.schema import HEIGHT_RANGE, THICKNESS_RANGE, ReportLanguage, WallSpec
from frp_assess.dynamics import MECHANISMS
from frp_assess.errors import InputError
from frp_assess.report.lang import LANGUAGES
from frp_assess.results import read_checks
from frp_assess.results.json_io import from_json, to_json

GOLDEN = Path(__file__).parents[1] / "golden" / "expected"
SMALL = GOLDEN / "small" / "results.json"


def _edited(edit: Any, *, raw: tuple[str, str] | None = None) -> str:
    data = json.loads(SMALL.read_text(encoding="utf-8"))
    edit(data)
    text = json.dumps(data, indent=1, ensure_ascii=False)
    return text.replace(*raw) if raw else text


def _set(path: str, value: Any) -> Any:
    """An edit setting the key path ``a.b[1].c`` of the data to ``value``."""

    def edit(data: Any) -> None:
        parts = path.replace("[", ".").replace("]", "").split(".")
        node = data
        for part in parts[:-1]:
            node = node[int(part)] if part.isdigit() else node[part]
        last = parts[-1]
        if last.isdigit():
            node[int(last)] = value
        else:
            node[last] = value

    return edit


@pytest.mark.parametrize(
    ("key", "value", "words"),
    [
        ("cases[1].records[0].pga", -1, "expected a finite number > 0, found -1"),
        ("records[0].pga", 0, "expected a finite number > 0, found 0"),
        ("demand.pga", -0.3, "expected a finite number > 0, found -0.3"),
        ("cases[0].records[0].a_dyn", -2.0, "expected a finite number > 0"),
        ("wall.height", -3, "expected 0.5 <= value <= 50 m, found -3"),
        ("wall.thickness", 7.0, "expected 0.05 <= value <= 5 m, found 7.0"),
        ("wall.alpha_deg", 90, "expected 0 < alpha_deg < 45 (B < H), found 90"),
        ("wall.alpha", 1.5707963, "expected 0 < alpha < pi/4 rad (B < H)"),
        ("wall.mechanism", "three-sided", "expected one of one-sided, two-sided"),
        ("recommended", "GFRP external 9", "expected the name of one of the 2 cases"),
        ("closest", "nothing", "expected the name of one of the 2 cases"),
        ("report.language", "fr", "expected one of en, it, found 'fr'"),
    ],
)
def test_a_value_edited_by_hand_is_refused_naming_file_and_key(
    key: str, value: Any, words: str
) -> None:
    with pytest.raises(InputError) as info:
        from_json(_edited(_set(key, value)), file="r/results.json")
    line = str(info.value)
    assert line.startswith(f"r/results.json: {key}: "), line
    assert words in line
    assert "\n" not in line


@pytest.mark.parametrize(
    "key",
    ["demand.pga", "wall.unit_weight", "cases[0].records[0].curve[0][2]", "records[0].sa[3]"],
)
@pytest.mark.parametrize("literal", ["1e999", "-1e999", "1" + "0" * 400])
def test_a_number_json_reads_as_infinite_is_refused(key: str, literal: str) -> None:
    """1e999 is inf to Python's json (and an integer of 401 digits overflows a float):
    refused wherever a number is read, the bulk arrays (curves, spectra) too."""
    marker = 12345.678
    text = _edited(_set(key, marker), raw=(repr(marker), literal))
    with pytest.raises(InputError) as info:
        from_json(text, file="results.json")
    assert str(info.value).startswith(f"results.json: {key}: expected a finite number")


def test_an_infinite_number_in_free_parameters_is_refused() -> None:
    marker = 12345.678
    text = _edited(
        _set("seismic.spectrum.parameters.extra", [1, {"x": marker}]),
        raw=(repr(marker), "1e999"),
    )
    with pytest.raises(InputError, match=r"seismic\.spectrum\.parameters\.extra\[1\]\.x: "):
        from_json(text, file="results.json")


@pytest.mark.parametrize("path", sorted(GOLDEN.glob("*/results.json")), ids=lambda p: p.parent.name)
def test_every_golden_file_reads_and_writes_back_unchanged(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert to_json(from_json(text, file=str(path))) == text


def test_the_checks_use_the_project_files_words_and_ranges() -> None:
    """The words the reader accepts are the project file's and the model's (results may not
    import dynamics or config: the layering keeps the copies, this test keeps them equal)."""
    assert read_checks.MECHANISMS == MECHANISMS
    assert read_checks.LANGUAGES == get_args(ReportLanguage) == LANGUAGES
    height = WallSpec.model_fields["height"].metadata
    assert {getattr(m, "ge", None) for m in height} >= {HEIGHT_RANGE[0]}
    assert {getattr(m, "le", None) for m in height} >= {HEIGHT_RANGE[1]}
    thickness = WallSpec.model_fields["thickness"].metadata
    assert {getattr(m, "ge", None) for m in thickness} >= {THICKNESS_RANGE[0]}
