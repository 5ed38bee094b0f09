"""The one decision rule of an assessment: which options pass, which is recommended.

An option (or the unreinforced wall) *passes* when every deciding check passes:

* the IDA: design a_dyn / (FC·a_g·S) ≥ the target (design a_dyn the mean over ≥ 7 records,
  else the least favourable; a record without collapse up to C_max enters at its lower bound
  C_max·PGA, so a value that is a lower bound passes only when the bound itself reaches the
  target);
* the time-history check of Circolare 2019 §C8.7.1.2.1.9 at SLV and at SLC, on the same
  model as the IDA, each at its own limit state's intensity (×FC when FC enters the
  dynamics): d0 never exceeded in any record and the mean of the peak displacements ≤ d_SLV
  under the SLV motions (≤ d_SLC under the SLC motions).  With the site given by its
  coordinates SLV and SLC have their own spectra (records generated for each, or the recorded
  ones scaled to each a_g·S); with one spectrum given by its parameters both run at it.  d0
  is where the *unreinforced* wall's restoring moment vanishes: the bars break brittly, so
  they are not among the actions surely present up to collapse that the Circolare keeps in d0.

The IDA's target stays on the assessment's limit state (the one its spectrum is built for,
SLV unless the project chooses another): §C8.7.1.2.1 states the checks of a local mechanism
at SLV and SLC but not an IDA, whose capacity/demand at the other limit states' a_g·S is
stated beside it and does not decide.

Each check has a margin, capacity over demand (≥ 1 passes): the IDA's value over the target;
the time history's min(d_lim/mean peak, d0/largest peak), 0 when a record made the wall fall.
The *governing* check is the one with the smallest margin.  The linear and nonlinear static
kinematic checks are supporting checks: shown, never deciding.

The recommendation is the cheapest passing option (then the lightest); when none passes,
there is none, and the *closest* is the option closest to passing: the largest governing
margin; equal governing margins (every time-history margin is 0 once a record makes the wall
fall) are told apart by the IDA's margin, the largest first, so that a tie never names the
cheapest, weakest option.  Ranking: the passing options first, cheapest first; then the
others by governing margin, highest first (a lower bound enters at its bound, ahead of an
equal exact value), then by the IDA's margin, highest first.  An option the pivot check
drops (no rocking mechanism) never passes and gets no rank.

What an option must reach is the category of the intervention's (NTC 2018 §8.4,
:mod:`frp_assess.rules.intervention`, :func:`requirements`): each deciding check has a ζ_E
(the IDA's design a_dyn/(FC·a_g·S); the time history's min(d_lim/mean peak, d0/largest peak))
and its margin is ζ_E over the ζ_E it must reach.  The *upgrade* (§8.4.3, the default) asks
ζ_E ≥ 1 of the time histories and ≥ the target of the IDA: the rule above.  An *improvement*
(§8.4.2) asks every check ζ_E ≥ 0.6 (use class III schools, class IV) or ≥ the unreinforced
mechanism's ζ_E (its smallest) + 0.1; a *local* intervention (§8.4.1) asks the checks that
govern the unreinforced wall to exceed their unreinforced ζ_E and every other check to keep
its own or the assessment's.  The unreinforced wall itself is always judged by the
assessment (ζ_E ≥ 1, the IDA's ≥ the target): whether a retrofit is needed.

Pure functions of plain numbers (:class:`Evidence`): no I/O, no model runs.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from frp_assess.assess.kinematic_nonlinear import time_history_check
from frp_assess.results.verdict import DecidingCheck, InterventionResult
from frp_assess.rules.intervention import (
    CATEGORY_CLAUSE,
    IMPROVEMENT_INCREASE,
    IMPROVEMENT_MINIMUM,
    UPGRADE_ZETA,
    Category,
    improvement_has_minimum,
    improvement_zeta,
    local_requirement,
    meets,
)
from frp_assess.rules.record_sets import design_statistic

IDA_CHECK = "IDA capacity/demand"
TH_SLV = "time history SLV"
TH_SLC = "time history SLC"
PIVOT_CHECK = "pivot check"

#: the decision rule in words, of the upgrade (ζ_E ≥ 1, the IDA's ≥ the target; the default)
DECISION_RULE = (
    "An option passes when every deciding check passes: the IDA's design a_dyn/(FC·a_g·S) "
    "≥ {target:g} at the assessment's limit state (a lower bound passes only if the bound "
    "reaches it) and the time-history check of Circolare 2019 §C8.7.1.2.1.9 at SLV and SLC "
    "with the same model, each at FC·a_g·S of its own limit state (d0 of the unreinforced "
    "wall never exceeded, mean peak ≤ d_SLV, ≤ d_SLC). The governing "
    "check is the one with the smallest margin (capacity/demand, ≥ 1 passes). The recommendation: "
    "the cheapest passing option, design-mode answers included; when none passes, none is "
    "recommended and the closest to passing (largest governing margin, equal ones by the IDA's "
    "margin) is named. The linear and "
    "nonlinear static kinematic checks are supporting checks, not deciding."
)

#: the decision rule in words of a local intervention or an improvement: {requirement} is
#: what every deciding check's ζ_E must reach (:func:`decision_rule`)
CATEGORY_DECISION_RULE = (
    "An option passes when the ζ_E (capacity/demand) of every deciding check {requirement}: "
    "the IDA's design a_dyn/(FC·a_g·S) at the assessment's limit state (a lower bound "
    "passes only if the bound reaches it) and the time-history check of Circolare 2019 "
    "§C8.7.1.2.1.9 at SLV and SLC with the same model, each at FC·a_g·S of its own limit "
    "state (ζ_E = min(d_SLV or d_SLC/mean peak, d0 of the unreinforced wall/largest peak)). "
    "The wall as it is is judged by the assessment (the IDA's ζ_E ≥ {target:g}, the time "
    "histories' ≥ 1). The governing check is the one with the smallest margin (ζ_E over the "
    "ζ_E it must reach, ≥ 1 passes). The recommendation: the cheapest passing option, "
    "design-mode answers included; when none passes, none is recommended and the closest to "
    "passing (largest governing margin, equal ones by the IDA's margin) is named. The linear "
    "and nonlinear static kinematic checks are supporting checks, not deciding."
)

RANKING_RULE = (
    "Options passing every deciding check first, cheapest first (then lightest); then the "
    "others by governing margin, highest first (a lower bound at its bound, ahead of an equal "
    "exact value; equal margins by the IDA's margin, highest first). Every option is ranked: "
    "none is dropped for the masonry at its base."
)


@dataclass(frozen=True)
class Evidence:
    """What the decision reads of one case (accelerations in g, displacements in m)."""

    name: str
    cost: float  #: [currency]
    mass: float  #: [kg]
    a_dyn: tuple[float, ...]  #: per record: a_dyn, or its lower bound C_max·PGA [g]
    censored: tuple[bool, ...]  #: per record: no collapse up to C_max (a_dyn a lower bound)
    demand: float  #: FC·a_g·S [g]
    target: float  #: required capacity/demand [-]
    #: per record: peak displacement under the SLV motions [m] (inf: it fell); None: the
    #: time-history check was not run
    peaks: tuple[float, ...] | None
    d0: float  #: [m]
    d_slv: float  #: [m]
    d_slc: float  #: [m]
    #: per record: peak displacement under the SLC motions [m] (inf: it fell); None: the
    #: SLV peaks (one spectrum known, or the time-history check was not run)
    peaks_slc: tuple[float, ...] | None = None
    dropped: bool = False  #: the pivot check finds no rocking mechanism
    unreinforced: bool = False
    #: "mean" (≥ 7 records) or "least": how the design a_dyn is taken; None: by the count
    design_value: str | None = None


@dataclass(frozen=True)
class Verdict:
    """The decision on one case."""

    checks: tuple[DecidingCheck, ...]
    passes: bool
    governing_check: str
    governing_margin: float | None  #: None: unbounded (nothing moved)
    governing_lower_bound: bool


@dataclass(frozen=True)
class InterventionCategory:
    """The category of the intervention (NTC 2018 §8.4, :mod:`frp_assess.rules.intervention`)
    and what its rule reads: the use class "I"-"IV" (None: not known; an improvement needs
    it) and whether a class III construction is used as a school."""

    category: Category = "upgrade"
    use_class: str | None = None
    school: bool = False

    @property
    def clause(self) -> str:
        """The clause of the category (NTC 2018 §8.4.1-§8.4.3)."""
        return CATEGORY_CLAUSE[self.category]


#: the upgrade of NTC 2018 §8.4.3, today's rule and the default
UPGRADE = InterventionCategory()


@dataclass(frozen=True)
class Requirement:
    """The ζ_E [-] one deciding check of an option must reach (``strict``: exceed)."""

    value: float
    strict: bool = False

    def shown(self) -> str:
        """The requirement in a detail sentence."""
        return f"{self.value:.3g} (to be exceeded)" if self.strict else f"{self.value:.3g}"


#: ζ_E each deciding check must reach, by check name (:data:`IDA_CHECK`, :data:`TH_SLV`,
#: :data:`TH_SLC`)
Requirements = Mapping[str, Requirement]


def _margin_key(margin: float | None) -> float:
    return math.inf if margin is None else margin


def _margin(zeta: float | None, req: Requirement) -> float | None:
    """ζ_E over the ζ_E it must reach [-] (≥ 1 passes, unless it must be exceeded); None:
    unbounded (nothing moved, or nothing to reach)."""
    if zeta is None:
        return None
    if req.value == 0.0:
        return None if zeta > 0.0 else 0.0
    return zeta / req.value


def ida_zeta(ev: Evidence) -> tuple[float, bool]:
    """The IDA's ζ_E = design a_dyn/(FC·a_g·S) [-] and whether it is a lower bound (a record
    that did not collapse enters the design value)."""
    rule = ev.design_value or design_statistic(len(ev.a_dyn))
    if rule == "mean":
        value = math.fsum(ev.a_dyn) / len(ev.a_dyn)
        bound = any(ev.censored)
    else:
        i = min(range(len(ev.a_dyn)), key=lambda k: ev.a_dyn[k])
        value, bound = ev.a_dyn[i], ev.censored[i]
    return value / ev.demand, bound


def ida_deciding_check(ev: Evidence, req: Requirement | None = None) -> DecidingCheck:
    """The IDA check: design a_dyn/(FC·a_g·S) against ``req`` (None: the assessment's
    target, ``ev.target``); a lower bound when a record that did not collapse enters the
    design value."""
    cd, bound = ida_zeta(ev)
    shown = f"≥ {cd:.3g}" if bound else f"{cd:.3g}"
    against = f"{ev.target:g}" if req is None else req.shown()
    req = Requirement(ev.target) if req is None else req
    return DecidingCheck(
        name=IDA_CHECK,
        margin=_margin(cd, req),
        passed=meets(cd, req.value, req.strict),
        lower_bound=bound,
        detail=f"design a_dyn/(FC·a_g·S) = {shown} against the target {against}",
    )


def time_history_deciding_check(
    peaks: Sequence[float],
    d0: float,
    d_limit: float,
    name: str,
    req: Requirement | None = None,
) -> DecidingCheck:
    """Circolare 2019 §C8.7.1.2.1.9 on the peaks [m]: d0 never exceeded, mean ≤ d_limit;
    ζ_E = min(d_limit/mean, d0/largest), 0 if a record made the wall fall, None if nothing
    moved; against ``req`` (None: ζ_E ≥ 1, the check itself)."""
    th = time_history_check(peaks, d0, d_limit)
    n = len(th.peaks)
    state = "SLV" if name == TH_SLV else "SLC"
    if not math.isfinite(th.max_peak):
        fell = sum(1 for p in th.peaks if not math.isfinite(p))
        detail = f"the wall falls under {fell} of {n} records at the {state} intensity"
    elif th.max_peak == 0.0:
        detail = f"no record makes the wall rock at the {state} intensity"
    else:
        over = sum(1 for p in th.peaks if p > d0)
        detail = (
            f"mean peak {th.mean_peak * 1000:.0f} mm against d_{state} = {d_limit * 1000:.0f} mm; "
            f"{over} of {n} records exceed d0 = {d0 * 1000:.0f} mm"
        )
    if req is None:  # ζ_E ≥ 1 is the check itself (TimeHistoryCheck.passed)
        return DecidingCheck(
            name=name, margin=th.margin, passed=th.passed, lower_bound=False, detail=detail
        )
    zeta = "unbounded" if th.margin is None else f"{th.margin:.3g}"
    return DecidingCheck(
        name=name,
        margin=_margin(th.margin, req),
        passed=meets(th.margin, req.value, req.strict),
        lower_bound=False,
        detail=f"{detail}; ζ_E {zeta} against the target {req.shown()}",
    )


def check_zetas(ev: Evidence) -> dict[str, float | None]:
    """ζ_E [-] of each deciding check of ``ev`` (None: unbounded, nothing moved)."""
    out: dict[str, float | None] = {IDA_CHECK: ida_zeta(ev)[0]}
    if ev.peaks is not None:
        out[TH_SLV] = time_history_check(ev.peaks, ev.d0, ev.d_slv).margin
        slc = ev.peaks if ev.peaks_slc is None else ev.peaks_slc
        out[TH_SLC] = time_history_check(slc, ev.d0, ev.d_slc).margin
    return out


def mechanism_zeta(ev: Evidence) -> float:
    """The mechanism's ζ_E [-]: the smallest ζ_E of its deciding checks (an unbounded one,
    nothing moved, counts as infinite; the IDA's is always finite)."""
    return min(math.inf if z is None else z for z in check_zetas(ev).values())


def intervention_result(as_is: Evidence, intervention: InterventionCategory) -> InterventionResult:
    """What results.json records of the category (NTC 2018 §8.4): the unreinforced
    mechanism's ζ_E and the ζ_E an option's mechanism must reach (or exceed)."""
    zeta = mechanism_zeta(as_is)
    required, strict = UPGRADE_ZETA, False
    if intervention.category == "improvement" and intervention.use_class is not None:
        required = improvement_zeta(zeta, intervention.use_class, intervention.school)
    elif intervention.category == "local":
        required, strict = zeta, True
    return InterventionResult(
        category=intervention.category,
        clause=intervention.clause,
        use_class=intervention.use_class,
        school=intervention.school,
        as_is_zeta=zeta,
        required_zeta=required,
        strict=strict,
    )


def requirements(as_is: Evidence, intervention: InterventionCategory) -> Requirements | None:
    """What every deciding check of an option must reach under ``intervention``, from the
    unreinforced wall's evidence ``as_is`` (NTC 2018 §8.4, rules/intervention.py); None: the
    assessment's own (the upgrade: the IDA's ζ_E ≥ ``as_is.target``, the others ≥ 1)."""
    if intervention.category == "upgrade":
        return None
    zetas = {k: math.inf if z is None else z for k, z in check_zetas(as_is).items()}
    mechanism = mechanism_zeta(as_is)
    if intervention.category == "improvement":
        if intervention.use_class is None:
            raise ValueError("an improvement (NTC 2018 §8.4.2) needs the use class")
        r = improvement_zeta(mechanism, intervention.use_class, intervention.school)
        return dict.fromkeys(zetas, Requirement(r))
    passing = {k: as_is.target if k == IDA_CHECK else UPGRADE_ZETA for k in zetas}
    return {k: Requirement(*local_requirement(z, mechanism, passing[k])) for k, z in zetas.items()}


def verdict(ev: Evidence, required: Requirements | None = None) -> Verdict:
    """Every deciding check of one case, whether it passes, and the governing check;
    ``required``: what each check must reach (:func:`requirements`; None: the assessment's).
    The unreinforced wall is always judged by the assessment."""
    req = None if ev.unreinforced or required is None else required
    checks = [ida_deciding_check(ev, None if req is None else req[IDA_CHECK])]
    if ev.peaks is not None:
        r_slv = None if req is None else req[TH_SLV]
        r_slc = None if req is None else req[TH_SLC]
        checks.append(time_history_deciding_check(ev.peaks, ev.d0, ev.d_slv, TH_SLV, r_slv))
        slc = ev.peaks if ev.peaks_slc is None else ev.peaks_slc
        checks.append(time_history_deciding_check(slc, ev.d0, ev.d_slc, TH_SLC, r_slc))
    if ev.dropped:  # first: it governs (margin 0) even where a time history gives 0 too
        checks.insert(
            0,
            DecidingCheck(
                name=PIVOT_CHECK,
                margin=0.0,
                passed=False,
                lower_bound=False,
                detail="the base cannot carry the weight and the bar force: no rocking mechanism",
            ),
        )
    gov = min(checks, key=lambda c: _margin_key(c.margin))  # the first of equal margins
    return Verdict(
        checks=tuple(checks),
        passes=all(c.passed for c in checks),
        governing_check=gov.name,
        governing_margin=gov.margin,
        governing_lower_bound=gov.lower_bound,
    )


def ida_margin(v: Verdict) -> float:
    """The IDA check's margin of a verdict (0 when it has none): what tells apart options
    whose governing margins tie (a record made the wall fall: every time-history margin 0)."""
    return next((_margin_key(c.margin) for c in v.checks if c.name == IDA_CHECK), 0.0)


def rank(evidence: Sequence[Evidence], verdicts: Sequence[Verdict]) -> list[int]:
    """Indices of the options (not the unreinforced wall, not the dropped) in ranked order:
    passing first by (cost, mass), then the others by governing margin, highest first (a
    lower bound ahead of an equal exact value), then by the IDA's margin, highest first
    (closest to passing when governing margins tie), then cost."""
    idx = [i for i, e in enumerate(evidence) if not e.unreinforced and not e.dropped]
    passing = [i for i in idx if verdicts[i].passes]
    others = [i for i in idx if not verdicts[i].passes]
    passing.sort(key=lambda i: (evidence[i].cost, evidence[i].mass, i))
    others.sort(
        key=lambda i: (
            -_margin_key(verdicts[i].governing_margin),
            0 if verdicts[i].governing_lower_bound else 1,
            -ida_margin(verdicts[i]),
            evidence[i].cost,
            i,
        )
    )
    return passing + others


@dataclass(frozen=True)
class Decision:
    """The verdict of every case, the ranking, the recommendation."""

    verdicts: tuple[Verdict, ...]
    order: tuple[int, ...]  #: ranked option indices, best first
    recommended: int | None  #: the cheapest passing option; None: none passes
    closest: int | None  #: when none passes: the largest governing margin; else None
    intervention: InterventionCategory = UPGRADE
    #: what each deciding check of an option had to reach (None: the assessment's)
    required: Requirements | None = None


def decide(evidence: Sequence[Evidence], intervention: InterventionCategory = UPGRADE) -> Decision:
    """The decision on every case (:func:`verdict`, :func:`rank`): the options against the
    requirement of ``intervention`` (:func:`requirements`, from the unreinforced case)."""
    as_is = next((e for e in evidence if e.unreinforced), None)
    required = None if as_is is None else requirements(as_is, intervention)
    verdicts = tuple(verdict(e, required) for e in evidence)
    order = rank(evidence, verdicts)
    recommended = next((i for i in order if verdicts[i].passes), None)
    closest = order[0] if recommended is None and order else None
    return Decision(verdicts, tuple(order), recommended, closest, intervention, required)


def without_record(ev: Evidence, k: int) -> Evidence:
    """The evidence of ``ev`` with record ``k`` left out; the design value keeps the case's
    rule (the mean stays the mean with one record fewer: the question is whether one record
    carries the verdict, not the code's rule for fewer than 7 records)."""
    rule = ev.design_value or design_statistic(len(ev.a_dyn))

    def drop(xs: tuple) -> tuple:
        return xs[:k] + xs[k + 1 :]

    return replace(
        ev,
        a_dyn=drop(ev.a_dyn),
        censored=drop(ev.censored),
        peaks=None if ev.peaks is None else drop(ev.peaks),
        peaks_slc=None if ev.peaks_slc is None else drop(ev.peaks_slc),
        design_value=rule,
    )


def leave_one_out(
    evidence: Sequence[Evidence], intervention: InterventionCategory = UPGRADE
) -> list[int | None]:
    """For each record k: the recommended case's index when record k is left out (the
    requirement of ``intervention`` taken again from the unreinforced wall without it)."""
    n = len(evidence[0].a_dyn)
    return [
        decide([without_record(e, k) for e in evidence], intervention).recommended for k in range(n)
    ]


def requirement_words(intervention: InterventionCategory) -> str:
    """What every deciding check's ζ_E must reach under ``intervention``, in words (NTC 2018
    §8.4): the phrase of :data:`CATEGORY_DECISION_RULE`."""
    if intervention.category == "local":
        return (
            "is above the unreinforced wall's in the check that governs the unreinforced wall "
            "and, in every other check, at least the unreinforced wall's or the value that "
            "passes the assessment (a local intervention, NTC 2018 §8.4.1: the mechanism's "
            "safety improves and nothing gets worse)"
        )
    if intervention.category == "improvement":
        cls = intervention.use_class or "?"
        school = " used as a school" if intervention.school else ""
        if improvement_has_minimum(cls, intervention.school):
            bound = f"≥ {IMPROVEMENT_MINIMUM:g}"
        else:
            bound = f"≥ the unreinforced mechanism's ζ_E + {IMPROVEMENT_INCREASE:g}"
        return (
            f"is {bound} (an improvement of a use class {cls} construction{school}, "
            "NTC 2018 §8.4.2; the mechanism's ζ_E is its smallest over the deciding checks)"
        )
    return f"is ≥ {UPGRADE_ZETA:g} (an upgrade, NTC 2018 §8.4.3)"


def decision_rule(intervention: InterventionCategory, target: float) -> str:
    """The decision rule in words (results.json ``decision_rule``): :data:`DECISION_RULE`
    for the upgrade (the IDA's ζ_E ≥ ``target`` [-]), else :data:`CATEGORY_DECISION_RULE`."""
    if intervention.category == "upgrade":
        return DECISION_RULE.format(target=target)
    return CATEGORY_DECISION_RULE.format(requirement=requirement_words(intervention), target=target)
