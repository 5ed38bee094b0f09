"""FRP and steel quantities and indicative costs of an option.

:func:`option_quantity` counts the bars as built (whole bars over the bar length, anchorages
included, docs/model.md §2.1); :func:`frp_quantity` is the smeared estimate from a ratio
(bars over the free height H), equal to it for the installed ratio when no anchorage length
is known.  :func:`tie_quantity` counts a tie option's steel and its cost per metre of wall
(docs/model.md §12).
"""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.bars_as_built import option_as_built
from frp_assess.assess.inputs import (
    AssessmentInputs,
    CostSettings,
    Material,
    RetrofitOption,
    TiePrices,
)
from frp_assess.assess.load_inputs import TieInput
from frp_assess.dynamics import Position
from frp_assess.results.as_built import AsBuilt
from frp_assess.rules.bars import bar_area, faces
from frp_assess.rules.tie_rods import tie_steel_mass

#: anchorage plates per tie: one at each end
PLATES_PER_TIE = 2
#: [m²] per [mm²]
M2_PER_MM2 = 1e-6


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
    :func:`frp_quantity` (which it falls back on for an option that cannot be built).  A tie
    alone has no bars: zero."""
    if option.material is None or option.position is None:
        return Quantity(0.0, 0.0, 0.0)
    built = option_as_built(inputs, option)
    return built_quantity(inputs, built, option.material, option.position, option.ratio)


@dataclass(frozen=True)
class TieQuantity:
    """The steel and the cost of a tie option, per metre of wall and for the whole wall."""

    mass_per_m: float  #: steel ρ·A_s·L_t/i_t [kg/m]
    mass: float  #: for the wall's length [kg]
    cost_per_tie: float  #: bar + plates + installation of one tie [currency]
    cost_per_m: float  #: cost_per_tie/i_t [currency/m]
    cost: float  #: for the wall's length [currency]


def tie_quantity(tie: TieInput, prices: TiePrices, length: float) -> TieQuantity:
    """One tie every i_t metres: steel ρ·A_s·L_t per tie (the free length; the bar through
    the walls and the plates not counted), each tie costing its bar (per kg and per metre),
    :data:`PLATES_PER_TIE` plates and its installation; per metre of wall ÷ i_t, and ×
    ``length`` L [m] for the wall (smeared: a fraction of a tie counts as such)."""
    area = tie.area * M2_PER_MM2
    mass_per_m = tie_steel_mass(area, tie.length, tie.spacing)
    per_tie = (
        mass_per_m * tie.spacing * prices.steel_per_kg
        + tie.length * prices.steel_per_metre
        + PLATES_PER_TIE * prices.plate
        + prices.installation
    )
    cost_per_m = per_tie / tie.spacing
    return TieQuantity(mass_per_m, mass_per_m * length, per_tie, cost_per_m, cost_per_m * length)
