"""What a run was given, as results.json records it: the software, the project's identification,
the wall, the model and IDA settings, the materials, the costs, the seismic input, the site
and the building.

Plain frozen dataclasses (standard library only), as :mod:`frp_assess.results.model`: field
names are the JSON keys, in the order written; units in each docstring.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Software:
    """The program that wrote the file."""

    name: str
    version: str


@dataclass(frozen=True)
class ReportSettings:
    """How the report is written: ``language`` en | it; ``template``: the Word file whose
    styles the DOCX report uses (a path as the run resolved it, or None)."""

    language: str = "en"
    template: str | None = None


@dataclass(frozen=True)
class ProjectInfo:
    """Who and where, as typed in the project file (free text)."""

    name: str = ""
    location: str = ""
    engineer: str = ""
    notes: str = ""


@dataclass(frozen=True)
class WallResult:
    """The wall: thickness, height, length [m]; unit_weight [kN/m³]; alpha [rad] with
    tan(alpha) = B/H, alpha_deg [°]; R half diagonal [m]; p frequency parameter [rad/s];
    mass per metre of wall [kg/m]; a_rm [g]: the unreinforced wall's model's, about its pivot
    (g·tan(alpha) with pivot: edge, g·(B − x)/H with pivot: crushing)."""

    thickness: float
    height: float
    length: float
    masonry: str | None  #: library key, or None when typed in
    masonry_description: str | None
    unit_weight: float
    mechanism: str  #: one-sided | two-sided
    alpha: float
    alpha_deg: float
    R: float
    p: float
    mass: float
    a_rm: float


@dataclass(frozen=True)
class Integration:
    """The integrator: local error tolerance [-] (docs/model.md §4.2); ``verify``: the
    numerical check was computed."""

    method: str
    tolerance: float
    verify: bool


@dataclass(frozen=True)
class IdaSettingsResult:
    """The IDA search: step ratio of the multiplier [-], relative tolerance on the collapse
    multiplier [-], largest multiplier C_max [-]; ``capacity``: the capacity of a record,
    effective (the effective collapse intensity, docs/model.md §11) | first-collapse (the
    first collapse, the paper's convention, §5); ``ladder_ratio`` r and ``offset``: the
    ladder of §11, C₀·r^(k+offset) [-]; ``early_stop_band``: the ladder stops once the wall
    has fallen at every step over this ratio of multipliers [-] (§11.2; a file written before
    it was recorded ran with 1.5); ``coarse_steps`` and ``fine_margin``: the default sampling
    of §11.2 (design (e)) runs the coarse ladder r^coarse_steps up to the first collapse and
    the fine one from fine_margin below it (1: the plain ladder r, every change bisected; a
    file written before they were recorded ran it)."""

    step_ratio: float
    tolerance: float
    max_multiplier: float
    capacity: str = "first-collapse"
    ladder_ratio: float = 1.05
    offset: float = 0.0
    early_stop_band: float = 1.5
    coarse_steps: int = 1
    fine_margin: float = 1.35


@dataclass(frozen=True)
class ModelSettings:
    """The model conventions of the run; restitution_ratio is the velocity ratio applied at
    an impact of the unreinforced wall's model, at the slenderness about its pivot [-],
    strain_factor c of eps_max = c·eps_u [-], free_vibration_tail [s], target
    capacity/demand [-]; design_value says how design_a_dyn is taken (prose)."""

    restitution: str | float  #: energy | velocity, or the coefficient itself [-]
    restitution_ratio: float
    rupture: str
    collapse: str  #: overturning | end-of-record | first-exceedance
    strain_factor: float
    free_vibration_tail: float
    integration: Integration
    ida: IdaSettingsResult
    target: float
    design_value: str


@dataclass(frozen=True)
class MaterialResult:
    """A bar material used by some case: E [GPa], ultimate strain [-], density [kg/m³],
    price [currency/kg]."""

    elastic_modulus: float
    ultimate_strain: float
    density: float
    price: float
    source: str


@dataclass(frozen=True)
class TiePricesResult:
    """The prices of a tie-rod (``costs.tie_*``) [currency/kg, currency/m, currency per
    plate (two per tie), currency per tie]; 0: not given."""

    steel_per_kg: float
    steel_per_metre: float
    plate: float
    installation: float


@dataclass(frozen=True)
class Costs:
    """Currency of every cost, installation cost per metre of bar [currency/m]; the tie's
    prices when some option has a tie (else not written)."""

    currency: str
    installation_per_metre: float
    ties: TiePricesResult | None = field(default=None, metadata={"omit_if_none": True})


@dataclass(frozen=True)
class SpectrumResult:
    """The elastic spectrum: ag_S = a_g·S [g]; corner periods [s] (None for tables);
    ``parameters`` as given and derived (numbers, text or lists, by spectrum type)."""

    type: str
    name: str
    description: str
    parameters: dict[str, object]
    ag_S: float
    T_B: float | None
    T_C: float | None
    T_D: float | None


@dataclass(frozen=True)
class Generator:
    """How artificial records were generated: duration [s], time step dt [s]."""

    method: str
    count: int
    seed: int
    duration: float
    dt: float


@dataclass(frozen=True)
class SeismicResult:
    """The seismic input: t1 reference period of the compliance checks [s]; periods [s];
    target_sa and mean_sa (mean 5 % spectrum of the records) at ``periods`` [g]."""

    spectrum: SpectrumResult
    t1: float
    records_kind: str  #: artificial | recorded
    generator: Generator | None  #: None for recorded motions
    scale_factor: float  #: common factor applied to record files (1 for artificial) [-]
    periods: tuple[float, ...]
    target_sa: tuple[float, ...]
    mean_sa: tuple[float, ...]


@dataclass(frozen=True)
class LimitStateSite:
    """One limit state at the site (NTC 2018 Tab. 3.2.I): P_VR [-]; TR [years] =
    −V_R/ln(1 − P_VR); TR_used [years], TR limited to the grid's 30–2475; ag [g] on rock,
    F0 [-], Tc_star = T_C* [s] interpolated on the NTC reference grid at TR_used."""

    P_VR: float
    TR: float
    TR_used: float
    ag: float
    F0: float
    Tc_star: float


@dataclass(frozen=True)
class SiteResult:
    """The site when the spectrum is given by its coordinates (docs/site-hazard.md):
    latitude, longitude [°]; V_N nominal life [years]; use class I–IV; C_U [-];
    V_R = max(V_N·C_U, 35) [years]; the four limit states SLO, SLD, SLV, SLC in order;
    ``limit_state`` the one whose a_g, F0, T_C* make the spectrum; nearest_node [km] the
    distance to the nearest grid node; ``interpolation`` "cell" (the four vertices of the
    grid cell containing the site, NTC 2008 Allegato A) or "nearest" (the four nearest
    nodes: no complete cell contains the site, at the grid's border)."""

    latitude: float
    longitude: float
    V_N: float
    use_class: str
    C_U: float
    V_R: float
    limit_states: dict[str, LimitStateSite]
    limit_state: str
    nearest_node: float
    interpolation: str = "cell"


@dataclass(frozen=True)
class BuildingResult:
    """Where the wall stands in the building (project block ``building``, docs/model.md §9):
    height H_b [m], storeys n [-], wall_base Z [m], z_over_h = Z/H_b = ψ1(Z) [-], period T1
    [s] used, period_default = 0.05·H_b^0.75 [s] (Circolare 2019 eq. C7.3.2; equal to
    ``period`` unless the project gave T1), damping ξ1 [-], gamma1 = 3n/(2n+1) [-], psi1 =
    Z/H_b [-] (Circolare 2019 §C7.2.3, eq. C7.2.10)."""

    height: float
    storeys: int
    wall_base: float
    z_over_h: float
    period: float
    period_default: float
    damping: float
    gamma1: float
    psi1: float
    shaken_by: str  #: one sentence: what moves the wall's base, and in which terms a_dyn is


@dataclass(frozen=True)
class FloorSpectraResult:
    """5 % pseudo-acceleration spectra at the wall's base, all in g at ``periods`` [s]: the
    mean of the records' floor motions (unscaled, as the IDA received them), the code's floor
    spectrum at Z of the target ground spectrum (Circolare 2019 eqs. C7.2.5-C7.2.9, first
    mode), the target ground spectrum, and each record's own floor spectrum (by record, in
    the order of ``records``)."""

    periods: tuple[float, ...]
    mean: tuple[float, ...]
    code: tuple[float, ...]
    ground: tuple[float, ...]
    records: tuple[tuple[float, ...], ...]
