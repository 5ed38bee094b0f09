"""The collapse fraction of a case's records at each intensity of the ladder of the effective
collapse intensity (docs/model.md §11), and the fragility fitted to it (Baker 2015).

Ladder point k of record r is the intensity C₀,r·r^(k+offset)·PGA_r (a_RM·r^(k+offset) for
every record of a wall at ground level).  The default sampling runs only some of them (the
coarse ladder up to the first collapse, the collapsed runs at a longer step, §11.2): a level
not run takes the outcome of the record's nearest sample in ln C, the midpoint rule of the
integral (below the first sample the wall stands).  Where a record's sampling stopped early
(the wall had fallen at every point run over a band), the levels above count as collapsed, as
the integral of §11 takes them; the levels above the highest any record reached are left out.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence

import numpy as np

from frp_assess.assess.statistics import LognormalFragility, fit_binomial_fragility
from frp_assess.dynamics import IdaResult, IdaSettings
from frp_assess.dynamics.effective import ladder
from frp_assess.motions import G
from frp_assess.results.model import CollapseFraction


def collapse_fractions(
    results: Sequence[IdaResult], settings: IdaSettings
) -> tuple[CollapseFraction, ...]:
    """Per ladder level: the intensity [g] (the geometric mean of the records' own), the
    records that collapsed there and the records (module docstring); empty unless every
    result is of the effective rule."""
    if not results or any(r.capacity != "effective" for r in results):
        return ()
    outcomes: list[list[bool]] = []  # per record, per ladder level run
    levels: list[np.ndarray] = []  # per record, every ladder level [g]
    for r in results:
        steps = ladder(r.c0, settings.max_multiplier * r.c0, settings.ladder_ratio, settings.offset)
        outcomes.append(_outcomes_at(steps, [(p.multiplier, p.collapsed) for p in r.curve]))
        levels.append(steps * (r.pga / G))
    top = max(len(o) for o in outcomes)
    if top == 0:
        return ()
    out = []
    for k in range(top):
        # a level past a record's early stop: collapsed (the integral's shortcut)
        fell = sum(1 for o in outcomes if (o[k] if k < len(o) else True))
        ln_im = [math.log(float(lv[k])) for lv in levels if k < lv.size]
        out.append(CollapseFraction(math.exp(sum(ln_im) / len(ln_im)), fell, len(outcomes)))
    return tuple(out)


def _outcomes_at(steps: np.ndarray, samples: Sequence[tuple[float, bool]]) -> list[bool]:
    """Whether the wall fell at each ladder level up to the highest sample (module docstring:
    the sample's outcome where it ran, else the nearest sample's in ln C; a tie: the lower)."""
    pts = sorted(samples)
    if not pts:
        return []
    ln = [math.log(c) for c, _ in pts]
    out = []
    for c in steps:
        if c > pts[-1][0]:
            break
        x = math.log(float(c))
        i = bisect.bisect_left(ln, x)
        if i < len(pts) and ln[i] == x:
            out.append(pts[i][1])
        elif i == 0:
            out.append(False)  # below the first sample the wall stands
        else:
            out.append(pts[i][1] if ln[i] - x < x - ln[i - 1] else pts[i - 1][1])
    return out


def fraction_fragility(fractions: Sequence[CollapseFraction]) -> LognormalFragility | None:
    """The lognormal fitted to ``fractions`` by binomial maximum likelihood (None: the
    outcomes do not overlap, :func:`~frp_assess.assess.statistics.fit_binomial_fragility`)."""
    if not fractions:
        return None
    return fit_binomial_fragility(
        [f.intensity for f in fractions],
        [f.collapsed for f in fractions],
        [f.records for f in fractions],
    )
