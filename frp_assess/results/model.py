"""The results of an assessment as frozen dataclasses: the definition of results.json.

One class per JSON object of docs/results-json.md; field names equal the JSON keys and are
declared in the order they are written, so :func:`frp_assess.results.json_io.to_json` of an
:class:`AssessmentResult` *is* results.json.  Sequences are tuples.  Units (as in the JSON):
lengths m, angles rad (unless ``_deg``), accelerations g, masses kg, times s, strains [-],
costs in ``costs.currency``.  A field with a default may be missing from a file (it was added
later); :data:`SCHEMA_VERSION` changes only when a file of the old version cannot be read
as this one.

The objects that record what the run was given (software, project, wall, settings,
materials, costs, seismic input, site, building) are in :mod:`frp_assess.results.run_inputs`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from frp_assess.results.as_built import AsBuilt
from frp_assess.results.carried_loads import LoadsResult, TieOptionResult
from frp_assess.results.checks import KinematicChecks
from frp_assess.results.independent import IndependentCheck
from frp_assess.results.pivot import MasonryResult, PivotResult
from frp_assess.results.run_inputs import BuildingResult as BuildingResult  # re-export
from frp_assess.results.run_inputs import (
    Costs,
    MaterialResult,
    ModelSettings,
    ProjectInfo,
    SeismicResult,
    Software,
    WallResult,
)
from frp_assess.results.run_inputs import FloorSpectraResult as FloorSpectraResult  # re-export
from frp_assess.results.run_inputs import LimitStateSite as LimitStateSite  # re-export
from frp_assess.results.run_inputs import ReportSettings as ReportSettings  # re-export
from frp_assess.results.run_inputs import SiteResult as SiteResult  # re-export
from frp_assess.results.verdict import DecidingCheck, InterventionResult, Robustness
from frp_assess.rules.record_sets import design_statistic

#: version of the contract written as ``schema_version``; another is refused on reading
SCHEMA_VERSION = 2
#: the name of the unreinforced wall's case
UNREINFORCED = "Unreinforced"


@dataclass(frozen=True)
class Demand:
    """The seismic demand: pga = a_g·S [g]."""

    pga: float


@dataclass(frozen=True)
class RecordInfo:
    """One ground motion: pga [g], duration [s], dt [s], 5 % spectrum ``sa`` at
    ``seismic.periods`` [g]."""

    name: str
    source: str
    pga: float
    duration: float
    dt: float
    scale_factor: float
    sa: tuple[float, ...]


@dataclass(frozen=True)
class ComplianceCheck:
    """One spectrum-compatibility check; ``margin`` in ``unit`` ("" = a ratio)."""

    code: str
    clause: str
    requirement: str
    found: str
    passed: bool
    margin: float
    unit: str


@dataclass(frozen=True)
class Compliance:
    """The record set against the code's spectrum-compatibility checks."""

    passed: bool
    checks: tuple[ComplianceCheck, ...]


@dataclass(frozen=True)
class CodeCheck:
    """NTC 2018 / Circolare 2019 §C8.7.1 linear kinematic check of the unreinforced wall:
    alpha0 load multiplier [-], e_star [-], M_star [kg/m], FC [-], behaviour factor [-],
    a0_star and demand [g] (a_g·S/q at ground level, a_Z/q above it: the floor's peak
    acceleration at the wall's base), ratio a0_star/demand [-]."""

    alpha0: float
    e_star: float
    M_star: float
    FC: float
    confidence_factor_level: str
    behaviour_factor: float
    a0_star: float
    demand: float
    ratio: float
    passed: bool
    note: str


#: one point of an IDA curve: (multiplier C [-], collapsed, peak |theta|/alpha [-])
CurvePoint = tuple[float, bool, float]


@dataclass(frozen=True)
class RecordResult:
    """The IDA of one case under one record: pga [g]; collapse multiplier C [-]; largest
    multiplier run without collapse [-]; a_dyn = C·pga [g]; q = a_dyn/a_rm [-] (multiplier,
    a_dyn and q None: no collapse up to C_max); ``curve``: every C the search ran, sorted."""

    record: str
    pga: float
    collapse_multiplier: float | None
    survivor_multiplier: float | None
    a_dyn: float | None
    q: float | None
    curve: tuple[CurvePoint, ...]
    #: PGA of the motion at the wall's base [g]: the floor motion at Z for a wall above
    #: ground (unscaled, as the IDA received it); None at ground level (it is ``pga``)
    floor_pga: float | None = None
    #: how the wall failed at the first collapse (docs/model.md §1.1): overturning | rupture
    #: then overturning | crushing | rupture then crushing | tie lost then overturning |
    #: rupture and tie lost then overturning; None without collapse
    failure_mode: str | None = None
    #: the lowest C that collapsed on the sampling: the first collapse, the paper's
    #: convention (with ``capacity: first-collapse`` it is ``collapse_multiplier``) [-]
    first_collapse_multiplier: float | None = None
    #: collapse windows (runs of collapsed samples) that begin below the capacity [-]
    windows_below: int = 0
    #: without a capacity (``collapse_multiplier`` None): the multiplier of its lower bound,
    #: the one the case's means use (C_max, or the effective intensity counted up to C_max) [-]
    lower_bound_multiplier: float | None = None


@dataclass(frozen=True)
class CollapseFraction:
    """The records that collapsed at one intensity of the ladder of docs/model.md §11:
    intensity a_dyn [g] (for a wall above ground, the mean of the records' own), the number of
    records that collapsed there (an early stop of the sampling counts as collapsed) and of
    records [-]."""

    intensity: float
    collapsed: int
    records: int


@dataclass(frozen=True)
class Fragility:
    """Lognormal fit: median [g], beta [-], method (mle | censored-mle: to the records'
    capacities; binomial-mle: to the collapse fractions at the sampled intensities, with the
    effective collapse intensity), P(collapse) at a_g·S [-]."""

    median: float
    beta: float
    method: str
    p_collapse_at_demand: float


@dataclass(frozen=True)
class Scatter:
    """How far a case's number can be trusted: median and standard deviation of a_dyn over
    the records [g], CoV [-]; records without collapse enter at C_max·PGA (a lower bound);
    ``fragility`` None with fewer than 2 distinct collapse values."""

    median_a_dyn: float
    std_a_dyn: float
    cov: float
    least_favourable_record: str
    records_without_collapse: int
    fragility: Fragility | None
    #: the collapse fraction of the records at each intensity of the ladder (docs/model.md
    #: §11), from the lowest up to the highest any record ran; empty with first-collapse
    collapse_fraction: tuple[CollapseFraction, ...] = ()


@dataclass(frozen=True)
class CaseResult:
    """One case (the unreinforced wall, or a retrofit option).

    ratio [‰]; elastic_modulus [GPa]; ultimate_strain [-]; K restraint stiffness term of
    Eq. 10 [-]; theta_max rupture rotation [rad]; accelerations (mean/min/design a_dyn) [g];
    q [-]; capacity_demand = design_a_dyn / (fc·demand.pga) [-] (a lower bound when
    ``lower_bound``); improvement = design_a_dyn over that of the unreinforced wall [-];
    frp_mass_per_m [kg/m]; frp_mass [kg] and frp_cost [currency] for the whole wall (of the
    bars as built when ``as_built`` is set); rank 1 = the first by the ranking rule (the
    recommendation only if ``recommended``), None for the unreinforced wall; q and mean_q are
    over a_RM = g·tan α_x (the same for every case of a wall).
    """

    name: str
    material: str | None
    position: str | None
    ratio: float
    elastic_modulus: float | None
    ultimate_strain: float | None
    K: float
    theta_max: float | None
    records: tuple[RecordResult, ...]
    mean_a_dyn: float
    min_a_dyn: float
    mean_q: float
    design_a_dyn: float
    lower_bound: bool  #: some record did not collapse up to C_max: a_dyn are lower bounds
    capacity_demand: float
    improvement: float
    scatter: Scatter
    frp_mass_per_m: float
    frp_mass: float
    frp_cost: float
    #: the IDA check alone: capacity/demand ≥ target (a lower bound counted at its bound);
    #: the verdict is ``passes``
    meets_target: bool
    rank: int | None  #: None: the unreinforced wall
    #: ρ asked [‰] (``ratio`` is the ratio the model uses: installed with bars.whole_bars);
    #: None for the unreinforced wall
    ratio_asked: float | None = None
    #: the bars as they will be built (None: unreinforced, or an option that cannot be built,
    #: which only bars.whole_bars: false lets through)
    as_built: AsBuilt | None = None
    #: the compression at the pivot and the drop rule (None in files written before it)
    pivot: PivotResult | None = None
    #: FC [-], the confidence factor dividing this case's capacity/demand (the knowledge
    #: level's, Circolare 2019 Tab. C8.5.IV; 1.0 when code_check.fc_in_ida is false)
    fc: float = 1.0
    #: the failure mode met most often over the records (``records[i].failure_mode``; a tie
    #: goes to the mode of the least favourable record among the tied); None when no record
    #: collapsed up to C_max
    failure_mode: str | None = None
    #: the deciding checks (docs/results-json.md, "The decision"); () in older files
    deciding_checks: tuple[DecidingCheck, ...] = ()
    #: every deciding check passes; None: not decided (an older file)
    passes: bool | None = None
    #: the deciding check with the smallest margin, and that margin [-] (None: unbounded)
    governing_check: str | None = None
    governing_margin: float | None = None
    governing_lower_bound: bool = False  #: the governing margin is a lower bound
    #: this case is the recommendation (the cheapest passing option)
    recommended: bool = False
    #: "option" (from interventions) or "design" (a design-mode answer)
    source: str = "option"
    #: one sentence explaining an odd result (weaker than the bare wall, q < 1); None: none
    remark: str | None = None
    #: "tie" (tie-rods alone) or "bars+tie"; None (not written): FRP bars, or the
    #: unreinforced wall
    kind: str | None = field(default=None, metadata={"omit_if_none": True})
    #: the tie-rods the option adds to the wall's loads, their steel and cost (None: none)
    tie: TieOptionResult | None = field(default=None, metadata={"omit_if_none": True})

    @property
    def is_unreinforced(self) -> bool:
        """The case without bars nor tie."""
        return self.material is None and self.tie is None

    @property
    def option_cost(self) -> float:
        """What the option costs [currency]: its bars and its tie (the ranking's cost)."""
        return self.frp_cost + (0.0 if self.tie is None else self.tie.cost)

    @property
    def option_mass(self) -> float:
        """FRP and tie steel [kg] (the ranking's second key)."""
        return self.frp_mass + (0.0 if self.tie is None else self.tie.steel_mass)


@dataclass(frozen=True)
class DesignRow:
    """Design mode, one (material, position): the smallest ratio on the grid passing every
    deciding check [‰] (None: none in range), its IDA capacity/demand [-], FRP mass [kg] and
    cost [currency]."""

    material: str
    position: str
    ratio: float | None
    capacity_demand: float | None
    frp_mass: float | None
    frp_cost: float | None
    message: str
    #: the bars of the answer as they will be built (None: no ratio met the target)
    as_built: AsBuilt | None = None
    #: the name of the case this answer was added as (None: no answer, or an option of the
    #: same material, position and ratio already in ``cases``)
    case: str | None = None


@dataclass(frozen=True)
class RuptureResult:
    """A bar broke at ``time`` [s]; ``side`` is the sign of theta then."""

    time: float
    side: int


@dataclass(frozen=True)
class HistoryRun:
    """One time history: multiplier [-]; fate fell | at rest | exceeded | standing;
    decided_time [s]; peak |theta|/alpha [-]; peak strain of an intact acting bar [-];
    ``time`` [s], ``theta_over_alpha`` [-] and ``strain`` [-] sampled alike."""

    label: str
    multiplier: float
    collapsed: bool
    fate: str
    decided_time: float | None
    peak_rotation_ratio: float
    peak_strain: float
    ruptures: tuple[RuptureResult, ...]
    impacts: int
    time: tuple[float, ...]
    theta_over_alpha: tuple[float, ...]
    strain: tuple[float, ...]


@dataclass(frozen=True)
class Governing:
    """Time histories of one case under the record failing first, at collapse and just
    below; rupture_strain eps_max = c·eps_u [-] (None when unreinforced)."""

    case: str
    record: str
    runs: tuple[HistoryRun, ...]
    rupture_strain: float | None


@dataclass(frozen=True)
class NumericalCheckResult:
    """The verification run (docs/model.md §4.5): tolerances [-]; largest relative change of
    a collapse multiplier [-] (None when a record collapsed in one run only, then
    ``fate_changed``), where it was, and how many (case, record) pairs moved."""

    tolerance: float
    check_tolerance: float
    max_change: float | None
    fate_changed: bool
    case: str
    record: str
    changed_pairs: int
    pairs: int


@dataclass(frozen=True)
class SensitivityRowResult:
    """One model convention: design a_dyn [g], capacity/demand [-]."""

    variant: str
    design_a_dyn: float
    capacity_demand: float
    lower_bound: bool


@dataclass(frozen=True)
class Sensitivity:
    """One case under each model convention."""

    case: str
    rows: tuple[SensitivityRowResult, ...]


@dataclass(frozen=True)
class AssessmentResult:
    """Everything ``frp-assess run`` found: the content of results.json.

    ``cases[0]`` is the unreinforced wall; ``recommended`` names the cheapest option passing
    every deciding check (or None; ``closest`` then names the nearest); ``governing``,
    ``design``, ``numerical_check``, ``sensitivity`` and ``robustness`` are None when not
    computed.
    """

    schema_version: int
    software: Software
    created: str  #: ISO date of the run
    input_file: str
    project: ProjectInfo
    wall: WallResult
    model: ModelSettings
    materials: dict[str, MaterialResult]
    costs: Costs
    seismic: SeismicResult
    demand: Demand
    records: tuple[RecordInfo, ...]
    compliance: Compliance
    code_check: CodeCheck
    cases: tuple[CaseResult, ...]
    ranking_rule: str
    recommended: str | None
    retrofit_required: bool
    design: tuple[DesignRow, ...] | None
    governing: Governing | None
    numerical_check: NumericalCheckResult | None
    input_warnings: tuple[str, ...]
    input_code_compliant: bool
    sensitivity: Sensitivity | None
    #: where the wall stands in the building; None: at ground level
    building: BuildingResult | None = None
    #: the floor spectra at the wall's base; None: at ground level
    floor_spectra: FloorSpectraResult | None = None
    #: the masonry strength behind the pivot check (None in files written before it)
    masonry_strength: MasonryResult | None = None
    #: the code's kinematic checks of every case (Circolare 2019 §C8.7.1); None: not computed
    kinematic_checks: KinematicChecks | None = None
    #: the decision rule in words ("" in older files)
    decision_rule: str = ""
    #: when nothing passes: the option with the largest governing margin; else None
    closest: str | None = None
    #: how firm the verdict is; None: not computed
    robustness: Robustness | None = None
    #: the report's language and Word template (None in files written before it: English)
    report: ReportSettings | None = None
    #: the site, when the spectrum is given by its coordinates; the key is absent otherwise
    site: SiteResult | None = field(default=None, metadata={"omit_if_none": True})
    #: "sha256:<hex>" of what the results depend on (project file, record files, frp-assess
    #: version, --rtol/--verify: frp_assess/app/rerun.py); None (the key absent) when not known
    inputs_digest: str | None = field(default=None, metadata={"omit_if_none": True})
    #: the independent checks of NTC 2018 §10.2 (frp_assess.assess.independent_checks); the
    #: key is absent in files written before them
    independent_checks: tuple[IndependentCheck, ...] | None = field(
        default=None, metadata={"omit_if_none": True}
    )
    #: the loads the wall carries and α₀ with them (docs/model.md §12); the key is absent
    #: without loads
    loads: LoadsResult | None = field(default=None, metadata={"omit_if_none": True})
    #: the category of the intervention and what an option had to reach (NTC 2018 §8.4);
    #: None in files written before it (they were judged as an upgrade)
    intervention: InterventionResult | None = None

    @property
    def urm(self) -> CaseResult:
        """The unreinforced wall (the first case by contract)."""
        return self.cases[0]

    @property
    def design_is_mean(self) -> bool:
        """design_a_dyn is the mean over the records, else the least favourable record
        (:func:`frp_assess.rules.record_sets.design_statistic`, NTC 2018 §7.3.5)."""
        return design_statistic(len(self.records)) == "mean"

    def case(self, name: str | None) -> CaseResult | None:
        """The case called ``name``, or None."""
        return next((c for c in self.cases if c.name == name), None)

    @property
    def options(self) -> tuple[CaseResult, ...]:
        """The retrofit options (every case but the unreinforced wall)."""
        return tuple(c for c in self.cases if not c.is_unreinforced)

    @property
    def ranked_options(self) -> tuple[CaseResult, ...]:
        """The options by rank (1 first); unranked ones last, in file order."""
        return tuple(sorted(self.options, key=lambda c: (c.rank is None, c.rank or 0)))
