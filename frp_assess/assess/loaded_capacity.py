"""The capacity curve of a wall carrying loads (Circolare 2019 §C8.7.1.2.1.2-C8.7.1.2.1.6;
docs/model.md §12 "Code checks").

α(θ) is the static bracket of §12 at an outward rotation θ about the outer base corner:
the moments that hold the wall (its weight, the top loads, the thrusts with their sign, the
ties at their force F_t(θ) = clip(k_t·h_t·sin θ, 0, F_y), the bars' K·W·R·sin θ while intact,
minus the crushing pivot's N₀·(x₀/2)·cos θ) over those of the horizontal inertia of the wall
and of the carried loads (:func:`frp_assess.rules.wall_loads.multiplier_at_rotation`).  A
brittle tie (F_a/i_t ≤ F_y) is lost where its force reaches F_a/i_t, a drop like a bar
rupture.  e* and M* count the carried loads (eq. C8.7.1.5); the spectral displacement is
d = d_C·Σ P·δ²/(δ_C·Σ P·δ) (eq. C8.7.1.4) with the centroid as control point (δ_C = H/2, a
carried load δ = H).  d0 is where α vanishes with the actions surely present up to collapse:
the vertical loads, the thrusts and the ductile ties (not the bars, not a brittle tie).

:class:`LoadedCapacityCurve` answers as :class:`~frp_assess.assess.kinematic_capacity.
CapacityCurve` does, so the limit-state checks use it unchanged.  Units: SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.optimize import brentq

from frp_assess.assess.kinematic_capacity import (
    CapacityCurve,
    control_displacement,
    rotation_at,
    spectral_acceleration,
    spectral_displacement,
)
from frp_assess.assess.loaded_overturning import base_moment, loaded_e_star, loaded_m_star
from frp_assess.dynamics import RockingModel
from frp_assess.dynamics.loads import NO_LOADS, Loads, Tie
from frp_assess.rules.kinematic import RUPTURE_DROP, a_star
from frp_assess.rules.tie_rods import tie_elongation, tie_force, tie_is_ductile
from frp_assess.rules.wall_loads import multiplier_at_rotation


def tie_loss_rotation(tie: Tie) -> float:
    """θ [rad] at which a brittle tie's force reaches F_a/i_t and the tie is lost (its steel
    elastic: k_t·h_t·sin θ = F_a/i_t); ``inf`` for a ductile tie or one never reaching it."""
    if tie_is_ductile(tie.yield_force, tie.anchorage_force):
        return math.inf
    s = tie.anchorage_force / (tie.stiffness * tie.height)
    return math.asin(s) if s <= 1.0 else math.inf


def _intact(theta: float, event: float, after: bool) -> bool:
    return theta < event or (theta == event and not after)


@dataclass(frozen=True)
class LoadedCapacityCurve(CapacityCurve):
    """The capacity curve of the wall with its loads and bars (module docstring)."""

    loads: Loads = NO_LOADS
    base: float = 0.0  #: N₀·x₀/2 [N·m/m], the crushing pivot's moment at rest
    theta0: float = 0.0  #: [rad] where α of the surely present actions vanishes
    ratio: float = 1.0  #: d/d_C [-] (eq. C8.7.1.4)
    tie_losses: tuple[float, ...] = field(default=())  #: θ [rad] of each tie's loss

    def multiplier(self, theta: float, *, after: bool = False, sure: bool = False) -> float:
        """α(θ) [-]; ``after``: just after a rupture or loss at θ; ``sure``: the actions
        surely present only (no bars, no brittle tie)."""
        w = self.wall
        extra = -self.base * math.cos(theta)
        if not sure and _intact(theta, self.rupture_rotation, after):
            extra += self.stiffness * w.weight * w.R * math.sin(theta)
        for tie, lost in zip(self.loads.ties, self.tie_losses, strict=True):
            if (sure and math.isfinite(lost)) or not _intact(theta, lost, after):
                continue
            f = tie_force(tie.stiffness, tie.yield_force, tie_elongation(tie.height, theta), 0.0)
            extra += f * tie.height * math.cos(theta)
        top, thrusts = self.loads.top, self.loads.thrusts
        return multiplier_at_rotation(
            theta, w.weight, w.thickness, w.height, top, thrusts, tie_moment=extra
        )

    @property
    def alpha(self) -> float:
        """θ0 [rad]: where the capacity of the surely present actions vanishes."""
        return self.theta0

    @property
    def d0(self) -> float:
        """d0 [m] at θ0 (module docstring)."""
        return control_displacement(self.theta0, self.wall) * self.ratio

    @property
    def a0(self) -> float:
        """a0* = α(0)·g/(e*·FC) [m/s²]: where rocking starts (the ties unstretched)."""
        return spectral_acceleration(self.multiplier(0.0), self.e_star, self.fc)

    def _displacement(self, theta: float) -> float:
        if theta >= self.theta0:
            return math.inf
        return control_displacement(theta, self.wall) * self.ratio

    @property
    def rupture_displacement(self) -> float:
        """d [m] at which the bars break (inf: not before θ0)."""
        return self._displacement(self.rupture_rotation)

    def a_at(self, d: float) -> float:
        """a(d) [m/s²], each component still holding at the displacement of its loss (the
        value just before it breaks, as :meth:`CapacityCurve.a_at`).  Whether a component
        holds is decided on d, not on the rotation: θ(d) of a loss's own displacement can come
        back an ulp beyond the loss, and d_SLV at a tie's loss then read the curve after it
        (the bare wall's a, a secant period 4× too long)."""
        theta = rotation_at(d / self.ratio, self.wall)
        for event in (self.rupture_rotation, *self.tie_losses):
            if d <= self._displacement(event):
                theta = min(theta, event)
        return spectral_acceleration(self.multiplier(theta), self.e_star, self.fc)

    @property
    def rupture_limit(self) -> float:
        """The first d [m] where a bar rupture or a tie's loss drops the capacity below
        (1 − 0.50)·a_max (§C8.7.1.2.1.6); inf if none does before d0."""
        for theta in sorted({self.rupture_rotation, *self.tie_losses}):
            if theta >= self.theta0:
                break
            after = spectral_acceleration(self.multiplier(theta, after=True), self.e_star, self.fc)
            if after < (1.0 - RUPTURE_DROP) * self.a_max:
                return self._displacement(theta)
        return math.inf


def loaded_capacity_curve(model: RockingModel, fc: float, points: int = 401) -> LoadedCapacityCurve:
    """The capacity curve of ``model`` with its loads (module docstring): ``points`` rotations
    in [0, θ0] and two points (before, after) at each rupture or loss inside it."""
    w = model.wall
    carried = [p.force for p in model.loads.top if p.carried]
    ratio = spectral_displacement(
        1.0, [w.weight, *carried], [w.height / 2.0] + [w.height] * len(carried), w.height / 2.0
    )
    curve = LoadedCapacityCurve(
        wall=w, stiffness=model.K, rupture_rotation=model.theta_max, fc=fc,
        e_star=loaded_e_star(model), m_star=loaded_m_star(model),
        d=np.zeros(0), a=np.zeros(0), loads=model.loads, base=base_moment(model), ratio=ratio,
        tie_losses=tuple(tie_loss_rotation(t) for t in model.loads.ties),
    )  # fmt: skip
    if curve.multiplier(0.0, sure=True) <= 0.0:
        raise ValueError("the loads tip the wall at rest: no capacity curve (alpha0 <= 0)")
    theta0 = float(brentq(lambda t: curve.multiplier(t, sure=True), 0.0, math.pi / 2.0,
                          xtol=1e-14))  # fmt: skip
    events = sorted(t for t in {model.theta_max, *curve.tie_losses} if t < theta0)
    grid = [(float(t), False) for t in np.linspace(0.0, theta0, points) if t not in events]
    grid += [(t, flag) for t in events for flag in (False, True)]
    grid.sort()
    theta = np.array([t for t, _ in grid])
    curve = replace(curve, theta0=theta0)
    mult = np.array([curve.multiplier(t, after=flag) for t, flag in grid])
    d = np.array([control_displacement(float(t), w) * ratio for t in theta])
    return replace(curve, d=d, a=a_star(mult, curve.e_star, fc))
