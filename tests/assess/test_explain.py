"""Odd results explained (frp_assess.assess.explain): an option weaker than its bare wall
says why, q < 1 is flagged.  Reference: the rules of the module docstring, on stand-in cases
whose numbers are set by hand."""

from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Any

from frp_assess.assess.explain import failure_mode, remark


def case(improvement: float, mean_q: float = 2.0, **kw: Any) -> Any:
    return SimpleNamespace(
        is_unreinforced=False,
        improvement=improvement,
        design_a_dyn=0.2 * improvement,
        mean_q=mean_q,
        records=kw.pop("records", ()),
        **kw,
    )


URM = SimpleNamespace(design_a_dyn=0.2)
BARE = SimpleNamespace(a_rm_g=0.115, theta_max=math.inf, alpha=0.117)


def test_weaker_than_the_bare_wall_because_the_pivot_moved():
    """a_RM 0.080 g < 0.115 g: the sentence names both and the moved pivot."""
    model = SimpleNamespace(a_rm_g=0.080, theta_max=math.inf, alpha=0.08)
    text = remark(case(0.71), URM, model, BARE, False)  # type: ignore[arg-type]
    assert text is not None
    assert "weaker than the unreinforced wall (design a_dyn 0.142 g against 0.200 g)" in text
    assert "a_RM = 0.080 g against the bare wall's 0.115 g" in text


def test_weaker_because_the_bars_break_before_tipping_with_the_failure_mode():
    """Same a_RM, θ_max = 0.05 rad < α = 0.117 rad; the records' failure mode is quoted (the
    most frequent one)."""
    model = SimpleNamespace(a_rm_g=0.115, theta_max=0.05, alpha=0.117)
    recs = (
        SimpleNamespace(failure_mode="bars broke, then fell"),
        SimpleNamespace(failure_mode="bars broke, then fell"),
        SimpleNamespace(failure_mode="fell intact"),
    )
    c = case(0.9, records=recs)
    assert failure_mode(c) == "bars broke, then fell"  # type: ignore[arg-type]
    text = remark(c, URM, model, BARE, False)  # type: ignore[arg-type]
    assert text is not None and "failure mode: bars broke, then fell" in text
    assert "θ_max = 0.0500 rad, before the wall would tip (α = 0.1170 rad)" in text


def test_q_below_one_is_an_error_at_ground_level_and_explained_above_it():
    ok = SimpleNamespace(a_rm_g=0.115, theta_max=math.inf, alpha=0.117)
    assert remark(case(1.2), URM, ok, BARE, False) is None  # type: ignore[arg-type]
    ground = remark(case(1.2, mean_q=0.8), URM, ok, BARE, False)  # type: ignore[arg-type]
    assert ground is not None and "impossible" in ground and "q = 0.80 < 1" in ground
    above = remark(case(1.2, mean_q=0.8), URM, ok, BARE, True)  # type: ignore[arg-type]
    assert above is not None and "ground terms" in above and "impossible" not in above


def test_a_fall_inside_the_ida_capacity_is_explained():
    """One record topples the wall at FC·a_g·S while the IDA put its first collapse above:
    the non-monotone response is named (the golden building-crushing run has two)."""
    ok = SimpleNamespace(a_rm_g=0.115, theta_max=math.inf, alpha=0.117)
    text = remark(case(1.2), URM, ok, BARE, False, falls_inside_ida=1)  # type: ignore[arg-type]
    assert text is not None and text.startswith("1 record topples the wall")
    assert "not monotone" in text
