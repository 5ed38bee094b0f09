"""The lognormal fragility curves of the Results tab, as plain numbers (no Textual).

A case's fit (results.json ``cases[i].scatter.fragility``, docs/model.md) gives the median
collapse acceleration θ [g] and the dispersion β [-]; the probability of collapse at a peak
ground acceleration a [g] is P(a) = Φ(ln(a/θ)/β), Φ the standard normal distribution.
"""

from __future__ import annotations

import math
from collections.abc import Sequence


def lognormal_cdf(a: float, median: float, beta: float) -> float:
    """P(collapse) [-] at PGA ``a`` [g] of a lognormal fit (``median`` [g], ``beta`` [-]).

    0 for a ≤ 0; Φ(z) = (1 + erf(z/√2))/2.
    """
    if not (median > 0.0 and beta > 0.0):
        raise ValueError(f"median and beta must be > 0, got {median!r}, {beta!r}")
    if a <= 0.0:
        return 0.0
    z = math.log(a / median) / beta
    return 0.5 * (1.0 + math.erf(z / math.sqrt(2.0)))


def pga_axis(
    medians: Sequence[float], betas: Sequence[float], demand: float, n: int = 120
) -> list[float]:
    """``n`` evenly spaced PGAs [g] from 0 to past every curve's 98th percentile
    (θ·exp(2.05·β)) and the demand, so that every curve rises to the top of the plot."""
    tops = [m * math.exp(2.05 * b) for m, b in zip(medians, betas, strict=True)]
    top = max([*tops, 1.2 * demand]) if tops or demand > 0 else 1.0
    return [top * i / (n - 1) for i in range(n)]
