"""Number formats and result sentences shared by the CLI, the TUI and the PDF report
(they read the typed results, :mod:`frp_assess.results.model`).

:func:`fmt_against` shows a ratio next to a verdict on it (capacity/demand against the target)
with enough digits that the number shown agrees with the verdict: 0.997 against a target of 1
is "0.997", never "1.00 … meets: no".
"""

from __future__ import annotations

from frp_assess.results.checks import CaseChecks
from frp_assess.results.model import AssessmentResult, CaseResult
from frp_assess.results.rounding import fmt_against as fmt_against  # re-export


def fmt_capacity(case: CaseResult, target: float) -> str:
    """capacity/demand of a case: "≥ 1.08" when it is a lower bound (records without
    collapse up to C_max), else :func:`fmt_against` the target (its decimals agree with the
    IDA check, ``capacity_demand ≥ target``)."""
    cd = case.capacity_demand
    if case.lower_bound:
        return f"≥ {fmt_against(cd, target, cd >= target)}"
    return fmt_against(cd, target, cd >= target)


def fmt_margin(margin: float | None, lower_bound: bool = False) -> str:
    """A deciding check's margin (capacity/demand, passes at ≥ 1): "≥ " before a lower
    bound, "unbounded" for None (nothing moved), "> 100" from 100 up."""
    if margin is None:
        return "unbounded"
    text = fmt_zeta(margin)
    return f"≥ {text}" if lower_bound and not text.startswith(">") else text


#: the governing margin shown for a time-history check that a record fails by toppling the
#: wall (margin 0)
FALLS = "falls"


def margin_text(case: CaseResult) -> str:
    """The governing check's margin of a case for a ranking column (≥ 1 passes):
    :func:`fmt_margin`, :data:`FALLS` for a time-history check that a record fails by
    toppling the wall, "—" without a decision (an older file)."""
    if case.governing_check is None:
        return "—"
    if case.governing_margin == 0.0 and case.governing_check.startswith("time history"):
        return FALLS
    return fmt_margin(case.governing_margin, case.governing_lower_bound)


def verdict_text(case: CaseResult) -> str:
    """ "passes: <governing check> <margin>", "fails: <governing check> <margin>" (the
    decision's governing check, the one with the smallest margin), or "—" when undecided
    (an older file)."""
    if case.passes is None:
        return "—"
    if case.passes:
        return (
            f"passes: {case.governing_check} "
            f"{fmt_margin(case.governing_margin, case.governing_lower_bound)}"
        )
    if case.governing_margin == 0.0 and (case.governing_check or "").startswith("time history"):
        return f"fails: {case.governing_check} (a record makes the wall fall)"
    return (
        f"fails: {case.governing_check} "
        f"{fmt_margin(case.governing_margin, case.governing_lower_bound)}"
    )


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


def noncompliant_sets(results: AssessmentResult) -> str:
    """Which record sets fail the code's spectrum-compatibility checks, in words: the
    assessment's (results.json ``compliance``) and those a limit state generated for its own
    spectrum (``kinematic_checks.intensities``, in ``records/<state>/``)."""
    sets = [] if results.compliance.passed else ["the records (table above)"]
    kc = results.kinematic_checks
    for i in () if kc is None else kc.intensities:
        if i.records_compliant is False:
            sets.append(f"the {i.limit_state} records (records/{i.limit_state}/)")
    return " and ".join(sets) or "the records"


def recommendation_label(results: AssessmentResult) -> str:
    """The label of :func:`recommendation_text`: "Recommended" when the decision names an
    option to install (results.json ``recommended`` of a wall with ``retrofit_required``),
    "Best ranked (input not code-compliant)" for that option when the record set fails the
    code's spectrum-compatibility checks; "Decision" when it names none (no retrofit
    needed, or none of the options passes)."""
    if results.recommended is None or not results.retrofit_required:
        return "Decision" if results.input_code_compliant else f"Decision ({NOT_COMPLIANT})"
    if results.input_code_compliant:
        return "Recommended"
    return f"Best ranked ({NOT_COMPLIANT})"


def recommendation_text(results: AssessmentResult) -> str:
    """One line saying what to do: the recommended option (it passes every deciding check,
    :mod:`frp_assess.assess.decision`), that no retrofit is needed, or that none passes and
    which one comes closest.

    ``recommended`` is the cheapest passing option even when the unreinforced wall already
    passes; this says so instead of presenting that option as required.
    """
    rec = results.recommended
    urm = results.cases[0]
    urm_ok = urm.passes if urm.passes is not None else urm.meets_target
    if urm_ok:
        text = "no retrofit needed: the unreinforced wall passes every deciding check"
        caveats = no_retrofit_caveats(results)
        if caveats:
            text += " (but " + "; ".join(caveats) + ")"
        return text + (f" (cheapest option for extra margin: {rec})" if rec else "")
    if rec:
        case = results.case(rec)
        if case is None or case.governing_check is None:
            return rec
        return (
            f"{rec} (passes every deciding check; governing: {case.governing_check}, "
            f"margin {fmt_margin(case.governing_margin, case.governing_lower_bound)})"
        )
    closest = results.case(results.closest)
    if closest is None:
        return "none of the options passes every deciding check"
    return (
        "none of the options passes every deciding check; the closest is "
        f"{closest.name} ({closest.governing_check} "
        f"{fmt_margin(closest.governing_margin, closest.governing_lower_bound)})"
    )


# --- the code's kinematic checks, in one line per case ----------------------------------------


def check_verdicts(checks: CaseChecks, labelled: bool = False) -> list[tuple[str, bool]]:
    """(name, passed) of every check made on one case, in the order of the report's table:
    linear, nonlinear SLV, nonlinear SLC, time history (SLV, SLC), IDA (when made).

    ``labelled``: the names say what each check is in the decision (docs/results-json.md,
    "The decision"): the linear and nonlinear static checks "(supporting)", the time history
    at SLV and at SLC and the IDA deciding; without it, the report's short names ("time
    history" alone when only the SLV one was run, as in files written before the SLC one)."""
    sup = " (supporting)" if labelled else ""
    out = [
        (f"linear{sup}", checks.linear.passed),
        (f"nonlinear SLV{sup}", checks.slv.passed),
        (f"nonlinear SLC{sup}", checks.slc.passed),
    ]
    both = checks.time_history_slc is not None
    if checks.time_history is not None:
        name = "time history SLV" if labelled or both else "time history"
        out.append((name, checks.time_history.passed))
    if checks.time_history_slc is not None:
        out.append(("time history SLC", checks.time_history_slc.passed))
    if checks.ida is not None:
        out.append(("IDA", checks.ida.passed))
    return out


def checks_failed(checks: CaseChecks) -> list[str]:
    """The names of the checks of one case that fail (:func:`check_verdicts`)."""
    return [name for name, ok in check_verdicts(checks) if not ok]


def checks_line(checks: CaseChecks, labelled: bool = False) -> str:
    """ "passes …; fails …" for one case (a list is left out when empty); ``labelled``: as
    :func:`check_verdicts`."""
    verdicts = check_verdicts(checks, labelled)
    passed = [n for n, ok in verdicts if ok]
    failed = [n for n, ok in verdicts if not ok]
    parts = []
    if passed:
        parts.append("passes " + ", ".join(passed))
    if failed:
        parts.append("fails " + ", ".join(failed))
    return "; ".join(parts)


def checks_summary(results: AssessmentResult, labelled: bool = False) -> list[tuple[str, str]]:
    """(label, :func:`checks_line`) for the unreinforced wall and the rank-1 option (the
    recommended one, else the closest), when the results hold the code's checks; else []."""
    kc = results.kinematic_checks
    if kc is None or not kc.cases:
        return []
    by_name = {c.case: c for c in kc.cases}
    out = [(kc.cases[0].case, checks_line(kc.cases[0], labelled))]
    best = next((c for c in results.cases if c.rank == 1), None)
    if best is not None and best.name in by_name:
        if results.recommended == best.name and not results.retrofit_required:
            # the wall passes unreinforced: the decision recommends no retrofit
            label = f"{best.name} (cheapest passing option; no retrofit needed)"
        elif results.recommended == best.name and results.input_code_compliant:
            label = f"{best.name} (recommended)"
        elif results.recommended is None and results.input_code_compliant:
            label = f"{best.name} (closest, not recommended)"
        elif results.input_code_compliant:
            label = f"{best.name} (best ranked)"
        else:
            label = f"{best.name} (best ranked, {NOT_COMPLIANT})"
        out.append((label, checks_line(by_name[best.name], labelled)))
    return out
