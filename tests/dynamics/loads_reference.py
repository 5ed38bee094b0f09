"""An independent solver of the rocking wall with the loads it carries (docs/model.md §12).

Written from the statics of the turned block, not from the kernel's normalised bracket: each
force is a force at a point, each moment its lever about the pivot corner in the turned
geometry, the inertia the sum over the wall and the carried masses; integrated by scipy's
``solve_ivp`` (DOP853, tolerance 1e-12) with its own event location.  It serves the tests as
a second solution of the same equation (unreinforced walls, edge pivot, no ties).

Coordinates of a side s (+1: outward about the outer corner; −1: inward about the inner
one) and q = |θ|: a point at distance u from the pivot corner (into the wall) and height y is
at X = u·cos q − y·sin q (horizontal, toward the wall's interior) and Y = u·sin q + y·cos q.
The ground acceleration ü_g is positive outward (the kernel's convention: a negative ü_g
tips the wall outward).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

G = 9.80665


@dataclass(frozen=True)
class LoadedWall:
    thickness: float  #: B [m]
    height: float  #: H [m]
    unit_weight: float  #: w [N/m³]
    top: Sequence[tuple[float, float, bool]] = ()  #: (P [N/m], d [m] from outer face, carried)
    thrusts: Sequence[tuple[float, float]] = ()  #: (F [N/m] outward, h [m])
    two_sided: bool = True

    @property
    def weight(self) -> float:
        return self.unit_weight * self.thickness * self.height

    def _points(self, side: int) -> list[tuple[float, float, float, bool]]:
        """(weight, u, y, carried) of the wall's centroid and of each top load."""
        b = self.thickness
        pts = [(self.weight, b / 2, self.height / 2, True)]
        for p, d, carried in self.top:
            pts.append((p, d if side > 0 else b - d, self.height, carried))
        return pts

    def inertia(self, side: int) -> float:
        """I about the pivot corner [kg·m²/m]: the block's (4/3)·m·R² plus m_i·(u_i² + H²)."""
        b, h = self.thickness, self.height
        m = self.weight / G
        total = m * (b * b + h * h) / 3.0
        for p, u, y, carried in self._points(side)[1:]:
            if carried:
                total += p / G * (u * u + y * y)
        return total

    def moment(self, q: float, side: int, ground: float) -> float:
        """The moment about the pivot of ``side`` that turns q = |θ| up [N·m/m], at ü_g =
        ``ground`` [m/s²]."""
        c, s = math.cos(q), math.sin(q)
        total = 0.0
        for weight, u, y, carried in self._points(side):
            total -= weight * (u * c - y * s)  # gravity holds
            if carried:
                total -= side * ground * weight / G * (u * s + y * c)  # inertia
        for force, h in self.thrusts:
            u = self.thickness if side > 0 else 0.0
            total += side * force * (u * s + h * c)
        return total

    def acceleration(self, theta: float, side: int, ground: float) -> float:
        """θ'' [rad/s²] while rocking on ``side``."""
        return side * self.moment(side * theta, side, ground) / self.inertia(side)

    def impact_ratio(self, new_side: int) -> float:
        """ω after/ω before a pivot change to ``new_side`` (angular momentum, point masses
        on the top; the block by Housner's integral)."""
        b, h = self.thickness, self.height
        m = self.weight / G
        old = -new_side
        # the block: ∫ r_old·r_new dm = m·(H²/3 − B²/6)
        before = m * (h * h / 3.0 - b * b / 6.0)
        for p, d, carried in self.top:
            if carried:
                u_old = d if old > 0 else b - d
                u_new = d if new_side > 0 else b - d
                # r_old·r_new: the two corners are B apart, so the horizontal parts point
                # opposite ways, −u_old·u_new, and the vertical ones are both H
                before += p / G * (h * h - u_old * u_new)
        return before / self.inertia(new_side)


def free_rocking(
    wall: LoadedWall,
    theta0: float,
    duration: float,
    times: np.ndarray,
    ground: float = 0.0,
) -> np.ndarray:
    """θ(t) [rad] at ``times`` from rest at θ0, under a constant ü_g = ``ground``, two-sided
    impacts by angular momentum (no restitution factor on top), falling stops the output
    (NaN after)."""
    out = np.full(times.shape, np.nan)
    t0, y0 = 0.0, np.array([theta0, 0.0])
    while t0 < duration:
        side0 = 1 if (y0[0] > 0.0 or (y0[0] == 0.0 and y0[1] > 0.0)) else -1

        def rhs(_t: float, y: np.ndarray, side: int = side0) -> list[float]:
            return [float(y[1]), wall.acceleration(float(y[0]), side, ground)]

        def cross(_t: float, y: np.ndarray) -> float:
            return float(y[0])

        cross.terminal = True  # type: ignore[attr-defined]
        cross.direction = -side0  # type: ignore[attr-defined]

        def fall(_t: float, y: np.ndarray) -> float:
            return abs(float(y[0])) - 0.5 * math.pi

        fall.terminal = True  # type: ignore[attr-defined]
        mask = times >= t0
        sol = solve_ivp(
            rhs,
            (t0, duration),
            y0,
            method="DOP853",
            rtol=1e-12,
            atol=1e-14,
            events=(cross, fall),
            dense_output=True,
        )
        t_end = float(sol.t[-1])
        sel = mask & (times <= t_end)
        out[sel] = sol.sol(times[sel])[0]
        if sol.status != 1 or sol.t_events[1].size:
            break
        omega = float(sol.y_events[0][0][1])
        new_side = -side0
        y0 = np.array([0.0, omega * wall.impact_ratio(new_side)])
        t0 = t_end
    return out
