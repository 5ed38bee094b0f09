"""How the assessed option depends on the model conventions (issue 16 §3; docs/model.md §3).

The conventions the paper leaves open — the impact rule, the collapse rule, the IDA's
sampling, the rupture rule, the cyclic strain factor — and a ±10 % change of the bars' elastic
modulus are varied one at a time on one case (the recommended option, else the best ranked
one, else the unreinforced wall), through the same cached runner as the assessment, so a
rerun costs nothing.  The sampling: with the effective collapse intensity (docs/model.md
§11) its ladder shifted by half a step, the "numerical spread" of the design value; with the
first collapse (§5) the hunt at √s, the same grid with one more multiplier between each pair,
which can meet a collapse window that s steps over (§5.1).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import NamedTuple

from frp_assess.assess.runner import IdaRunner, summarise
from frp_assess.dynamics import COLLAPSE_RULES, RUPTURE_RULES, IdaResult, IdaSettings, RockingModel

#: relative change of the elastic modulus E of the bars [-]
MODULUS_CHANGE = 0.10


class Variant(NamedTuple):
    """One convention: its label, the model, and the IDA search when not the run's."""

    label: str
    model: RockingModel
    settings: IdaSettings | None = None


@dataclass(frozen=True)
class SensitivityRow:
    variant: str  #: what was changed ("as assessed" for the case itself)
    design_a_dyn: float  #: [g]
    capacity_demand: float  #: design_a_dyn / (FC·a_g·S) [-], as the cases'
    lower_bound: bool  #: some record did not collapse up to C_max


def sampling_variant(model: RockingModel, settings: IdaSettings) -> Variant:
    """The numerical one: with the effective collapse intensity (docs/model.md §11) its
    ladder shifted by half a step, the "numerical spread"; with the first collapse (§5) the
    hunt at √s."""
    if settings.capacity == "effective":
        shifted = replace(settings, offset=(settings.offset + 0.5) % 1.0)
        return Variant(
            f"numerical spread: IDA ladder shifted by half a step (offset {shifted.offset:g})",
            model,
            shifted,
        )
    finer = replace(settings, step_ratio=settings.step_ratio**0.5)
    return Variant(f"IDA step ratio s = {finer.step_ratio:.4g}", model, finer)


def convention_variants(model: RockingModel, settings: IdaSettings) -> list[Variant]:
    """The case itself, then one variant per convention: a different value of each option,
    the sampling (:func:`sampling_variant`; ``settings``: the run's IDA search), and with
    bars the rupture rule, the strain factor set to 1 or 0.5 and E ∓ 10 %.  The variants
    every case has come first, in the same order, so that the i-th variant of two cases is
    the same convention."""
    o = model.options
    out = [Variant("as assessed", model)]
    other_restitution = "velocity" if o.restitution == "energy" else "energy"
    out.append(
        Variant(
            f"restitution: {other_restitution}", model.with_options(restitution=other_restitution)
        )
    )
    for rule in COLLAPSE_RULES:
        if rule != o.collapse:
            out.append(Variant(f"collapse: {rule}", model.with_options(collapse=rule)))
    out.append(sampling_variant(model, settings))
    bars = model.rebars
    if bars is None:
        return out
    for rupture in RUPTURE_RULES:
        if rupture != o.rupture:
            out.append(Variant(f"rupture: {rupture}", model.with_options(rupture=rupture)))
    factor = 1.0 if bars.strain_factor < 1.0 else 0.5
    out.append(
        Variant(
            f"strain factor c = {factor:g}",
            replace(model, rebars=replace(bars, strain_factor=factor)),
        )
    )
    for sign in (-1.0, 1.0):
        e = bars.elastic_modulus * (1.0 + sign * MODULUS_CHANGE)
        label = f"E {sign * MODULUS_CHANGE:+.0%} ({e / 1e9:.4g} GPa)"
        out.append(Variant(label, replace(model, rebars=replace(bars, elastic_modulus=e))))
    return out


def run_variants(runner: IdaRunner, variants: list[Variant]) -> list[list[IdaResult]]:
    """The IDAs of every variant (one list per variant, one result per record): those with the
    run's search in one call of the runner, each other one in a call of its own."""
    plain = [i for i, v in enumerate(variants) if v.settings is None]
    out: dict[int, list[IdaResult]] = dict(
        zip(plain, runner.run([variants[i].model for i in plain]), strict=True)
    )
    for i, v in enumerate(variants):
        if v.settings is not None:
            out[i] = runner.run([v.model], settings=v.settings)[0]
    return [out[i] for i in range(len(variants))]


def sensitivity(
    runner: IdaRunner,
    model: RockingModel,
    demand_g: float,
    max_multiplier: float,
) -> list[SensitivityRow]:
    """Design a_dyn and capacity/demand of ``model`` under every convention variant;
    ``demand_g`` [g] is what divides the capacity, FC·a_g·S (as the cases')."""
    variants = convention_variants(model, runner.settings)
    rows = []
    for (label, variant, _), res in zip(variants, run_variants(runner, variants), strict=True):
        # a_RM of the variant's own model: with pivot: crushing E and c move the pivot
        s = summarise(res, max_multiplier, variant.a_rm_g)
        rows.append(SensitivityRow(label, s.design_a_dyn, s.design_a_dyn / demand_g, s.lower_bound))
    return rows
