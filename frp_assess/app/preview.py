"""The derived quantities the TUI shows next to the fields while a project is typed.

α, R, p and a_RM of the wall (about the model's pivot, with x_W for the crushing pivot), the
elastic spectrum (and so a_g·S) of a ``seismic.spectrum`` block, the FRP mass per metre of an
option and the options' quantities and costs, the design-value rule for a number of records:
each computed by the one function the run uses (:mod:`frp_assess.assess.wall_model`,
:mod:`frp_assess.assess.quantities`, :mod:`frp_assess.assess.from_project`,
:mod:`frp_assess.assess.runner`), so that what the form previews is what the run will compute.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from frp_assess.assess.from_project import costs_of, loads_of, material_of, option_of, spectrum_of
from frp_assess.assess.inputs import CostSettings
from frp_assess.assess.quantities import frp_quantity, tie_quantity
from frp_assess.assess.runner import design_value_rule
from frp_assess.assess.wall_model import (
    WallInput,
    case_design_strength,
    rocking_model,
    weight_depth,
)
from frp_assess.config import FrpMaterial, Project
from frp_assess.config.schema import Ntc2018Spectrum, Spectrum, WallSpec
from frp_assess.dynamics import ModelOptions, Position
from frp_assess.dynamics.base_reaction import PivotRule
from frp_assess.motions import ElasticSpectrum

__all__ = [
    "OptionRow",
    "WallDerived",
    "design_value_rule",
    "elastic_spectrum",
    "frp_mass_per_metre",
    "option_rows",
    "wall_derived",
]


@dataclass(frozen=True)
class WallDerived:
    """Derived constants of the wall (per metre of length; docs/model.md §1)."""

    alpha: float  #: slenderness α [rad]
    R: float  #: half diagonal [m]  # noqa: N815
    p: float  #: frequency parameter [rad/s]
    a_rm: float  #: rocking activation acceleration [g], about the model's pivot
    mass: float  #: [kg/m]
    unit_weight: float  #: [kN/m³]
    #: x_W [m], the compressed zone under the wall's weight with ``pivot: crushing`` (0: edge)
    depth: float = 0.0
    pivot: str = "edge"  #: the pivot the model turns about

    @property
    def alpha_deg(self) -> float:
        """α [°]."""
        return math.degrees(self.alpha)


def wall_derived(spec: WallSpec, pivot: PivotRule = "crushing", level: str = "LC1") -> WallDerived:
    """The derived constants of the unreinforced wall's model for a valid ``wall`` block, the
    pivot rule and the knowledge level (its FC gives f_d): the model ``run`` builds
    (:mod:`frp_assess.assess.wall_model`), with the loads it carries (a_RM with them,
    docs/model.md §12).  Raises InputError when the base cannot carry the wall and its loads,
    or when the loads tip it at rest."""
    f_d = case_design_strength(spec.masonry, level, spec.compressive_strength)
    model = rocking_model(
        WallInput(spec.thickness, spec.height, spec.unit_weight_kn, f_d),
        spec.mechanism,
        None,
        ModelOptions(pivot=pivot),
        loads=loads_of(spec.loads).loads(),
    )
    w = model.wall
    depth = weight_depth(w) if pivot == "crushing" else 0.0
    return WallDerived(w.alpha, w.R, w.p, model.a_rm_g, w.mass, spec.unit_weight_kn, depth, pivot)


def elastic_spectrum(spec: Spectrum) -> ElasticSpectrum:
    """The elastic spectrum of a valid ``seismic.spectrum`` block (its ``pga_g`` is a_g·S)."""
    return spectrum_of(spec)


def site_warning(spec: Spectrum) -> str:
    """The warning of a site near Italy's land border (the one ``site``, ``validate`` and
    ``run`` print: :func:`~frp_assess.motions.site.territory.check_in_italy`) for a spectrum
    given by coordinates; "" for any other spectrum or site."""
    hazard = spec.site_hazard() if isinstance(spec, Ntc2018Spectrum) else None
    return "" if hazard is None else hazard.border_warning


def frp_mass_per_metre(
    thickness: float, height: float, material: FrpMaterial, position: Position, ratio: float
) -> float:
    """Installed FRP [kg per metre of wall] of one option: B, H [m], ρ [‰] (both faces when
    external)."""
    q = frp_quantity(thickness, height, 1.0, material_of(material), position, ratio, CostSettings())
    return q.mass_per_m


@dataclass(frozen=True)
class OptionRow:
    """One retrofit option the run will compare, with its FRP and tie steel quantities and
    its cost."""

    name: str
    mass_per_m: float  #: FRP mass per metre of wall length [kg/m]
    mass: float  #: FRP mass over the wall length [kg]
    cost: float  #: FRP, tie and installation cost [currency]
    kind: str = "bars"  #: bars | tie | bars+tie
    steel_per_m: float = 0.0  #: the tie's steel per metre of wall length [kg/m]


def option_rows(project: Project) -> list[OptionRow]:
    """The options after expanding sweeps, with their quantities (wall length L)."""
    w = project.wall
    table = {name: material_of(m) for name, m in project.material_table().items()}
    costs = costs_of(project)
    rows = []
    for expanded in project.expand_interventions():
        o = option_of(expanded, table)
        mass_per_m = mass = cost = steel = 0.0
        if o.material is not None and o.position is not None:
            q = frp_quantity(
                w.thickness, w.height, w.length, o.material, o.position, o.ratio, costs
            )
            mass_per_m, mass, cost = q.mass_per_m, q.mass, q.cost
        if o.tie is not None:
            t = tie_quantity(o.tie, costs.ties, w.length)
            steel, cost = t.mass_per_m, cost + t.cost
        rows.append(OptionRow(o.name, mass_per_m, mass, cost, o.kind, steel))
    return rows
