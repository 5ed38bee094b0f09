"""The cross product of a study's axes, as a lazily indexed list of cases.

Cases are grouped by *wall group* = (spectrum, mechanism, height, α or B, and the height Z of
the wall's base when the study has a ``building``).  Within a group the
first case is the unreinforced wall, followed by every material × position × ratio; so each
unreinforced wall is computed once and shared by all the reinforced cases of its group, and it
always precedes them (a streaming pass can compute improvements with a small dict).

Nothing here does I/O: ``StudyPlan.case(i)`` decodes case ``i`` from its index, so a plan of
10⁵ cases costs no memory.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Iterator
from dataclasses import dataclass

from frp_assess.assess.inputs import BuildingSettings
from frp_assess.assess.wall_model import (
    BarsInput,
    WallInput,
    base_problem,
    case_design_strength,
    rocking_model,
)
from frp_assess.config.library import FRP_MATERIALS, did_you_mean
from frp_assess.dynamics import RockingModel
from frp_assess.errors import InputError
from frp_assess.rules.geometry import slenderness, thickness_of
from frp_assess.study.schema import StudyFile, spectrum_label, spectrum_text


@dataclass(frozen=True)
class StudyMaterial:
    """An FRP material as used by a study: E [GPa], ε_u [-], density [kg/m³]."""

    name: str
    elastic_modulus: float
    ultimate_strain: float
    density: float


@dataclass(frozen=True)
class Case:
    """One case of the study (unreinforced when ``material`` is ``None``).

    Attributes:
        index: position in the plan (0-based).
        group: wall group index (spectrum × mechanism × height × α/B).
        unreinforced_index: index of the matching unreinforced case (itself if unreinforced).
        spectrum: spectrum label.
        mechanism: ``one-sided`` | ``two-sided``.
        height: H [m].
        thickness: B [m].
        alpha_deg: α [°] (the axis value when the study gives α, else atan(B/H)).
        material: material name or ``None``.
        position: ``centred`` | ``external`` or ``None``.
        ratio: ρ [‰] or ``None``.
        wall_base: Z [m] of the wall's base in the study's building, ``None`` without one.
    """

    index: int
    group: int
    unreinforced_index: int
    spectrum: str
    mechanism: str
    height: float
    thickness: float
    alpha_deg: float
    material: str | None
    position: str | None
    ratio: float | None
    wall_base: float | None = None

    @property
    def reinforced(self) -> bool:
        return self.material is not None

    @property
    def label(self) -> str:
        base = f"{self.spectrum}/{self.mechanism}/H{self.height:g}/a{self.alpha_deg:g}"
        if self.wall_base is not None:
            base += f"/Z{self.wall_base:g}"
        if self.material is None:
            return base + "/URM"
        return f"{base}/{self.material}-{self.position}-{self.ratio:g}"


def resolve_materials(study: StudyFile) -> dict[str, StudyMaterial]:
    """The materials the study uses: the library (docs/model.md §7) overridden by ``materials``."""
    table: dict[str, StudyMaterial] = {
        k: StudyMaterial(k, m.elastic_modulus, m.ultimate_strain, m.density)
        for k, m in FRP_MATERIALS.items()
    }
    for k, m in study.materials.items():
        table[k] = StudyMaterial(k, m.elastic_modulus, m.ultimate_strain, m.density)
    out: dict[str, StudyMaterial] = {}
    for i, name in enumerate(study.material):
        if name not in table:
            raise InputError(
                f"unknown material {name!r}{did_you_mean(name, table)}; known: "
                f"{', '.join(table)} (or define it under materials:)",
                key=f"material.{i}",
            )
        out[name] = table[name]
    return out


class StudyPlan:
    """All cases of a study, decoded on demand from their index."""

    def __init__(self, study: StudyFile) -> None:
        self.study = study
        self.materials = resolve_materials(study)
        self.spectra = [spectrum_label(s) for s in study.spectrum]
        self.spectrum_texts = {spectrum_label(s): spectrum_text(s) for s in study.spectrum}
        self.mechanisms = list(study.mechanism)
        self.heights = list(study.height)
        self.by_alpha = study.alpha_deg is not None
        self.geometry = list(
            study.alpha_deg if study.alpha_deg is not None else study.thickness or []
        )
        self.reinforcements: list[tuple[str, str, float]] = [
            (m, p, r) for m in study.material for p in study.position for r in study.ratio
        ]
        self.group_size = 1 + len(self.reinforcements)
        building = study.building
        #: the wall_base axis [m] ([None]: walls at ground level)
        self.wall_bases: list[float | None] = (
            [None] if building is None else list(building.wall_base)
        )
        self.n_groups = (
            len(self.spectra)
            * len(self.mechanisms)
            * len(self.heights)
            * len(self.geometry)
            * len(self.wall_bases)
        )
        self.options = study.model.model_options(study.model.integration_tolerance)
        self.ida_settings = study.ida.settings()
        #: f_d = f_m/FC [MPa] of every wall of the study (the crushing pivot's masonry)
        self.design_strength = case_design_strength(
            study.masonry, study.knowledge_level, study.compressive_strength
        )
        for h in self.heights:  # the one refusal of the masonry at the base, before any case
            for g in self.geometry:
                b, _ = self.thickness_and_alpha(h, g)
                problem = base_problem(WallInput(b, h, study.unit_weight, self.design_strength))
                if problem is not None:
                    raise InputError(f"H = {h:g} m: {problem}", key="height")

    def __len__(self) -> int:
        return self.n_groups * self.group_size

    @property
    def n_unreinforced(self) -> int:
        return self.n_groups

    @property
    def n_reinforced(self) -> int:
        return self.n_groups * len(self.reinforcements)

    def case(self, index: int) -> Case:
        """Case ``index`` (0 ≤ index < len(self))."""
        if not 0 <= index < len(self):
            raise IndexError(index)
        group, within = divmod(index, self.group_size)
        rest, zi = divmod(group, len(self.wall_bases))
        rest, gi = divmod(rest, len(self.geometry))
        rest, hi = divmod(rest, len(self.heights))
        si, mi = divmod(rest, len(self.mechanisms))
        h = self.heights[hi]
        b, a_deg = self.thickness_and_alpha(h, self.geometry[gi])
        mat: str | None = None
        pos: str | None = None
        ratio: float | None = None
        if within > 0:
            mat, pos, ratio = self.reinforcements[within - 1]
        return Case(
            index=index,
            group=group,
            unreinforced_index=group * self.group_size,
            spectrum=self.spectra[si],
            mechanism=self.mechanisms[mi],
            height=h,
            thickness=b,
            alpha_deg=a_deg,
            material=mat,
            position=pos,
            ratio=ratio,
            wall_base=self.wall_bases[zi],
        )

    def thickness_and_alpha(self, height: float, geometry: float) -> tuple[float, float]:
        """B [m] and α [°] of the wall of height H [m] and the geometry axis' value (α [°]
        when the study gives ``alpha_deg``, else B [m])."""
        if self.by_alpha:
            return thickness_of(height, math.radians(geometry)), geometry
        return geometry, math.degrees(slenderness(geometry, height))

    def building(self, case: Case) -> BuildingSettings | None:
        """Where the wall of ``case`` stands (None: at ground level, docs/model.md §9)."""
        b = self.study.building
        if b is None or case.wall_base is None:
            return None
        return BuildingSettings(b.height, b.storeys, case.wall_base, b.first_period, b.damping)

    def cases(self, start: int = 0, stop: int | None = None) -> Iterator[Case]:
        """Cases ``start`` ≤ i < ``stop`` in order."""
        end = len(self) if stop is None else min(stop, len(self))
        for i in range(start, end):
            yield self.case(i)

    def model(self, case: Case) -> RockingModel:
        """The dynamics model of ``case`` (SI units inside)."""
        wall = WallInput(case.thickness, case.height, self.study.unit_weight, self.design_strength)
        bars = None
        if case.material is not None:
            m = self.materials[case.material]
            assert case.position is not None and case.ratio is not None
            bars = BarsInput(
                m.elastic_modulus,
                m.ultimate_strain,
                case.position,  # type: ignore[arg-type]
                case.ratio,
                self.study.model.strain_factor,
            )
        return rocking_model(wall, case.mechanism, bars, self.options, key="height")  # type: ignore[arg-type]

    def digest(self) -> str:
        """Hash of everything that determines the study's results and its chunking."""
        payload = self.study.model_dump(mode="json", exclude={"name", "description"})
        if payload.get("building") is None:  # studies without one keep their digest
            payload.pop("building", None)
        payload["_materials"] = {k: list(vars(v).values()) for k, v in self.materials.items()}
        return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()[:16]
