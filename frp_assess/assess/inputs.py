"""What an assessment needs, as plain domain objects (the YAML schema maps onto these).

Practitioners' units are kept here (GPa, ‰, kN/m³, g) because these objects are also
written into results.json; conversion to SI happens when the dynamics models are built.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from frp_assess.assess.bar_catalogue import (
    DEFAULT_MAX_SPACING,
    DEFAULT_MIN_SPACING,
    BarLayout,
    BarSize,
)
from frp_assess.assess.bar_strain import (
    DesignStrain,
    bar_design_strain,
    fibre_of,
)
from frp_assess.assess.decision import UPGRADE, InterventionCategory
from frp_assess.assess.load_inputs import NO_LOAD_INPUTS, LoadsInput, TieInput
from frp_assess.assess.masonry_strength import masonry_strength
from frp_assess.assess.wall_model import BarsInput, WallInput, rocking_model
from frp_assess.dynamics import (
    IdaSettings,
    Mechanism,
    ModelOptions,
    Position,
    Rebars,
    RockingModel,
    Wall,
)
from frp_assess.dynamics.options import STRAIN_FACTOR, VERIFY
from frp_assess.motions import ElasticSpectrum
from frp_assess.motions.site import SiteHazard
from frp_assess.results.pivot import MasonryResult
from frp_assess.results.run_inputs import ReportSettings
from frp_assess.rules.bars import (
    DEFAULT_STRAIN_COV,
    FRACTILE_5_PERCENT,
    characteristic_strain,
    rupture_strain,
)

#: the name of case 0, the wall without bars
UNREINFORCED = "Unreinforced"


@dataclass(frozen=True)
class Material:
    """An FRP bar material."""

    name: str
    elastic_modulus: float  #: E [GPa]
    ultimate_strain: float  #: ε_u [-]
    density: float  #: [kg/m³]
    price: float  #: [currency/kg], indicative
    source: str = ""
    characteristic_strain: float | None = None  #: ε_fk [-]; None: ε_u·(1 − k·CoV), 5 %
    fibre: str | None = None  #: glass | carbon | aramid | basalt; None: by the name

    @property
    def characteristic(self) -> float:
        """ε_fk [-]: the producer's value, else the 5 % fractile of ε_u with a CoV of 0.10
        (:data:`~frp_assess.rules.bars.DEFAULT_STRAIN_COV`)."""
        if self.characteristic_strain is not None:
            return self.characteristic_strain
        return characteristic_strain(self.ultimate_strain, DEFAULT_STRAIN_COV)

    @property
    def characteristic_source(self) -> str:
        """Where ε_fk comes from (one line for results.json)."""
        if self.characteristic_strain is not None:
            return "given (characteristic_strain)"
        return f"eps_u*(1 - {FRACTILE_5_PERCENT:g}*{DEFAULT_STRAIN_COV:g}), CoV assumed"


@dataclass(frozen=True)
class RetrofitOption:
    """One retrofit option: FRP bars of a material, a position and a ratio, steel tie-rods
    (``tie``), or both (docs/model.md §12).

    ``ratio`` is the ratio the model uses: the ratio installed by whole bars of ``layout``
    (``bars.whole_bars``, the default), else the ratio asked; ``ratio_asked`` is the
    project's (0: not given, i.e. equal to ``ratio``).  A tie alone has no ``material`` nor
    ``position`` and ratio 0.
    """

    name: str
    material: Material | None  #: None: a tie alone
    position: Position | None  #: None: a tie alone
    ratio: float  #: ρ [‰], active bars, as the model uses it
    ratio_asked: float = 0.0  #: ρ asked [‰]
    diameter: float | None = None  #: bar diameter asked [mm]; None: chosen by the layout
    layout: BarLayout | None = None  #: the bars over the wall
    tie: TieInput | None = None  #: tie-rods the option adds to the wall's loads

    @property
    def asked(self) -> float:
        """ρ asked [‰]."""
        return self.ratio_asked or self.ratio

    @property
    def kind(self) -> str:
        """``bars``, ``tie`` or ``bars+tie`` (results.json's ``kind``)."""
        if self.material is None:
            return "tie"
        return "bars" if self.tie is None else "bars+tie"


@dataclass(frozen=True)
class ArtificialRecords:
    count: int = 7
    seed: int = 1
    duration: float = 25.0  #: [s]
    dt: float = 0.005  #: [s]


@dataclass(frozen=True)
class RecordFile:
    path: str  #: absolute, or relative to the working directory
    format: str = "auto"
    units: str = "g"
    dt: float | None = None  #: [s], one-column files only
    name: str | None = None


@dataclass(frozen=True)
class DesignRequest:
    """Design mode: the smallest ratio meeting the target, per material and position."""

    materials: tuple[Material, ...]
    positions: tuple[Position, ...]
    ratio_range: tuple[float, float] = (0.5, 5.0)  #: [‰]
    resolution: float = 0.05  #: [‰]


@dataclass(frozen=True)
class TiePrices:
    """Prices of a tie-rod (``costs.tie_*``), each 0 when not given."""

    steel_per_kg: float = 0.0  #: [currency/kg] of the tie's bar
    steel_per_metre: float = 0.0  #: [currency/m] of the tie's bar
    plate: float = 0.0  #: [currency] per anchorage plate, two per tie
    installation: float = 0.0  #: [currency] per tie

    @property
    def given(self) -> bool:
        """Some price is given (else a tie costs 0: the outputs say costs not given)."""
        return any(
            p > 0 for p in (self.steel_per_kg, self.steel_per_metre, self.plate, self.installation)
        )


@dataclass(frozen=True)
class CostSettings:
    currency: str = "EUR"
    installation_per_metre: float = 0.0  #: per metre of wall length and layer of bars
    ties: TiePrices = TiePrices()


@dataclass(frozen=True)
class AnchorageSettings:
    """Bond of the bars in resin-filled holes (``bars.anchorage``)."""

    hole_clearance: float  #: d_h − d [mm]
    bond_bar: float  #: τ_b, bar–resin [MPa]
    bond_masonry: float  #: τ_m, resin–masonry [MPa]
    tensile_strength: float | None = None  #: f_t of the masonry [MPa]; None: 1.5·τ0d


@dataclass(frozen=True)
class BarSettings:
    """The bars as built (``bars:``, docs/model.md §2.1)."""

    exposure: str = "external"  #: internal | external | aggressive
    design_values: bool = True  #: ε_d = c·η_a·ε_fk/γ_f; False: c·ε_u
    whole_bars: bool = True  #: the model uses the installed ratio; False: the asked one
    min_spacing: float = DEFAULT_MIN_SPACING  #: [m]
    max_spacing: float = DEFAULT_MAX_SPACING  #: [m]
    catalogue: tuple[BarSize, ...] = ()  #: the project's sizes
    anchorage: AnchorageSettings | None = None


@dataclass(frozen=True)
class CodeCheckSettings:
    knowledge_level: str = "LC1"  #: LC1 | LC2 | LC3
    behaviour_factor: float = 2.0  #: q of Circolare 2019 §C8.7.1
    #: FC also divides the IDA capacity, a_dyn/(FC·a_g·S) (assess.kinematic_checks)
    fc_in_ida: bool = True


@dataclass(frozen=True)
class BuildingSettings:
    """Where the wall stands in the building (docs/model.md §9): its rocking base moves with
    the absolute acceleration of the floor at Z (first mode only, Circolare 2019 §C7.2.3)."""

    height: float  #: H_b [m], height of the building above the foundation
    storeys: int  #: n [-]
    wall_base: float  #: Z [m], height of the wall's rocking base, 0 <= Z < H_b
    period: float  #: T1 [s], fundamental period of the building
    damping: float = 0.05  #: ξ1 [-], damping ratio of its first mode

    @property
    def z_over_h(self) -> float:
        """Z/H_b [-], the linear first mode ψ1(Z) at the wall's base."""
        return self.wall_base / self.height


@dataclass(frozen=True)
class AssessmentInputs:
    """One wall, its site, its candidate retrofits and the analysis settings."""

    thickness: float  #: B [m]
    height: float  #: H [m]
    unit_weight: float  #: w [kN/m³]
    mechanism: Mechanism
    spectrum: ElasticSpectrum
    records: ArtificialRecords | tuple[RecordFile, ...]
    options: tuple[RetrofitOption, ...] = ()
    length: float = 1.0  #: L [m]
    masonry: str | None = None
    masonry_description: str = ""
    compressive_strength: float | None = None  #: f_m given by the project [MPa]
    scale_to_spectrum: bool = True
    t1: float = 1.0  #: reference period of the compliance checks [s]
    model: ModelOptions = ModelOptions()
    #: repeat every IDA at a 10× tighter tolerance (docs/model.md §4.5)
    verify: bool = VERIFY.default
    strain_factor: float = STRAIN_FACTOR.default
    ida: IdaSettings = IdaSettings()
    target: float = 1.0  #: required mean capacity/demand
    costs: CostSettings = CostSettings()
    design: DesignRequest | None = None
    code_check: CodeCheckSettings = CodeCheckSettings()
    #: where the wall stands in the building; None: at ground level (shaken by the ground)
    building: BuildingSettings | None = None
    project: dict[str, str] = field(default_factory=dict)
    input_file: str = ""
    #: the project's values outside the range of practice, ``key: message`` each
    #: (:mod:`frp_assess.config.plausibility`); stored in results.json's input_warnings
    warnings: tuple[str, ...] = ()
    bars: BarSettings = BarSettings(design_values=False, whole_bars=False)
    #: the report's language and Word template
    report: ReportSettings = ReportSettings()
    #: the site's hazard when the spectrum is given by coordinates (docs/site-hazard.md), and
    #: the limit state whose a_g, F0, T_C* make ``spectrum``
    site: SiteHazard | None = None
    site_limit_state: str = "SLV"
    #: what bears on and pushes the wall (docs/model.md §12); empty: free-standing
    loads: LoadsInput = NO_LOAD_INPUTS
    #: the category of the intervention: what an option must reach (NTC 2018 §8.4)
    intervention: InterventionCategory = UPGRADE

    @property
    def masonry_strength(self) -> MasonryResult:
        """f_m and f_d of the masonry (docs/model.md §1.1): the project's value, else the
        type's by the knowledge level, else the lowest of Tab. C8.5.I."""
        return masonry_strength(
            self.masonry, self.code_check.knowledge_level, self.compressive_strength
        )

    @property
    def wall_input(self) -> WallInput:
        """The wall of the model, with f_d for the crushing pivot (assess/wall_model.py)."""
        return WallInput(self.thickness, self.height, self.unit_weight, self.masonry_strength.f_d)

    @property
    def wall(self) -> Wall:
        """The dynamics wall (SI), with f_d for the crushing pivot."""
        return self.wall_input.wall()

    def design_strain(self, material: Material) -> DesignStrain | None:
        """ε_d = c·η_a·ε_fk/γ_f of ``material`` with c = ``strain_factor`` (docs/model.md
        §2.1), or None when the design values are off."""
        if not self.bars.design_values:
            return None
        return bar_design_strain(
            material.characteristic,
            material.name,
            self.bars.exposure,
            cyclic_factor=self.strain_factor,
            fibre=fibre_of(material.name, material.fibre),
        )

    def strain_at_rupture(self, material: Material) -> float:
        """The bar's strain at rupture that the cyclic factor c multiplies [-]: ε_fd =
        η_a·ε_fk/γ_f with design values, else the mean ε_u (docs/model.md §2.1)."""
        d = self.design_strain(material)
        return material.ultimate_strain if d is None else d.fd

    def rupture_strain(self, material: Material) -> float:
        """The rupture strain the model uses [-]: ε_max = c·ε_fd with design values, else
        c·ε_u (:func:`~frp_assess.rules.bars.rupture_strain`)."""
        return rupture_strain(self.strain_at_rupture(material), self.strain_factor)

    def bars_input(self, material: Material, position: Position, ratio: float) -> BarsInput:
        """The bars of the model.  The cyclic factor c stays the model's ``strain_factor``;
        the strain it multiplies is :meth:`strain_at_rupture`, so that c is applied once."""
        return BarsInput(
            material.elastic_modulus,
            self.strain_at_rupture(material),
            position,
            ratio,
            self.strain_factor,
        )

    def rebars(self, material: Material, position: Position, ratio: float) -> Rebars:
        """The dynamics bars (SI) of :meth:`bars_input`."""
        return self.bars_input(material, position, ratio).rebars()

    def model_of(self, material: Material, position: Position, ratio: float) -> RockingModel:
        """The dynamics model of the wall with bars of ``material`` at ``position`` and ρ
        ``ratio`` [‰] (assess/wall_model.py)."""
        bars = self.bars_input(material, position, ratio)
        return rocking_model(
            self.wall_input, self.mechanism, bars, self.model, loads=self.loads.loads()
        )

    def loads_for(self, option: RetrofitOption | None) -> LoadsInput:
        """The loads of the wall of ``option``: the wall's, with the option's tie added to its
        ties (the path every tie takes into the model, docs/model.md §12)."""
        if option is None or option.tie is None:
            return self.loads
        return replace(self.loads, ties=(*self.loads.ties, option.tie))

    def model_for(self, option: RetrofitOption | None) -> RockingModel:
        """The dynamics model of the unreinforced wall (``None``) or of an option: its bars
        (none for a tie alone) and the wall's loads with the option's tie."""
        loads = self.loads_for(option).loads()
        if option is None or option.material is None or option.position is None:
            return rocking_model(self.wall_input, self.mechanism, None, self.model, loads=loads)
        bars = self.bars_input(option.material, option.position, option.ratio)
        return rocking_model(self.wall_input, self.mechanism, bars, self.model, loads=loads)

    def case_models(self) -> list[RockingModel]:
        """The models of every case of a run: the unreinforced wall, then each option."""
        return [self.model_for(None), *(self.model_for(o) for o in self.options)]

    def case_names(self) -> list[str]:
        """The names of the cases, in the order of :meth:`case_models`."""
        return [UNREINFORCED, *(o.name for o in self.options)]
