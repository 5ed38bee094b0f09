"""FRP quantities and indicative costs of an option."""

from __future__ import annotations

from dataclasses import dataclass

from frp_assess.assess.inputs import AssessmentInputs, Costs, Material
from frp_assess.dynamics import Position


@dataclass(frozen=True)
class Quantity:
    mass_per_m: float  #: installed FRP per metre of wall length [kg/m] (both faces if external)
    mass: float  #: for the whole wall [kg]
    cost: float  #: material + installation for the whole wall [currency]


def layers(position: Position) -> int:
    """Layers of bars installed: 1 centred, 2 external (one on each face, docs/model.md §2)."""
    return 1 if position == "centred" else 2


def frp_quantity(
    thickness: float,
    height: float,
    length: float,
    material: Material,
    position: Position,
    ratio: float,
    costs: Costs,
) -> Quantity:
    """Installed area ρ·B per metre per layer, bars over the full height H.

    Args:
        thickness, height, length: B, H, L [m].
        ratio: ρ [‰] of the active bars.
    """
    area_per_m = ratio * 1e-3 * thickness * layers(position)  # [m²/m]
    mass_per_m = area_per_m * height * material.density
    mass = mass_per_m * length
    cost = mass * material.price + costs.installation_per_metre * length * layers(position)
    return Quantity(mass_per_m, mass, cost)


def quantity_for(
    inputs: AssessmentInputs, material: Material, position: Position, ratio: float
) -> Quantity:
    return frp_quantity(
        inputs.thickness, inputs.height, inputs.length, material, position, ratio, inputs.costs
    )
