"""results.json's ``loads``: every load the wall carries, as the project gave it with its
per-metre values, and α₀ of simple overturning term by term (docs/model.md §12,
docs/results-json.md), so that a reviewer recomputes α₀ by hand.  None without loads (the
key is then absent: a file without loads is the file it was before loads existed).
"""

from __future__ import annotations

import math

from frp_assess.assess.inputs import AssessmentInputs
from frp_assess.assess.load_inputs import TieInput
from frp_assess.assess.loaded_overturning import overturning_result
from frp_assess.dynamics.units import N_PER_KN
from frp_assess.results.carried_loads import LoadsResult, ThrustResult, TieResult, TopLoadResult
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
