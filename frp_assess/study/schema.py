"""The study file: parameter axes whose full cross product is analysed (pydantic v2).

A study file is YAML.  Every list is an *axis*; the study is the cross product of all axes
(see :mod:`frp_assess.study.plan`).  Units are the practitioners' ones: m, degrees, ‰, GPa,
kN/m³, s.  Unknown keys are rejected (``extra="forbid"``) with the key path and, when the
file is read with :func:`load_study`, the line number.

Example (the paper's Table 1 is ``projects/paper-study.yaml``)::

    name: tiny
    height: [3.0, 4.0]          # H [m]
    alpha_deg: [7.5]            # slenderness α [°] (or thickness: [B, ...] in m)
    ratio: [1.0, 2.0]           # ρ [‰]
    material: [CFRP]
    position: [external]
    mechanism: [one-sided]
    spectrum: [A2]              # preset, or "ec8:...", "ntc:...", "table:..."
    records: {count: 3, seed: 1, duration: 14.0}
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from frp_assess.assess.wall_model import slenderness_problem
from frp_assess.config.library import MASONRY, did_you_mean
from frp_assess.config.messages import Loc, schema_problems
from frp_assess.config.problems import raise_all
from frp_assess.config.schema import (
    HEIGHT_RANGE,
    MAX_NAME_CHARS,
    MAX_NOTES_CHARS,
    MAX_RECORD_DURATION,
    MAX_SEED,
    MIN_TIME_STEP,
    THICKNESS_RANGE,
    IdaSpec,
    ModelOptionsSpec,
    Number,
    option_field,
)
from frp_assess.config.yaml_source import parse_yaml, read_text_file
from frp_assess.dynamics.options import INTEGRATION_TOLERANCE
from frp_assess.dynamics.rebars import POSITIONS, Position
from frp_assess.dynamics.wall import MECHANISMS, Mechanism
from frp_assess.errors import InputError
from frp_assess.rules.masonry import CONFIDENCE_FACTORS
from frp_assess.study.building import StudyBuilding

#: most cases of one study (the paper's Table 1 has 2,052)
MAX_CASES = 100_000
#: the keys only a study file has at its top level (see :func:`looks_like_study`)
STUDY_ONLY_KEYS = frozenset({"height", "alpha_deg", "ratio", "material", "position", "spectrum"})


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class MaterialSpec(_Strict):
    """An FRP bar material (overrides or extends the built-in library)."""

    elastic_modulus: Number = Field(gt=0, le=1000, description="E [GPa], 0-1000")
    ultimate_strain: Number = Field(gt=0, lt=1, description="ultimate strain ε_u [-]")
    density: Number = Field(default=2000.0, gt=0, le=10000, description="density [kg/m³]")


class SpectrumSpec(_Strict):
    """A named target spectrum given by its text form (``frp_assess.motions.parse_spectrum``)."""

    name: str = Field(
        min_length=1, max_length=MAX_NAME_CHARS, description="label used in the outputs"
    )
    spec: str = Field(
        min_length=1,
        description="A1|A2|A3, 'ec8:type=1,ground=B,ag=0.25', 'ntc:ag=..,F0=..,tc=..,soil=..' "
        "or 'table:T/Se,...' (T in s, Se in g)",
    )


class RecordSetSpec(_Strict):
    """Artificial spectrum-compatible records (SIMQKE), one set per spectrum."""

    count: int = Field(default=7, ge=1, le=100, description="records per spectrum [-], 1-100")
    seed: int = Field(
        default=1,
        ge=0,
        le=MAX_SEED,
        description=f"generator seed, 0-{MAX_SEED} (same seed, same records)",
    )
    duration: Number = Field(
        default=25.0,
        gt=0,
        le=MAX_RECORD_DURATION,
        description=f"total duration [s], at most {MAX_RECORD_DURATION:g}",
    )
    dt: Number = Field(
        default=0.005,
        ge=MIN_TIME_STEP,
        le=0.05,
        description=f"time step [s], {MIN_TIME_STEP:g}-0.05",
    )
    stationary: Number = Field(
        default=10.0, gt=0, description="stationary part [s], shorter than the duration"
    )
    t1: Number = Field(
        default=1.0, gt=0, le=10, description="reference period of the compliance range [s], 0-10"
    )

    @model_validator(mode="after")
    def _stationary(self) -> RecordSetSpec:
        if self.stationary >= self.duration:
            raise ValueError(
                f"stationary part {self.stationary:g} s must be shorter than the duration "
                f"{self.duration:g} s"
            )
        return self


class ModelSpec(ModelOptionsSpec):
    """Model options of docs/model.md §2–4: those of a project's ``analysis`` (the same
    fields, checks and defaults) and the integration tolerance, here flat."""

    integration_tolerance: Number = option_field(INTEGRATION_TOLERANCE)


def _unique_positive(values: list[float], what: str) -> list[float]:
    if not values:
        raise ValueError(f"{what}: give at least one value")
    for v in values:
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{what}: every value must be > 0, got {v!r}")
    if len(set(values)) != len(values):
        raise ValueError(f"{what}: repeated values {values}")
    return values


class StudyFile(_Strict):
    """A parametric study: the cross product of the axes below.

    Unreinforced walls (one per wall × mechanism × spectrum) are always included and shared
    by every reinforced case of that wall; ``ratio``, ``material`` and ``position`` only
    multiply the reinforced cases.
    """

    name: str = Field(
        min_length=1, max_length=MAX_NAME_CHARS, description="study name (output labels)"
    )
    description: str = Field("", max_length=MAX_NOTES_CHARS)
    # the ranges of a project's wall.height and wall.thickness (config.schema.spec_base)
    height: list[Annotated[Number, Field(ge=HEIGHT_RANGE[0], le=HEIGHT_RANGE[1])]] = Field(
        description="wall heights H [m], 0.5-50"
    )
    alpha_deg: list[Number] | None = Field(
        default=None, description="slenderness α [°], tan α = B/H (give this or thickness)"
    )
    thickness: (
        list[Annotated[Number, Field(ge=THICKNESS_RANGE[0], le=THICKNESS_RANGE[1])]] | None
    ) = Field(default=None, description="wall thickness B [m], 0.05-5 (give this or alpha_deg)")
    ratio: list[Annotated[Number, Field(le=20)]] = Field(
        default_factory=list, description="ρ [‰] of the active bars, <= 20"
    )
    material: list[str] = Field(default_factory=list, description="FRP material names")
    materials: dict[str, MaterialSpec] = Field(
        default_factory=dict, description="materials added to / overriding the library"
    )
    position: list[Position] = Field(default_factory=lambda: [POSITIONS[1]])  # external
    mechanism: list[Mechanism] = Field(default_factory=lambda: [MECHANISMS[0]])  # one-sided
    spectrum: list[str | SpectrumSpec] = Field(description="target spectra")
    records: RecordSetSpec = RecordSetSpec()
    model: ModelSpec = ModelSpec()
    ida: IdaSpec = IdaSpec()
    building: StudyBuilding | None = Field(
        None, description="walls above the ground floor: the building, wall_base an axis"
    )
    unit_weight: Number = Field(
        default=18.0, ge=5, le=30, description="masonry unit weight w [kN/m³], 5-30"
    )
    masonry: str | None = Field(
        default=None,
        description="masonry type of Circolare 2019 Tab. C8.5.I whose f_m sizes the compressed "
        "zone of the crushing pivot (LC1: minimum, LC2/LC3: mean; the unit weight stays "
        "unit_weight): " + ", ".join(MASONRY),
    )
    compressive_strength: Number | None = Field(
        default=None,
        gt=0,
        le=100,
        description="compressive strength f_m of the masonry [MPa], 0-100; wins over masonry "
        "(neither: the lowest f_m of Tab. C8.5.I, as a project)",
    )
    knowledge_level: Literal["LC1", "LC2", "LC3"] = Field(
        default="LC1",
        description="knowledge level: f_d = f_m/FC, FC = "
        + ", ".join(f"{fc:.2f}" for fc in CONFIDENCE_FACTORS.values()),
    )
    chunk_size: int = Field(
        default=64, ge=1, le=100_000, description="cases per chunk written to disk [-]"
    )

    @field_validator("height", "thickness", "ratio")
    @classmethod
    def _positive(cls, v: list[float] | None, info: Any) -> list[float] | None:
        if v is None or (info.field_name == "ratio" and not v):
            return v
        return _unique_positive(v, info.field_name)

    @field_validator("alpha_deg")
    @classmethod
    def _alpha(cls, v: list[float] | None) -> list[float] | None:
        if v is None:
            return v
        _unique_positive(v, "alpha_deg")
        for a in v:
            if a >= 45.0:
                raise ValueError(f"alpha_deg: a rocking wall needs α < 45°, got {a!r}")
        return v

    @field_validator("masonry")
    @classmethod
    def _known_masonry(cls, value: str | None) -> str | None:
        if value is not None and value not in MASONRY:
            raise ValueError(
                f"unknown masonry {value!r}{did_you_mean(value, MASONRY)}; "
                f"expected one of {', '.join(MASONRY)}"
            )
        return value

    @field_validator("position", "mechanism", "material")
    @classmethod
    def _distinct(cls, v: list[str], info: Any) -> list[str]:
        if len(set(v)) != len(v):
            raise ValueError(f"{info.field_name}: repeated values {v}")
        return v

    @model_validator(mode="after")
    def _consistent(self) -> StudyFile:
        if (self.alpha_deg is None) == (self.thickness is None):
            raise ValueError("give exactly one of alpha_deg (α [°]) and thickness (B [m])")
        if self.thickness is not None:
            for b in self.thickness:
                for h in self.height:
                    if (problem := slenderness_problem(b, h)) is not None:
                        raise ValueError(problem)
        for a in self.alpha_deg or ():  # B = H tan α: a project's wall.thickness range
            for h in self.height:
                b = h * math.tan(math.radians(a))
                if not THICKNESS_RANGE[0] <= b <= THICKNESS_RANGE[1]:
                    raise ValueError(
                        f"alpha_deg: α = {a:g}° with H = {h:g} m gives B = {b:.3g} m; a wall "
                        f"is {THICKNESS_RANGE[0]:g}-{THICKNESS_RANGE[1]:g} m thick"
                    )
        reinforced = [bool(self.ratio), bool(self.material), bool(self.position)]
        if any(reinforced[:2]) and not all(reinforced):
            raise ValueError(
                "reinforced cases need ratio, material and position (or omit ratio and "
                "material for an unreinforced-only study)"
            )
        if not self.spectrum:
            raise ValueError("spectrum: give at least one spectrum")
        labels = [spectrum_label(s) for s in self.spectrum]
        if len(set(labels)) != len(labels):
            raise ValueError(f"spectrum: repeated labels {labels}")
        cases = self.case_count()
        if cases > MAX_CASES:
            raise ValueError(
                f"the axes give {cases:,} cases, more than {MAX_CASES:,}; split the study"
            )
        return self

    def case_count(self) -> int:
        """Number of cases: walls × mechanisms × spectra × (1 + reinforcements)."""
        geometry = len(self.alpha_deg if self.alpha_deg is not None else self.thickness or [])
        walls = len(self.height) * geometry * len(self.mechanism) * len(self.spectrum)
        walls *= 1 if self.building is None else len(self.building.wall_base)
        return walls * (1 + len(self.ratio) * len(self.material) * len(self.position))


def spectrum_label(s: str | SpectrumSpec) -> str:
    """The label of a spectrum entry in the outputs (the text itself, or its ``name``)."""
    return s.name if isinstance(s, SpectrumSpec) else s.strip()


def spectrum_text(s: str | SpectrumSpec) -> str:
    """The text form of a spectrum entry (for ``parse_spectrum``)."""
    return s.spec if isinstance(s, SpectrumSpec) else s.strip()


# --- reading a file ---------------------------------------------------------------------------


def looks_like_study(data: Any) -> bool:
    """Whether parsed YAML is a study file rather than a project file.

    A project file has ``wall``/``seismic`` blocks; a study file has none and lists its axes
    (``height``, ``spectrum``, ...) at the top level.
    """
    if not isinstance(data, dict) or "wall" in data or "seismic" in data:
        return False
    return any(key in data for key in STUDY_ONLY_KEYS)


def parse_study(
    data: Any,
    *,
    file: str | None = None,
    text: str | None = None,
    lines: Mapping[Loc, int] | None = None,
) -> StudyFile:
    """Validate a parsed study mapping; every problem as a one-line :class:`InputError`.

    Args:
        data: the parsed YAML.
        file: shown as the file name in the messages.
        text: the YAML text, to find the line of each problem (or give ``lines``).
        lines: key path -> 1-based line, as :func:`~frp_assess.config.yaml_source.parse_yaml`
            returns.
    """
    if lines is None and text is not None:
        _, lines = parse_yaml(text, file or "<study>")
    if not isinstance(data, dict):
        raise InputError(
            "a study file must be a mapping of keys to values",
            file=file,
            line=1 if lines is not None else None,
        )
    try:
        return StudyFile.model_validate(data)
    except ValidationError as exc:
        raise_all(schema_problems(StudyFile, exc, file=file, lines=lines))
        raise  # pragma: no cover - schema_problems never returns an empty list


def load_study_text(text: str, name: str) -> StudyFile:
    """Parse and validate study YAML held in memory (``name``: shown in the messages)."""
    data, lines = parse_yaml(text, name)
    if data is None:
        raise InputError("the study file is empty", file=name, line=1)
    return parse_study(data, file=name, lines=lines)


def load_study(path: str | Path) -> StudyFile:
    """Read and validate a study file (YAML, a regular file of at most 2 MB)."""
    p = Path(path)
    return load_study_text(read_text_file(p, "study file"), str(p))
