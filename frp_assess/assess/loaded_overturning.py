"""α₀ of simple overturning with the loads the wall carries, term by term (Circolare 2019
§C8.7.1.2, eq. C8.7.1.1; e* and M* of eq. C8.7.1.5; docs/model.md §12 "Code checks").

A virtual outward rotation about the outer base corner O: the wall's weight and the top loads
hold (W·B/2, P_i·d_i), the base reaction of the crushing pivot takes N₀·x₀/2 from them
(N₀ = W + ΣP_i, x₀ = N₀/(0.85·f_d); 0 with the edge pivot, docs/model.md §10), the thrusts
overturn (F_j·h_j), the ties at their capacity do the internal work L_i = min(F_y, F_a/i_t)·h_t
(the Circolare's rigid-plastic kinematic analysis), and the horizontal inertia of the wall and
of the carried loads drives (W·H/2, P_c·H per g).  The formulas are
:mod:`frp_assess.rules.wall_loads`'; this module applies them to a model and names the terms.
Units: SI inside (N/m, m), kN/m and kNm/m in the results.
"""

from __future__ import annotations

from frp_assess.assess.load_inputs import LoadsInput
from frp_assess.dynamics import RockingModel
from frp_assess.dynamics.loads import Loads
from frp_assess.dynamics.units import N_PER_KN
from frp_assess.results.carried_loads import (
    BASE_REACTION,
    WALL_WEIGHT,
    MomentTerm,
    OverturningResult,
)
from frp_assess.rules.constants import G
from frp_assess.rules.masonry import compressed_zone_depth
from frp_assess.rules.tie_rods import tie_capacity
from frp_assess.rules.wall_loads import (
    overturning_multiplier,
    participating_mass_ratio,
    participating_weight,
)


def base_moment(model: RockingModel) -> float:
    """N₀·x₀/2 [N·m/m]: the moment the crushing pivot's stress block takes from the
    stabilising ones at rest, N₀ = W + ΣP_i, x₀ = N₀/(0.85·f_d) (0 with the edge pivot)."""
    if model.base_reaction.weight_depth == 0.0:
        return 0.0
    n0 = model.wall.weight + model.loads.vertical
    return n0 * compressed_zone_depth(n0, model.wall.compressive_strength) / 2.0


def tie_work(loads: Loads) -> float:
    """L_i = Σ min(F_y, F_a/i_t)·h_t [N·m/m]: the ties at their capacity for a unit virtual
    rotation (Circolare 2019 §C8.7.1.2)."""
    return sum(tie_capacity(t.yield_force, t.anchorage_force) * t.height for t in loads.ties)


def loaded_alpha0(model: RockingModel, *, with_ties: bool = True) -> float:
    """α₀ [-] of eq. C8.7.1.1 with the model's loads (module docstring); ``with_ties=False``:
    without the ties' work (a_RM/g, where rocking starts)."""
    w = model.wall
    loads = model.loads
    return overturning_multiplier(
        w.weight,
        w.thickness,
        w.height,
        loads.top,
        loads.thrusts,
        tie_work(loads) if with_ties else 0.0,
        base_moment(model),
    )


def loaded_e_star(model: RockingModel) -> float:
    """e* [-] of eq. C8.7.1.5 with the carried loads."""
    return participating_mass_ratio(model.wall.weight, model.wall.height, model.loads.top)


def loaded_m_star(model: RockingModel) -> float:
    """M* = e*·(W + ΣP_c)/g [kg/m] (eq. C8.7.1.5)."""
    return loaded_e_star(model) * participating_weight(model.wall.weight, model.loads.top) / G


def _term(name: str, role: str, force: float, lever: float, sign: float = 1.0) -> MomentTerm:
    return MomentTerm(name, role, force / N_PER_KN, lever, sign * force * lever / N_PER_KN)


def moment_terms(model: RockingModel, names: LoadsInput) -> tuple[MomentTerm, ...]:
    """Every term of α₀ (kN/m, m, kNm/m), named as the project names the loads."""
    w = model.wall
    loads = model.loads
    terms = [_term(WALL_WEIGHT, "stabilising", w.weight, w.thickness / 2.0)]
    terms += [
        _term(n.name, "stabilising", p.force, p.distance)
        for n, p in zip(names.top, loads.top, strict=True)
    ]
    if (m := base_moment(model)) > 0.0:
        n0 = w.weight + loads.vertical
        terms.append(_term(BASE_REACTION, "stabilising", n0,
                           m / n0, -1.0))  # fmt: skip
    terms += [
        _term(n.name, "overturning", f.force, f.height)
        for n, f in zip(names.thrusts, loads.thrusts, strict=True)
    ]
    terms += [
        _term(n.name, "internal work", tie_capacity(t.yield_force, t.anchorage_force), t.height)
        for n, t in zip(names.ties, loads.ties, strict=True)
    ]
    terms.append(_term(WALL_WEIGHT, "inertia", w.weight, w.height / 2.0))
    terms += [
        _term(n.name, "inertia", p.force, w.height)
        for n, p in zip(names.top, loads.top, strict=True)
        if p.carried
    ]
    return tuple(terms)


def _sum(terms: tuple[MomentTerm, ...], role: str) -> float:
    return sum(t.moment for t in terms if t.role == role)


def overturning_result(model: RockingModel, names: LoadsInput) -> OverturningResult:
    """α₀ with its terms, e* and M* (module docstring), for results.json and the report."""
    terms = moment_terms(model, names)
    stab, over = _sum(terms, "stabilising"), _sum(terms, "overturning")
    work, inertia = _sum(terms, "internal work"), _sum(terms, "inertia")
    alpha0 = loaded_alpha0(model)
    formula = (
        f"alpha0 = (sum P*dPy - sum F*dF + L_i) / sum (P+Q)*dPQx = ({stab:.4g} - {over:.4g} "
        f"+ {work:.4g}) / {inertia:.4g} = {alpha0:.4g}"
    )
    return OverturningResult(
        terms=terms,
        stabilising=stab,
        overturning=over,
        internal_work=work,
        inertia=inertia,
        alpha0=alpha0,
        alpha0_without_ties=loaded_alpha0(model, with_ties=False),
        e_star=loaded_e_star(model),
        m_star=loaded_m_star(model),
        formula=formula,
    )
