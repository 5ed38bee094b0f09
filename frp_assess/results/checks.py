"""The code's kinematic checks of every case, side by side (results.json ``"kinematic_checks"``).

Circolare 2019 §C8.7.1 (docs/model.md, "Displacement-based checks"): the linear check, the
nonlinear static SLV and SLC checks, the time-history check of §C8.7.1.2.1.9 and the IDA's
verdict, each with its safety index ζ_E = capacity/demand.  Plain frozen dataclasses of
floats, strings, booleans, tuples and None (no numpy, no other frp_assess module): the field
names are the results.json keys; :mod:`frp_assess.results.json_io` reads and writes them.

Units: ground accelerations in g (a_g·S, the design intensity at the site); spectral
accelerations of the capacity curve in m/s²; displacements in m; periods in s; damping ratios
and ζ_E as fractions.  A value that does not exist (a bar that never breaks before d0, a wall
that fell under a record) is None, never an infinity, so that the JSON stays standard.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class FloorBasis:
    """Where the wall stands in the building, when its base is above ground (Circolare 2019
    §C7.2.3, first mode): the demand of every check uses the floor spectrum (C8.7.1.12)."""

    z_over_h: float  #: Z/H_b, height of the wall's base over the building's height [-]
    storeys: int  #: n [-]
    period: float  #: T1 of the building [s]
    damping: float  #: ξ1 of the building's first mode [-]
    floor_ratio: float  #: a_Z,1 / (a_g·S), the floor's peak acceleration per unit ground [-]


@dataclass(frozen=True)
class CapacitySummary:
    """The capacity curve of the wall with its bars, converted to the equivalent SDOF system
    (Circolare 2019 §C8.7.1.2.1.3, eqs. C8.7.1.3-C8.7.1.5)."""

    e_star: float  #: e*, participating mass fraction [-]
    m_star: float  #: M*, participating mass [kg per metre of wall]
    a0_star: float  #: a0* = α0·g/(e*·FC), spectral acceleration that starts rocking [m/s²]
    a_max: float  #: largest spectral acceleration of the curve [m/s²]
    d0: float  #: displacement where the bare wall's capacity vanishes (B/2) [m]
    stiffness: float  #: K of Eq. 10 while the bars are intact [-] (0 unreinforced)
    rupture_displacement: float | None  #: d at which the bars break [m]; None: not before d0
    rupture_limit: float | None  #: d where a rupture drops a below 50 % of a_max [m]; None: none


@dataclass(frozen=True)
class LinearCheck:
    """The linear (force-based) check: a0* ≥ demand/q (Circolare 2019 §C8.7.1.2.1.7)."""

    a0_star: float  #: a0* [g]
    demand: float  #: a_g·S/q at ground level, a_Z/q above it [g]
    behaviour_factor: float  #: q [-]
    zeta_e: float  #: a0* / demand [-]
    passed: bool
    #: α0 [-] of the model the IDA runs (a_RM/g, about its pivot or with its base reaction);
    #: None in files written before it (then B/H)
    alpha0: float | None = None


@dataclass(frozen=True)
class LimitStateResult:
    """The nonlinear static check of one limit state (Circolare 2019 §C8.7.1.2.1.6-8)."""

    limit_state: str  #: "SLV" or "SLC"
    d_limit: float  #: d_SLV or d_SLC [m]
    a_limit: float  #: a(d_limit) on the capacity curve [m/s²]
    period: float  #: secant period T_SLV or T_SLC [s]
    damping: float  #: equivalent damping of the mechanism [-] (0.08 SLV, 0.10 SLC)
    demand: float  #: displacement demand at the design intensity [m]
    a_g: (
        float  #: the intensity a_g·S of this limit state [g] (its own spectrum with the site known)
    )
    a_g_sld: float  #: a_g,SLD, the lower bound of a_g,SLV [g]
    a_g_capacity: float  #: a_g,SLV or a_g,SLC, the intensity whose demand equals d_limit [g]
    zeta_e: float  #: a_g_capacity / a_g [-]
    passed: bool


@dataclass(frozen=True)
class TimeHistoryResult:
    """The time-history check of Circolare 2019 §C8.7.1.2.1.9 at the design intensity: the
    model the IDA runs, under every record, d0 never exceeded, the mean peak displacement
    ≤ d_SLV (``limit_state`` SLV) or ≤ d_SLC (SLC).  d0 is the bare wall's (the bars are not
    counted: they break brittly, so they are not surely present up to collapse)."""

    #: factor on the records scaled to PGA = a_g·S (FC when FC enters the dynamics) [-]
    scale: float
    peaks: tuple[float | None, ...]  #: peak displacement of each record [m]; None: it fell
    mean_peak: float | None  #: mean of the peaks [m]; None if a record made the wall fall
    max_peak: float | None  #: largest peak [m]; None if a record made the wall fall
    d0: float  #: [m]
    d_limit: float  #: d_SLV or d_SLC [m]
    d0_respected: bool  #: no record exceeds d0
    mean_respected: bool  #: mean peak ≤ d_SLV
    #: d_SLV / mean peak [-], a ratio of displacements, not of PGA (0: a record made the
    #: wall fall; None: no record made it rock, the mean peak is 0)
    ratio: float | None
    passed: bool
    limit_state: str = "SLV"  #: "SLV" or "SLC"
    #: min(d_limit/mean peak, d0/largest peak) [-]: the check passes at ≥ 1; 0 when a record
    #: made the wall fall; None when no record made it rock (unbounded)
    margin: float | None = None
    #: a_g·S of the limit state [g], the PGA every record is scaled to (before ×FC); None in
    #: files written before it
    a_g: float | None = None

    @property
    def zeta_e(self) -> float | None:
        """ζ_E of the check, the number every output prints: :attr:`margin`, or
        :attr:`ratio` in files written before the margin was stored."""
        return self.margin if self.margin is not None or self.ratio is None else self.ratio


@dataclass(frozen=True)
class IdaCheck:
    """The IDA's verdict in the same terms: ζ_E = a_dyn / (FC·a_g·S) (docs/model.md §5)."""

    fc: float  #: confidence factor applied to the IDA capacity [-] (1 when turned off)
    demand: float  #: a_g·S [g]
    zeta_e_mean: float  #: mean a_dyn / (FC·a_g·S) over the records [-]
    zeta_e_least: float  #: least favourable record's a_dyn / (FC·a_g·S) [-]
    design_value: str  #: "mean" (≥ 7 records) or "least" (fewer): which ζ_E decides
    zeta_e: float  #: the deciding ζ_E [-]
    passed: bool
    #: the limit state whose a_g·S is the demand ("SLV", "SLC"); None: the assessment's
    limit_state: str | None = None


@dataclass(frozen=True)
class CaseChecks:
    """Every check of one case: the unreinforced wall or one retrofit option."""

    case: str  #: the case's name (as in results.json "cases")
    capacity: CapacitySummary
    linear: LinearCheck
    slv: LimitStateResult
    slc: LimitStateResult
    time_history: TimeHistoryResult | None  #: None: not run
    ida: IdaCheck | None  #: None: no IDA result given
    #: the time-history check against d_SLC (None: not run, or a file written before it)
    time_history_slc: TimeHistoryResult | None = None
    #: the IDA's capacity/demand a_dyn/(FC·a_g·S) at each checked limit state's own a_g·S
    #: (SLV, SLC); supporting: ``ida`` (the assessment's limit state) decides
    ida_limit_states: tuple[IdaCheck, ...] = ()

    @property
    def passed(self) -> bool:
        """Every check that was made passes."""
        parts = [self.linear.passed, self.slv.passed, self.slc.passed]
        made = (self.time_history, self.time_history_slc, self.ida)
        parts += [c.passed for c in made if c is not None]
        return all(parts)


@dataclass(frozen=True)
class LimitStateIntensity:
    """The seismic action one limit state is checked at (NTC 2018 §3.2.3.2.1)."""

    limit_state: str  #: "SLV" or "SLC"
    a_g_s: float  #: a_g·S [g], the spectrum's zero-period value
    ag: float | None  #: a_g on rock [g]; None: a spectrum without it (a table)
    S: float | None  #: S = S_S·S_T [-]; None: not an NTC spectrum
    F0: float | None  #: [-]; None: not an NTC spectrum
    Tc_star: float | None  #: T_C* [s]; None: not an NTC spectrum
    #: "site": this limit state's own spectrum from the site's coordinates; "typed": the
    #: project's one spectrum (given by its parameters), the same for every limit state
    source: str
    records: str  #: how the time-history check's records are obtained (one phrase)
    #: a set of its own (artificial, for this limit state's spectrum) passes the code's
    #: spectrum-compatibility checks (EC8 §3.2.3.1.2, NTC 2018 §3.2.3.6) against it; None:
    #: the assessment's set, whose checks are results.json "compliance"
    records_compliant: bool | None = None


@dataclass(frozen=True)
class KinematicChecks:
    """The code checks of every case, with the basis of the confidence factor."""

    knowledge_level: str  #: LC1 | LC2 | LC3
    fc: float  #: FC of the code checks [-]
    fc_basis: str  #: one sentence: where FC comes from
    fc_in_ida: bool  #: FC also divides the IDA capacity (and scales the time-history records)
    a_g: float  #: the assessment's design intensity a_g·S [g] (its limit state's)
    floor: FloorBasis | None  #: None: the wall stands at ground level
    cases: tuple[CaseChecks, ...]
    #: the action each checked limit state is checked at (SLV, SLC); empty in older files
    intensities: tuple[LimitStateIntensity, ...] = ()
    #: one sentence: whether each limit state has its own spectrum or all share one
    intensity_basis: str = ""
