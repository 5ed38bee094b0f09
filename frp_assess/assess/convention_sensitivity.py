"""How the assessed option depends on the model conventions (issue 16 §3; docs/model.md §3).

The conventions the paper leaves open — the impact rule, the collapse rule, the rupture rule,
the cyclic strain factor — and a ±10 % change of the bars' elastic modulus are varied one at a
time on one case (the recommended option, else the best ranked one, else the unreinforced
wall), through the same cached runner as the assessment, so a rerun costs nothing.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from frp_assess.assess.runner import IdaRunner, summarise
from frp_assess.dynamics import COLLAPSE_RULES, RUPTURE_RULES, RockingModel

#: relative change of the elastic modulus E of the bars [-]
MODULUS_CHANGE = 0.10


@dataclass(frozen=True)
class SensitivityRow:
    variant: str  #: what was changed ("as assessed" for the case itself)
    design_a_dyn: float  #: [g]
    capacity_demand: float  #: design_a_dyn / (FC·a_g·S) [-], as the cases'
    lower_bound: bool  #: some record did not collapse up to C_max


def convention_variants(model: RockingModel) -> list[tuple[str, RockingModel]]:
    """The case itself, then one variant per convention (a different value of each option,
    the strain factor set to 1 or 0.5, and E ∓ 10 % when there are bars)."""
    o = model.options
    out: list[tuple[str, RockingModel]] = [("as assessed", model)]
    other_restitution = "velocity" if o.restitution == "energy" else "energy"
    out.append(
        (f"restitution: {other_restitution}", model.with_options(restitution=other_restitution))
    )
    for rule in COLLAPSE_RULES:
        if rule != o.collapse:
            out.append((f"collapse: {rule}", model.with_options(collapse=rule)))
    bars = model.rebars
    if bars is None:
        return out
    for rupture in RUPTURE_RULES:
        if rupture != o.rupture:
            out.append((f"rupture: {rupture}", model.with_options(rupture=rupture)))
    factor = 1.0 if bars.strain_factor < 1.0 else 0.5
    out.append(
        (
            f"strain factor c = {factor:g}",
            replace(model, rebars=replace(bars, strain_factor=factor)),
        )
    )
    for sign in (-1.0, 1.0):
        e = bars.elastic_modulus * (1.0 + sign * MODULUS_CHANGE)
        label = f"E {sign * MODULUS_CHANGE:+.0%} ({e / 1e9:.4g} GPa)"
        out.append((label, replace(model, rebars=replace(bars, elastic_modulus=e))))
    return out


def sensitivity(
    runner: IdaRunner,
    model: RockingModel,
    demand_g: float,
    max_multiplier: float,
) -> list[SensitivityRow]:
    """Design a_dyn and capacity/demand of ``model`` under every convention variant;
    ``demand_g`` [g] is what divides the capacity, FC·a_g·S (as the cases')."""
    variants = convention_variants(model)
    results = runner.run([m for _, m in variants])
    rows = []
    for (label, variant), res in zip(variants, results, strict=True):
        # a_RM of the variant's own model: with pivot: crushing E and c move the pivot
        s = summarise(res, max_multiplier, variant.a_rm_g)
        rows.append(SensitivityRow(label, s.design_a_dyn, s.design_a_dyn / demand_g, s.lower_bound))
    return rows
