"""What a results.json value must be beyond its type: the value checks of
:func:`frp_assess.results.json_io.from_json`, in one place (issue 36 item 6).

``report`` renders what results.json says, and a file edited by hand (PGA −1, H −3, α 90°,
mechanism "three-sided", a recommended case that is not among the cases) is read back as
strictly as the project file it came from: the same ranges (the wall's from
:mod:`frp_assess.rules.geometry`, as config.schema uses them), each refused with one line
naming the file and the key.  Two tables, in the style of the cache's checks
(:data:`frp_assess.assess.cache.FIELD_CHECKS`):

- :data:`FIELD_CHECKS`: (dataclass, field) -> a check of that field's converted value;
- :data:`OBJECT_CHECKS`: dataclass -> a check between fields of the built object (a name
  that must be one of the cases).

A check returns None when the value is right, else what was expected ("expected ...");
the reader adds the key and what it found.  Every number is also finite (the reader refuses
inf, which Python's json makes of 1e999, wherever a number is read).  No check may refuse a
file that frp-assess wrote: the golden files and every test read through them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from frp_assess.results.model import (
    AssessmentResult,
    Demand,
    RecordInfo,
    RecordResult,
)
from frp_assess.results.run_inputs import ReportSettings, WallResult
from frp_assess.results.verdict import InterventionResult
from frp_assess.rules.geometry import HEIGHT_RANGE, THICKNESS_RANGE
from frp_assess.rules.intervention import CATEGORIES

#: what one check says of a value: None (right) or what was expected
FieldCheck = Callable[[Any], "str | None"]
#: what one check says of a built object: None, or (the key under the object, expected)
ObjectCheck = Callable[[Any], "tuple[str, str] | None"]

#: the wall's mechanisms (as frp_assess.dynamics.MECHANISMS: results may not import dynamics,
#: tests/results/test_read_checks.py checks they are the same)
MECHANISMS = ("one-sided", "two-sided")
#: the report's languages (as config.schema's ReportLanguage and report/lang.py's LANGUAGES,
#: checked alike by the tests)
LANGUAGES = ("en", "it")


def positive(value: float | None) -> str | None:
    """A number > 0 (None passes: an optional field)."""
    if value is None or value > 0:
        return None
    return "expected a finite number > 0"


def within(low: float, high: float, unit: str) -> FieldCheck:
    """A number in [low, high]."""

    def check(value: float) -> str | None:
        if low <= value <= high:
            return None
        return f"expected {low:g} <= value <= {high:g} {unit}"

    return check


def one_of(allowed: tuple[str, ...]) -> FieldCheck:
    """One of the words ``allowed``."""

    def check(value: str) -> str | None:
        return None if value in allowed else f"expected one of {', '.join(allowed)}"

    return check


def _slenderness_rad(value: float) -> str | None:
    # B < H: tan α = B/H < 1 (rules/geometry.py)
    return None if 0 < value < math.pi / 4 else "expected 0 < alpha < pi/4 rad (B < H)"


def _slenderness_deg(value: float) -> str | None:
    return None if 0 < value < 45 else "expected 0 < alpha_deg < 45 (B < H)"


#: (dataclass, field) -> the check of that field's value
FIELD_CHECKS: dict[tuple[type, str], FieldCheck] = {
    (Demand, "pga"): positive,
    (RecordInfo, "pga"): positive,
    (RecordInfo, "duration"): positive,
    (RecordInfo, "dt"): positive,
    (RecordResult, "pga"): positive,
    (RecordResult, "collapse_multiplier"): positive,
    (RecordResult, "survivor_multiplier"): positive,
    (RecordResult, "a_dyn"): positive,
    (RecordResult, "q"): positive,
    (WallResult, "thickness"): within(*THICKNESS_RANGE, "m"),
    (WallResult, "height"): within(*HEIGHT_RANGE, "m"),
    (WallResult, "mechanism"): one_of(MECHANISMS),
    (WallResult, "alpha"): _slenderness_rad,
    (WallResult, "alpha_deg"): _slenderness_deg,
    (ReportSettings, "language"): one_of(LANGUAGES),
    (InterventionResult, "category"): one_of(CATEGORIES),
}


def _named_cases(result: AssessmentResult) -> tuple[str, str] | None:
    """``recommended`` and ``closest`` name cases of the file."""
    names = [c.name for c in result.cases]
    for key in ("recommended", "closest"):
        name = getattr(result, key)
        if name is not None and name not in names:
            listed = ", ".join(names[:5]) + (", …" if len(names) > 5 else "")
            return key, f"expected the name of one of the {len(names)} cases ({listed})"
    return None


#: dataclass -> the check between the fields of the built object
OBJECT_CHECKS: dict[type, ObjectCheck] = {
    AssessmentResult: _named_cases,
}
