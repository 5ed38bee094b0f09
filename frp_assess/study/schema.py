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
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from frp_assess.errors import InputError


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class MaterialSpec(_Strict):
    """An FRP bar material (overrides or extends the built-in library)."""

    elastic_modulus: float = Field(gt=0, description="E [GPa]")
    ultimate_strain: float = Field(gt=0, lt=1, description="ultimate strain ε_u [-]")
    density: float = Field(default=2000.0, gt=0, description="density [kg/m³]")


class SpectrumSpec(_Strict):
    """A named target spectrum given by its text form (``frp_assess.motions.parse_spectrum``)."""

    name: str = Field(min_length=1, description="label used in the outputs")
    spec: str = Field(
        min_length=1,
        description="A1|A2|A3, 'ec8:type=1,ground=B,ag=0.25', 'ntc:ag=..,F0=..,tc=..,soil=..' "
        "or 'table:T/Se,...' (T in s, Se in g)",
    )


class RecordSetSpec(_Strict):
    """Artificial spectrum-compatible records (SIMQKE), one set per spectrum."""

    count: int = Field(default=7, ge=1, le=100, description="records per spectrum [-]")
    seed: int = Field(default=1, ge=0, description="generator seed (same seed, same records)")
    duration: float = Field(default=25.0, gt=0, description="total duration [s]")
    dt: float = Field(default=0.005, gt=0, le=0.05, description="time step [s]")
    stationary: float = Field(default=10.0, gt=0, description="stationary part [s]")
    t1: float = Field(default=1.0, gt=0, description="reference period of the compliance range [s]")


class ModelSpec(_Strict):
    """Model options of MODEL.md §3 and the cyclic strain factor of §2."""

    restitution: Literal["energy", "velocity"] | float = Field(
        default="energy",
        description="impact rule: 'energy' (|θ'+| = √r·|θ'-|), 'velocity' (r·|θ'-|) or a "
        "velocity ratio in (0, 1]",
    )
    rupture: Literal["energy-transfer", "velocity-continuous"] = "energy-transfer"
    collapse: Literal["end-of-record", "first-exceedance"] = "end-of-record"
    strain_factor: float = Field(default=0.5, gt=0, le=1, description="c in ε_max = c·ε_u [-]")
    free_vibration_tail: float = Field(
        default=0.0, ge=0, description="zero ground motion appended to each record [s]"
    )

    @field_validator("restitution")
    @classmethod
    def _ratio_range(cls, v: Any) -> Any:
        if isinstance(v, float) and not (0.0 < v <= 1.0):
            raise ValueError("a numeric restitution is a velocity ratio in (0, 1]")
        return v


class IdaSpec(_Strict):
    """IDA search rule of MODEL.md §5."""

    step_ratio: float = Field(default=1.10, gt=1.0, description="hunt ratio s [-]")
    tolerance: float = Field(default=0.005, gt=0, le=0.1, description="bisection tolerance [-]")
    max_multiplier: float = Field(default=100.0, gt=1.0, description="C_max / C₀ [-]")


Position = Literal["centred", "external"]
Mechanism = Literal["one-sided", "two-sided"]


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

    name: str = Field(min_length=1, description="study name (output labels)")
    description: str = ""
    height: list[float] = Field(description="wall heights H [m]")
    alpha_deg: list[float] | None = Field(
        default=None, description="slenderness α [°], tan α = B/H (give this or thickness)"
    )
    thickness: list[float] | None = Field(
        default=None, description="wall thickness B [m] (give this or alpha_deg)"
    )
    ratio: list[float] = Field(default_factory=list, description="ρ [‰] of the active bars")
    material: list[str] = Field(default_factory=list, description="FRP material names")
    materials: dict[str, MaterialSpec] = Field(
        default_factory=dict, description="materials added to / overriding the library"
    )
    position: list[Position] = Field(default_factory=lambda: ["external"])
    mechanism: list[Mechanism] = Field(default_factory=lambda: ["one-sided"])
    spectrum: list[str | SpectrumSpec] = Field(description="target spectra")
    records: RecordSetSpec = RecordSetSpec()
    model: ModelSpec = ModelSpec()
    ida: IdaSpec = IdaSpec()
    unit_weight: float = Field(default=18.0, gt=0, description="masonry unit weight w [kN/m³]")
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
                    if b >= h:
                        raise ValueError(f"thickness {b} m is not smaller than height {h} m")
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
        return self


def spectrum_label(s: str | SpectrumSpec) -> str:
    """The label of a spectrum entry in the outputs (the text itself, or its ``name``)."""
    return s.name if isinstance(s, SpectrumSpec) else s.strip()


def spectrum_text(s: str | SpectrumSpec) -> str:
    """The text form of a spectrum entry (for ``parse_spectrum``)."""
    return s.spec if isinstance(s, SpectrumSpec) else s.strip()


# --- reading a file ---------------------------------------------------------------------------


def _line_of(root: yaml.Node | None, loc: tuple[Any, ...]) -> int | None:
    """1-based line of the YAML node at the key path ``loc`` (the deepest one found)."""
    node = root
    line = None if node is None else node.start_mark.line + 1
    for part in loc:
        if isinstance(node, yaml.MappingNode):
            for k, v in node.value:
                if isinstance(k, yaml.ScalarNode) and k.value == str(part):
                    line = k.start_mark.line + 1
                    node = v
                    break
            else:
                return line
        elif isinstance(node, yaml.SequenceNode) and isinstance(part, int):
            if part >= len(node.value):
                return line
            node = node.value[part]
            line = node.start_mark.line + 1
        else:
            return line
    return line


def parse_study(data: Any, *, file: str | None = None, text: str | None = None) -> StudyFile:
    """Validate a parsed study mapping; errors become one-line :class:`InputError`."""
    if not isinstance(data, dict):
        raise InputError("a study file must be a mapping of keys to values", file=file)
    try:
        return StudyFile.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        loc = tuple(p for p in err["loc"] if not (isinstance(p, str) and "[" in p))
        key = ".".join(str(p) for p in loc) or None
        if err["type"] == "extra_forbidden":
            allowed = _allowed_keys(loc[:-1])
            msg = "unknown key" + (f"; allowed keys: {', '.join(allowed)}" if allowed else "")
        else:
            msg = str(err["msg"]).removeprefix("Value error, ")
        line = None
        if text is not None:
            try:
                line = _line_of(yaml.compose(text, Loader=yaml.SafeLoader), loc)
            except yaml.YAMLError:
                line = None
        raise InputError(msg, file=file, line=line, key=key) from None


def _allowed_keys(loc: tuple[Any, ...]) -> list[str]:
    model: type[BaseModel] = StudyFile
    for part in loc:
        field = model.model_fields.get(str(part))
        ann = None if field is None else field.annotation
        if isinstance(ann, type) and issubclass(ann, BaseModel):
            model = ann
        else:
            return []
    return list(model.model_fields)


def load_study(path: str | Path) -> StudyFile:
    """Read and validate a study file (YAML)."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read the study file: {exc.strerror}", file=str(p)) from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        raise InputError(
            f"not valid YAML: {getattr(exc, 'problem', exc)}",
            file=str(p),
            line=None if mark is None else mark.line + 1,
        ) from None
    return parse_study(data, file=str(p), text=text)
