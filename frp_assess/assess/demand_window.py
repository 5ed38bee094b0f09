"""Whether the time-history check at the demand sits on a collapse window (docs/model.md §11,
"the time-history check at the demand"; Circolare 2019 §C8.7.1.2.1.9).

The check runs each record once, at the demand; a rocking wall can fall at exactly that
intensity and stand 1 % above or below it (its collapse windows).  The robustness statement
repeats the check with every motion at 0.98 and 1.02 times the demand: where the verdict
differs from the one at the demand, it sits on a collapse window and is not robust.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

from frp_assess.assess.check_demand import LimitStateDemand
from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.assess.kinematic_checks import checks_at
from frp_assess.dynamics import RockingModel
from frp_assess.results.checks import CaseChecks
from frp_assess.results.verdict import NearDemand

#: the factors on the demand the check is repeated at [-]
NEAR_DEMAND_FACTORS = (0.98, 1.02)


def time_histories_pass(checks: CaseChecks) -> bool | None:
    """Whether every time-history check made passes (SLV and SLC); None: none made."""
    made = [t for t in (checks.time_history, checks.time_history_slc) if t is not None]
    return None if not made else all(t.passed for t in made)


def scaled_demands(
    demands: Mapping[str, LimitStateDemand], factor: float
) -> dict[str, LimitStateDemand]:
    """The same actions with every base motion multiplied by ``factor`` (the floor filter is
    linear, so a floor motion scales with its ground record)."""
    return {
        state: d
        if d.motions is None
        else replace(d, motions=[(acc * factor, dt) for acc, dt in d.motions])
        for state, d in demands.items()
    }


def near_demand(
    name: str,
    model: RockingModel,
    inputs: AssessmentInputs,
    demands: Mapping[str, LimitStateDemand],
) -> tuple[NearDemand, ...]:
    """The time-history checks of ``model`` with the motions at each of
    :data:`NEAR_DEMAND_FACTORS` times the demand (empty: no time-history check is made)."""
    out = []
    for factor in NEAR_DEMAND_FACTORS:
        passed = time_histories_pass(
            checks_at(name, model, inputs, scaled_demands(demands, factor))
        )
        if passed is None:
            return ()
        out.append(NearDemand(factor, passed))
    return tuple(out)


def on_collapse_window(at_demand: bool | None, near: tuple[NearDemand, ...]) -> bool:
    """The verdict at the demand differs from one beside it."""
    return at_demand is not None and any(n.passes != at_demand for n in near)
