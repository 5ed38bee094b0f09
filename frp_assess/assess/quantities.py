"""FRP quantities and indicative costs of an option.

:func:`option_quantity` counts the bars as built (whole bars over the bar length, anchorages
included, docs/model.md §2.1); :func:`frp_quantity` is the smeared estimate from a ratio
(bars over the free height H), equal to it for the installed ratio when no anchorage length
is known.
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.bars_as_built import option_as_built
from frp_assess.assess.inputs import AssessmentInputs, CostSettings, Material, RetrofitOption
from frp_assess.dynamics import Position
from frp_assess.results.as_built import AsBuilt
from frp_assess.rules.bars import bar_area, faces


@dataclass(frozen=True)
class Quantity:
    mass_per_m: float  #: installed FRP per metre of wall length [kg/m] (both faces if external)
    mass: float  #: for the whole wall [kg]
    cost: float  #: material + installation for the whole wall [currency]


def frp_quantity(
    thickness: float,
    height: float,
    length: float,
    material: Material,
    position: Position,
    ratio: float,
    costs: CostSettings,
) -> Quantity:
    """Installed area ρ·B per metre per layer, bars over the full height H.

    Args:
        thickness, height, length: B, H, L [m].
        ratio: ρ [‰] of the active bars (an option's ``ratio``: the installed one).
    """
    lines = faces(position)  # 1 centred, 2 external (one on each face, docs/model.md §2)
    area_per_m = bar_area(ratio, thickness) * lines  # [m²/m]
    mass_per_m = area_per_m * height * material.density
    mass = mass_per_m * length
    cost = mass * material.price + costs.installation_per_metre * length * lines
    return Quantity(mass_per_m, mass, cost)


def quantity_for(
    inputs: AssessmentInputs, material: Material, position: Position, ratio: float
) -> Quantity:
    return frp_quantity(
        inputs.thickness, inputs.height, inputs.length, material, position, ratio, inputs.costs
    )


def built_quantity(
    inputs: AssessmentInputs,
    built: AsBuilt | None,
    material: Material,
    position: Position,
    ratio: float,
) -> Quantity:
    """The quantity of the bars as ``built`` (mass and cost over the bar length); without a
    layout (``bars.whole_bars: false`` and no size fits) the smeared estimate of ``ratio``
    [‰] (:func:`quantity_for`)."""
    if built is None:
        return quantity_for(inputs, material, position, ratio)
    return Quantity(built.mass / inputs.length, built.mass, built.cost)


def option_quantity(inputs: AssessmentInputs, option: RetrofitOption) -> Quantity:
    """The bars of ``option`` as built: n whole bars per line × lines × bar length
    (H + 2·bond length when ``bars.anchorage`` is given), × bar area × density; cost as
    :func:`frp_quantity` (which it falls back on for an option that cannot be built)."""
    built = option_as_built(inputs, option)
    return built_quantity(inputs, built, option.material, option.position, option.ratio)
