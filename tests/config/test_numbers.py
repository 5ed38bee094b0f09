"""Every number of a project file is finite and within its stated bounds (class tests)."""

from __future__ import annotations

import copy
import math
from pathlib import Path
from typing import Any

import pytest

import frp_assess
from frp_assess.config import load_project, project_data, validate_data
from frp_assess.config.messages import Loc, format_path
from frp_assess.config.problems import problems_of
from frp_assess.errors import InputError

TEMPLATE = Path(frp_assess.__file__).parent / "templates" / "wall.yaml"


def numeric_leaves(data: Any, path: Loc = ()) -> list[Loc]:
    """Key paths of every number (not bool) of nested data."""
    if isinstance(data, dict):
        return [p for k, v in data.items() for p in numeric_leaves(v, (*path, k))]
    if isinstance(data, list):
        return [p for i, v in enumerate(data) for p in numeric_leaves(v, (*path, i))]
    return [path] if isinstance(data, int | float) and not isinstance(data, bool) else []


def full_data() -> dict[str, Any]:
    """The template with every block present, as nested data (every default included)."""
    data = project_data(load_project(TEMPLATE).project)
    data["wall"]["unit_weight"] = 18.0
    data["materials"]["GFRP"] = {"elastic_modulus": 46.0, "price": 8.0}
    data["interventions"][0]["ratio"] = 1.5
    return data


def put(data: dict[str, Any], path: Loc, value: Any) -> None:
    node: Any = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value


LEAVES = numeric_leaves(full_data())


def test_the_full_data_has_many_numbers() -> None:
    assert len(LEAVES) >= 30
    validate_data(full_data())


@pytest.mark.parametrize("value", [math.inf, -math.inf, math.nan])
@pytest.mark.parametrize("path", LEAVES, ids=[format_path(p) for p in LEAVES])
def test_every_number_is_finite(path: Loc, value: float) -> None:
    data = copy.deepcopy(full_data())
    put(data, path, value)
    with pytest.raises(InputError) as info:
        validate_data(data)
    keys = [p.key for p in problems_of(info.value)]
    assert format_path(path) in keys, keys


@pytest.mark.parametrize(
    ("path", "value", "fragment"),
    [
        (("analysis", "ida", "tolerance"), 1e-300, "[0.0001, 0.1], found 1e-300"),
        (("analysis", "ida", "step_ratio"), 1.0000000001, "[1.01, 10], found 1.0000000001"),
        (("analysis", "ida", "max_multiplier"), 1e6, "(1, 1000], found 1000000"),
        (("seismic", "records", "artificial", "dt"), 1e-9, "[0.0001, 0.05], found 1e-09"),
        (("seismic", "records", "artificial", "dt"), 5e-324, "found 4.94065645841e-324"),
        (("seismic", "records", "artificial", "duration"), 1e6, "[13.5, 600], found 1000000"),
        (("seismic", "records", "artificial", "seed"), -1, "found -1"),
        (("seismic", "records", "artificial", "count"), 101, "[1, 100], found 101"),
        (("design", "resolution"), 1e-12, "[0.001, 1], found 1e-12"),
        (("analysis", "free_vibration_tail"), 1e9, "[0, 60], found 1000000000"),
        (("project", "name"), "x" * 20_000, "at most 200 characters, found 20000"),
        (("costs", "currency"), "<b>EUR" * 3, "at most 12 characters"),
    ],
)
def test_work_is_bounded_with_the_numbers_in_the_message(
    path: Loc, value: Any, fragment: str
) -> None:
    data = full_data()
    put(data, path, value)
    with pytest.raises(InputError) as info:
        validate_data(data)
    assert info.value.key == format_path(path) and fragment in info.value.message


def test_options_are_bounded_before_expansion() -> None:
    data = full_data()
    many = [round(0.01 * k, 2) for k in range(1, 1001)]
    data["interventions"] = [
        {
            "sweep": {
                "material": ["GFRP", "CFRP"],
                "position": ["centred", "external"],
                "ratio": many,
            }
        }
    ]
    with pytest.raises(InputError) as info:
        validate_data(data)
    assert info.value.key == "interventions[0]"
    assert "expand to 4000, more than 2000" in info.value.message
