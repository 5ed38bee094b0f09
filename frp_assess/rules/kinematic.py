"""The linear and nonlinear kinematic analysis of a wall's local mechanism (Circolare 2019
§C8.7.1.2.1; NTC 2018 §8.7.1).

The equivalent single-degree-of-freedom system of a mechanism turns its load multiplier α
into a spectral acceleration: a* = α·g/(e*·FC), with e* the participating mass fraction and
FC the confidence factor of the knowledge level; at activation α = α0 and a* = a0*.  The
limit states of the nonlinear check: d_SLV and d_SLC as fractions of d0 (§C8.7.1.2.1.6), the
secant periods (eqs. C8.7.1.10–11), the damping of the demand (§C8.7.1.2.1.8), a_g,SLD
(eq. C8.7.1.8), the ground acceleration at a limit state and ζ_E.
"""

from __future__ import annotations

import math
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


#: A rupture that leaves less than this fraction of the largest capacity limits d_SLV
#: ("riduzione della capacità ... superiore al 50 % del valore massimo", §C8.7.1.2.1.6) [-].
RUPTURE_DROP = 0.50
#: Equivalent viscous damping of the mechanism (Circolare 2019 §C8.7.1.2.1.8) [-].
XI_SLV = 0.08
XI_SLC = 0.10
#: Fractions of d0 that bound d_SLV and d_SLC (Circolare 2019 §C8.7.1.2.1.6) [-].
D0_FRACTION_SLV = 0.40
D0_FRACTION_SLC = 0.60
#: Coefficients of the secant periods, eqs. C8.7.1.10 and C8.7.1.11 [-].
PERIOD_FACTOR_SLV = 1.68
PERIOD_FACTOR_SLC = 1.56


# --- the limit states (Circolare 2019 §C8.7.1.2.1.6 and .8) ------------------------------------


def d_slv(d0: float, d_rupture: float = math.inf) -> float:
    """d_SLV = min(0.40·d0, d where a rupture drops the capacity by more than 50 %) [m]
    (Circolare 2019 §C8.7.1.2.1.6)."""
    return min(D0_FRACTION_SLV * d0, d_rupture)


def d_slc(d0: float, d_instability: float = math.inf) -> float:
    """d_SLC = min(0.60·d0, d of a local instability, where it can be assessed) [m]
    (Circolare 2019 §C8.7.1.2.1.6: the text's second SLC criterion is a situation locally
    incompatible with the stability of the building's elements, e.g. beams sliding off, not
    the rupture of ties, which is an SLV criterion)."""
    return min(D0_FRACTION_SLC * d0, d_instability)


def _secant_period(factor: float, d: float, a: float) -> float:
    if not (d > 0.0 and a > 0.0):
        raise ValueError(f"the secant period needs d > 0 and a(d) > 0, got {d!r}, {a!r}")
    return factor * math.pi * math.sqrt(d / a)


def t_slv(d: float, a: float) -> float:
    """T_SLV = 1.68·π·√(d_SLV/a(d_SLV)) [s], d [m], a [m/s²] (Circolare 2019 eq. C8.7.1.10)."""
    return _secant_period(PERIOD_FACTOR_SLV, d, a)


def t_slc(d: float, a: float) -> float:
    """T_SLC = 1.56·π·√(d_SLC/a(d_SLC)) [s], d [m], a [m/s²] (Circolare 2019 eq. C8.7.1.11)."""
    return _secant_period(PERIOD_FACTOR_SLC, d, a)


def a_g_sld(a0_star: float, floor_ratio: float = 1.0) -> float:
    """a_g,SLD [units of a0*]: the ground acceleration at which the floor's peak acceleration
    a_Z reaches a0* (Circolare 2019 eq. C8.7.1.8, a_Z,SLD = α0·g/(e*·FC)).

    Args:
        a0_star: a0* = α0·g/(e*·FC).
        floor_ratio: a_Z per unit ground acceleration [-] (1 at ground level, in a_g·S terms).
    """
    if not floor_ratio > 0.0:
        raise ValueError(f"floor ratio must be > 0, got {floor_ratio!r}")
    return a0_star / floor_ratio


def a_g_limit(
    a_g: float, capacity: float, demand: float, a_g_sld_value: float | None = None
) -> float:
    """a_g,SLV (or a_g,SLC) [units of a_g]: the ground acceleration whose displacement demand
    equals the capacity, a_g·d_lim/D(a_g), not less than a_g,SLD (Circolare 2019
    §C8.7.1.2.1.8, below eq. C8.7.1.12).

    The demand is taken as proportional to a_g (the spectrum's shape kept, as for the floor
    spectrum, which is linear in the ground spectrum).

    Args:
        a_g: the design intensity the demand was computed for (any units, e.g. a_g·S in g).
        capacity: d_SLV or d_SLC [m].
        demand: D [m] at a_g.
        a_g_sld_value: a_g,SLD in the units of a_g (None: no floor).
    """
    if not (capacity > 0.0 and demand > 0.0 and a_g > 0.0):
        raise ValueError("a_g, capacity and demand must be > 0")
    value = a_g * capacity / demand
    return value if a_g_sld_value is None else max(value, a_g_sld_value)


def zeta_e(capacity: float, demand: float) -> float:
    """ζ_E = capacity / demand [-], in PGA terms (a_g,SLV / a_g, or a_dyn/(FC·a_g·S)), both in
    one unit (Circolare 2019 §C8.7.1.2.1.8)."""
    if not (capacity >= 0.0 and demand > 0.0):
        raise ValueError(f"need capacity >= 0 and demand > 0, got {capacity!r}, {demand!r}")
    return capacity / demand
