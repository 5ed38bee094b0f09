"""The robustness sentence of a wall that passes unreinforced (issue 39): it says no retrofit
is needed and whether that holds with each record left out, never that an option "stays
recommended" (frp_assess/assess/verdict_pipeline.py)."""

from __future__ import annotations

from frp_assess.assess.decision import Evidence
from frp_assess.assess.robustness import _unreinforced_sentence


def urm(a_dyn: tuple[float, ...]) -> Evidence:
    """The wall as it is, judged by the IDA alone (no time-history peaks): it passes when
    the mean of ``a_dyn`` reaches the demand 0.2 g (target 1)."""
    return Evidence(
        name="unreinforced",
        cost=0.0,
        mass=0.0,
        a_dyn=a_dyn,
        censored=(False,) * len(a_dyn),
        demand=0.2,
        target=1.0,
        peaks=None,
        d0=0.1,
        d_slv=0.05,
        d_slc=0.07,
        unreinforced=True,
        design_value="mean",
    )


def test_no_retrofit_holds_whichever_record_is_left_out() -> None:
    # hand calculation: the means without one record are 0.35, 0.35, 0.30 g, all ≥ 0.2 g
    text = _unreinforced_sentence(urm((0.3, 0.3, 0.4)), ["r1", "r2", "r3"])
    assert text == (
        "no retrofit needed: the unreinforced wall passes every deciding check "
        "whichever record is left out"
    )


def test_no_retrofit_names_the_record_it_rests_on() -> None:
    # mean 0.2 g = demand: passes; without r3 the mean is 0.1 g < 0.2 g: fails; without r1
    # or r2 it is 0.25 g: passes
    text = _unreinforced_sentence(urm((0.1, 0.1, 0.4)), ["r1", "r2", "r3"])
    assert text.endswith("as assessed, but not without r3"), text
    assert "recommended" not in text
