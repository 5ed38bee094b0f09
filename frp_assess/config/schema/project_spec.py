"""The root model :class:`Project` of a project file, and its ``project`` block
(identification); the cross-checks that need several blocks.
"""

from __future__ import annotations

from pydantic import (
    Field,
    model_validator,
)

from frp_assess.config.library import FRP_MATERIALS, FrpMaterial, did_you_mean
from frp_assess.config.schema.analysis_spec import (
    AnalysisSpec,
    CodeCheckSpec,
)
from frp_assess.config.schema.loads_spec import TieSpec
from frp_assess.config.schema.report_spec import CostsSpec, ReportSpec
from frp_assess.config.schema.retrofit_spec import (
    BarsSpec,
    DesignSpec,
    FrpMaterialSpec,
    Intervention,
    InterventionItem,
    TieOption,
    tie_label,
)
from frp_assess.config.schema.seismic_spec import (
    SeismicSpec,
)
from frp_assess.config.schema.spec_base import (
    MAX_NAME_CHARS,
    MAX_NOTES_CHARS,
    MAX_OPTIONS,
    FreeText,
    _Model,
    located_error,
    option_name,
)
from frp_assess.config.schema.wall_spec import BuildingSpec, WallSpec
from frp_assess.rules.tie_rods import MAX_TIE_LEVELS, TIE_LEVELS_RULE, tie_level_of_each


# --------------------------------------------------------------------------------- project
class ProjectInfoSpec(_Model):
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


# ----------------------------------------------------------------------------------- root
class Project(_Model):
    """A project file: one wall, its site, candidate retrofits and analysis settings."""

    project: ProjectInfoSpec = Field(default_factory=ProjectInfoSpec, description="Identification.")
    wall: WallSpec = Field(description="The wall.")
    building: BuildingSpec | None = Field(
        None,
        description="Where the wall stands in the building (optional; omit for a wall at "
        "ground level): its base then moves with the floor at wall_base.",
    )
    seismic: SeismicSpec = Field(description="Spectrum and records.")
    materials: dict[str, FrpMaterialSpec] = Field(
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
        self._check_tie_heights()
        known = self.material_names()
        for i, item in enumerate(self.interventions):
            if isinstance(item, Intervention):
                self._check_material(item.material, known, "interventions", i, "material")
            elif isinstance(item, TieOption):
                continue
            else:
                for j, m in enumerate(item.sweep.material):
                    self._check_material(m, known, "interventions", i, "sweep", "material", j)
        if self.design is not None:
            for j, m in enumerate(self.design.materials):
                self._check_material(m, known, "design", "materials", j)
        for j, size in enumerate(self.bars.catalogue):
            self._check_material(size.material, known, "bars", "catalogue", j, "material")
        seen: dict[str, Intervention | TieOption] = {}
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
            if isinstance(item, Intervention | TieOption)
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

    def _check_tie_heights(self) -> None:
        """A tie option's tie is on the wall, 0 < height <= H, and with the wall's own ties makes
        at most MAX_TIE_LEVELS tie levels (the time histories' limit, docs/model.md §12)."""
        height = float(self.wall.height)
        existing = () if self.wall.loads is None else self.wall.loads.ties
        for i, item in enumerate(self.interventions):
            loc: tuple[str | int, ...]
            tie: TieSpec
            if isinstance(item, TieOption):
                tie, loc = item, ("interventions", i, "height")
            elif isinstance(item, Intervention) and item.tie is not None:
                tie, loc = item.tie, ("interventions", i, "tie", "height")
            else:
                continue
            if tie.height > height:
                raise located_error(
                    f"expected a tie on the wall, 0 < height <= H = {height:g} m, found "
                    f"{tie.height:g}",
                    *loc,
                )
            levels = tie_level_of_each([t.per_metre() for t in (*existing, tie)])
            if levels[-1] >= MAX_TIE_LEVELS:
                raise located_error(
                    f"the time histories model {TIE_LEVELS_RULE}; with the wall's own ties "
                    f"(wall.loads.ties) this option's tie is a level {levels[-1] + 1}",
                    *loc[:-1],
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

    def _expanded_with_index(self) -> list[tuple[int, Intervention | TieOption]]:
        out: list[tuple[int, Intervention | TieOption]] = []
        for i, item in enumerate(self.interventions):
            if isinstance(item, TieOption):
                out.append((i, item.model_copy(update={"name": item.name or tie_label(item)})))
                continue
            if isinstance(item, Intervention):
                name = item.name or option_name(item.material, item.position, item.ratio)
                if not item.name and item.diameter is not None:
                    name += f" Ø{item.diameter:g}"
                if not item.name and item.tie is not None:
                    name += f" + t{tie_label(item.tie)[1:]}"
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

    def expand_interventions(self) -> list[Intervention | TieOption]:
        """The concrete options, in file order, every one named; an option equal to an earlier
        one (same material, position, ratio, diameter and tie; or the same tie) is dropped."""
        seen: set[tuple[object, ...]] = set()
        out: list[Intervention | TieOption] = []
        for _, option in self._expanded_with_index():
            key = _key(option)
            if key not in seen:
                seen.add(key)
                out.append(option)
        return out


def _tie_key(tie: TieSpec | None) -> tuple[float | None, ...] | None:
    """What makes two ties the same (all but the name)."""
    if tie is None:
        return None
    a = None if tie.anchorage is None else float(tie.anchorage)
    return (
        float(tie.height),
        tie.area_mm2,
        float(tie.spacing),
        float(tie.length),
        float(tie.yield_strength),
        float(tie.elastic_modulus),
        a,
    )


def _key(option: Intervention | TieOption) -> tuple[object, ...]:
    if isinstance(option, TieOption):
        return ("tie", _tie_key(option))
    d = None if option.diameter is None else float(option.diameter)
    return (option.material, option.position, float(option.ratio), d, _tie_key(option.tie))
