"""The third contestant of the speed benchmark: scipy's ``solve_ivp`` with event location.

The unreinforced wall about its base corners (docs/model.md §3), integrated one sample interval
at a time (the ground acceleration is linear there) by RK45 at rtol 1e-8 with the impact and
the fall as terminal events.  Only its throughput is measured (simulated seconds per
CPU-second); it is far too slow for whole IDAs.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp

G = 9.80665


def run_unreinforced(
    acc: NDArray[np.float64], dt: float, scale: float, thickness: float, height: float,
    one_sided: bool,
) -> bool:  # fmt: skip
    """True when the wall falls (|θ| reaches π/2) during the record."""
    alpha = math.atan2(thickness, height)
    p2 = 3.0 * G / (2.0 * math.hypot(thickness, height))
    one = 1.0 - 1.5 * math.sin(alpha) ** 2
    e_imp = abs(one**2 * (1.0 - 1.5 * math.cos(alpha) ** 2)) if one_sided else one
    u = scale * np.asarray(acc, dtype=float) / G
    theta, omega, s, resting = 0.0, 0.0, 1.0, True
    tan_a = math.tan(alpha)
    for i in range(u.shape[0] - 1):
        ua, slope = u[i], (u[i + 1] - u[i]) / dt
        t0 = 0.0
        while t0 < dt:
            if resting:
                ue = ua + slope * dt
                if ue < -tan_a or (not one_sided and ue > tan_a):
                    level = -tan_a if ue < -tan_a else tan_a
                    ux = ua + slope * t0
                    t0 = t0 if abs(ux) > tan_a else t0 + (level - ux) / slope
                    s, resting, theta, omega = (1.0 if level < 0 else -1.0), False, 0.0, 0.0
                else:
                    break

            def rhs(
                t: float, y: NDArray[np.float64], s: float = s, ua: float = ua, k: float = slope
            ) -> list[float]:
                ug = ua + k * t
                return [
                    y[1],
                    -p2 * (math.sin(alpha * s - y[0]) + ug * math.cos(alpha * s - y[0])),
                ]

            def impact(t: float, y: NDArray[np.float64], s: float = s) -> float:
                return s * y[0]

            def fall(t: float, y: NDArray[np.float64], s: float = s) -> float:
                return s * y[0] - 0.5 * math.pi

            impact.terminal = True  # type: ignore[attr-defined]
            impact.direction = -1  # type: ignore[attr-defined]
            fall.terminal = True  # type: ignore[attr-defined]
            sol = solve_ivp(
                rhs, (t0, dt), [theta, omega], method="RK45", rtol=1e-8, atol=1e-12,
                events=(impact, fall),
            )  # fmt: skip
            theta, omega = float(sol.y[0, -1]), float(sol.y[1, -1])
            if sol.status == 1 and sol.t_events[1].size:
                return True
            if sol.status == 1 and sol.t_events[0].size:
                t0 = float(sol.t_events[0][0])
                theta = 0.0
                omega = (-e_imp if one_sided else e_imp) * omega
                s = s if one_sided else -s
                if abs(omega) < 1e-7 * math.sqrt(p2):
                    resting, omega = True, 0.0
                continue
            t0 = dt
    return False
