"""The linear and nonlinear kinematic analysis of a wall's local mechanism (Circolare 2019
§C8.7.1.2.1; NTC 2018 §8.7.1).

The equivalent single-degree-of-freedom system of a mechanism turns its load multiplier α
into a spectral acceleration: a* = α·g/(e*·FC), with e* the participating mass fraction and
FC the confidence factor of the knowledge level; at activation α = α0 and a* = a0*.
"""

from __future__ import annotations

from typing import TypeVar

from frp_assess.rules.constants import G

#: a float, or an array of them (numpy's arithmetic): the rule is the same expression
Multiplier = TypeVar("Multiplier")


def a_star(multiplier: Multiplier, e_star: float, fc: float, g: float = G) -> Multiplier:
    """a* = α·g/(e*·FC) (Circolare 2019 §C8.7.1.2.1.3, eq. C8.7.1.3; a0* at α = α0).

    Args:
        multiplier: the load multiplier α [-] (a float or an array of them).
        e_star: the participating mass fraction e* [-] (eq. C8.7.1.5).
        fc: the confidence factor FC [-] (Tab. C8.5.IV).
        g: the acceleration of gravity in the unit of the result: :data:`G` [m/s²] (the
            default), 1.0 for a* in g.
    """
    return multiplier * g / (e_star * fc)  # type: ignore[operator, return-value]
