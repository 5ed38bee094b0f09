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

Pure functions of plain numbers (:class:`Evidence`): no I/O, no model runs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

from frp_assess.assess.kinematic_nonlinear import time_history_check
from frp_assess.results.verdict import DecidingCheck
from frp_assess.rules.record_sets import design_statistic

IDA_CHECK = "IDA capacity/demand"
TH_SLV = "time history SLV"
TH_SLC = "time history SLC"
PIVOT_CHECK = "pivot check"

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


def _margin_key(margin: float | None) -> float:
    return math.inf if margin is None else margin


def ida_deciding_check(ev: Evidence) -> DecidingCheck:
    """The IDA check: design a_dyn/(FC·a_g·S) against the target; a lower bound when a record
    that did not collapse enters the design value."""
    rule = ev.design_value or design_statistic(len(ev.a_dyn))
    if rule == "mean":
        value = math.fsum(ev.a_dyn) / len(ev.a_dyn)
        bound = any(ev.censored)
    else:
        i = min(range(len(ev.a_dyn)), key=lambda k: ev.a_dyn[k])
        value, bound = ev.a_dyn[i], ev.censored[i]
    cd = value / ev.demand
    shown = f"≥ {cd:.3g}" if bound else f"{cd:.3g}"
    return DecidingCheck(
        name=IDA_CHECK,
        margin=cd / ev.target,
        passed=cd >= ev.target,
        lower_bound=bound,
        detail=f"design a_dyn/(FC·a_g·S) = {shown} against the target {ev.target:g}",
    )


def time_history_deciding_check(
    peaks: Sequence[float], d0: float, d_limit: float, name: str
) -> DecidingCheck:
    """Circolare 2019 §C8.7.1.2.1.9 on the peaks [m]: d0 never exceeded, mean ≤ d_limit;
    margin min(d_limit/mean, d0/largest), 0 if a record made the wall fall, None if nothing
    moved."""
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
    return DecidingCheck(
        name=name, margin=th.margin, passed=th.passed, lower_bound=False, detail=detail
    )


def verdict(ev: Evidence) -> Verdict:
    """Every deciding check of one case, whether it passes, and the governing check."""
    checks = [ida_deciding_check(ev)]
    if ev.peaks is not None:
        checks.append(time_history_deciding_check(ev.peaks, ev.d0, ev.d_slv, TH_SLV))
        slc = ev.peaks if ev.peaks_slc is None else ev.peaks_slc
        checks.append(time_history_deciding_check(slc, ev.d0, ev.d_slc, TH_SLC))
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


def decide(evidence: Sequence[Evidence]) -> Decision:
    """The decision on every case (:func:`verdict`, :func:`rank`)."""
    verdicts = tuple(verdict(e) for e in evidence)
    order = rank(evidence, verdicts)
    recommended = next((i for i in order if verdicts[i].passes), None)
    closest = order[0] if recommended is None and order else None
    return Decision(verdicts, tuple(order), recommended, closest)


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


def leave_one_out(evidence: Sequence[Evidence]) -> list[int | None]:
    """For each record k: the recommended case's index when record k is left out."""
    n = len(evidence[0].a_dyn)
    return [decide([without_record(e, k) for e in evidence]).recommended for k in range(n)]
