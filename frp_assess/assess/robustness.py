"""How firm the verdict of a run is (docs/results-json.md, "robustness"): P(collapse) of the
recommended (else the closest) case at FC·a_g·S, the decision with each record left out, the
case under each model convention and who takes over when it fails, and the time-history check
beside the demand; with the one or two sentences the outputs print.  Called by
:mod:`frp_assess.assess.verdict_pipeline` once the decision is taken.
"""

from __future__ import annotations

from collections.abc import Sequence

from frp_assess.assess.collapse_fraction import fraction_fragility
from frp_assess.assess.decision import (
    Decision,
    Evidence,
    leave_one_out,
    verdict,
    without_record,
)
from frp_assess.assess.demand_window import on_collapse_window
from frp_assess.assess.runner import CaseSummary
from frp_assess.assess.statistics import fit_lognormal_fragility
from frp_assess.results.model import CaseResult
from frp_assess.results.verdict import ConventionOutcome, LeaveOneOut, NearDemand, Robustness


def robustness(
    cases: Sequence[CaseResult],
    ev: Sequence[Evidence],
    summary: CaseSummary,
    decision: Decision,
    focus: int,
    outcomes: Sequence[ConventionOutcome],
    names: Sequence[str],
    design_intensity: float,
    *,
    near: tuple[NearDemand, ...] = (),
    at_demand: bool | None = None,
) -> Robustness:
    """P(collapse) of the focus case at FC·a_g·S, the decision without each record, the
    conventions, and the time-history checks beside the demand (``near``; ``at_demand``:
    their verdict at the demand), with one or two sentences."""
    fractions = cases[focus].scatter.collapse_fraction
    fit_of = "the collapse fractions at the sampled intensities"
    p = None
    if fractions:
        fit = fraction_fragility(fractions)
        p = None if fit is None else fit.probability(design_intensity)
    else:
        fit_of = "the records' collapse accelerations"
        exact = [a for a in summary.a_dyn if a is not None]
        if len(set(exact)) >= 2:
            censored = [
                b for a, b in zip(summary.a_dyn, summary.a_dyn_bound, strict=True) if a is None
            ]
            p = fit_lognormal_fragility(exact, censored).probability(design_intensity)
    # with one record there is nothing to leave out
    picks = leave_one_out(ev, decision.intervention) if len(names) > 1 else []
    loo = [
        LeaveOneOut(
            record=name,
            recommended=None if k is None else cases[k].name,
            survives=k == decision.recommended,
        )
        for name, k in zip(names, picks, strict=False)
    ]
    name = cases[focus].name
    survives = all(r.survives for r in loo) and all(o.passes for o in outcomes)
    no_retrofit = decision.verdicts[0].passes
    parts = [_unreinforced_sentence(ev[0], names[: len(loo)])] if no_retrofit else []
    if p is not None:
        parts.append(
            f"P(collapse) of {name} at FC·a_g·S = {design_intensity:.3f} g is {p:.1%} "
            f"(lognormal fit to {fit_of})"
        )
    lost = [r for r in loo if not r.survives]
    if decision.recommended is None and no_retrofit:
        parts.append("no option is needed")
    elif decision.recommended is None:
        gained = [r for r in loo if r.recommended is not None]
        parts.append(
            "nothing passes; leaving out one record "
            + (
                "changes nothing"
                if not gained
                else "would make "
                + ", ".join(f"{r.recommended} pass (without {r.record})" for r in gained)
            )
        )
    elif lost:
        parts.append(
            ("the cheapest option for extra margin" if no_retrofit else "the recommendation")
            + " changes when a record is left out: "
            + "; ".join(f"without {r.record}: {r.recommended or 'nothing passes'}" for r in lost)
        )
    elif no_retrofit:
        parts.append(
            f"{name}, the cheapest option for extra margin, passes whichever record is left out"
        )
    else:
        parts.append(f"{name} stays recommended whichever record is left out")
    failing = [o for o in outcomes if not o.passes]
    others = sum(1 for i, v in enumerate(decision.verdicts) if v.passes and i not in (0, focus))
    takeover_none = (
        "no other option passes even as assessed"
        if others == 0
        else "none of the next passing options passes under it"
    )
    if decision.recommended is not None:
        if failing:
            parts.append(
                "under "
                + "; ".join(
                    f"{o.variant} it fails ({o.governing_check}); "
                    + (f"{o.takes_over} takes over" if o.takes_over else takeover_none)
                    for o in failing
                )
            )
        else:
            parts.append("it passes under every model convention tried")
    window = on_collapse_window(at_demand, near)
    if window:
        parts.append(
            f"the time-history check of {name} sits on a collapse window: it "
            + ("passes" if at_demand else "fails")
            + " at the demand but "
            + ", ".join(
                f"{'passes' if n.passes else 'fails'} at {n.factor:g} × the demand" for n in near
            )
            + ", so it is not robust"
        )
    return Robustness(
        case=name,
        design_intensity=design_intensity,
        p_collapse=p,
        leave_one_out=tuple(loo),
        conventions=tuple(outcomes),
        survives=survives and decision.recommended is not None,
        summary="; ".join(parts) + ".",
        time_history_near_demand=near,
        on_collapse_window=window,
    )


def _unreinforced_sentence(urm: Evidence, records: Sequence[str]) -> str:
    """What the decision says of a wall that passes unreinforced (results.json
    ``retrofit_required`` false): no retrofit is needed, and whether that holds with each
    record left out (:func:`~frp_assess.assess.decision.without_record`)."""
    text = "no retrofit needed: the unreinforced wall passes every deciding check"
    if not records:
        return text
    fails = [r for k, r in enumerate(records) if not verdict(without_record(urm, k)).passes]
    if not fails:
        return text + " whichever record is left out"
    return text + " as assessed, but not without " + ", ".join(fails)
