"""A slow, obviously-correct solution of docs/model.md §3, independent of the compiled kernel.

scipy's DOP853 (8th order, rtol 1e-11) integrates Eq. 10 one sample interval at a time
(where ü_g is linear, hence smooth), with scipy's own event location for impacts, ruptures
and collapse, and the exact linear uplift instant from rest.  Only the model is shared with
the package (no code): the equation, the jumps and the collapse rule are written out again.

``tail_from`` (the free vibration appended to a record for the `overturning` rule) stops the
integration once the wall's energy proves it can never again reach its peak so far, α, or
the bars' rupture rotation (see :func:`settled`): what is left of the record can then change
neither the peak nor the collapse flag, only the impact count.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

G = 9.80665


@dataclass
class RefSystem:
    B: float  # m
    H: float  # m
    w: float  # N/m3
    one_sided: bool
    E: float = 0.0  # Pa (0: unreinforced)
    eps_u: float = 0.0
    position: str = "centred"
    rho: float = 0.0  # per mille
    c: float = 0.5
    e_vel: float | None = None  # velocity ratio; None -> energy convention
    energy_transfer: bool = True
    first_exceedance: bool = False

    def __post_init__(self) -> None:
        self.alpha = math.atan(self.B / self.H)
        self.R = 0.5 * math.hypot(self.B, self.H)
        self.p2 = 3 * G / (4 * self.R)
        m = self.w * self.B * self.H / G
        A = self.rho * 1e-3 * self.B
        rp = 1.0 if self.position == "centred" else 4.0
        a = self.alpha
        self.K = math.sin(a) * math.tan(a) * rp / 2 * self.E * A / (m * G) if self.E else 0.0
        br = (0.5 if self.position == "centred" else 1.0) * self.B
        arg = self.c * self.eps_u * self.H / (2 * br) if self.E else 2.0
        self.theta_max = 2 * math.asin(arg) if arg < 1 else math.inf
        if self.e_vel is None:
            r2 = (1 - 1.5 * math.sin(a) ** 2) ** 2
            r1 = (r2 * (1 - 1.5 * math.cos(a) ** 2)) ** 2
            self.e_vel = math.sqrt(r1 if self.one_sided else r2)


def settled(
    sys: RefSystem, theta: float, omega: float, k_s: float, peak: float, bars: bool
) -> bool:
    """In free vibration (ü_g = 0): the wall can never again reach |θ| = min(peak, α, θ_max).

    Energy per unit rotational inertia, from Eq. 10 with ü_g = 0 (θ'' = −p²[sin(α − |θ|) +
    k sin|θ|]·sign θ): E = ω²/2 + p²[cos(α − |θ|) − cos α + k(1 − cos θ)], zero at rest.  Between
    impacts E is conserved; an impact (θ = 0) keeps or lowers it; the bars' potential
    p²k(1 − cos θ) ≥ 0 on either side.  So |θ| stays below θ_b with V₀(θ_b) = E for
    V₀(θ) = p²[cos(α − θ) − cos α], increasing on [0, α]: if E < V₀(θ_lim), |θ| < θ_lim for ever
    (no new peak, no fall, no rupture, hence no energy transferred by one).
    """
    a, p2 = sys.alpha, sys.p2
    lim = min(peak, a, sys.theta_max if bars else math.inf)
    energy = 0.5 * omega**2 + p2 * (
        math.cos(a - abs(theta)) - math.cos(a) + k_s * (1.0 - math.cos(theta))
    )
    return energy < p2 * (math.cos(a - lim) - math.cos(a))


def reference_run(
    sys: RefSystem, acc: np.ndarray, dt: float, scale: float, tail_from: int | None = None
) -> dict:
    """Peak |θ|, collapse flag and impact count under scale·acc [m/s²].

    ``tail_from``: the index from which acc is all zero (free vibration); the run ends there as
    soon as :func:`settled` holds (the impacts are then counted only up to that instant).
    """
    if tail_from is not None and np.any(np.asarray(acc[tail_from:]) != 0.0):
        raise ValueError("the record is not zero from tail_from on")
    a = sys.alpha
    shared = sys.position == "centred"
    intact = {1: sys.K > 0, -1: sys.K > 0}
    level_c = a if sys.first_exceedance else math.pi / 2
    u = scale * np.asarray(acc, float) / G
    theta, omega, s, rest = 0.0, 0.0, 1, True
    peak, impacts = 0.0, 0
    for i in range(len(u) - 1):
        if tail_from is not None and i >= tail_from:
            k_now = sys.K if intact[s] else 0.0
            if rest or settled(sys, theta, omega, k_now, peak, any(intact.values())):
                return {"peak": peak, "collapsed": False, "impacts": impacts}
        t0, t1 = i * dt, (i + 1) * dt
        ua, ub = u[i], u[i + 1]

        def ug(t: float, t0: float = t0, ua: float = ua, ub: float = ub) -> float:
            return ua + (ub - ua) * (t - t0) / dt

        t = t0
        while t < t1 - 1e-15:
            if rest:
                ta, tb = ug(t), ug(t1)
                tan_a = math.tan(a)
                if ta < -tan_a:
                    s = 1
                elif not sys.one_sided and ta > tan_a:
                    s = -1
                elif tb < -tan_a:
                    t = t + (-tan_a - ta) / (ub - ua) * dt
                    s = 1
                elif not sys.one_sided and tb > tan_a:
                    t = t + (tan_a - ta) / (ub - ua) * dt
                    s = -1
                else:
                    break
                rest, theta, omega = False, 0.0, 0.0
                continue
            k_s = sys.K if intact[s] else 0.0

            def f(tt, y, s=s, k_s=k_s):
                th = y[0]
                return [
                    y[1],
                    -sys.p2
                    * (math.sin(a * s - th) + ug(tt) * math.cos(a * s - th) + k_s * math.sin(th)),
                ]

            def ev_impact(tt, y, s=s):
                return s * y[0]

            ev_impact.terminal, ev_impact.direction = True, -1 * 1

            def ev_rupture(tt, y, s=s):
                return s * y[0] - sys.theta_max

            ev_rupture.terminal, ev_rupture.direction = True, 1

            def ev_collapse(tt, y, s=s):
                return s * y[0] - level_c

            ev_collapse.terminal, ev_collapse.direction = True, 1
            events = [ev_impact, ev_collapse] + (
                [ev_rupture] if k_s > 0 and math.isfinite(sys.theta_max) else []
            )
            # the impact event must not fire at the start of the step (θ = 0 after an impact)
            sol = solve_ivp(
                f,
                (t, t1),
                [theta, omega],
                method="DOP853",
                rtol=1e-11,
                atol=1e-14,
                events=events,
                dense_output=True,
            )
            # peak |θ| on the dense output
            tt = np.linspace(t, sol.t[-1], 12)
            peak = max(peak, float(np.max(np.abs(sol.sol(tt)[0]))), abs(sol.y[0, -1]))
            fired = [
                (k, te[0]) for k, te in enumerate(sol.t_events) if len(te) and te[0] > t + 1e-14
            ]
            if not fired:
                theta, omega = sol.y[0, -1], sol.y[1, -1]
                t = t1
                continue
            k, te = min(fired, key=lambda kv: kv[1])
            y = sol.sol(te)
            theta, omega, t = y[0], y[1], te
            name = events[k].__name__
            if name == "ev_impact":
                impacts += 1
                theta = 0.0
                if sys.one_sided:
                    omega = -sys.e_vel * omega
                else:
                    omega = sys.e_vel * omega
                    s = -s
                if abs(omega) < 1e-7 * math.sqrt(sys.p2):
                    rest, omega = True, 0.0
            elif name == "ev_collapse":
                return {"peak": level_c, "collapsed": True, "impacts": impacts}
            else:
                theta = s * sys.theta_max
                if shared:
                    intact = {1: False, -1: False}
                else:
                    intact[s] = False
                if sys.energy_transfer:
                    boost = 2 * sys.p2 * sys.K * (1 - math.cos(sys.theta_max))
                    omega = math.copysign(math.sqrt(omega**2 + boost), omega)
    return {"peak": peak, "collapsed": abs(theta) >= a, "impacts": impacts}
