"""Intensity envelopes I(t) ∈ [0, 1] of artificial accelerograms (pure functions, t in s).

* trapezoidal -- linear rise over ``rise``, 1 over ``stationary``, linear decay to 0 at the end;
* compound -- Jennings, Housner & Tsai (1968): (t/t_r)² rise, 1 over ``stationary``, then
  exp(−c·(t − t_2)) with c such that the envelope is 0.05 at the end;
* exponential -- a gamma-type envelope (t/t_p)^α·exp(α(1 − t/t_p)) (the continuous analogue of
  Saragoni & Hart 1974), peak 1 at t_p = rise + stationary/2, α chosen so the envelope is
  ≥ 1/√2 for ``stationary`` seconds (its "strong part"; it has no flat part).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from frp_assess import libm

ENVELOPES: tuple[str, ...] = ("trapezoidal", "compound", "exponential")


def trapezoidal(t: NDArray[np.float64], rise: float, stationary: float, total: float) -> NDArray:
    """Linear rise on [0, rise], 1 on [rise, rise + stationary], linear to 0 at ``total`` [s]."""
    t2 = rise + stationary
    up = np.clip(t / rise, 0.0, 1.0) if rise > 0 else np.ones_like(t)
    down = np.clip((total - t) / max(total - t2, 1e-12), 0.0, 1.0)
    return np.minimum(up, down)


def compound(t: NDArray[np.float64], rise: float, stationary: float, total: float) -> NDArray:
    """Jennings et al. (1968): quadratic rise, flat, exponential decay to 0.05 at ``total``."""
    t2 = rise + stationary
    c = -math.log(0.05) / max(total - t2, 1e-12)
    up = np.clip(t / rise, 0.0, 1.0) ** 2 if rise > 0 else np.ones_like(t)
    return np.where(t <= t2, up, libm.exp(-c * (t - t2)))


def _gamma(t: NDArray[np.float64], tp: float, alpha: float) -> NDArray:
    x = np.maximum(t, 0.0) / tp
    with np.errstate(divide="ignore"):
        return libm.exp(alpha * (1.0 + libm.log(np.maximum(x, 1e-300)) - x))


def exponential(t: NDArray[np.float64], rise: float, stationary: float, total: float) -> NDArray:
    """Gamma-type envelope, ≥ 1/√2 over ``stationary`` s around its peak at rise + stationary/2."""
    tp = rise + 0.5 * stationary
    grid = np.linspace(0.0, total, 2001)
    lo, hi = 0.05, 500.0
    for _ in range(60):  # bisection: a larger α gives a narrower envelope
        alpha = math.sqrt(lo * hi)
        width = np.count_nonzero(_gamma(grid, tp, alpha) >= 2**-0.5) * (grid[1] - grid[0])
        lo, hi = (alpha, hi) if width > stationary else (lo, alpha)
    return _gamma(t, tp, math.sqrt(lo * hi))


def envelope(
    kind: str, t: NDArray[np.float64], rise: float, stationary: float, total: float
) -> NDArray[np.float64]:
    """The envelope ``kind`` (one of :data:`ENVELOPES`) at times ``t`` [s]."""
    functions = {"trapezoidal": trapezoidal, "compound": compound, "exponential": exponential}
    if kind not in functions:
        raise ValueError(f"unknown envelope {kind!r}; expected one of {', '.join(ENVELOPES)}")
    return np.asarray(functions[kind](np.asarray(t, dtype=float), rise, stationary, total))
