"""results.json edited by hand, as a property (issue 36 item 6): any checked key set to a value
a run cannot write is refused with one line naming the file and that key, whatever the value;
a value the run could write reads back.

Reference: the golden results.json of ``tests/golden/expected/small`` (written by a run); the
ranges are the project file's (config.schema's fields), typed here as the strategies' bounds.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from frp_assess.errors import InputError
from frp_assess.results.json_io import from_json

SMALL = Path(__file__).parents[1] / "golden" / "expected" / "small" / "results.json"
DATA = json.loads(SMALL.read_text(encoding="utf-8"))
MARK = 12345.678

#: key paths of numbers that must be > 0
POSITIVE = ["demand.pga", "records[1].pga", "cases[0].records[1].pga", "cases[1].records[0].q"]


def _text(key: str, literal: str) -> str:
    data = json.loads(json.dumps(DATA))
    parts = key.replace("[", ".").replace("]", "").split(".")
    node: Any = data
    for part in parts[:-1]:
        node = node[int(part)] if part.isdigit() else node[part]
    node[parts[-1]] = MARK
    return json.dumps(data, indent=1).replace(repr(MARK), literal)


def _refused(text: str, key: str) -> str:
    with pytest.raises(InputError) as info:
        from_json(text, file="results.json")
    line = str(info.value)
    assert line.startswith(f"results.json: {key}: expected ") and "\n" not in line, line
    return line


@given(
    key=st.sampled_from(POSITIVE),
    value=st.floats(max_value=0.0, allow_nan=False, allow_infinity=False)
    | st.integers(max_value=0)
    | st.sampled_from(["1e999", "-1e999", "1" + "0" * 400]),
)
def test_a_number_not_finite_and_positive_is_refused_at_its_key(key: str, value: Any) -> None:
    """NaN and Infinity are not JSON (the reader refuses them before any key); 1e999 and an
    integer of 401 digits are numbers of JSON that no float holds."""
    literal = value if isinstance(value, str) else json.dumps(value)
    _refused(_text(key, literal), key)


@given(value=st.floats(min_value=1e-6, max_value=1e3))
def test_a_positive_pga_reads_back(value: float) -> None:
    assert math.isfinite(from_json(_text("demand.pga", repr(value))).demand.pga)


@given(
    height=st.floats(allow_nan=False).filter(lambda h: not 0.5 <= h <= 50.0),
    word=st.text(max_size=20).filter(lambda w: w not in ("one-sided", "two-sided")),
)
def test_a_wall_outside_the_project_files_ranges_is_refused(height: float, word: str) -> None:
    literal = "1e999" if math.isinf(height) else repr(height)
    _refused(_text("wall.height", literal), "wall.height")
    data = json.loads(json.dumps(DATA))
    data["wall"]["mechanism"] = word
    _refused(json.dumps(data), "wall.mechanism")
