"""The collapse fraction of a case's records at each intensity of the ladder of the effective
collapse intensity (docs/model.md §11), and the fragility fitted to it (Baker 2015).

Every record's sampling runs the ladder C₀·r^(k+offset) in order (its transitions refined in
between); ladder point k of record r is the intensity C₀,r·r^(k+offset)·PGA_r (a_RM·r^(k+offset)
for every record of a wall at ground level).  Where a record's sampling stopped early (the wall
had fallen at every ladder point of a band), the points above count as collapsed, as the
integral of §11 takes them; the levels above the highest any record ran are left out.
"""

from __future__ import annotations

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
        ran = {p.multiplier: p.collapsed for p in r.curve}
        outcomes.append([ran[c] for c in steps if c in ran])
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
