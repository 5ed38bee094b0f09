"""Figures about the project being edited, shown next to the fields (no Textual here)."""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.from_project import material_of
from frp_assess.assess.inputs import Costs
from frp_assess.assess.quantities import frp_quantity
from frp_assess.assess.runner import design_value_rule
from frp_assess.config import Project


@dataclass(frozen=True)
class OptionRow:
    """One retrofit option the run will compare, with its FRP quantity and cost."""

    name: str
    mass_per_m: float  #: FRP mass per metre of wall length [kg/m]
    mass: float  #: FRP mass over the wall length [kg]
    cost: float  #: FRP and installation cost [currency]


def record_count(project: Project) -> int:
    """How many records the run uses (artificial ones or files)."""
    recs = project.seismic.records
    return recs.artificial.count if recs.artificial is not None else len(recs.files or [])


def option_rows(project: Project) -> list[OptionRow]:
    """The options after expanding sweeps, with their quantities (wall length L)."""
    w, table = project.wall, project.material_table()
    costs = Costs(str(project.costs.currency), project.costs.installation_per_metre)
    rows = []
    for o in project.expand_interventions():
        q = frp_quantity(
            w.thickness,
            w.height,
            w.length,
            material_of(table[o.material]),
            o.position,
            o.ratio,
            costs,
        )
        rows.append(OptionRow(str(o.name), q.mass_per_m, q.mass, q.cost))
    return rows


def retrofits_summary(project: Project | None) -> str:
    """The line above the retrofit table: options, cases and IDAs of a run."""
    if project is None:
        return "Retrofit options (FRP mass per metre of wall, both faces if external)"
    n_rec = record_count(project)
    n = len(project.expand_interventions())
    return (
        f"Retrofit options: {n} after expanding sweeps (repeats dropped); with the "
        f"unreinforced wall {n + 1} cases × {n_rec} records = {(n + 1) * n_rec} IDAs"
    )


def records_summary(project: Project) -> tuple[str, str]:
    """What the records are (one sentence) and the design-value rule for their number."""
    recs = project.seismic.records
    n = record_count(project)
    if recs.artificial is not None:
        a = recs.artificial
        text = (
            f"{a.count} artificial records of {a.duration:g} s at dt = {a.dt:g} s "
            f"({int(round(a.duration / a.dt)) + 1} samples), compatible with the site "
            f"spectrum; seed {a.seed}."
        )
    else:
        text = f"{n} record files, " + (
            "scaled together to a_g·S of the spectrum."
            if recs.scale_to_spectrum
            else "used as recorded."
        )
    return text, design_value_rule(n)
