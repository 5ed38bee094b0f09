"""Number formats and result sentences shared by the CLI, the TUI and the PDF report
(they read the typed results, :mod:`frp_assess.results.model`).

:func:`fmt_against` shows a ratio next to a verdict on it (capacity/demand against the target)
with enough digits that the number shown agrees with the verdict: 0.997 against a target of 1
is "0.997", never "1.00 … meets: no".
"""

from __future__ import annotations

import math

from frp_assess.results.checks import CaseChecks
from frp_assess.results.model import AssessmentResult

#: most decimals :func:`fmt_against` shows before giving up on separating value and threshold
MAX_DECIMALS = 6


def fmt_against(value: float, threshold: float, meets: bool | None, decimals: int = 2) -> str:
    """``value`` with ``decimals`` decimals, or more when that rounding would contradict the
    verdict ``meets`` (``value ≥ threshold``): the shown number then reads on the verdict's
    side of ``threshold``.  ``meets`` None (no verdict) keeps ``decimals``."""
    if not math.isfinite(value):
        return f"{value}"
    text = f"{value:.{decimals}f}"
    if meets is None:
        return text
    for d in range(decimals, MAX_DECIMALS + 1):
        text = f"{value:.{d}f}"
        if (float(text) >= threshold) == bool(meets):
            return text
    return text


#: ζ_E at or above this is shown as "> 100" (a wall that barely moves under the design records)
ZETA_SHOWN_MAX = 100.0


def fmt_zeta(value: float | None) -> str:
    """ζ_E = capacity/demand [-] of a code check (it passes at ζ_E ≥ 1) with 2 decimals, or
    more when 2 would round across 1 (0.997 is "0.997", not "1.00"); "> 100" from 100 up,
    "—" for None."""
    if value is None:
        return "—"
    if value >= ZETA_SHOWN_MAX:
        return f"> {ZETA_SHOWN_MAX:.0f}"
    return fmt_against(value, 1.0, value >= 1.0)


def numerical_check_text(results: AssessmentResult) -> str | None:
    """The verification run in one sentence, or None when it was not asked for."""
    nc = results.numerical_check
    if nc is None:
        return None
    head = (
        f"Numerical check: every IDA was repeated at a 10× tighter integration tolerance "
        f"({nc.check_tolerance:g} instead of {nc.tolerance:g}). "
    )
    if nc.fate_changed or nc.max_change is None:
        return head + (
            f"For {nc.case} under {nc.record} a record collapsed in one run and not in "
            f"the other: that result is ill-conditioned (sensitive to the integrator's "
            f"round-off); {nc.changed_pairs} of {nc.pairs} multipliers moved by more "
            "than the IDA tolerance."
        )
    return head + (
        f"The largest change of a collapse multiplier was {nc.max_change:.2%} "
        f"({nc.case}, {nc.record}); {nc.changed_pairs} of {nc.pairs} "
        "multipliers moved by more than the IDA tolerance."
    )


#: a fitted collapse probability at the demand above this makes "no retrofit needed" say so
SCATTER_ALERT = 0.10


def no_retrofit_caveats(results: AssessmentResult) -> list[str]:
    """What a "no retrofit needed" verdict must say alongside (issue 15 §3): the code's
    kinematic check of the same wall failing, or a margin within the scatter of the records
    (fitted P(collapse) at the demand ≥ 10 %, or capacity/demand − 1 below the records' CoV)."""
    out = []
    kc = results.kinematic_checks
    failed = [] if kc is None or not kc.cases else checks_failed(kc.cases[0])
    if failed:
        out.append(
            f"the code check{'s' if len(failed) > 1 else ''} {', '.join(failed)} of "
            "Circolare 2019 §C8.7.1 fail" + ("" if len(failed) > 1 else "s")
        )
    elif not results.code_check.passed:
        out.append("the linear kinematic check of Circolare 2019 §C8.7.1 is NOT satisfied")
    urm = results.cases[0]
    sc = urm.scatter
    p = None if sc.fragility is None else sc.fragility.p_collapse_at_demand
    margin = urm.capacity_demand / results.model.target - 1.0
    if p is not None and p >= SCATTER_ALERT:
        out.append(f"the fitted probability of collapse at the demand is {p:.0%}")
    elif margin < sc.cov:
        out.append(
            f"the margin ({margin:.0%}) is within the scatter of the records (CoV {sc.cov:.0%})"
        )
    return out


#: said in place of "recommended" when the record set fails the code's compatibility checks
NOT_COMPLIANT = "input not code-compliant"


def recommendation_label(results: AssessmentResult) -> str:
    """The label of the rank-1 option: "Recommended", or "Best ranked (input not
    code-compliant)" when the record set fails the code's spectrum-compatibility checks."""
    if results.input_code_compliant:
        return "Recommended"
    return f"Best ranked ({NOT_COMPLIANT})"


def recommendation_text(results: AssessmentResult) -> str:
    """One line saying what to do: the recommended option, or that no retrofit is needed.

    ``recommended`` is the cheapest option meeting the target even when the unreinforced wall
    already meets it; this says so instead of presenting that option as required.
    """
    rec = results.recommended
    if results.cases[0].meets_target:
        text = "no retrofit needed: the unreinforced wall already meets the target"
        caveats = no_retrofit_caveats(results)
        if caveats:
            text += " (but " + "; ".join(caveats) + ")"
        return text + (f" (cheapest option for extra margin: {rec})" if rec else "")
    return rec or "none of the options meets the target"


# --- the code's kinematic checks, in one line per case ----------------------------------------


def check_verdicts(checks: CaseChecks) -> list[tuple[str, bool]]:
    """(name, passed) of every check made on one case, in the order of the report's table:
    linear, nonlinear SLV, nonlinear SLC, time history, IDA (the last two when made)."""
    out = [
        ("linear", checks.linear.passed),
        ("nonlinear SLV", checks.slv.passed),
        ("nonlinear SLC", checks.slc.passed),
    ]
    if checks.time_history is not None:
        out.append(("time history", checks.time_history.passed))
    if checks.ida is not None:
        out.append(("IDA", checks.ida.passed))
    return out


def checks_failed(checks: CaseChecks) -> list[str]:
    """The names of the checks of one case that fail (:func:`check_verdicts`)."""
    return [name for name, ok in check_verdicts(checks) if not ok]


def checks_line(checks: CaseChecks) -> str:
    """ "passes …; fails …" for one case (a list is left out when empty)."""
    verdicts = check_verdicts(checks)
    passed = [n for n, ok in verdicts if ok]
    failed = [n for n, ok in verdicts if not ok]
    parts = []
    if passed:
        parts.append("passes " + ", ".join(passed))
    if failed:
        parts.append("fails " + ", ".join(failed))
    return "; ".join(parts)


def checks_summary(results: AssessmentResult) -> list[tuple[str, str]]:
    """(label, :func:`checks_line`) for the unreinforced wall and the rank-1 option (the
    recommended or best ranked one), when the results hold the code's checks; else []."""
    kc = results.kinematic_checks
    if kc is None or not kc.cases:
        return []
    by_name = {c.case: c for c in kc.cases}
    out = [(kc.cases[0].case, checks_line(kc.cases[0]))]
    best = next((c for c in results.cases if c.rank == 1), None)
    if best is not None and best.name in by_name:
        if results.recommended == best.name and results.input_code_compliant:
            label = f"{best.name} (recommended)"
        elif results.input_code_compliant:
            label = f"{best.name} (best ranked)"
        else:
            label = f"{best.name} (best ranked, {NOT_COMPLIANT})"
        out.append((label, checks_line(by_name[best.name])))
    return out
