"""The decision's part of results.json: deciding checks and the robustness of the verdict.

Plain frozen dataclasses (the field names are the JSON keys; :mod:`frp_assess.results.json_io`
reads and writes them), filled by :mod:`frp_assess.assess.decision` and
:mod:`frp_assess.assess.verdict_pipeline`.  Margins are capacity/demand ratios [-] (≥ 1 passes),
accelerations in g, probabilities as fractions.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "ConventionOutcome",
    "DecidingCheck",
    "InterventionResult",
    "LeaveOneOut",
    "NearDemand",
    "Robustness",
]


@dataclass(frozen=True)
class DecidingCheck:
    """One deciding check of a case (:mod:`frp_assess.assess.decision`): ``margin`` is its
    capacity over demand [-] (passes at ≥ 1; None: unbounded, nothing moved); ``lower_bound``:
    the margin is a lower bound (records without collapse up to C_max); ``detail`` one sentence
    with the numbers."""

    name: str  #: "IDA capacity/demand" | "time history SLV" | "time history SLC" | "pivot check"
    margin: float | None
    passed: bool
    lower_bound: bool
    detail: str


@dataclass(frozen=True)
class LeaveOneOut:
    """The decision with one record left out: what is recommended then."""

    record: str  #: the record left out
    recommended: str | None  #: None: nothing passes without it
    survives: bool  #: the recommendation is the same


@dataclass(frozen=True)
class ConventionOutcome:
    """The recommended (or closest) case under one model convention (``sensitivity``):
    whether it still passes every deciding check, and which option takes over if not."""

    variant: str
    passes: bool
    governing_check: str
    governing_margin: float | None  #: [-]; None: unbounded
    #: the next cheapest option that passes as assessed and under this variant; None: none
    #: (or the case survives)
    takes_over: str | None


@dataclass(frozen=True)
class NearDemand:
    """The time-history checks (SLV and SLC) of the case with every record at ``factor``
    times the demand (docs/model.md §11): whether they pass."""

    factor: float  #: [-]
    passes: bool


@dataclass(frozen=True)
class Robustness:
    """How firm the verdict is: P(collapse) of the case at the design intensity FC·a_g·S
    [g] from the lognormal fragility fit (None: fewer than 2 distinct collapses), the
    decision with each record left out, and the case under each model convention."""

    case: str  #: the recommended option, else the closest
    design_intensity: float  #: FC·a_g·S [g]
    p_collapse: float | None  #: [-]
    leave_one_out: tuple[LeaveOneOut, ...]
    conventions: tuple[ConventionOutcome, ...]
    survives: bool  #: the same case is recommended in every leave-one-out and convention
    summary: str  #: one or two sentences
    #: the time-history checks at 0.98 and 1.02 times the demand (empty: none made)
    time_history_near_demand: tuple[NearDemand, ...] = ()
    #: their verdict differs from the one at the demand: it sits on a collapse window
    on_collapse_window: bool = False


@dataclass(frozen=True)
class InterventionResult:
    """The category of the intervention (NTC 2018 §8.4, ``code_check.intervention``) and
    what an option had to reach: the mechanism's ζ_E is the smallest ζ_E of its deciding
    checks [-]."""

    category: str  #: "local" | "improvement" | "upgrade"
    clause: str  #: "NTC 2018 §8.4.1" | "NTC 2018 §8.4.2" | "NTC 2018 §8.4.3"
    use_class: str | None  #: "I"-"IV"; None: not given (an improvement needs it)
    school: bool  #: a class III building used as a school
    as_is_zeta: float  #: the unreinforced mechanism's ζ_E [-]
    #: the ζ_E [-] the option's mechanism must reach: the upgrade's 1 (the IDA's: ``model.
    #: target``), the improvement's 0.6 or as_is_zeta + 0.1, the local's as_is_zeta (to be
    #: exceeded; each other check keeps its own or the assessment's)
    required_zeta: float
    #: the option's ζ_E must exceed required_zeta (a local intervention), not only reach it
    strict: bool
