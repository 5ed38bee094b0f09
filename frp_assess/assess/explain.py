"""One sentence for each odd result of a case (results.json ``cases[].remark``).

* An option weaker than its bare wall (improvement < 1): its failure mode (the field
  ``failure_mode`` of the case or of its records, where the dynamics give it) and why — its
  a_RM below the bare wall's, or bars that break before the wall would tip.
* A record that topples the wall at the design intensity although the IDA put its first
  collapse above it: the response is not monotone in the intensity (collapse windows fall
  between the IDA's steps), and the time-history check, run at that intensity, sees it.
* q < 1 (a_dyn below a_RM): impossible for a rigid block at ground level (it cannot fall
  before it rocks, and it rocks only once the base acceleration exceeds a_RM, so a_dyn =
  C·PGA ≥ a_RM); above ground it is the ground-terms convention (the floor amplifies the
  record).  Found at ground level it is flagged as an error of the model.

Units: accelerations in g, rotations in rad.
"""

from __future__ import annotations

from collections import Counter

from frp_assess.dynamics import RockingModel
from frp_assess.results.model import CaseResult

#: a ratio this far below 1 counts as "below" (not a rounding of equal values)
SLACK = 1e-9


def failure_mode(case: CaseResult) -> str | None:
    """The case's failure mode: its own ``failure_mode`` field, else the most frequent one
    of its records (None where the results do not carry it)."""
    own = getattr(case, "failure_mode", None)
    if isinstance(own, str) and own:
        return own
    modes = [getattr(r, "failure_mode", None) for r in case.records]
    found = Counter(m for m in modes if isinstance(m, str) and m)
    return found.most_common(1)[0][0] if found else None


def weaker_reason(model: RockingModel, bare: RockingModel) -> str:
    """Why an option's model can fall at a lower intensity than the bare wall's."""
    if model.a_rm_g < bare.a_rm_g * (1.0 - 1e-6):
        return (
            f"its wall starts rocking at a_RM = {model.a_rm_g:.3f} g against the bare wall's "
            f"{bare.a_rm_g:.3f} g (the bar force at rupture deepens the compressed zone and "
            "moves the pivot inward, docs/model.md §1.1)"
        )
    if model.theta_max < model.alpha:
        return (
            f"its bars break at θ_max = {model.theta_max:.4f} rad, before the wall would tip "
            f"(α = {model.alpha:.4f} rad), and leave a bare wall already displaced and moving"
        )
    return "its bars change the rocking (impacts, period) in a way the records punish"


def remark(
    case: CaseResult,
    urm: CaseResult,
    model: RockingModel,
    bare: RockingModel,
    above_ground: bool,
    falls_inside_ida: int = 0,
) -> str | None:
    """One sentence for an odd result of ``case`` (module docstring), or None;
    ``falls_inside_ida``: records that topple the wall at the design intensity although their
    IDA collapse lies above it."""
    parts = []
    if falls_inside_ida:
        parts.append(
            f"{falls_inside_ida} record{'s' if falls_inside_ida > 1 else ''} "
            f"{'topple' if falls_inside_ida > 1 else 'topples'} the wall "
            "at the design intensity although the IDA placed the first collapse above it: the "
            "response is not monotone in the intensity (collapse windows between the IDA's "
            "steps), so the time-history check governs"
        )
    if not case.is_unreinforced and case.improvement < 1.0 - SLACK:
        mode = failure_mode(case)
        parts.append(
            f"weaker than the unreinforced wall (design a_dyn {case.design_a_dyn:.3f} g "
            f"against {urm.design_a_dyn:.3f} g"
            + (f"; failure mode: {mode}" if mode else "")
            + f"): {weaker_reason(model, bare)}"
        )
    if case.mean_q < 1.0 - SLACK:
        if above_ground:
            parts.append(
                f"q = {case.mean_q:.2f} < 1 because a_dyn is in ground terms while the wall's "
                "base moves with the floor, which amplifies the record"
            )
        else:
            parts.append(
                f"q = {case.mean_q:.2f} < 1 at ground level is impossible for a rigid block "
                "(it falls only after it rocks, at a base acceleration above a_RM): an error "
                "of the model, do not use this case"
            )
    return "; ".join(parts) if parts else None
