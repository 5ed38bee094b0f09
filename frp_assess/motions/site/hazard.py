"""The seismic parameters of a site from its coordinates (NTC 2018 §3.2, NTC 2008 Allegati A/B).

From the coordinates, the nominal life V_N and the use class: V_R = V_N·C_U, then for each
limit state T_R = −V_R/ln(1 − P_VR) (clamped to 30-2475 years), then a_g, F0, T_C* at the
site: the inverse-distance mean of the four vertices of the grid cell that contains the site
(the 4 nearest nodes where no complete cell does, at the grid's border) at the two grid
return periods around T_R, then the log-log interpolation between them
(docs/site-hazard.md).  A site the grid reaches but that lies abroad is refused, and a site
near the land border carries a warning (:func:`~frp_assess.motions.site.territory.check_in_italy`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from frp_assess.motions.site.cells import containing_cell
from frp_assess.motions.site.formulas import (
    C_U,
    GRID_RETURN_PERIODS,
    LIMIT_STATES,
    P_VR,
    T_R,
    V_R,
    bracket,
    clamp_return_period,
    inverse_distance_mean,
    log_interpolation,
)
from frp_assess.motions.site.grid import NearNode, load_grid, near_nodes, nearest_nodes
from frp_assess.motions.site.territory import check_in_italy

#: how the site's values were interpolated: the four vertices of the grid cell that
#: contains the site (NTC 2008 Allegato A), or the four nearest nodes (no complete cell
#: contains the site: the grid's border)
INTERPOLATIONS = ("cell", "nearest")


@dataclass(frozen=True)
class LimitStateHazard:
    """One limit state at the site: TR [years] (as computed; ``TR_used`` after the clamp to
    30-2475 years), ag [g] on rock, F0 [-], Tc_star = T_C* [s]."""

    TR: float
    TR_used: float
    ag: float
    F0: float
    Tc_star: float


@dataclass(frozen=True)
class SiteHazard:
    """The site: latitude, longitude [°]; V_N [years]; use class; C_U [-]; V_R [years]; the
    four limit states (SLO, SLD, SLV, SLC, in order); the grid nodes used, nearest first;
    ``interpolation`` "cell" (the vertices of the cell containing the site) or "nearest"
    (the four nearest nodes, for a site in no complete cell); ``border_warning`` the
    warning for a site near Italy's land border ("" elsewhere)."""

    latitude: float
    longitude: float
    V_N: float
    use_class: str
    C_U: float
    V_R: float
    states: dict[str, LimitStateHazard]
    nodes: tuple[NearNode, ...]
    interpolation: str = "cell"
    border_warning: str = ""

    def __getitem__(self, limit_state: str) -> LimitStateHazard:
        return self.states[limit_state]


def site_nodes(latitude: float, longitude: float) -> tuple[tuple[NearNode, ...], str]:
    """The grid nodes whose values make the site's [°], nearest first, and how they were
    chosen (:data:`INTERPOLATIONS`): the four vertices of the cell that contains the site,
    or the four nearest nodes when no complete cell does.  Raises
    :class:`~frp_assess.motions.site.grid.OutsideGridError` for a site off the grid."""
    nearest = nearest_nodes(latitude, longitude)
    cell = containing_cell(latitude, longitude, tuple(n.index for n in nearest))
    if cell is None:
        return nearest, "nearest"
    vertices = near_nodes(latitude, longitude, np.array(cell))
    return tuple(sorted(vertices, key=lambda n: (n.distance, n.index))), "cell"


def grid_values(nodes: tuple[NearNode, ...], column: int) -> tuple[float, float, float]:
    """(a_g [g], F0, T_C* [s]) at the site for the grid's return period of index ``column``:
    the inverse-distance mean of the nodes' values (NTC 2008 Allegato A eq. 2)."""
    g = load_grid()
    idx = [n.index for n in nodes]
    d = [n.distance for n in nodes]
    return (
        inverse_distance_mean([float(g.ag[i, column]) for i in idx], d),
        inverse_distance_mean([float(g.F0[i, column]) for i in idx], d),
        inverse_distance_mean([float(g.Tc_star[i, column]) for i in idx], d),
    )


def parameters_at(nodes: tuple[NearNode, ...], TR: float) -> tuple[float, float, float]:  # noqa: N803
    """(a_g [g], F0, T_C* [s]) at the site for the return period ``TR`` [years], 30-2475:
    each parameter at the two grid return periods around TR, then log-log interpolated
    (NTC 2008 Allegato A eq. 3); exactly the grid's values when TR is one of them."""
    lo, hi = bracket(TR)
    p1 = grid_values(nodes, GRID_RETURN_PERIODS.index(lo))
    if lo == hi or TR == lo:
        return p1
    p2 = grid_values(nodes, GRID_RETURN_PERIODS.index(hi))
    if TR == hi:
        return p2
    a, b, c = (log_interpolation(TR, lo, x1, hi, x2) for x1, x2 in zip(p1, p2, strict=True))
    return a, b, c


def site_hazard(
    latitude: float, longitude: float, nominal_life: float = 50.0, use_class: str = "II"
) -> SiteHazard:
    """The NTC parameters of the four limit states at a site given by its coordinates [°],
    its nominal life V_N [years] and use class ("I"-"IV").  Raises
    :class:`~frp_assess.motions.site.grid.OutsideGridError` (an InputError) for a site the
    grid does not cover or :class:`~frp_assess.motions.site.territory.OutsideItalyError` for
    one abroad (both InputError), ValueError for a bad V_N or use class."""
    c_u = C_U(use_class)
    v_r = V_R(nominal_life, c_u)
    nodes, interpolation = site_nodes(latitude, longitude)
    warning = check_in_italy(latitude, longitude) or ""
    states: dict[str, LimitStateHazard] = {}
    for state in LIMIT_STATES:
        tr = T_R(v_r, P_VR[state])
        used = clamp_return_period(tr)
        ag, f0, tc = parameters_at(nodes, used)
        states[state] = LimitStateHazard(tr, used, ag, f0, tc)
    return SiteHazard(
        latitude,
        longitude,
        nominal_life,
        use_class,
        c_u,
        v_r,
        states,
        nodes,
        interpolation,
        warning,
    )
