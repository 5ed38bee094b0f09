"""The NTC 2018 formulas from a site's coordinates to its seismic parameters (pure functions).

Names follow the code's symbols.  Sources: NTC 2018 (D.M. 17 gennaio 2018) §2.4 (nominal life
V_N, use class, C_U, V_R) and §3.2.1 (P_VR of each limit state, Tab. 3.2.I); NTC 2008
Allegato A (kept by NTC 2018 §3.2): the return period T_R of P_VR in V_R, the spatial
interpolation on the reference grid (inverse-distance mean of 4 nodes) and the interpolation
between return periods (linear in log p vs log T_R).  Distances in km, periods in years.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

#: the limit states, in the order of NTC 2018 Tab. 3.2.I
LIMIT_STATES: tuple[str, ...] = ("SLO", "SLD", "SLV", "SLC")
#: P_VR [-]: probability of exceedance in V_R of each limit state (NTC 2018 Tab. 3.2.I)
P_VR: dict[str, float] = {"SLO": 0.81, "SLD": 0.63, "SLV": 0.10, "SLC": 0.05}
#: C_U [-] of the use classes I-IV (NTC 2018 Tab. 2.4.II)
USE_COEFFICIENTS: dict[str, float] = {"I": 0.7, "II": 1.0, "III": 1.5, "IV": 2.0}
USE_CLASSES: tuple[str, ...] = tuple(USE_COEFFICIENTS)
#: the shortest reference period [years]: "se V_R <= 35 anni si pone comunque V_R = 35 anni"
#: (NTC 2018 §2.4.3)
MIN_REFERENCE_PERIOD = 35.0
#: the return periods of the reference grid [years] (NTC 2008 Allegato B)
GRID_RETURN_PERIODS: tuple[int, ...] = (30, 50, 72, 101, 140, 201, 475, 975, 2475)
#: mean Earth radius [km] of the great-circle distance (IUGG mean radius R1)
EARTH_RADIUS_KM = 6371.0


def C_U(use_class: str) -> float:  # noqa: N802
    """C_U [-], the coefficient of use class ``use_class`` ("I"-"IV"), NTC 2018 Tab. 2.4.II."""
    try:
        return USE_COEFFICIENTS[use_class]
    except KeyError:
        raise ValueError(f"expected a use class I, II, III or IV, found {use_class!r}") from None


def V_R(V_N: float, C_U: float) -> float:  # noqa: N802, N803
    """V_R = V_N·C_U [years], the reference period (NTC 2018 eq. 2.4.1), at least 35 years
    (§2.4.3).  V_N [years] the nominal life, C_U [-] the use coefficient."""
    if not (V_N > 0 and math.isfinite(V_N)):
        raise ValueError(f"expected a nominal life V_N > 0 years, found {V_N!r}")
    return max(V_N * C_U, MIN_REFERENCE_PERIOD)


def T_R(V_R: float, P_VR: float) -> float:  # noqa: N802, N803
    """T_R = −V_R / ln(1 − P_VR) [years], the return period of the action exceeded with
    probability P_VR [-] in V_R [years] (NTC 2008 Allegato A eq. 1; NTC 2018 §3.2.1,
    Circolare 2019 Tab. C3.2.I)."""
    if not 0.0 < P_VR < 1.0:
        raise ValueError(f"expected 0 < P_VR < 1, found {P_VR!r}")
    return -V_R / math.log(1.0 - P_VR)


def clamp_return_period(TR: float) -> float:  # noqa: N803
    """T_R [years] limited to the grid's range 30-2475 years (NTC 2008 Allegato A: the grid
    gives the hazard for 30 <= T_R <= 2475 years; outside it the nearest end is used)."""
    return min(max(TR, GRID_RETURN_PERIODS[0]), GRID_RETURN_PERIODS[-1])


def great_circle_distance(lat1: float, lon1: float, lat2: float, lon2: float) -> float:
    """Distance [km] between two points [°] on a sphere of radius 6371 km (haversine form,
    accurate down to zero distance)."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    dp, dl = p2 - p1, math.radians(lon2 - lon1)
    h = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return 2.0 * EARTH_RADIUS_KM * math.asin(min(1.0, math.sqrt(h)))


def inverse_distance_mean(values: Sequence[float], distances: Sequence[float]) -> float:
    """p = Σ(p_i/d_i) / Σ(1/d_i): the mean of the node values p_i weighted by the inverse of
    their distances d_i [km] from the site (NTC 2008 Allegato A eq. 2).  A site on a node
    (d_i = 0) takes that node's value exactly."""
    if len(values) != len(distances) or not values:
        raise ValueError("expected one distance per value")
    for p, d in zip(values, distances, strict=True):
        if d == 0.0:
            return p
    num = sum(p / d for p, d in zip(values, distances, strict=True))
    return num / sum(1.0 / d for d in distances)


def log_interpolation(TR: float, TR1: float, p1: float, TR2: float, p2: float) -> float:  # noqa: N803
    """p at T_R between the grid's T_R1 < T_R2 with values p1, p2 (NTC 2008 Allegato A eq. 3):
    log(p) = log(p1) + log(p2/p1)·log(T_R/T_R1)·[log(T_R2/T_R1)]⁻¹.  Units of p as given."""
    if TR == TR1:
        return p1
    if TR == TR2:
        return p2
    return math.exp(math.log(p1) + math.log(p2 / p1) * math.log(TR / TR1) / math.log(TR2 / TR1))


def bracket(TR: float) -> tuple[int, int]:  # noqa: N803
    """The grid's return periods T_R1 <= T_R <= T_R2 around ``TR`` (30 <= TR <= 2475)."""
    grid = GRID_RETURN_PERIODS
    if not grid[0] <= TR <= grid[-1]:
        raise ValueError(f"expected {grid[0]} <= T_R <= {grid[-1]} years, found {TR!r}")
    for lo, hi in zip(grid, grid[1:], strict=False):
        if TR <= hi:
            return lo, hi
    raise AssertionError("unreachable")  # pragma: no cover
