"""The project file as pydantic v2 models (``extra="forbid"``, units in every description).

The root model is :class:`Project`.  Field names are the YAML keys of issue 4.  Numbers are
strict (a quoted ``"0.4"`` or a ``yes`` is an error, not a silent conversion); free-text fields
accept any scalar.  Cross-checks that need several fields (B < H, known materials and masonry,
exactly one record source) raise :class:`~pydantic_core.PydanticCustomError` whose context
``loc`` completes the location of the error, so that the loader can point at the right line.
"""

from __future__ import annotations

import datetime as _dt
import functools
import math
from pathlib import PurePath
from typing import Annotated, Any, Literal, get_args

from pydantic import (
    AllowInfNan,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Discriminator,
    Field,
    Strict,
    Tag,
    WithJsonSchema,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError

from frp_assess.config.library import FRP_MATERIALS, MASONRY, FrpMaterial, did_you_mean
from frp_assess.dynamics.base_reaction import PivotRule
from frp_assess.dynamics.ida import IdaSettings
from frp_assess.dynamics.options import (
    COLLAPSE,
    FREE_VIBRATION_TAIL,
    IDA_MAX_MULTIPLIER,
    IDA_OPTIONS,
    IDA_STEP_RATIO,
    IDA_TOLERANCE,
    INTEGRATION_TOLERANCE,
    MODEL_OPTIONS,
    PIVOT,
    RESTITUTION,
    RUPTURE,
    STRAIN_FACTOR,
    VERIFY,
    CollapseRule,
    Option,
    RuptureRule,
)
from frp_assess.dynamics.rebars import POSITIONS, Position
from frp_assess.dynamics.rocking import ModelOptions
from frp_assess.dynamics.wall import Mechanism
from frp_assess.errors import InputError
from frp_assess.motions.floor import default_period
from frp_assess.motions.site import SiteHazard, site_hazard
from frp_assess.rules.bars import MAX_RATIO
from frp_assess.rules.geometry import slenderness_problem
from frp_assess.rules.masonry import CONFIDENCE_FACTORS as CONFIDENCE_FACTORS  # re-export
from frp_assess.rules.masonry import confidence_factor

#: the hazard of a site, computed once per (latitude, longitude, V_N, use class)
site_hazard_cached = functools.lru_cache(maxsize=64)(site_hazard)

GroundType = Literal["A", "B", "C", "D", "E"]

#: accepted ``format`` of a record file (as frp_assess.motions.readers.FORMATS)
RecordFormat = Literal["auto", "at2", "esm", "two-column", "one-column"]
RECORD_FORMATS: tuple[str, ...] = get_args(RecordFormat)
#: accepted ``units`` of a record file (as frp_assess.motions.readers.UNITS)
RecordUnits = Literal["g", "m/s2", "m/s^2", "cm/s2", "cm/s^2", "gal"]
#: the largest bar diameter [mm] and area [mm²] accepted
MAX_BAR_DIAMETER = 50.0
MAX_BAR_AREA = 2000.0
MIN_BAR_DIAMETER = 1.0
#: smallest ratio [‰] of an option: below it the bars carry nothing measurable (the
#: plausibility warning starts at 0.1 ‰)
MIN_RATIO = 0.001
#: smallest spacing between bar axes [m]: two drilled holes need about 20 mm between axes
MIN_SPACING = 0.02
#: exposure of the bars (CNR-DT 200 R1/2013 Table 3.2) and fibres of its η_a
Exposure = Literal["internal", "external", "aggressive"]
Fibre = Literal["glass", "carbon", "aramid", "basalt"]
#: shortest artificial record [s]: the generator's envelope rise (2.5 s) + stationary part
#: (10 s) + 1 s of decay (frp_assess.motions.simqke; a test keeps the two equal)
MIN_ARTIFICIAL_DURATION = 13.5


def located_error(message: str, *loc: str | int) -> PydanticCustomError:
    """A validation error whose ``ctx['loc']`` extends the location pydantic reports."""
    return PydanticCustomError(
        "cross_check", message.replace("{", "(").replace("}", ")"), {"loc": loc}
    )


def _to_text(value: Any) -> Any:
    """Free text: any YAML scalar (number, date) becomes a string; null becomes ``""``."""
    if value is None:
        return ""
    if isinstance(value, bool | int | float | _dt.date):
        return str(value)
    return value


#: every number of the file: strict (no quoted "0.4", no yes/no) and finite (YAML reads 1e400
#: and .inf as infinity, .nan as not-a-number; none of them is a value of any field)
Number = Annotated[float, Strict(), AllowInfNan(False)]
FreeText = Annotated[str, BeforeValidator(_to_text)]
#: an integer of the file (a float such as 7.0 or 1e400 is refused)
WholeNumber = Annotated[int, Strict()]

#: The range of every number below is the range the model is valid for (refused outside, with
#: the file's line); each bound is written once, on its field, with its unit and its reason.
#: Values inside the range but outside the range of practice give a warning instead
#: (frp_assess.config.plausibility).
#: smallest a_g [g] of a code spectrum and smallest largest ordinate of a table [g]: below
#: 0.001 g there is no seismic action to assess, and records scaled to it lose their digits
MIN_SPECTRUM_G = 0.001
#: ranges shared with the command line's wall and bar options (cli/wall_args.py), [low, high]:
#: thickness B [m] (below 50 mm no masonry leaf stands, a brick on edge is 55-60 mm), height H
#: [m] (below 0.5 m the wall is a block, not a rocking panel), E [GPa] and eps_u [-] of a bar
#: (FRP bars: 30-250 GPa, 0.005-0.035; a bar softer than 1 GPa or breaking at 0.01 % is none)
THICKNESS_RANGE = (0.05, 5.0)
HEIGHT_RANGE = (0.5, 50.0)
MODULUS_RANGE = (1.0, 1000.0)
STRAIN_RANGE = (1e-4, 0.1)
#: reference period T1 [s] of the compatibility checks (also the records command's --t1): the
#: checks' ranges start at 0.2*T1, below T1 = 0.05 s they leave the spectra's periods (and
#: T1 = 1e-300 never ended)
T1_RANGE = (0.05, 10.0)
#: periods [s] up to which a table's ordinates must reach MIN_SPECTRUM_G
TABLE_BAND = 2.0
#: bounds on the work one project asks for (refused before any computation, see each field)
MAX_OPTIONS = 2000  #: retrofit options after the sweeps are expanded
MAX_RECORD_DURATION = 600.0  #: [s] longest artificial record
MIN_TIME_STEP = 1e-4  #: [s] smallest time step of a record
MAX_SEED = 2**32 - 1  #: largest random seed
MAX_TABLE_POINTS = 1000  #: points of a spectrum table
#: longest free texts [characters]
MAX_NAME_CHARS = 200
MAX_NOTES_CHARS = 5000


#: longest record name [characters] (it names the exported ``records/<name>.AT2``)
MAX_RECORD_NAME = 100
#: characters a record name may not contain: path separators and what Windows refuses
_UNSAFE_NAME_CHARS = '/\\:*?"<>|'


def unsafe_name_reason(name: str) -> str | None:
    """Why ``name`` is not safe as a file name (``records/<name>.AT2``), or None if it is.

    Refused: empty, longer than :data:`MAX_RECORD_NAME`, a path separator or one of
    ``: * ? " < > |``, a control character, a leading dot or blank (``..``, hidden files),
    a trailing dot or blank.
    """
    if not name.strip():
        return "it is empty"
    if len(name) > MAX_RECORD_NAME:
        return f"it has {len(name)} characters, more than {MAX_RECORD_NAME}"
    bad = sorted({c for c in name if c in _UNSAFE_NAME_CHARS})
    if bad:
        return f'it contains {" ".join(bad)} (names may not contain / \\ : * ? " < > |)'
    if any(ord(c) < 32 or 0x7F <= ord(c) <= 0x9F for c in name):
        return "it contains control characters"
    if name[0] in ". " or name[-1] in ". ":
        return "it starts or ends with a dot or a blank"
    return None


def format_ratio(ratio: float) -> str:
    """A ratio [‰] without trailing zeros: 1.0 -> ``1``, 1.50 -> ``1.5``."""
    return f"{ratio:.6g}"


def option_name(material: str, position: str, ratio: float) -> str:
    """The generated name of an option, e.g. ``GFRP centred 1‰``."""
    return f"{material} {position} {format_ratio(ratio)}‰"


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


# --------------------------------------------------------------------------------- project
class ProjectInfo(_Model):
    """Free-text identification of the project, copied into the results and the report."""

    name: FreeText = Field(
        "Untitled wall",
        max_length=MAX_NAME_CHARS,
        description=f"Name of the wall or project (text, at most {MAX_NAME_CHARS} characters).",
    )
    location: FreeText = Field(
        "",
        max_length=MAX_NAME_CHARS,
        description=f"Site, e.g. town and address (text, at most {MAX_NAME_CHARS} characters).",
    )
    engineer: FreeText = Field(
        "",
        max_length=MAX_NAME_CHARS,
        description=f"Who made the assessment (text, at most {MAX_NAME_CHARS} characters).",
    )
    notes: FreeText = Field(
        "",
        max_length=MAX_NOTES_CHARS,
        description=f"Any notes for the report (text, at most {MAX_NOTES_CHARS} characters).",
    )


# ------------------------------------------------------------------------------------ wall
class WallSpec(_Model):
    """The masonry wall, a rigid rocking block (docs/model.md §1)."""

    thickness: Number = Field(  # the ranges' reasons: at THICKNESS_RANGE
        ge=THICKNESS_RANGE[0],
        le=THICKNESS_RANGE[1],
        description="Thickness B [m], 0.05 <= B <= 5, < height.",
    )
    height: Number = Field(
        ge=HEIGHT_RANGE[0],
        le=HEIGHT_RANGE[1],
        description="Height H [m] above the rocking base, 0.5 <= H <= 50.",
    )
    # below 0.1 m no bar fits: a length shorter than one bar spacing has no layout
    length: Number = Field(
        1.0,
        ge=0.1,
        le=1000,
        description="Length L [m] of the wall, for quantities and costs, 0.1 <= L <= 1000 "
        "(default 1).",
    )
    masonry: str | None = Field(
        None,
        description="Masonry type, a key of Circolare 2019 Tab. C8.5.I: "
        + ", ".join(f"{k} ({m.unit_weight:g} kN/m3)" for k, m in MASONRY.items())
        + ". Gives the unit weight unless unit_weight is given.",
    )
    unit_weight: Number | None = Field(
        None, ge=5.0, le=30.0, description="Unit weight w [kN/m3], 5-30; wins over masonry."
    )
    # the weakest masonry of Tab. C8.5.I has 1.0 MPa; below 0.1 MPa no wall carries itself
    compressive_strength: Number | None = Field(
        None,
        ge=0.1,
        le=100,
        description="Compressive strength f_m of the masonry [MPa], 0.1-100; wins over the "
        "masonry type's value of Tab. C8.5.I (LC1: minimum, LC2/LC3: mean).  Divided by FC of "
        "code_check.knowledge_level, it sizes the compressed zone at the pivot.",
    )
    mechanism: Mechanism = Field(
        description="one-sided: wall restrained on one side (rebounds on impact); "
        "two-sided: free-standing wall rocking both ways."
    )

    @field_validator("masonry")
    @classmethod
    def _known_masonry(cls, value: str | None) -> str | None:
        if value is not None and value not in MASONRY:
            raise PydanticCustomError(
                "unknown_masonry",
                f"unknown masonry {value!r}{did_you_mean(value, MASONRY)}; "
                f"expected one of {', '.join(MASONRY)}",
            )
        return value

    @model_validator(mode="after")
    def _check_wall(self) -> WallSpec:
        if slenderness_problem(self.thickness, self.height) is not None:
            raise located_error(
                f"expected thickness B < height H = {self.height:g} m, found {self.thickness:g}"
                " (a rocking wall is slender)",
                "thickness",
            )
        if self.masonry is None and self.unit_weight is None:
            raise located_error(
                "give 'masonry' (a library key) or 'unit_weight' [kN/m3]; neither was found"
            )
        return self

    @property
    def unit_weight_kn(self) -> float:
        """Unit weight w [kN/m³]: the explicit value, else the masonry library's."""
        if self.unit_weight is not None:
            return float(self.unit_weight)
        assert self.masonry is not None
        return MASONRY[self.masonry].unit_weight


# -------------------------------------------------------------------------------- spectra
class SiteCoordinates(_Model):
    """Where the site is: decimal degrees, as in the NTC reference grid (docs/site-hazard.md)."""

    latitude: Number = Field(ge=-90, le=90, description="Latitude [°], decimal, e.g. 42.35.")
    longitude: Number = Field(
        ge=-180, le=180, description="Longitude [°], decimal, east positive, e.g. 13.40."
    )


UseClass = Literal["I", "II", "III", "IV"]
LimitState = Literal["SLO", "SLD", "SLV", "SLC"]
#: the keys of the spectrum given by its parameters, and of the one given by coordinates
NTC_PARAMETER_KEYS = ("ag", "F0", "Tc_star")
NTC_SITE_KEYS = ("site", "nominal_life", "use_class", "limit_state")


class Ntc2018Spectrum(_Model):
    """NTC 2018 §3.2.3.2.1 elastic spectrum, from the site's parameters a_g, F0, T_C* or from
    the site's coordinates (``site``: the parameters of ``limit_state`` interpolated on the
    NTC reference grid, NTC 2018 §3.2 and NTC 2008 Allegati A/B; docs/site-hazard.md)."""

    type: Literal["ntc2018"] = Field(description="Spectrum kind.")
    ag: Annotated[Number, Field(ge=MIN_SPECTRUM_G, le=1.5)] | None = Field(
        None, description=f"a_g [g] on rock, {MIN_SPECTRUM_G:g} <= a_g <= 1.5."
    )
    # F0 is an amplification of the ground motion: at least 1 (NTC's grid: 2.2-3)
    F0: Annotated[Number, Field(ge=1.0, le=5.0)] | None = Field(
        None, description="F0 [-], maximum amplification on rock, 1-5."
    )
    # T_C* of the NTC grid is 0.15-0.6 s; below 0.05 s the plateau vanishes
    Tc_star: Annotated[Number, Field(ge=0.05, le=3.0)] | None = Field(
        None, description="T_C* [s], start of the velocity branch, 0.05-3."
    )
    site: SiteCoordinates | None = Field(
        None,
        description="Coordinates {latitude, longitude} [°]: a_g, F0, T_C* from the NTC "
        "reference grid instead of ag, F0, Tc_star.",
    )
    nominal_life: Annotated[Number, Field(gt=0, le=1000)] | None = Field(
        None, description="Nominal life V_N [years], 0-1000 (50), with site (Tab. 2.4.I)."
    )
    use_class: UseClass | None = Field(
        None, description="Use class I-IV (II), with site: C_U = 0.7, 1, 1.5, 2 (Tab. 2.4.II)."
    )
    limit_state: LimitState | None = Field(
        None, description="Limit state SLO, SLD, SLV or SLC (SLV), with site (Tab. 3.2.I)."
    )
    soil: GroundType = Field(description="Subsoil category A-E (S_S, C_C of Tab. 3.2.IV).")
    topography: Literal["T1", "T2", "T3", "T4"] = Field(
        "T1", description="Topographic category T1-T4 (S_T of Tab. 3.2.V)."
    )
    damping: Number = Field(0.05, gt=0, lt=1, description="Viscous damping ratio [-] (0.05).")

    @model_validator(mode="after")
    def _one_form(self) -> Ntc2018Spectrum:
        given = [k for k in NTC_PARAMETER_KEYS if getattr(self, k) is not None]
        if self.site is not None:
            if given:
                raise located_error(
                    f"give either site (coordinates) or ag, F0, Tc_star, not both; found "
                    f"{', '.join(given)} with site",
                    given[0],
                )
            self._site_hazard()
            return self
        for key in NTC_SITE_KEYS[1:]:
            if getattr(self, key) is not None:
                raise located_error(f"{key} needs site: {{latitude, longitude}}", key)
        missing = [k for k in NTC_PARAMETER_KEYS if getattr(self, k) is None]
        if missing:
            fields = type(self).model_fields
            described = "; ".join(
                f"{k}: {(fields[k].description or '').rstrip('.')}" for k in missing
            )
            raise located_error(
                f"missing required key{'s' if len(missing) > 1 else ''} "
                f"{', '.join(repr(k) for k in missing)} ({described}), or give the site's "
                "coordinates instead: site: {latitude, longitude}"
            )
        return self

    @property
    def by_coordinates(self) -> bool:
        """The spectrum is given by the site's coordinates (not by a_g, F0, T_C*)."""
        return self.site is not None

    @property
    def V_N(self) -> float:  # noqa: N802
        """Nominal life V_N [years] (50 when not given)."""
        return 50.0 if self.nominal_life is None else float(self.nominal_life)

    @property
    def chosen_limit_state(self) -> str:
        """The limit state whose parameters make the spectrum (SLV when not given)."""
        return self.limit_state or "SLV"

    def _site_hazard(self) -> Any:
        assert self.site is not None
        try:
            return site_hazard_cached(
                float(self.site.latitude),
                float(self.site.longitude),
                self.V_N,
                self.use_class or "II",
            )
        except InputError as exc:
            raise located_error(exc.message, "site") from None

    def site_hazard(self) -> SiteHazard | None:
        """The hazard at the site (all four limit states), or None without ``site``."""
        return None if self.site is None else self._site_hazard()

    def parameters(self) -> tuple[float, float, float]:
        """(a_g [g], F0 [-], T_C* [s]) of the spectrum: as given, or interpolated at the site
        for the chosen limit state."""
        hazard = self.site_hazard()
        if hazard is None:
            assert self.ag is not None and self.F0 is not None and self.Tc_star is not None
            return float(self.ag), float(self.F0), float(self.Tc_star)
        state = hazard[self.chosen_limit_state]
        return state.ag, state.F0, state.Tc_star


class Ec8Spectrum(_Model):
    """EN 1998-1 §3.2.2.2 elastic spectrum."""

    type: Literal["ec8"] = Field(description="Spectrum kind.")
    ag: Number = Field(
        ge=MIN_SPECTRUM_G,
        le=1.5,
        description=f"a_g [g] on type A ground, {MIN_SPECTRUM_G:g} <= a_g <= 1.5.",
    )
    ground: GroundType = Field(description="Ground type A-E (Table 3.2/3.3).")
    spectrum_type: Literal[1, 2] = Field(1, description="1 (M_s > 5.5) or 2.")
    damping: Number = Field(0.05, gt=0, lt=1, description="Viscous damping ratio [-] (0.05).")


class PresetSpectrum(_Model):
    """One of the paper's spectra (a_g·S = 0.106 g, EC8 shape)."""

    type: Literal["preset"] = Field(description="Spectrum kind.")
    name: Literal["A1", "A2", "A3"] = Field(description="Preset A1, A2 or A3 (docs/model.md §6).")


class TableSpectrum(_Model):
    """A user table of (T, Se) points, linear between them."""

    type: Literal["table"] = Field(description="Spectrum kind.")
    periods: list[Annotated[Number, Field(ge=0, le=100)]] = Field(
        min_length=2,
        max_length=MAX_TABLE_POINTS,
        description=f"Periods T [s], increasing, 0-100, 2 to {MAX_TABLE_POINTS} points.",
    )
    accelerations: list[Annotated[Number, Field(ge=0, le=20)]] = Field(
        min_length=2,
        max_length=MAX_TABLE_POINTS,
        description="Spectral accelerations Se(T) [g], 0-20, one per period.",
    )

    @model_validator(mode="after")
    def _check_table(self) -> TableSpectrum:
        if len(self.accelerations) != len(self.periods):
            raise located_error(
                f"expected {len(self.periods)} accelerations (one per period), "
                f"found {len(self.accelerations)}",
                "accelerations",
            )
        for i, (t, se) in enumerate(zip(self.periods, self.accelerations, strict=True)):
            # Se(T0) is the a_g*S the records are scaled to; up to 2 s it shapes the records
            if (i == 0 or t <= TABLE_BAND) and se < MIN_SPECTRUM_G:
                raise located_error(
                    f"expected Se >= {MIN_SPECTRUM_G:g} g at the first period and at every "
                    f"period up to {TABLE_BAND:g} s (the band the records are made for), "
                    f"found {se:g} at T = {t:g} s",
                    "accelerations",
                    i,
                )
        for i in range(1, len(self.periods)):
            if self.periods[i] <= self.periods[i - 1]:
                raise located_error(
                    f"expected increasing periods, found {self.periods[i]:g} s after "
                    f"{self.periods[i - 1]:g} s",
                    "periods",
                    i,
                )
        return self


Spectrum = Annotated[
    Ntc2018Spectrum | Ec8Spectrum | PresetSpectrum | TableSpectrum,
    Field(discriminator="type"),
]


# -------------------------------------------------------------------------------- records
class ArtificialRecords(_Model):
    """Spectrum-compatible artificial accelerograms (SIMQKE), reproducible from the seed."""

    count: WholeNumber = Field(7, ge=1, le=100, description="Number, 1-100 (7).")
    seed: WholeNumber = Field(
        1, ge=0, le=MAX_SEED, description=f"Random seed, 0-{MAX_SEED} (same seed, same set)."
    )
    duration: Number = Field(
        25.0,
        ge=MIN_ARTIFICIAL_DURATION,
        le=MAX_RECORD_DURATION,
        description=f"Total duration [s], {MIN_ARTIFICIAL_DURATION:g}-{MAX_RECORD_DURATION:g} "
        "(25, NTC minimum).",
    )
    dt: Number = Field(
        0.005,
        ge=MIN_TIME_STEP,
        le=0.05,
        description=f"Time step [s], {MIN_TIME_STEP:g}-0.05 (0.005).",
    )


class RecordFile(_Model):
    """A recorded accelerogram file."""

    path: str = Field(description="File path, relative to the project file.")
    format: RecordFormat = Field(
        "auto", description="auto | at2 (PEER NGA) | esm (ESM/ITACA) | two-column | one-column."
    )
    units: RecordUnits = Field("g", description="Units of the samples: g | m/s2 | cm/s2 | gal.")
    dt: Number | None = Field(
        None,
        ge=MIN_TIME_STEP,
        le=0.05,
        description=f"Time step [s], {MIN_TIME_STEP:g}-0.05, required for one-column files.",
    )
    name: str | None = Field(
        None,
        description="Name in the results and of the exported records/<name>.AT2 (default: the "
        f"file name without extension); unique, at most {MAX_RECORD_NAME} characters, no path "
        "separators, not starting with a dot.",
    )

    @property
    def record_name(self) -> str:
        """The record's name: ``name``, else the file name without its extension."""
        return self.name if self.name is not None else PurePath(self.path).stem

    @field_validator("name")
    @classmethod
    def _safe_name(cls, value: str | None) -> str | None:
        if value is not None and (reason := unsafe_name_reason(value)) is not None:
            raise located_error(
                f"record name {value!r} is not a safe file name: {reason}; the results export "
                "it as records/<name>.AT2"
            )
        return value

    @model_validator(mode="after")
    def _dt_for_one_column(self) -> RecordFile:
        if self.format == "one-column" and self.dt is None:
            raise located_error("a one-column file needs 'dt' [s]; none was found", "dt")
        return self


class RecordsSpec(_Model):
    """The accelerograms: artificial ones or files (exactly one of the two)."""

    artificial: ArtificialRecords | None = Field(
        None, description="Generate artificial records compatible with the spectrum."
    )
    files: list[RecordFile] | None = Field(
        None, min_length=1, description="Recorded accelerograms, read from files."
    )
    scale_to_spectrum: bool = Field(
        True, description="Scale every record file to the spectrum's a_g*S (true)."
    )

    @model_validator(mode="after")
    def _exactly_one(self) -> RecordsSpec:
        if self.artificial is not None and self.files is not None:
            raise located_error("give either 'artificial' or 'files', not both", "files")
        if self.artificial is None and self.files is None:
            raise located_error("give either 'artificial' or 'files'; neither was found")
        return self

    @model_validator(mode="after")
    def _unique_names(self) -> RecordsSpec:
        first: dict[str, int] = {}
        for i, f in enumerate(self.files or []):
            name = f.record_name
            key = "name" if f.name is not None else "path"
            if f.name is None and (reason := unsafe_name_reason(name)) is not None:
                raise located_error(
                    f"the file name {name!r} is not a safe record name: {reason}; give a 'name:'",
                    "files",
                    i,
                    key,
                )
            j = first.setdefault(name.casefold(), i)
            if j != i:
                raise located_error(
                    f"record name {name!r} is already the name of files[{j}]; each record needs "
                    "its own name (give a 'name:')",
                    "files",
                    i,
                    key,
                )
        return self


def _default_records() -> RecordsSpec:
    return RecordsSpec(artificial=ArtificialRecords())


class SeismicSpec(_Model):
    """The site's seismic action: a spectrum and the records compatible with it."""

    spectrum: Spectrum = Field(
        description="Elastic spectrum at 5 % damping: type ntc2018 | ec8 | preset | table."
    )
    records: RecordsSpec = Field(
        default_factory=_default_records,
        description="Accelerograms (default: 7 artificial, seed 1, 25 s, dt 0.005 s).",
    )
    t1: Number = Field(
        1.0,
        ge=T1_RANGE[0],
        le=T1_RANGE[1],
        description="Reference period T1 [s] of the compatibility checks, 0.05-10.",
    )


# ------------------------------------------------------------------------------ materials
class MaterialSpec(_Model):
    """An FRP bar material added to, or overriding fields of, the library (GFRP, BFRP, CFRP).

    For a library material only the fields given are replaced; a new material needs
    elastic_modulus, ultimate_strain, density and price.
    """

    # FRP bars: E 30-250 GPa, eps_u 0.005-0.035, density 1400-2600 kg/m3; the ranges are
    # what any bar material can be (see MODULUS_RANGE; no bar is lighter than 100 kg/m3)
    elastic_modulus: Number | None = Field(
        None, ge=MODULUS_RANGE[0], le=MODULUS_RANGE[1], description="E [GPa], 1-1000."
    )
    ultimate_strain: Number | None = Field(
        None, ge=STRAIN_RANGE[0], le=STRAIN_RANGE[1], description="eps_u [-], 0.0001-0.1."
    )
    density: Number | None = Field(
        None, ge=100, le=10000, description="Density [kg/m3], 100-10000."
    )
    price: Number | None = Field(
        None, ge=0, le=1e6, description="Indicative price [currency/kg], 0-1e6."
    )
    source: FreeText | None = Field(
        None,
        max_length=MAX_NAME_CHARS,
        description=f"Source of the values (text, at most {MAX_NAME_CHARS} characters).",
    )
    characteristic_strain: Number | None = Field(
        None,
        ge=STRAIN_RANGE[0],
        le=STRAIN_RANGE[1],
        description="Characteristic rupture strain eps_fk [-] (5 % fractile, producer's data "
        "sheet); default eps_u*(1 - 1.645*0.10) (docs/model.md §2.1).",
    )
    fibre: Fibre | None = Field(
        None,
        description="Fibre for the environmental factor eta_a (CNR-DT 200 R1/2013 Table 3.2): "
        "glass | carbon | aramid | basalt (default: by the library key, glass for a new "
        "material).",
    )


# ------------------------------------------------------------------------------------ bars
class BarSizeSpec(_Model):
    """A bar size added to the built-in catalogue (nominal diameters 6-16 mm, area pi*d^2/4)."""

    material: str = Field(description="Material: a library key or one of 'materials'.")
    # no bar is thinner than 1 mm (the catalogue starts at 6 mm)
    diameter: Number = Field(
        ge=MIN_BAR_DIAMETER,
        le=MAX_BAR_DIAMETER,
        description=f"Nominal diameter d [mm], {MIN_BAR_DIAMETER:g}-{MAX_BAR_DIAMETER:g}.",
    )
    area: Number = Field(
        ge=0.5,
        le=MAX_BAR_AREA,
        description=f"Nominal area [mm2] (the producer's data sheet), 0.5-{MAX_BAR_AREA:g}.",
    )
    source: FreeText = Field(
        "user input",
        max_length=MAX_NAME_CHARS,
        description=f"Source (text, at most {MAX_NAME_CHARS} characters).",
    )


class AnchorageSpec(_Model):
    """Bond of the bars in resin-filled holes, for the anchorage length and the pull-out cone."""

    # a bond below 0.01 MPa anchors nothing (lengths of kilometres); the resin needs a
    # clearance of at least 0.1 mm around the bar
    hole_clearance: Number = Field(
        ge=0.1,
        le=50,
        description="Hole diameter minus bar diameter [mm] (d_h = d + clearance), 0.1-50.",
    )
    bond_bar: Number = Field(
        ge=0.01, le=50, description="Bond strength bar-resin tau_b [MPa] (producer's tests)."
    )
    bond_masonry: Number = Field(
        ge=0.01, le=10, description="Bond strength resin-masonry tau_m [MPa] (pull-out tests)."
    )
    tensile_strength: Number | None = Field(
        None,
        ge=0.001,
        le=10,
        description="Tensile strength f_t of the masonry for the pull-out cone [MPa] "
        "(default 1.5*tau_0d of wall.masonry and the knowledge level).",
    )


class BarsSpec(_Model):
    """The bars as they are built: catalogue, spacing rule, exposure, design values."""

    exposure: Exposure = Field(
        "external",
        description="Exposure of the bars (CNR-DT 200 R1/2013 Table 3.2): internal | external "
        "| aggressive (external).",
    )
    design_values: bool = Field(
        True,
        description="Use the design rupture strain c*eta_a*eps_fk/gamma_f (true); false: "
        "c*eps_u, the mean producer value (the paper).",
    )
    whole_bars: bool = Field(
        True,
        description="The model uses the ratio installed by whole bars (true); false: the "
        "ratio asked, smeared (the paper).",
    )
    min_spacing: Number = Field(
        0.10,
        ge=MIN_SPACING,
        le=10,
        description=f"Smallest spacing between bar axes [m], {MIN_SPACING:g}-10 (0.10).",
    )
    max_spacing: Number = Field(
        1.0,
        ge=MIN_SPACING,
        le=10,
        description=f"Largest spacing between bar axes [m], {MIN_SPACING:g}-10 (1.0).",
    )
    catalogue: list[BarSizeSpec] = Field(
        default_factory=list,
        max_length=200,
        description="Bar sizes added to (same diameter: replacing) the built-in nominal "
        "diameters 6-16 mm.",
    )
    anchorage: AnchorageSpec | None = Field(
        None, description="Bond strengths for the anchorage length and pull-out cone."
    )

    @model_validator(mode="after")
    def _spacing(self) -> BarsSpec:
        if self.min_spacing > self.max_spacing:
            raise located_error(
                f"expected min_spacing <= max_spacing = {self.max_spacing:g} m, found "
                f"{self.min_spacing:g}",
                "min_spacing",
            )
        seen: dict[tuple[str, float], int] = {}
        for i, size in enumerate(self.catalogue):
            j = seen.setdefault((size.material, float(size.diameter)), i)
            if j != i:
                raise located_error(
                    f"{size.material} Ø{size.diameter:g} is already catalogue[{j}]",
                    "catalogue",
                    i,
                    "diameter",
                )
        return self


# -------------------------------------------------------------------------- interventions
Ratio = Annotated[Number, Field(ge=MIN_RATIO, le=MAX_RATIO)]


class Intervention(_Model):
    """One retrofit option: vertical FRP bars of a material, position and ratio."""

    name: FreeText | None = Field(
        None,
        max_length=MAX_NAME_CHARS,
        description="Name in the results (default e.g. 'GFRP external 1‰'), at most "
        f"{MAX_NAME_CHARS} characters.",
    )
    material: str = Field(description="Material: a library key or one of 'materials'.")
    position: Position = Field(description="centred (one bar) | external (one on each face).")
    ratio: Ratio = Field(
        description=f"Ratio rho [per mille] of the active bars, {MIN_RATIO:g}-{MAX_RATIO:g}."
    )
    diameter: Number | None = Field(
        None,
        ge=MIN_BAR_DIAMETER,
        le=MAX_BAR_DIAMETER,
        description="Bar diameter d [mm], from the catalogue (default: the size installing "
        "the least ratio within the spacing rule).",
    )


class SweepAxes(_Model):
    """Every combination of the listed materials, positions and ratios."""

    material: list[str] = Field(min_length=1, description="Materials (library or 'materials').")
    position: list[Position] = Field(min_length=1, description="Positions: centred, external.")
    ratio: list[Ratio] = Field(
        min_length=1, description=f"Ratios [per mille], {MIN_RATIO:g}-{MAX_RATIO:g}."
    )


class Sweep(_Model):
    """A sweep: expands into one option per combination."""

    sweep: SweepAxes = Field(description="The axes of the sweep.")


def _intervention_tag(value: Any) -> str:
    if isinstance(value, dict):
        return "sweep-item" if "sweep" in value else "option"
    return "sweep-item" if isinstance(value, Sweep) else "option"


InterventionItem = Annotated[
    Annotated[Intervention, Tag("option")] | Annotated[Sweep, Tag("sweep-item")],
    Discriminator(_intervention_tag),
]


# ------------------------------------------------------------------------------- analysis
def option_field(option: Option[Any]) -> Any:
    """The pydantic field of a declared option: its default, range and description."""
    bounds: dict[str, float] = {}
    if option.numeric and not option.choices:
        if option.low is not None:
            bounds["gt" if option.low_open else "ge"] = option.low
        if option.high is not None:
            bounds["lt" if option.high_open else "le"] = option.high
    return Field(option.default, description=option.describe(), **bounds)  # type: ignore[call-overload]


def _restitution(value: Any) -> Any:
    if isinstance(value, str) and RESTITUTION.accepts(value):
        return value
    if isinstance(value, int | float) and RESTITUTION.accepts(value):
        return float(value)
    raise PydanticCustomError(
        "restitution", f"expected {RESTITUTION.allowed_text()}, found {value!r}"
    )


Restitution = Annotated[
    Literal["energy", "velocity"] | float,
    BeforeValidator(_restitution),
    WithJsonSchema(
        {
            "anyOf": [
                {"enum": list(RESTITUTION.choices), "type": "string"},
                {
                    "type": "number",
                    "exclusiveMinimum": RESTITUTION.low,
                    "maximum": RESTITUTION.high,
                },
            ]
        }
    ),
]


class IdaSpec(_Model):
    """The incremental dynamic analysis rule (docs/model.md §5)."""

    step_ratio: Number = option_field(IDA_STEP_RATIO)
    tolerance: Number = option_field(IDA_TOLERANCE)
    max_multiplier: Number = option_field(IDA_MAX_MULTIPLIER)

    def settings(self) -> IdaSettings:
        """The search rule these fields give."""
        return IdaSettings(**{key: getattr(self, key) for key in IDA_OPTIONS})


class IntegrationSpec(_Model):
    """Error control of the time integration (docs/model.md §4)."""

    tolerance: Number = option_field(INTEGRATION_TOLERANCE)
    verify: bool = option_field(VERIFY)


class ModelOptionsSpec(_Model):
    """The model options of docs/model.md §2–4 a project and a study file share."""

    restitution: Restitution = option_field(RESTITUTION)
    rupture: RuptureRule = option_field(RUPTURE)
    collapse: CollapseRule = option_field(COLLAPSE)
    strain_factor: Number = option_field(STRAIN_FACTOR)
    free_vibration_tail: Number = option_field(FREE_VIBRATION_TAIL)
    pivot: PivotRule = option_field(PIVOT)

    def model_options(self, tolerance: float) -> ModelOptions:
        """The model options these fields give, integrated at ``tolerance`` [-] (a project
        file holds it under ``integration``, a study file as ``integration_tolerance``)."""
        given = {key: getattr(self, key) for key in MODEL_OPTIONS if key != "tolerance"}
        return ModelOptions(**given, tolerance=tolerance)


class AnalysisSpec(ModelOptionsSpec):
    """Model options and the IDA settings (docs/model.md §3–5)."""

    integration: IntegrationSpec = Field(
        default_factory=IntegrationSpec, description="Time integration."
    )
    ida: IdaSpec = Field(default_factory=IdaSpec, description="IDA rule.")
    # a required capacity/demand below 0.01 accepts any wall
    target: Number = Field(
        1.0,
        ge=0.01,
        le=10,
        description="Required mean capacity/demand, mean a_dyn/(a_g*S), 0.01-10 (1.0).",
    )


# ---------------------------------------------------------------------- design/code/costs
class DesignSpec(_Model):
    """Design mode: the smallest ratio meeting the target per material and position."""

    materials: list[str] = Field(min_length=1, description="Materials to design with.")
    positions: list[Position] = Field(
        default_factory=lambda: list(POSITIONS),
        min_length=1,
        description="Positions (both by default).",
    )
    ratio_range: tuple[Ratio, Ratio] = Field(
        (0.5, 5.0),
        description=f"Search range [per mille], {MIN_RATIO:g} <= low < high <= {MAX_RATIO:g}.",
    )
    resolution: Number = Field(
        0.05, ge=0.001, le=1, description="Resolution [per mille], 0.001-1 (0.05)."
    )

    @model_validator(mode="after")
    def _range(self) -> DesignSpec:
        lo, hi = self.ratio_range
        if not lo < hi:
            raise located_error(f"expected low < high, found [{lo:g}, {hi:g}]", "ratio_range")
        res = self.resolution  # the search runs on the multiples of the resolution
        if math.floor(hi / res + 1e-9) < math.ceil(lo / res - 1e-9):
            raise located_error(
                f"expected a range holding a multiple of the resolution {res:g} ‰, found "
                f"[{lo:g}, {hi:g}]",
                "ratio_range",
            )
        return self


class CodeCheckSpec(_Model):
    """Linear kinematic check of Circolare 2019 §C8.7.1 beside the IDA."""

    knowledge_level: Literal["LC1", "LC2", "LC3"] = Field(
        "LC1", description="Knowledge level: FC = 1.35 (LC1), 1.20 (LC2), 1.00 (LC3)."
    )
    behaviour_factor: Number = Field(2.0, ge=1, le=4, description="Behaviour factor q (2.0).")
    fc_in_ida: bool = Field(
        True,
        description="Divide the IDA capacity by FC too: capacity/demand = a_dyn/(FC*a_g*S) "
        "(true; Circolare 2019 C8.7.1.2.1.3: a rigid block uses LC1's FC = 1.35).",
    )

    @property
    def confidence_factor(self) -> float:
        """FC [-] of the knowledge level."""
        return confidence_factor(self.knowledge_level)


class CostsSpec(_Model):
    """Indicative costs: bars by weight (material price) plus installation."""

    currency: FreeText = Field(
        "EUR", max_length=12, description="Currency of all prices (text, at most 12 characters)."
    )
    installation_per_metre: Number = Field(
        0.0,
        ge=0,
        le=1e6,
        description="Installation [currency per metre of wall length per layer of "
        "bars] (centred: 1 layer, external: 2), 0-1e6; default 0: bars only.",
    )


# ---------------------------------------------------------------------------------- report
#: languages of the report (the console and the TUI stay English)
ReportLanguage = Literal["en", "it"]


class ReportSpec(_Model):
    """The written report: its language and, for the Word file, a firm's template."""

    language: ReportLanguage = Field(
        "en", description="Language of the report: en (English) | it (Italian); default en."
    )
    template: FreeText | None = Field(
        None,
        max_length=1000,
        description="Word file (.docx) whose styles, page and header the DOCX report uses, "
        "relative to the project file (optional).",
    )


# -------------------------------------------------------------------------------- building
class BuildingSpec(_Model):
    """Where the wall stands in the building: its base moves with the floor at Z
    (first mode only, Circolare 2019 §C7.2.3; docs/model.md §9)."""

    # one storey is at least 2 m high
    height: Number = Field(
        ge=2,
        le=200,
        description="H_b [m], height of the building above the foundation, 2-200.",
    )
    storeys: WholeNumber = Field(ge=1, le=60, description="n, number of storeys, 1-60.")
    wall_base: Number = Field(
        ge=0,
        description="Z [m], height of the wall's rocking base above the foundation, 0 <= Z < H_b.",
    )
    # below 0.02 s the floor moves as the ground (the default for H_b = 2 m is 0.08 s)
    period: Number | None = Field(
        None,
        ge=0.02,
        le=5,
        description="T1 [s], fundamental period of the building, 0.02-5; default "
        "0.05*H_b^0.75 (Circolare 2019 eq. C7.3.2, masonry).",
    )
    # below 0.5 % no building is damped (steel frames have about 2 %)
    damping: Number = Field(
        0.05,
        ge=0.005,
        le=0.3,
        description="xi of the building's first mode [-], 0.005-0.3 (0.05).",
    )

    @model_validator(mode="after")
    def _check_base(self) -> BuildingSpec:
        if self.wall_base >= self.height:
            raise located_error(
                f"expected 0 <= Z < height H_b = {self.height:g} m, found {self.wall_base:g}",
                "wall_base",
            )
        return self

    @property
    def first_period(self) -> float:
        """T1 [s]: the given period, else C1·H_b^(3/4) with C1 = 0.050 (eq. C7.3.2)."""
        if self.period is not None:
            return float(self.period)
        return default_period(float(self.height))


# ----------------------------------------------------------------------------------- root
class Project(_Model):
    """A project file: one wall, its site, candidate retrofits and analysis settings."""

    project: ProjectInfo = Field(default_factory=ProjectInfo, description="Identification.")
    wall: WallSpec = Field(description="The wall.")
    building: BuildingSpec | None = Field(
        None,
        description="Where the wall stands in the building (optional; omit for a wall at "
        "ground level): its base then moves with the floor at wall_base.",
    )
    seismic: SeismicSpec = Field(description="Spectrum and records.")
    materials: dict[str, MaterialSpec] = Field(
        default_factory=dict,
        description="Additions/overrides of the FRP library (GFRP, "
        "BFRP, CFRP): E [GPa], eps_u, density [kg/m3], price [currency/kg].",
    )
    interventions: list[InterventionItem] = Field(
        default_factory=list,
        max_length=MAX_OPTIONS,
        description=f"Retrofit options: single options and sweeps (at most {MAX_OPTIONS} "
        "options once the sweeps are expanded).",
    )
    analysis: AnalysisSpec = Field(default_factory=AnalysisSpec, description="Settings.")
    design: DesignSpec | None = Field(None, description="Design mode (optional).")
    code_check: CodeCheckSpec = Field(
        default_factory=CodeCheckSpec, description="Code kinematic check settings."
    )
    costs: CostsSpec = Field(default_factory=CostsSpec, description="Indicative costs.")
    bars: BarsSpec = Field(
        default_factory=BarsSpec,
        description="Bars as built: exposure, design values, spacing rule, catalogue, anchorage.",
    )
    report: ReportSpec = Field(
        default_factory=ReportSpec, description="The written report: language, Word template."
    )

    @model_validator(mode="after")
    def _cross_checks(self) -> Project:
        for name, spec in self.materials.items():
            if name in FRP_MATERIALS:
                continue
            missing = [
                f
                for f in ("elastic_modulus", "ultimate_strain", "density", "price")
                if getattr(spec, f) is None
            ]
            if missing:
                raise located_error(
                    f"new material {name!r} needs {', '.join(missing)} (not in the library "
                    f"{', '.join(FRP_MATERIALS)})",
                    "materials",
                    name,
                )
        table = self.material_table()
        for name in self.materials:  # the library gives no eps_fk: the file gave this one
            eps_u, eps_fk = table[name].ultimate_strain, table[name].characteristic_strain
            if eps_fk is not None and eps_fk > eps_u:
                raise located_error(
                    f"expected characteristic_strain eps_fk <= ultimate_strain eps_u = "
                    f"{eps_u:g} (the 5 % fractile lies below the mean), found "
                    f"{eps_fk:g}",
                    "materials",
                    name,
                    "characteristic_strain",
                )
        self._check_option_count()
        known = self.material_names()
        for i, item in enumerate(self.interventions):
            if isinstance(item, Intervention):
                self._check_material(item.material, known, "interventions", i, "material")
            else:
                for j, m in enumerate(item.sweep.material):
                    self._check_material(m, known, "interventions", i, "sweep", "material", j)
        if self.design is not None:
            for j, m in enumerate(self.design.materials):
                self._check_material(m, known, "design", "materials", j)
        for j, size in enumerate(self.bars.catalogue):
            self._check_material(size.material, known, "bars", "catalogue", j, "material")
        seen: dict[str, Intervention] = {}
        for i, option in self._expanded_with_index():
            other = seen.setdefault(str(option.name), option)
            if other is not option and _key(other) != _key(option):
                raise located_error(
                    f"two different options are named {option.name!r}", "interventions", i
                )
        return self

    def _check_option_count(self) -> None:
        sizes = [
            1
            if isinstance(item, Intervention)
            else len(item.sweep.material) * len(item.sweep.position) * len(item.sweep.ratio)
            for item in self.interventions
        ]
        total, running = sum(sizes), 0
        for i, size in enumerate(sizes):
            running += size
            if running > MAX_OPTIONS:
                raise located_error(
                    f"the options expand to {total}, more than {MAX_OPTIONS} (each needs an IDA "
                    "of every record); split the project",
                    "interventions",
                    i,
                )

    @staticmethod
    def _check_material(name: str, known: list[str], *loc: str | int) -> None:
        if name not in known:
            raise located_error(
                f"unknown material {name!r}{did_you_mean(name, known)}; "
                f"expected one of {', '.join(known)}",
                *loc,
            )

    def material_names(self) -> list[str]:
        """Names of the library materials and of those the file adds."""
        return list(dict.fromkeys([*FRP_MATERIALS, *self.materials]))

    def unit_weight_kn(self) -> float:
        """Unit weight w of the wall [kN/m³] (explicit value, else the masonry library's)."""
        return self.wall.unit_weight_kn

    def material_table(self) -> dict[str, FrpMaterial]:
        """The FRP library merged with the file's additions and overrides, by name."""
        table = dict(FRP_MATERIALS)
        for name, spec in self.materials.items():
            base = table.get(name)
            fields = {
                f: getattr(spec, f)
                for f in (
                    "elastic_modulus",
                    "ultimate_strain",
                    "density",
                    "price",
                    "source",
                    "characteristic_strain",
                    "fibre",
                )
                if getattr(spec, f) is not None
            }
            if base is None:
                fields.setdefault("source", "user input")
                table[name] = FrpMaterial(name=name, description="user material", **fields)
            else:
                if "source" not in fields and set(fields) - {"price", "fibre"}:
                    fields["source"] = "user input (overrides the library)"
                table[name] = FrpMaterial(
                    name=name,
                    elastic_modulus=fields.get("elastic_modulus", base.elastic_modulus),
                    ultimate_strain=fields.get("ultimate_strain", base.ultimate_strain),
                    density=fields.get("density", base.density),
                    price=fields.get("price", base.price),
                    source=fields.get("source", base.source),
                    description=base.description,
                    characteristic_strain=fields.get(
                        "characteristic_strain", base.characteristic_strain
                    ),
                    fibre=fields.get("fibre", base.fibre),
                )
        return table

    def _expanded_with_index(self) -> list[tuple[int, Intervention]]:
        out: list[tuple[int, Intervention]] = []
        for i, item in enumerate(self.interventions):
            if isinstance(item, Intervention):
                name = item.name or option_name(item.material, item.position, item.ratio)
                if not item.name and item.diameter is not None:
                    name += f" Ø{item.diameter:g}"
                out.append((i, item.model_copy(update={"name": name})))
                continue
            ax = item.sweep
            for m in ax.material:
                for p in ax.position:
                    for r in ax.ratio:
                        out.append(
                            (
                                i,
                                Intervention(
                                    name=option_name(m, p, r), material=m, position=p, ratio=r
                                ),
                            )
                        )
        return out

    def expand_interventions(self) -> list[Intervention]:
        """The concrete options, in file order, every one named; an option equal to an earlier
        one (same material, position, ratio and diameter) is dropped."""
        seen: set[tuple[str, str, float, float | None]] = set()
        out: list[Intervention] = []
        for _, option in self._expanded_with_index():
            key = _key(option)
            if key not in seen:
                seen.add(key)
                out.append(option)
        return out


def _key(option: Intervention) -> tuple[str, str, float, float | None]:
    d = None if option.diameter is None else float(option.diameter)
    return (option.material, option.position, float(option.ratio), d)
