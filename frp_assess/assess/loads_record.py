"""results.json's ``loads``: every load the wall carries, as the project gave it with its
per-metre values, and α₀ of simple overturning term by term (docs/model.md §12,
docs/results-json.md), so that a reviewer recomputes α₀ by hand.  None without loads (the
key is then absent: a file without loads is the file it was before loads existed); and a
tie option's tie with its steel and cost, and the tie's prices (docs/model.md §12.2).
"""

from __future__ import annotations

import math

from frp_assess.assess.inputs import AssessmentInputs, RetrofitOption
from frp_assess.assess.load_inputs import TieInput
from frp_assess.assess.loaded_overturning import overturning_result
from frp_assess.assess.quantities import tie_quantity
from frp_assess.dynamics.units import N_PER_KN
from frp_assess.results.carried_loads import (
    LoadsResult,
    ThrustResult,
    TieOptionResult,
    TieResult,
    TopLoadResult,
)
from frp_assess.results.run_inputs import TiePricesResult
from frp_assess.rules.tie_rods import tie_capacity, tie_is_ductile

#: what docs/model.md §12 does not model, for the report's assumptions
NOT_MODELLED = (
    "Masses that push on the wall without bearing on it (Q_k of Circolare 2019 eq. C8.7.1.1) "
    "are not modelled: every load either bears on the wall or is not given.",
    "The friction of the orthogonal walls (Circolare 2019 §C8.7.1.2) is neglected: the façade "
    "is free to turn away from them.",
    "The vertical inertia of the loads is neglected, as the wall's own.",
    "A tie fails only at its anchorage (the plate punching the masonry); the rupture of its "
    "steel is not modelled: a yielding tie keeps its yield force.",
)


def tie_result(tie: TieInput) -> TieResult:
    """One tie as given, with k_t, F_y, F_a/i_t and its capacity per metre (kN/m)."""
    si = tie.tie()
    anchorage = si.anchorage_force / N_PER_KN if math.isfinite(si.anchorage_force) else None
    return TieResult(
        name=tie.name,
        height=tie.height,
        area=tie.area,
        diameter=tie.diameter,
        spacing=tie.spacing,
        length=tie.length,
        yield_strength=tie.yield_strength,
        elastic_modulus=tie.elastic_modulus,
        anchorage=tie.anchorage,
        stiffness=si.stiffness / N_PER_KN,
        yield_force=si.yield_force / N_PER_KN,
        anchorage_force=anchorage,
        capacity=tie_capacity(si.yield_force, si.anchorage_force) / N_PER_KN,
        ductile=tie_is_ductile(si.yield_force, si.anchorage_force),
    )


def loads_result(inputs: AssessmentInputs) -> LoadsResult | None:
    """The loads of ``inputs`` and α₀ with them (module docstring); None without loads."""
    loads = inputs.loads
    if not loads:
        return None
    return LoadsResult(
        top=tuple(TopLoadResult(p.name, p.load, p.distance, p.inertia) for p in loads.top),
        thrust=tuple(ThrustResult(f.name, f.force, f.height) for f in loads.thrusts),
        ties=tuple(tie_result(t) for t in loads.ties),
        overturning=overturning_result(inputs.model_for(None), loads),
        not_modelled=NOT_MODELLED,
    )


def tie_prices_result(inputs: AssessmentInputs) -> TiePricesResult | None:
    """The tie's prices of ``costs`` when some option has a tie, else None (not written)."""
    if not any(o.tie is not None for o in inputs.options):
        return None
    p = inputs.costs.ties
    return TiePricesResult(p.steel_per_kg, p.steel_per_metre, p.plate, p.installation)


def tie_option_result(inputs: AssessmentInputs, option: RetrofitOption) -> TieOptionResult | None:
    """The tie of ``option`` (None: none) as results.json records it, with its steel and cost
    (:func:`~frp_assess.assess.quantities.tie_quantity`)."""
    if option.tie is None:
        return None
    prices = inputs.costs.ties
    q = tie_quantity(option.tie, prices, inputs.length)
    return TieOptionResult(
        tie=tie_result(option.tie),
        steel_mass_per_m=q.mass_per_m,
        steel_mass=q.mass,
        cost_per_tie=q.cost_per_tie,
        cost_per_m=q.cost_per_m,
        cost=q.cost,
        prices_given=prices.given,
    )
