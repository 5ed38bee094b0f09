"""The effective collapse intensity of a record (docs/model.md §11).

    a_c = C₀ · exp( ∫ from ln C₀ to ln C_max of S(C) d(ln C) )

with S = 1 where the wall stands when the scaled record has ended, 0 where it collapsed.
S is known at the sampled multipliers only (by default
:func:`~frp_assess.dynamics.ida_refine.next_refined` chooses them); between two samples it is
taken as the outcome of the nearer one in ln C (the midpoint rule: two samples that agree hold
their outcome over the whole gap, two that disagree meet halfway; the sampling bisects such a
pair to the tolerance where it follows a run of agreeing samples, docs/model.md §11.2).  Below
the first sample the wall stands (below C₀ nothing moves); above the last one, its outcome
holds up to C_max (after the sampling's early stop: collapsed, the shortcut of §11 (ii)).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from frp_assess.dynamics.ida import IdaPoint

#: The early stop of the sampling (docs/model.md §11): once the ladder points have collapsed
#: without a break over this ratio of multipliers, the wall is taken as collapsed up to C_max.
EARLY_STOP_BAND = 1.5
#: The coarse ladder of the default sampling (docs/model.md §11.2, design (e)): every this many
#: points of the fine ladder C₀·r^(k+offset), r = ladder_ratio (r^8 ≈ 1.104 for 1.0125); 1:
#: the plain ladder of :func:`~frp_assess.dynamics.ida_search.next_sample`.
COARSE_STEPS = 8
#: The fine ladder starts this ratio below the first collapse found on the coarse one.
FIRST_COLLAPSE_MARGIN = 1.35
#: A ladder cell whose ends disagree is walked at this many times the ladder's density before
#: its changes of outcome are bisected (docs/model.md §11).
CELL_SUBDIVISIONS = 1


def ladder(c0: float, c_max: float, ratio: float, offset: float) -> NDArray[np.float64]:
    """C₀·r^(k+offset), k = 0, 1, … up to C_max (docs/model.md §11)."""
    out: list[float] = []
    while (c := c0 * ratio ** (len(out) + offset)) <= c_max * (1.0 + 1e-12):
        out.append(c)
    return np.array(out)


@dataclass(frozen=True)
class EffectiveCapacity:
    """What the samples of one record give (multipliers C [-])."""

    multiplier: float  #: a_c/PGA: the effective collapse multiplier
    lower_bound: bool  #: the wall stood at the last sample: a_c counts no fall above it
    first_collapse: float | None  #: the lowest C that collapsed (the paper's convention)
    windows_below: int  #: collapse windows (runs of collapsed samples) that begin below a_c


def effective_capacity(
    samples: Sequence[tuple[float, bool]], c0: float, c_max: float
) -> EffectiveCapacity:
    """The integral of the module docstring over ``samples`` = (C, collapsed), any order."""
    pts = sorted(samples)
    if not pts or pts[0][0] > c0:
        pts.insert(0, (c0, False))  # below the ladder the wall stands
    hi = math.log(c_max)
    standing = 0.0
    for (ca, fa), (cb, fb) in zip(pts, pts[1:], strict=False):
        xa, xb = math.log(ca), math.log(cb)
        mid = 0.5 * (xa + xb)
        standing += (0.0 if fa else mid - xa) + (0.0 if fb else xb - mid)
    last_c, last_fell = pts[-1]
    if not last_fell:
        standing += max(0.0, hi - math.log(last_c))
    a_c = c0 * math.exp(standing)
    windows = 0
    fell_before = False
    for c, fell in pts:
        if fell and not fell_before and c < a_c:
            windows += 1
        fell_before = fell
    first = next((c for c, fell in pts if fell), None)
    return EffectiveCapacity(a_c, not last_fell, first, windows)


def collapse_and_below(curve: Sequence[IdaPoint], capacity: float) -> tuple[float, float | None]:
    """The lowest C of ``curve`` that collapsed at or above ``capacity`` (else the highest that
    collapsed, else ``capacity``) and the largest C below it that stood (None: none): the
    time histories that show a record's collapse at its effective capacity."""
    fell = [p.multiplier for p in curve if p.collapsed]
    above = [c for c in fell if c >= capacity]
    c = min(above) if above else (max(fell) if fell else capacity)
    stood = [p.multiplier for p in curve if not p.collapsed and p.multiplier < c]
    return c, (max(stood) if stood else None)
